#include "plugins/motors/CageCircuitFit.h"

#include "plugins/scene/Format.h"

#include <Eigen/Dense>

#include <algorithm>
#include <atomic>
#include <map>
#include <memory>
#include <mutex>
#include <cmath>
#include <complex>
#include <limits>
#include <stdexcept>

namespace milldyn {

using Complex = std::complex<double>;

CagePoint cageSteadyState(const CageCircuit& c, double V, double f, int p, double s) {
    // The circuit of the per-phase equivalent (stator Zs = Rs + jωLsσ, the
    // magnetising branch jXm in parallel with each cage k's R_k/s + jωL_kσ),
    // solved by reducing the parallel branches: I0 = V/(Zs + 1/Y),
    // E = I0/Y, I_k = E/(R_k/s + jωL_kσ). The same equations as the mesh
    // matrix [Rs + j(Xs + Xm), jXm, …; s·jXm, R_k + s·j(X_k + Xm), …] with
    // its rotor rows divided by s, in a few complex operations: the fit
    // evaluates some 10⁵ slips, and the 3 × 3 full-pivot LU made reading a
    // datasheet motor cost 0.6 s of CPU (13.6 s under the fuzzer's
    // sanitizers, past its 10 s timeout).
    const double w = 2 * M_PI * f;
    const Complex Zs(c.statorResistance, w * c.statorLeakage);
    const Complex Zm(0, w * c.mainInductance);
    CagePoint out;
    Complex I0;
    double airGap = 0;
    if (s == 0) {
        I0 = V / (Zs + Zm);  // no rotor current at synchronous speed
    } else {
        Complex Y = 1.0 / Zm;
        for (std::size_t k = 0; k < c.rotorResistances.size(); ++k)
            Y += 1.0 / Complex(c.rotorResistances[k] / s, w * c.rotorLeakages[k]);
        I0 = V / (Zs + 1.0 / Y);
        const Complex E = I0 / Y;
        for (std::size_t k = 0; k < c.rotorResistances.size(); ++k)
            airGap += 3 * std::norm(E / Complex(c.rotorResistances[k] / s, w * c.rotorLeakages[k])) *
                      c.rotorResistances[k] / s;
    }
    out.current = std::abs(I0);
    out.inputPower = 3 * std::real(V * std::conj(I0));
    out.powerFactor = out.current > 0 ? out.inputPower / (3 * V * out.current) : 0;
    out.torque = s != 0 ? airGap / (w / p) : 0;
    return out;
}

CageBreakdown cageBreakdown(const CageCircuit& c, double V, double f, int p) {
    auto T = [&](double s) { return cageSteadyState(c, V, f, p, s).torque; };
    // Log-spaced scan from slip 1e-4 to 1, then golden section around the best.
    const int n = 160;
    std::vector<double> s(n), t(n);
    int best = 0;
    for (int i = 0; i < n; ++i) {
        s[i] = std::pow(10.0, -4.0 + 4.0 * i / (n - 1));
        t[i] = T(s[i]);
        if (t[i] > t[best]) best = i;
    }
    if (best == n - 1) return {t[best], 1.0};
    double a = s[std::max(best - 1, 0)], b = s[std::min(best + 1, n - 1)];
    const double g = 0.5 * (std::sqrt(5.0) - 1);
    double x1 = b - g * (b - a), x2 = a + g * (b - a), f1 = T(x1), f2 = T(x2);
    for (int i = 0; i < 60; ++i) {
        if (f1 > f2) {
            b = x2, x2 = x1, f2 = f1, x1 = b - g * (b - a), f1 = T(x1);
        } else {
            a = x1, x1 = x2, f1 = f2, x2 = a + g * (b - a), f2 = T(x2);
        }
    }
    const double sm = 0.5 * (a + b);
    return {T(sm), sm};
}

double cageSwitchOnPeakTorque(const CageCircuit& c, double V, double f, int p, double cycles) {
    const int n = 1 + static_cast<int>(c.rotorResistances.size());
    Eigen::MatrixXd L = Eigen::MatrixXd::Constant(n, n, c.mainInductance);
    L(0, 0) += c.statorLeakage;
    for (int k = 1; k < n; ++k) L(k, k) += c.rotorLeakages[k - 1];
    const Eigen::MatrixXd G = L.inverse();
    Eigen::VectorXd R(n);
    R[0] = c.statorResistance;
    for (int k = 1; k < n; ++k) R[k] = c.rotorResistances[k - 1];
    const double w = 2 * M_PI * f, h = 1 / (400 * f);
    // ψ' = v − R·Γ·ψ (rotor at rest), v = [√2·V·e^(jωt), 0, …].
    auto rate = [&](double t, const Eigen::VectorXcd& psi) {
        Eigen::VectorXcd d = -(R.asDiagonal() * (G.cast<Complex>() * psi));
        d[0] += std::polar(std::sqrt(2.0) * V, w * t);
        return d;
    };
    Eigen::VectorXcd psi = Eigen::VectorXcd::Zero(n);
    double peak = 0;
    const int steps = static_cast<int>(std::ceil(cycles * 400));
    for (int k = 0; k < steps; ++k) {
        const double t = k * h;
        const Eigen::VectorXcd k1 = rate(t, psi), k2 = rate(t + h / 2, psi + h / 2 * k1),
                               k3 = rate(t + h / 2, psi + h / 2 * k2), k4 = rate(t + h, psi + h * k3);
        psi += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
        const Complex is = (G.cast<Complex>() * psi)[0];
        peak = std::max(peak, std::abs(1.5 * p * std::imag(std::conj(psi[0]) * is)));
    }
    return peak;
}

namespace {

int polePairsOf(const MotorDatasheet& d) {
    if (d.polePairs > 0) return d.polePairs;
    const double ratio = 2 * M_PI * d.frequency / d.ratedSpeed;  // p·ω_s/p over ω_n
    return std::max(1, static_cast<int>(std::ceil(ratio)) - 1);
}

}  // namespace

DatasheetProblem checkDatasheet(const MotorDatasheet& d) {
    const int p = polePairsOf(d);
    const double ws = 2 * M_PI * d.frequency / p;
    if (!(d.ratedSpeed < ws))
        return {"rated_speed", "the rated speed " + formatNumber(d.ratedSpeed * 30 / M_PI) +
                                   " rpm is not below the synchronous speed " + formatNumber(ws * 30 / M_PI) +
                                   " rpm of " + std::to_string(p) + " pole pairs at " + formatNumber(d.frequency) +
                                   " Hz: an induction motor runs with slip"};
    const double Mn = d.ratedPower / d.ratedSpeed;
    if (!(d.breakdownTorqueRatio > 1))
        return {"breakdown_ratio", "Mk/Mn = " + formatNumber(d.breakdownTorqueRatio) +
                                       " must exceed 1: the rated point lies below the breakdown torque"};
    if (d.lockedRotorTorqueRatio > 0 && d.lockedRotorTorqueRatio > d.breakdownTorqueRatio)
        return {"breakdown_ratio", "Mk/Mn = " + formatNumber(d.breakdownTorqueRatio) + " is below Ma/Mn = " +
                                       formatNumber(d.lockedRotorTorqueRatio) +
                                       ": the breakdown torque is the largest torque of the curve"};
    const double apparent = std::sqrt(3.0) * d.lineVoltage * d.ratedCurrent;
    const double input = apparent * d.powerFactor;
    if (!(Mn * ws < input))
        return {"rated_current", "the air-gap power at the rated point Mn·ω_s = " + formatNumber(Mn * ws) +
                                     " W is not below the electrical input √3·V·I·cos φ = " + formatNumber(input) +
                                     " W: no machine converts more than its input"};
    const double inputByEfficiency = d.ratedPower / d.efficiency;
    if (std::abs(inputByEfficiency / input - 1) > 0.1)
        return {"rated_efficiency", "P_n/η = " + formatNumber(inputByEfficiency) + " W and √3·V·I·cos φ = " +
                                        formatNumber(input) + " W differ by " +
                                        formatNumber(100 * std::abs(inputByEfficiency / input - 1), 3) +
                                        " % (more than 10 %): the datasheet's power, efficiency, voltage, current and "
                                        "power factor contradict each other"};
    const double Ma = d.lockedRotorTorqueRatio * Mn, Ia = d.lockedRotorCurrentRatio * d.ratedCurrent;
    if (Ma > 0 && Ia > 0 && !(Ma * ws < std::sqrt(3.0) * d.lineVoltage * Ia))
        return {"locked_rotor_ratio", "the air-gap power at standstill Ma·ω_s = " + formatNumber(Ma * ws) +
                                          " W exceeds the apparent input √3·V·Ia = " +
                                          formatNumber(std::sqrt(3.0) * d.lineVoltage * Ia) +
                                          " W: no machine gives this starting torque from this starting current"};
    // A published curve: torques and/or line currents at its speeds.
    const std::size_t n = d.curveSpeeds.size();
    if (d.curveTorques.size() != n && !d.curveTorques.empty())
        return {"curve_torques", "give one torque per curve speed"};
    if (d.curveCurrents.size() != n && !d.curveCurrents.empty())
        return {"curve_currents", "give one current per curve speed"};
    if (n > 0 && d.curveTorques.empty() && d.curveCurrents.empty())
        return {"curve_speeds", "curve speeds without curve_torques or curve_currents"};
    const double Mk = d.breakdownTorqueRatio * Mn;
    for (std::size_t i = 0; i < n; ++i) {
        const double speed = d.curveSpeeds[i];
        const std::string at = " at " + formatNumber(speed * 30 / M_PI, 5) + " rpm";
        const double T = d.curveTorques.empty() ? 0 : d.curveTorques[i];
        const double I = d.curveCurrents.empty() ? 0 : d.curveCurrents[i];
        if (T > 0 && !(speed < ws))
            return {"curve_speeds", "the curve drives with " + formatNumber(T, 5) + " N*m" + at +
                                        ", not below the synchronous speed " + formatNumber(ws * 30 / M_PI) +
                                        " rpm: a motor's torque there is zero or braking"};
        if (T > Mk)
            return {"curve_torques", "the curve's " + formatNumber(T, 5) + " N*m" + at + " exceeds the breakdown torque Mk = " +
                                         formatNumber(Mk, 5) + " N*m, the largest torque of the curve"};
        if (T > 0 && I > 0 && !(T * ws < std::sqrt(3.0) * d.lineVoltage * I))
            return {"curve_currents", "the air-gap power T·ω_s = " + formatNumber(T * ws) + " W" + at +
                                          " exceeds the apparent input √3·V·I = " +
                                          formatNumber(std::sqrt(3.0) * d.lineVoltage * I) +
                                          " W there: no machine gives this torque from this current"};
        if (speed == 0 && T > 0 && Ma > 0 && std::abs(T / Ma - 1) > 0.1)
            return {"curve_torques", "the curve's standstill torque " + formatNumber(T, 5) + " N*m and Ma = " +
                                         formatNumber(Ma, 5) + " N*m (locked_rotor_ratio) differ by " +
                                         formatNumber(100 * std::abs(T / Ma - 1), 3) + " % (more than 10 %)"};
        if (speed == 0 && I > 0 && Ia > 0 && std::abs(I / Ia - 1) > 0.1)
            return {"curve_currents", "the curve's standstill current " + formatNumber(I, 5) + " A and Ia = " +
                                          formatNumber(Ia, 5) + " A (locked_rotor_current_ratio) differ by " +
                                          formatNumber(100 * std::abs(I / Ia - 1), 3) + " % (more than 10 %)"};
    }
    return {};
}

namespace {
std::atomic<long> g_fits{0};
}  // namespace

long cageFitCount() { return g_fits.load(); }

CageFitResult fitCageCircuitCached(const MotorDatasheet& d, int cages) {
    struct Entry {
        std::once_flag once;
        CageFitResult result;
    };
    // A refused datasheet throws here, outside call_once (a throwing
    // callable there has deadlocked some standard libraries).
    if ((cages != 1 && cages != 2) || !checkDatasheet(d).key.empty() ||
        (cages == 2 && !(d.lockedRotorTorqueRatio > 0 && d.lockedRotorCurrentRatio > 0)))
        return fitCageCircuit(d, cages);
    static std::mutex mutex;
    static std::map<std::vector<double>, std::shared_ptr<Entry>> cache;
    std::vector<double> key = {double(cages),       d.ratedPower,  d.ratedSpeed,
                               d.lineVoltage,       d.ratedCurrent, d.powerFactor,
                               d.efficiency,        d.lockedRotorTorqueRatio, d.breakdownTorqueRatio,
                               d.lockedRotorCurrentRatio, d.frequency, double(d.polePairs),
                               double(d.curveSpeeds.size()), double(d.curveTorques.size()),
                               double(d.curveCurrents.size())};
    key.insert(key.end(), d.curveSpeeds.begin(), d.curveSpeeds.end());
    key.insert(key.end(), d.curveTorques.begin(), d.curveTorques.end());
    key.insert(key.end(), d.curveCurrents.begin(), d.curveCurrents.end());
    std::shared_ptr<Entry> entry;
    {
        const std::lock_guard<std::mutex> lock(mutex);
        std::shared_ptr<Entry>& slot = cache[key];
        if (!slot) slot = std::make_shared<Entry>();
        entry = slot;
    }
    // Outside the map's lock: other keys fit meanwhile.
    std::call_once(entry->once, [&] { entry->result = fitCageCircuit(d, cages); });
    return entry->result;
}

CageFitResult fitCageCircuit(const MotorDatasheet& d, int cages) {
    if (cages != 1 && cages != 2) throw std::invalid_argument("fitCageCircuit: 1 or 2 cages");
    const DatasheetProblem problem = checkDatasheet(d);
    if (!problem.key.empty()) throw std::invalid_argument(problem.key + ": " + problem.reason);
    if (cages == 2 && !(d.lockedRotorTorqueRatio > 0 && d.lockedRotorCurrentRatio > 0))
        throw std::invalid_argument("locked_rotor_ratio: a double cage is fitted to its starting values Ma/Mn and Ia/In");
    ++g_fits;
    CageFitResult out;
    out.polePairs = polePairsOf(d);
    out.phaseVoltage = d.lineVoltage / std::sqrt(3.0);
    const int p = out.polePairs;
    const double V = out.phaseVoltage, f = d.frequency, w = 2 * M_PI * f, ws = w / p;
    const double Mn = d.ratedPower / d.ratedSpeed, sn = 1 - d.ratedSpeed / ws;

    // Parameters: log of Rs, Lσ (= Lsσ; single cage: also Lrσ), Lm, Rr
    // (running cage) [, Rr,1 and Lrσ,1 of the starting cage, Lrσ,2 of the
    // running one]. The double cage's seven parameters meet six
    // independent data (η_n follows from P_n, I_n, cos φ_n): the damped
    // steps pick the solution nearest the starting point.
    const int np = cages == 1 ? 4 : 7;
    auto circuitOf = [&](const Eigen::VectorXd& x) {
        CageCircuit c;
        c.statorResistance = std::exp(x[0]);
        c.statorLeakage = std::exp(x[1]);
        c.mainInductance = std::exp(x[2]);
        if (cages == 1) {
            c.rotorResistances = {std::exp(x[3])};
            c.rotorLeakages = {std::exp(x[1])};
        } else {
            c.rotorResistances = {std::exp(x[4]), std::exp(x[3])};
            c.rotorLeakages = {std::exp(x[5]), std::exp(x[6])};
        }
        return c;
    };
    // Which datasheet value each model value is: rated point, breakdown,
    // the standstill values when given, then the curve.
    enum class What { RatedTorque, RatedCurrent, RatedPowerFactor, RatedEfficiency, LockedTorque, LockedCurrent,
                      Breakdown, CurveTorque, CurveCurrent };
    struct Target {
        std::string name, key, unit;
        double data;
        What what;
        double speed = 0;
    };
    std::vector<Target> targets = {
        {"rated torque Mn = P_n/ω_n at the rated slip", "rated_power", "N*m", Mn, What::RatedTorque},
        {"rated current I_n", "rated_current", "A", d.ratedCurrent, What::RatedCurrent},
        {"rated power factor cos φ_n", "rated_power_factor", "1", d.powerFactor, What::RatedPowerFactor},
        {"rated efficiency η_n (circuit: P_n/P_in)", "rated_efficiency", "1", d.efficiency, What::RatedEfficiency},
    };
    if (d.lockedRotorTorqueRatio > 0)
        targets.push_back({"locked-rotor torque Ma", "locked_rotor_ratio", "N*m", d.lockedRotorTorqueRatio * Mn,
                           What::LockedTorque});
    if (d.lockedRotorCurrentRatio > 0)
        targets.push_back({"locked-rotor current Ia", "locked_rotor_current_ratio", "A",
                           d.lockedRotorCurrentRatio * d.ratedCurrent, What::LockedCurrent});
    targets.push_back({"breakdown torque Mk", "breakdown_ratio", "N*m", d.breakdownTorqueRatio * Mn, What::Breakdown});
    for (std::size_t i = 0; i < d.curveTorques.size(); ++i)
        targets.push_back({"curve torque at " + formatNumber(d.curveSpeeds[i] * 30 / M_PI, 5) + " rpm", "curve_torques",
                           "N*m", d.curveTorques[i], What::CurveTorque, d.curveSpeeds[i]});
    for (std::size_t i = 0; i < d.curveCurrents.size(); ++i)
        targets.push_back({"curve current at " + formatNumber(d.curveSpeeds[i] * 30 / M_PI, 5) + " rpm", "curve_currents",
                           "A", d.curveCurrents[i], What::CurveCurrent, d.curveSpeeds[i]});
    const int nt = static_cast<int>(targets.size());
    auto modelValues = [&](const Eigen::VectorXd& x) {
        const CageCircuit c = circuitOf(x);
        const CagePoint rated = cageSteadyState(c, V, f, p, sn);
        const CagePoint locked = cageSteadyState(c, V, f, p, 1.0);
        std::vector<double> m;
        m.reserve(targets.size());
        for (const Target& t : targets) switch (t.what) {
                case What::RatedTorque: m.push_back(rated.torque); break;
                case What::RatedCurrent: m.push_back(rated.current); break;
                case What::RatedPowerFactor: m.push_back(rated.powerFactor); break;
                case What::RatedEfficiency: m.push_back(rated.torque * d.ratedSpeed / rated.inputPower); break;
                case What::LockedTorque: m.push_back(locked.torque); break;
                case What::LockedCurrent: m.push_back(locked.current); break;
                case What::Breakdown: m.push_back(cageBreakdown(c, V, f, p).torque); break;
                case What::CurveTorque: m.push_back(cageSteadyState(c, V, f, p, 1 - t.speed / ws).torque); break;
                case What::CurveCurrent: m.push_back(cageSteadyState(c, V, f, p, 1 - t.speed / ws).current); break;
            }
        return m;
    };
    auto residuals = [&](const Eigen::VectorXd& x) {
        const std::vector<double> m = modelValues(x);
        Eigen::VectorXd r(nt);
        for (int i = 0; i < nt; ++i) r[i] = (m[i] - targets[i].data) / std::abs(targets[i].data);
        return r;
    };

    // Starting points from the usual per-unit estimates: X_m from the
    // magnetising share of I_n, the total leakage from Ia, Rr from the
    // rated slip, Rs like Rr; the starting cage 5× Rr with half the leakage.
    // Without Ia (a slip-ring motor's datasheet) the leakage from Mk:
    // Mk·ω_s ≈ 3·V²/(2·X) with Rs neglected, so Ia ≈ V/X = 2·Mk·ω_s/(3·V).
    const double In = d.ratedCurrent,
                 Ia = d.lockedRotorCurrentRatio > 0 ? d.lockedRotorCurrentRatio * In
                                                    : 2 * d.breakdownTorqueRatio * Mn * ws / (3 * V);
    const double sinPhi = std::sqrt(std::max(1e-6, 1 - d.powerFactor * d.powerFactor));
    const double Xm0 = V / (0.8 * In * sinPhi), Xs0 = 0.5 * V / Ia, Rr0 = sn * V / (In * d.powerFactor);
    Eigen::VectorXd bestX;
    double bestCost = std::numeric_limits<double>::infinity();
    for (double scaleR : {1.0, 0.5, 2.0})
        for (double scaleX : {1.0, 0.6, 1.6}) {
            if (bestCost < 1e-16) break;
            Eigen::VectorXd x(np);
            x[0] = std::log(scaleR * Rr0);
            x[1] = std::log(scaleX * Xs0 / w);
            x[2] = std::log(Xm0 / w);
            x[3] = std::log(Rr0);
            if (cages == 2) {
                x[4] = std::log(5 * scaleR * Rr0);
                x[5] = std::log(0.5 * scaleX * Xs0 / w);
                x[6] = x[1];
            }
            Eigen::VectorXd r = residuals(x);
            double cost = r.squaredNorm(), lambda = 1e-2;
            for (int it = 0; it < 200 && cost > 1e-24; ++it) {
                Eigen::MatrixXd J(nt, np);
                for (int j = 0; j < np; ++j) {
                    Eigen::VectorXd xp = x;
                    xp[j] += 1e-6;
                    J.col(j) = (residuals(xp) - r) / 1e-6;
                }
                const Eigen::MatrixXd JtJ = J.transpose() * J;
                const Eigen::VectorXd g = J.transpose() * r;
                bool improved = false;
                for (int tries = 0; tries < 12; ++tries) {
                    Eigen::MatrixXd A = JtJ;
                    A.diagonal() += lambda * (JtJ.diagonal().array() + 1e-12).matrix();
                    Eigen::VectorXd step = A.ldlt().solve(-g);
                    // Keep the steps moderate in the logarithms.
                    const double big = step.cwiseAbs().maxCoeff();
                    if (big > 1.0) step *= 1.0 / big;
                    const Eigen::VectorXd xn = x + step;
                    const Eigen::VectorXd rn = residuals(xn);
                    const double cn = rn.squaredNorm();
                    if (std::isfinite(cn) && cn < cost) {
                        x = xn, r = rn;
                        improved = cost - cn > 1e-14 * cost;
                        cost = cn;
                        lambda = std::max(lambda / 3, 1e-12);
                        break;
                    }
                    lambda *= 4;
                }
                if (!improved) break;
            }
            if (cost < bestCost) bestCost = cost, bestX = x;
            if (bestCost < 1e-16) break;  // an exact fit: no other start needed
        }
    out.circuit = circuitOf(bestX);
    const std::vector<double> m = modelValues(bestX);
    for (int i = 0; i < nt; ++i) {
        FitPoint pt{targets[i].name, targets[i].key, targets[i].data, m[i],
                    (m[i] - targets[i].data) / std::abs(targets[i].data), targets[i].unit};
        if (std::abs(pt.residual) > out.worstResidual) {
            out.worstResidual = std::abs(pt.residual);
            out.worstPoint = out.points.size();
        }
        out.points.push_back(pt);
    }
    return out;
}

}  // namespace milldyn
