#include "driver/analyses/LinearModel.h"

#include "driver/Simulation.h"

#include <algorithm>
#include <cmath>

namespace milldyn {

void calcUndampedModes(LinearModel& lm) {
    const int n = static_cast<int>(lm.M.rows());
    // Undamped modes: K is symmetric for our elements up to the differencing
    // error; its symmetric part is what the generalized solver needs.
    const Eigen::MatrixXd Ksym = 0.5 * (lm.K + lm.K.transpose());
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> modes(Ksym, lm.M);
    lm.naturalFrequencies = modes.eigenvalues().cwiseMax(0.0).cwiseSqrt();
    lm.modeShapes = modes.eigenvectors();
    for (int c = 0; c < n; ++c) {
        Eigen::Index at = 0;
        lm.modeShapes.col(c).cwiseAbs().maxCoeff(&at);
        lm.modeShapes.col(c) /= lm.modeShapes(at, c);
    }
}

LinearModel linearizeScene(const Scene& scene, const SimTK::State& operatingPoint, bool withModes) {
    const SimTK::System& system = scene.system();
    SimTK::State x0 = operatingPoint;
    scene.setExcitationsOn(x0, false);
    const int n = x0.getNU();
    if (x0.getNQ() != n)
        throw AnalysisError("linearize: only joints whose q̇ = u (pins, gimbals, bushings) are supported, got nq = " +
                            std::to_string(x0.getNQ()) + ", nu = " + std::to_string(n));
    // Constraints (a rigid GearPair, GearMesh, a rigid BeltDrive) tie the
    // coordinates: M, C and K would have to be reduced to the independent
    // ones, which this linearization does not do; refuse rather than give
    // the unconstrained system's modes.
    const auto& matter = scene.matter();
    for (SimTK::ConstraintIndex c(0); c < matter.getNumConstraints(); ++c)
        if (!matter.getConstraint(c).isDisabled(x0))
            throw AnalysisError("linearize: the model has kinematic constraints (a rigid GearPair or BeltDrive, a "
                                "GearMesh), which this linearization does not reduce; use GearPair law: compliant");
    const auto& probes = scene.probes();
    const int np = static_cast<int>(probes.size());

    // Perturbs q or u entry j by h and returns (udot, probe values).
    auto evaluate = [&](bool onQ, int j, double h, Eigen::VectorXd& udot, Eigen::VectorXd& out) {
        SimTK::State s = x0;
        if (onQ) s.updQ()[j] += h;
        else s.updU()[j] += h;
        system.realize(s, SimTK::Stage::Acceleration);
        udot.resize(n);
        for (int i = 0; i < n; ++i) udot[i] = s.getUDot()[i];
        out.resize(np);
        for (int p = 0; p < np; ++p) out[p] = probes[p].value(s);
    };

    LinearModel lm;
    SimTK::Matrix Msim;
    system.realize(x0, SimTK::Stage::Position);
    scene.matter().calcM(x0, Msim);
    lm.M.resize(n, n);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) lm.M(i, j) = Msim(i, j);

    Eigen::MatrixXd dUdq(n, n), dUdu(n, n);
    lm.outputQ.resize(np, n);
    lm.outputU.resize(np, n);
    for (int j = 0; j < n; ++j) {
        for (int which = 0; which < 2; ++which) {
            const bool onQ = which == 0;
            const double base = onQ ? x0.getQ()[j] : x0.getU()[j];
            // Central differences; the step scales with the value, and is
            // large enough that round-off in the accelerations stays small.
            const double h = 1e-5 * std::max(1.0, std::abs(base));
            Eigen::VectorXd up, um, op, om;
            evaluate(onQ, j, +h, up, op);
            evaluate(onQ, j, -h, um, om);
            (onQ ? dUdq : dUdu).col(j) = (up - um) / (2 * h);
            (onQ ? lm.outputQ : lm.outputU).col(j) = (op - om) / (2 * h);
        }
    }
    lm.K = -lm.M * dUdq;
    lm.C = -lm.M * dUdu;

    lm.A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
    lm.A.topRightCorner(n, n) = Eigen::MatrixXd::Identity(n, n);
    lm.A.bottomLeftCorner(n, n) = dUdq;
    lm.A.bottomRightCorner(n, n) = dUdu;
    lm.dofNames = mobilityNames(scene, x0);
    for (const auto& p : probes) {
        lm.outputNames.push_back(p.name);
        lm.outputUnits.push_back(p.unit);
    }
    if (!withModes) return lm;
    Eigen::EigenSolver<Eigen::MatrixXd> eig(lm.A);
    std::vector<std::complex<double>> ev(eig.eigenvalues().data(), eig.eigenvalues().data() + 2 * n);
    std::sort(ev.begin(), ev.end(), [](const auto& a, const auto& b) {
        if (std::abs(std::abs(a.imag()) - std::abs(b.imag())) > 1e-9 * (1 + std::abs(a)))
            return std::abs(a.imag()) < std::abs(b.imag());
        if (a.real() != b.real()) return a.real() > b.real();
        return a.imag() > b.imag();
    });
    lm.eigenvalues = Eigen::Map<Eigen::VectorXcd>(ev.data(), 2 * n);

    calcUndampedModes(lm);
    return lm;
}

Eigen::VectorXcd harmonicResponse(const LinearModel& model, double P, const Eigen::VectorXcd& force) {
    const std::complex<double> i(0, 1);
    const Eigen::MatrixXcd Z = model.K.cast<std::complex<double>>() -
                               (P * P) * model.M.cast<std::complex<double>>() +
                               (i * P) * model.C.cast<std::complex<double>>();
    return Z.fullPivLu().solve(force);
}

}  // namespace milldyn
