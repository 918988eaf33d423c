#include "driver/analyses/LinearModel.h"

#include "driver/Simulation.h"
#include "driver/analyses/Analysis.h"
#include "driver/analyses/AnalysisRegistry.h"
#include "plugins/scene/DriveCapabilities.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <tuple>

namespace milldyn {

void calcUndampedModes(LinearModel& lm) {
    const int r = static_cast<int>(lm.M.rows());
    // Undamped modes: K is symmetric for our elements up to the differencing
    // error; its symmetric part is what the generalized solver needs.
    const Eigen::MatrixXd Ksym = 0.5 * (lm.K + lm.K.transpose());
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> modes(Ksym, lm.M);
    lm.naturalFrequencies = modes.eigenvalues().cwiseMax(0.0).cwiseSqrt();
    // Expanded to every mobility, u = N·v (N empty: the coordinates are the mobilities).
    lm.modeShapes = lm.N.size() ? Eigen::MatrixXd(lm.N * modes.eigenvectors()) : modes.eigenvectors();
    for (int c = 0; c < r; ++c) {
        Eigen::Index at = 0;
        lm.modeShapes.col(c).cwiseAbs().maxCoeff(&at);
        lm.modeShapes.col(c) /= lm.modeShapes(at, c);
    }
}

// The drives with electrical states of their own (ElectricalStates: a
// DqInductionMotor's fluxes), in build order.
std::vector<std::string> dqMachineNames(const Scene& scene) {
    std::vector<std::string> names;
    for (const Scene::Drive& d : scene.drives())
        if (scene.findElement<ElectricalStates>(d.element)) names.push_back(d.element);
    return names;
}

namespace {

/// "between a and b": the bodies a constraint ties, for messages.
std::string constraintName(const Scene& scene, const SimTK::Constraint& c) {
    std::vector<std::string> names;
    auto add = [&](const SimTK::MobilizedBody& b) {
        for (const SceneBody& sb : scene.bodies())
            if (sb.mobod.getMobilizedBodyIndex() == b.getMobilizedBodyIndex() &&
                std::find(names.begin(), names.end(), sb.name) == names.end())
                names.push_back(sb.name);
    };
    for (SimTK::ConstrainedMobilizerIndex i(0); i < c.getNumConstrainedMobilizers(); ++i)
        add(c.getMobilizedBodyFromConstrainedMobilizer(i));
    for (SimTK::ConstrainedBodyIndex i(0); i < c.getNumConstrainedBodies(); ++i)
        add(c.getMobilizedBodyFromConstrainedBody(i));
    std::string out = "constraint " + std::to_string(int(c.getConstraintIndex())) + " (between";
    for (std::size_t i = 0; i < names.size(); ++i) out += (i ? (i + 1 == names.size() ? " and " : ", ") : " ") + names[i];
    return out + ")";
}

Eigen::MatrixXd constraintJacobian(const SimTK::SimbodyMatterSubsystem& matter, const SimTK::State& s) {
    SimTK::Matrix Gsim;
    matter.calcG(s, Gsim);
    Eigen::MatrixXd G(Gsim.nrow(), Gsim.ncol());
    for (int i = 0; i < Gsim.nrow(); ++i)
        for (int j = 0; j < Gsim.ncol(); ++j) G(i, j) = Gsim(i, j);
    return G;
}

/// The independent coordinates of holonomic constraints linear in q:
/// G·u = 0 (G = ∂perr/∂q, constant) has the solutions u = N·v, v the
/// velocities of the mobilities kept independent. The dependent ones are
/// picked from the last mobility back (the first bodies of the file, the
/// drive's, stay independent): a mobility is dependent when its column of
/// G raises the rank of the dependent columns taken so far. Fills
/// lm.N, lm.independent, lm.eliminated; throws for constraints it cannot
/// reduce (nonholonomic, acceleration-only, or with G changing with q).
void calcIndependentBasis(const Scene& scene, const SimTK::State& x0, LinearModel& lm) {
    const auto& matter = scene.matter();
    const int n = x0.getNU();
    std::vector<std::string> rowOwner;  // the constraint each row of G belongs to
    for (SimTK::ConstraintIndex c(0); c < matter.getNumConstraints(); ++c) {
        const SimTK::Constraint& con = matter.getConstraint(c);
        if (con.isDisabled(x0)) continue;
        int mp = 0, mv = 0, ma = 0;
        con.getNumConstraintEquationsInUse(x0, mp, mv, ma);
        if (mv || ma)
            throw AnalysisError("linearize: " + constraintName(scene, con) +
                                " is nonholonomic or acceleration-only, which the linearization cannot reduce to "
                                "independent coordinates");
        for (int k = 0; k < mp; ++k) rowOwner.push_back(constraintName(scene, con));
    }
    const std::vector<std::string> names = mobilityNames(scene, x0);
    if (rowOwner.empty()) {
        for (int j = 0; j < n; ++j) lm.independent.push_back(j);
        return;
    }
    const Eigen::MatrixXd G = constraintJacobian(matter, x0);
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qrG(G);
    const int rank = static_cast<int>(qrG.rank());
    std::vector<int> dependent;
    Eigen::MatrixXd taken(G.rows(), 0);
    for (int j = n - 1; j >= 0 && static_cast<int>(dependent.size()) < rank; --j) {
        Eigen::MatrixXd trial(G.rows(), taken.cols() + 1);
        trial << taken, G.col(j);
        if (Eigen::ColPivHouseholderQR<Eigen::MatrixXd>(trial).rank() > taken.cols()) {
            taken = trial;
            dependent.push_back(j);
        }
    }
    std::vector<bool> isDependent(n, false);
    for (int j : dependent) isDependent[j] = true;
    for (int j = 0; j < n; ++j) (isDependent[j] ? lm.eliminated : lm.independent).push_back(j);
    const int r = static_cast<int>(lm.independent.size());
    Eigen::MatrixXd Gi(G.rows(), r), Gd(G.rows(), dependent.size());
    for (int k = 0; k < r; ++k) Gi.col(k) = G.col(lm.independent[k]);
    for (std::size_t k = 0; k < dependent.size(); ++k) Gd.col(k) = G.col(dependent[k]);
    // G_d·u_d + G_i·u_i = 0 → u_d = −G_d⁺·G_i·u_i (G_d has full column rank;
    // rows of redundant constraints are consistent).
    const Eigen::MatrixXd Ud = -Gd.colPivHouseholderQr().solve(Gi);
    lm.N = Eigen::MatrixXd::Zero(n, r);
    for (int k = 0; k < r; ++k) lm.N(lm.independent[k], k) = 1;
    for (std::size_t k = 0; k < dependent.size(); ++k) lm.N.row(dependent[k]) = Ud.row(k);
    const double scale = G.cwiseAbs().maxCoeff() * std::max(1.0, lm.N.cwiseAbs().maxCoeff());
    if ((G * lm.N).cwiseAbs().maxCoeff() > 1e-9 * scale)
        throw AnalysisError("linearize: the constraints' Jacobian has no consistent independent coordinates "
                            "(redundant constraints that contradict each other)");
    // Linear in q: G must not change when the state moves along the
    // constrained motion (gear and belt ratio constraints: G is constant).
    for (int k = 0; k < r; ++k) {
        for (double step : {-1e-2, 1e-2}) {
            SimTK::State s = x0;
            for (int i = 0; i < n; ++i) s.updQ()[i] += step * lm.N(i, k);
            scene.system().realize(s, SimTK::Stage::Velocity);
            const Eigen::MatrixXd Gs = constraintJacobian(matter, s);
            for (Eigen::Index row = 0; row < G.rows(); ++row)
                if ((Gs.row(row) - G.row(row)).cwiseAbs().maxCoeff() > 1e-9 * scale)
                    throw AnalysisError("linearize: " + rowOwner[row] + " is not linear in the angles (its Jacobian "
                                        "changes as " + names[lm.independent[k]] +
                                        " turns), which the linearization cannot reduce");
        }
    }
}

}  // namespace

const char* motorModelName(MotorModel model) {
    switch (model) {
        case MotorModel::DqStates: return "dq_states";
        case MotorModel::FrozenFlux: return "frozen_flux";
        case MotorModel::StaticSlope: return "static_slope";
    }
    return "";
}

MotorModel motorModelFromName(const std::string& word) {
    if (word == "frozen_flux") return MotorModel::FrozenFlux;
    if (word == "static_slope") return MotorModel::StaticSlope;
    if (word == "dq_states") return MotorModel::DqStates;
    throw AnalysisError("motor_model: '" + word + "' is not one of dq_states, frozen_flux, static_slope");
}

ParamSchema motorModelParam() {
    return ParamSchema::choice("motor_model", {"dq_states", "frozen_flux", "static_slope"},
                               "how DqInductionMotor fluxes enter the linear model: dq_states (their flux states, "
                               "electrical damping), frozen_flux (held: no electrical damping), static_slope (the "
                               "steady torque-speed slope); InductionMotor is its static slope in all three")
        .optional("dq_states");
}

LinearModel linearizeScene(const Scene& scene, const SimTK::State& operatingPoint, bool withModes,
                           bool reduceConstraints, MotorModel motorModel) {
    const SimTK::System& system = scene.system();
    SimTK::State x0 = operatingPoint;
    scene.setExcitationsOn(x0, false);
    const int n = x0.getNU();
    if (x0.getNQ() != n)
        throw AnalysisError("linearize: only joints whose q̇ = u (pins, gimbals, bushings) are supported, got nq = " +
                            std::to_string(x0.getNQ()) + ", nu = " + std::to_string(n));
    system.realize(x0, SimTK::Stage::Velocity);  // calcG needs the velocity-stage bias
    LinearModel lm;
    const auto& matter = scene.matter();
    if (!reduceConstraints) {
        // This caller works in every mobility (forces, probes, loads per
        // body): constraints would need the reduced coordinates it does not
        // handle; refuse rather than give the unconstrained system's answer.
        for (SimTK::ConstraintIndex c(0); c < matter.getNumConstraints(); ++c)
            if (!matter.getConstraint(c).isDisabled(x0))
                throw AnalysisError("the model has kinematic constraints (a rigid GearPair or BeltDrive, a GearMesh: " +
                                    constraintName(scene, matter.getConstraint(c)) +
                                    "), which this analysis does not reduce (linearize, resonance_map and frequency_response do); make "
                                    "it compliant: GearPair and PlanetaryGearSet law: compliant with mesh_stiffness, "
                                    "or a GearMesh replaced by a compliant GearPair or PlanetaryGearSet");
    }
    calcIndependentBasis(scene, x0, lm);
    const int r = static_cast<int>(lm.independent.size());
    // Without constraints N = I: keep it implicit (lm.N empty).
    const Eigen::MatrixXd N = lm.N.size() ? lm.N : Eigen::MatrixXd::Identity(n, n);
    const auto& probes = scene.probes();
    const int np = static_cast<int>(probes.size());

    // Elements' own states (dq machines' fluxes): their z indices, and per
    // entry the speed its phasor pair turns at in steady running.
    std::vector<int> zIndex;
    std::vector<double> zFrame;
    for (const std::string& name : dqMachineNames(scene)) {
        const ElectricalStates* dq = scene.findElement<ElectricalStates>(name);
        system.realize(x0, SimTK::Stage::Acceleration);
        const int first = dq->firstElectricalState(x0);
        for (int k = 0; k < dq->electricalStateCount(); ++k) {
            zIndex.push_back(first + k);
            zFrame.push_back(dq->electricalFrameSpeed());
            lm.stateNames.push_back(name + "." + dq->electricalStateName(k));
        }
    }
    const int nz = static_cast<int>(zIndex.size());
    Eigen::VectorXd zdotOut;  // the last evaluation's ż of those states

    double maxUDot = 0, minStep = 1;  // for the round-off floor of the frequencies
    // Moves q or u by h along column k of N; returns (udot, probe values).
    auto evaluate = [&](bool onQ, int k, double h, Eigen::VectorXd& udot, Eigen::VectorXd& out) {
        SimTK::State s = x0;
        for (int i = 0; i < n; ++i) {
            if (N(i, k) == 0) continue;
            if (onQ) s.updQ()[i] += h * N(i, k);
            else s.updU()[i] += h * N(i, k);
        }
        system.realize(s, SimTK::Stage::Acceleration);
        udot.resize(n);
        for (int i = 0; i < n; ++i) udot[i] = s.getUDot()[i];
        zdotOut.resize(nz);
        for (int i = 0; i < nz; ++i) zdotOut[i] = s.getZDot()[zIndex[i]];
        maxUDot = std::max(maxUDot, udot.cwiseAbs().maxCoeff());
        out.resize(np);
        for (int p = 0; p < np; ++p) out[p] = probes[p].value(s);
    };

    SimTK::Matrix Msim;
    matter.calcM(x0, Msim);
    Eigen::MatrixXd Mfull(n, n);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) Mfull(i, j) = Msim(i, j);

    // dU·(∂u̇/∂v): the accelerations of every mobility as v moves; along N
    // the constraints stay satisfied, and u̇ stays in N's range.
    Eigen::MatrixXd dUdq(n, r), dUdu(n, r), dZdq(nz, r), dZdu(nz, r);
    lm.outputQ.resize(np, r);
    lm.outputU.resize(np, r);
    for (int k = 0; k < r; ++k) {
        const int j = lm.independent[k];
        for (int which = 0; which < 2; ++which) {
            const bool onQ = which == 0;
            const double base = onQ ? x0.getQ()[j] : x0.getU()[j];
            // Central differences; the step scales with the value, and is
            // large enough that round-off in the accelerations stays small.
            const double h = 1e-5 * std::max(1.0, std::abs(base));
            minStep = std::min(minStep, h);
            Eigen::VectorXd up, um, op, om;
            evaluate(onQ, k, +h, up, op);
            const Eigen::VectorXd zp = zdotOut;
            evaluate(onQ, k, -h, um, om);
            (onQ ? dUdq : dUdu).col(k) = (up - um) / (2 * h);
            (onQ ? dZdq : dZdu).col(k) = (zp - zdotOut) / (2 * h);
            (onQ ? lm.outputQ : lm.outputU).col(k) = (op - om) / (2 * h);
        }
    }
    // Nᵀ·(M·u̇ + Gᵀλ) = Nᵀ·f: the constraint forces drop out (G·N = 0).
    lm.M = N.transpose() * Mfull * N;
    lm.K = -N.transpose() * Mfull * dUdq;
    lm.C = -N.transpose() * Mfull * dUdu;
    // v̈ = (NᵀMN)⁻¹·NᵀM·ü; without constraints N = I and this is ∂u̇/∂q itself.
    const Eigen::MatrixXd dVdq = lm.N.size() ? Eigen::MatrixXd(lm.M.ldlt().solve(-lm.K)) : dUdq;
    const Eigen::MatrixXd dVdu = lm.N.size() ? Eigen::MatrixXd(lm.M.ldlt().solve(-lm.C)) : dUdu;

    lm.frequencyFloor = std::sqrt(100 * std::numeric_limits<double>::epsilon() * maxUDot / minStep);
    lm.A = Eigen::MatrixXd::Zero(2 * r, 2 * r);
    lm.A.topRightCorner(r, r) = Eigen::MatrixXd::Identity(r, r);
    lm.A.bottomLeftCorner(r, r) = dVdq;
    lm.A.bottomRightCorner(r, r) = dVdu;
    lm.motorModel = motorModel;
    lm.outputZ = Eigen::MatrixXd::Zero(np, nz);
    if (nz > 0) {
        // The states' own columns: ∂u̇/∂z and ∂ż/∂z by central differences,
        // the step scaled to the element's largest state.
        Eigen::MatrixXd dUdz(n, nz), dZdz(nz, nz);
        double zScale = 0;
        for (int i = 0; i < nz; ++i) zScale = std::max(zScale, std::abs(x0.getZ()[zIndex[i]]));
        const double h = 1e-6 * (zScale > 0 ? zScale : 1.0);
        for (int k = 0; k < nz; ++k) {
            Eigen::VectorXd up, um, zp, op;
            for (double sign : {1.0, -1.0}) {
                SimTK::State s = x0;
                s.updZ()[zIndex[k]] += sign * h;
                system.realize(s, SimTK::Stage::Acceleration);
                Eigen::VectorXd ud(n), zd(nz), od(np);
                for (int i = 0; i < n; ++i) ud[i] = s.getUDot()[i];
                for (int i = 0; i < nz; ++i) zd[i] = s.getZDot()[zIndex[i]];
                for (int p = 0; p < np; ++p) od[p] = probes[p].value(s);
                if (sign > 0) up = ud, zp = zd, op = od;
                else um = ud, dZdz.col(k) = (zp - zd) / (2 * h), lm.outputZ.col(k) = (op - od) / (2 * h);
            }
            dUdz.col(k) = (up - um) / (2 * h);
        }
        // In the frame turning with the phasors (z = R(t)·z̃, R(t0) = I):
        // dz̃/dt = ż − Ω·z̃, Ω = [[0, −ω], [ω, 0]] per pair.
        for (int i = 0; i + 1 < nz; i += 2)
            if (zFrame[i] > 0) {
                dZdz(i, i + 1) += zFrame[i];
                dZdz(i + 1, i) -= zFrame[i];
            }
        const Eigen::MatrixXd dVdz = lm.N.size() ? Eigen::MatrixXd(lm.M.ldlt().solve(N.transpose() * Mfull * dUdz)) : dUdz;
        lm.Afull = Eigen::MatrixXd::Zero(2 * r + nz, 2 * r + nz);
        lm.Afull.topLeftCorner(2 * r, 2 * r) = lm.A;
        lm.Afull.block(r, 2 * r, r, nz) = dVdz;
        lm.Afull.block(2 * r, 0, nz, r) = dZdq;
        lm.Afull.block(2 * r, r, nz, r) = dZdu;
        lm.Afull.bottomRightCorner(nz, nz) = dZdz;
        // Static slope: the fluxes at their steady state for the momentary
        // q, u (ż̃ = 0 in the supply's frame): z̃ = −A_zz⁻¹·A_zm·[q; u], which
        // turns the mechanical rows into A_mm − A_mz·A_zz⁻¹·A_zm. A_zz is
        // the machine's electrical matrix at the slip of the operating point,
        // invertible with resistances in both windings.
        const Eigen::PartialPivLU<Eigen::MatrixXd> zz(dZdz);
        const Eigen::MatrixXd elim = zz.solve(lm.Afull.bottomLeftCorner(nz, 2 * r));  // A_zz⁻¹·A_zm
        lm.Afrozen = lm.A;
        lm.Astatic = lm.A - lm.Afull.topRightCorner(2 * r, nz) * elim;
        if (motorModel == MotorModel::StaticSlope) {
            lm.A = lm.Astatic;
            lm.K = -lm.M * lm.A.bottomLeftCorner(r, r);
            lm.C = -lm.M * lm.A.bottomRightCorner(r, r);
            const Eigen::MatrixXd outElim = lm.outputZ * elim;
            lm.outputQ -= outElim.leftCols(r);
            lm.outputU -= outElim.rightCols(r);
            lm.outputZ.setZero();
        }
    }
    lm.bodyNames = mobilityNames(scene, x0);
    for (int j : lm.independent) lm.dofNames.push_back(lm.bodyNames[j]);
    for (const auto& p : probes) {
        lm.outputNames.push_back(p.name);
        lm.outputUnits.push_back(p.unit);
    }
    if (!withModes) return lm;
    auto sortedEigenvalues = [](const Eigen::MatrixXd& A) {
        Eigen::EigenSolver<Eigen::MatrixXd> eig(A);
        std::vector<std::complex<double>> ev(eig.eigenvalues().data(), eig.eigenvalues().data() + A.rows());
        std::sort(ev.begin(), ev.end(), [](const auto& a, const auto& b) {
            if (std::abs(std::abs(a.imag()) - std::abs(b.imag())) > 1e-9 * (1 + std::abs(a)))
                return std::abs(a.imag()) < std::abs(b.imag());
            if (a.real() != b.real()) return a.real() > b.real();
            return a.imag() > b.imag();
        });
        return Eigen::VectorXcd(Eigen::Map<Eigen::VectorXcd>(ev.data(), A.rows()));
    };
    lm.eigenvalues = sortedEigenvalues(lm.A);
    if (nz > 0) {
        lm.eigenvaluesFull = sortedEigenvalues(lm.Afull);
        lm.eigenvaluesFrozen = sortedEigenvalues(lm.Afrozen);
        lm.eigenvaluesStatic = sortedEigenvalues(lm.Astatic);
        if (motorModel == MotorModel::DqStates) lm.eigenvalues = lm.eigenvaluesFull;
    }

    calcUndampedModes(lm);
    return lm;
}

double rigidModeBound(const LinearModel& model) {
    const double top = model.naturalFrequencies.size() > 0 ? model.naturalFrequencies.maxCoeff() : 0.0;
    return std::max(1e-6 * top, model.frequencyFloor);
}

std::vector<int> elasticModes(const LinearModel& model) {
    const double bound = rigidModeBound(model);
    std::vector<int> out;
    for (Eigen::Index k = 0; k < model.naturalFrequencies.size(); ++k)
        if (model.naturalFrequencies[k] > bound) out.push_back(int(k));
    std::sort(out.begin(), out.end(),
              [&](int a, int b) { return model.naturalFrequencies[a] < model.naturalFrequencies[b]; });
    return out;
}

bool isRigidEigenvalue(const LinearModel& model, std::complex<double> lambda) {
    const double scale = model.eigenvalues.size() > 0 ? model.eigenvalues.cwiseAbs().maxCoeff() : 0.0;
    return std::abs(lambda) <= std::max(1e-9 * scale, model.frequencyFloor);
}

namespace {

/// For each oscillating eigenvalue (imag > 0, not rigid) of `frozen`, the
/// nearest one of `other` (oscillating, or real: overdamped) not taken yet (greedy, closest pairs
/// first); -1 where `other` has none left.
std::vector<int> matchModes(const LinearModel& lm, const Eigen::VectorXcd& frozen, const Eigen::VectorXcd& other) {
    std::vector<int> from, to;
    for (Eigen::Index i = 0; i < frozen.size(); ++i)
        if (frozen[i].imag() > 0 && !isRigidEigenvalue(lm, frozen[i])) from.push_back(int(i));
    for (Eigen::Index j = 0; j < other.size(); ++j)
        if (other[j].imag() >= 0 && !isRigidEigenvalue(lm, other[j])) to.push_back(int(j));  // overdamped too
    std::vector<std::tuple<double, int, int>> pairs;
    for (std::size_t a = 0; a < from.size(); ++a)
        for (int j : to) pairs.emplace_back(std::abs(frozen[from[a]] - other[j]), int(a), j);
    std::sort(pairs.begin(), pairs.end());
    std::vector<int> match(from.size(), -1);
    std::vector<bool> used(other.size(), false);
    for (const auto& [d, a, j] : pairs)
        if (match[a] < 0 && !used[j]) match[a] = j, used[j] = true;
    return match;
}

std::vector<int> oscillating(const LinearModel& lm, const Eigen::VectorXcd& ev) {
    std::vector<int> out;
    for (Eigen::Index i = 0; i < ev.size(); ++i)
        if (ev[i].imag() > 0 && !isRigidEigenvalue(lm, ev[i])) out.push_back(int(i));
    return out;
}

double dampingRatio(std::complex<double> l) { return -l.real() / std::abs(l); }

std::string formatted(double v, int digits) {
    char text[32];
    std::snprintf(text, sizeof text, "%.*g", digits, v);
    return text;
}

}  // namespace

DataTable modeDampingTable(const LinearModel& lm) {
    DataTable t{"mode_damping_by_motor_model",
                {"mode", "frequency_frozen_flux", "damping_ratio_frozen_flux", "frequency_static_slope",
                 "damping_ratio_static_slope", "frequency_dq_states", "damping_ratio_dq_states"},
                {"1", "Hz", "1", "Hz", "1", "Hz", "1"},
                {}};
    if (lm.Afull.size() == 0) {
        t.name.clear();
        return t;
    }
    const std::vector<int> modes = oscillating(lm, lm.eigenvaluesFrozen);
    const std::vector<int> toStatic = matchModes(lm, lm.eigenvaluesFrozen, lm.eigenvaluesStatic);
    const std::vector<int> toFull = matchModes(lm, lm.eigenvaluesFrozen, lm.eigenvaluesFull);
    for (std::size_t m = 0; m < modes.size(); ++m) {
        // A mode none of the other models has (more oscillating modes than
        // they have eigenvalues left) gets no row.
        if (toStatic[m] < 0 || toFull[m] < 0) continue;
        const auto f = lm.eigenvaluesFrozen[modes[m]], st = lm.eigenvaluesStatic[toStatic[m]],
                   fu = lm.eigenvaluesFull[toFull[m]];
        std::vector<double> row = {double(m + 1), f.imag() / (2 * M_PI), dampingRatio(f), st.imag() / (2 * M_PI),
                                   dampingRatio(st), fu.imag() / (2 * M_PI), dampingRatio(fu)};
        t.rows.push_back(row);
    }
    return t;
}

std::vector<std::string> motorDampingNotes(const Scene& scene, const LinearModel& lm) {
    std::vector<std::string> notes;
    std::vector<std::string> dq = dqMachineNames(scene), statics;
    for (const Scene::Drive& d : scene.drives())
        if (std::find(dq.begin(), dq.end(), d.element) == dq.end() && scene.findElement<StaticTorqueSpeedCurve>(d.element))
            statics.push_back(d.element);
    if (dq.empty() && statics.empty()) return notes;
    auto list = [](const std::vector<std::string>& names) {
        std::string out;
        for (std::size_t i = 0; i < names.size(); ++i) out += (i ? ", " : "") + names[i];
        return out;
    };
    std::string which = std::string("motor_model ") + motorModelName(lm.motorModel) + ": ";
    if (!dq.empty()) {
        which += list(dq) + (lm.motorModel == MotorModel::DqStates    ? " with their flux states (the electrical "
                                                                        "damping and stiffness, and the machines' own "
                                                                        "electrical modes)"
                             : lm.motorModel == MotorModel::FrozenFlux ? " with their fluxes frozen (no electrical "
                                                                         "damping)"
                                                                       : " as their steady torque-speed slope at the "
                                                                         "operating point (fluxes at steady state)");
    }
    if (!statics.empty()) {
        std::vector<std::string> types;  // of the static-curve drives, as the scene built them
        for (const ElementRecord& r : scene.elementRecords())
            if (std::find(statics.begin(), statics.end(), r.element) != statics.end() &&
                std::find(types.begin(), types.end(), r.type) == types.end())
                types.push_back(r.type);
        which += (dq.empty() ? "" : "; ") + list(statics) + " (" + list(types) +
                 ") as the static torque-speed slope at the operating point, in every motor model";
    }
    notes.push_back(which);
    if (dq.empty()) return notes;
    const DataTable t = modeDampingTable(lm);
    const int used = lm.motorModel == MotorModel::FrozenFlux ? 0 : lm.motorModel == MotorModel::StaticSlope ? 1 : 2;
    static const char* const kNames[] = {"frozen_flux", "static_slope", "dq_states"};
    for (const auto& row : t.rows) {
        std::string text = "mode " + formatted(row[0], 3) + ": damping ratio " + formatted(row[2 + 2 * used], 4) +
                           " at " + formatted(row[1 + 2 * used], 5) + " Hz from motor_model " + kNames[used] +
                           " (the one used here); the same mode";
        bool first = true;
        for (int k = 0; k < 3; ++k) {
            if (k == used) continue;
            text += std::string(first ? " " : ", ") + kNames[k] + " " + formatted(row[2 + 2 * k], 4) + " at " +
                    formatted(row[1 + 2 * k], 5) + " Hz";
            first = false;
        }
        notes.push_back(text + " (table mode_damping_by_motor_model; modes matched by nearest eigenvalue)");
    }
    return notes;
}

Eigen::VectorXcd harmonicResponse(const LinearModel& model, double P, const Eigen::VectorXcd& force,
                                  Eigen::VectorXcd* states) {
    const std::complex<double> i(0, 1);
    const int r = static_cast<int>(model.M.rows());
    if (model.motorModel == MotorModel::DqStates && model.Afull.size()) {
        // First order with the flux states: (iP·I − Afull)·x = b, b the
        // forcing's accelerations M⁻¹·f in the u rows.
        const int nx = static_cast<int>(model.Afull.rows());
        Eigen::VectorXcd b = Eigen::VectorXcd::Zero(nx);
        b.segment(r, r) = model.M.cast<std::complex<double>>().fullPivLu().solve(force);
        const Eigen::MatrixXcd Z = (i * P) * Eigen::MatrixXcd::Identity(nx, nx) - model.Afull.cast<std::complex<double>>();
        const Eigen::VectorXcd x = Z.fullPivLu().solve(b);
        if (states) *states = x.tail(nx - 2 * r);
        return x.head(r);
    }
    if (states) states->resize(0);
    const Eigen::MatrixXcd Z = model.K.cast<std::complex<double>>() -
                               (P * P) * model.M.cast<std::complex<double>>() +
                               (i * P) * model.C.cast<std::complex<double>>();
    return Z.fullPivLu().solve(force);
}

std::complex<double> harmonicProbeResponse(const LinearModel& model, double P, const Eigen::VectorXcd& force,
                                           int probe) {
    Eigen::VectorXcd z;
    const Eigen::VectorXcd X = harmonicResponse(model, P, force, &z);
    using C = std::complex<double>;
    C y = (model.outputQ.row(probe).cast<C>() * X).value() +
          C(0, P) * (model.outputU.row(probe).cast<C>() * X).value();
    if (z.size()) y += (model.outputZ.row(probe).cast<C>() * z).value();
    return y;
}

}  // namespace milldyn
