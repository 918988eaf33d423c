#include "validation/oracles/DqMachineOracle.h"

#include <array>
#include <cmath>
#include <complex>
#include <limits>
#include <stdexcept>

namespace milldyn::oracles {

double DqSupply::factor(double t, double stepStart) const {
    switch (kind) {
        case Kind::DirectOnLine:
            return 1.0;
        case Kind::StarDelta:
            // Decided at the step's start, so that the step ending at the
            // switch is integrated in star throughout (the switch is a step
            // boundary, checked by dqMachineStart).
            return stepStart < switchTime ? 1 / std::sqrt(3.0) : 1.0;
        case Kind::SoftStart:
            return initialVoltage + (1 - initialVoltage) * std::min(t / rampTime, 1.0);
    }
    return 1.0;
}

namespace {

// State: i_qs, i_ds, i'_qr, i'_dr [A], ω_m [rad/s].
using State = std::array<double, 5>;

struct Machine {
    DqMachine m;
    double ls = 0, lr = 0, det = 0, we = 0;
    explicit Machine(const DqMachine& mm) : m(mm) {
        ls = m.lls + m.lm;
        lr = m.llr + m.lm;
        det = ls * lr - m.lm * m.lm;
        we = 2 * M_PI * m.frequency;
    }
    double torque(const State& x) const { return 1.5 * m.polePairs * m.lm * (x[0] * x[3] - x[1] * x[2]); }

    // Krause eqs 6.5-1..8 in the synchronous frame (ω = ω_e), ω_r = p·ω_m:
    //   v_qs  = r_s·i_qs + ω·λ_ds + dλ_qs/dt      v_ds  = r_s·i_ds − ω·λ_qs + dλ_ds/dt
    //   0     = r'_r·i'_qr + (ω − ω_r)·λ'_dr + dλ'_qr/dt
    //   0     = r'_r·i'_dr − (ω − ω_r)·λ'_qr + dλ'_dr/dt
    // with λ_qs = L_s·i_qs + L_M·i'_qr, λ'_qr = L_M·i_qs + L'_r·i'_qr (and d):
    // the 2×2 inductance matrix of each axis inverted.
    State rates(const State& x, double vqs, const std::function<double(double)>& load, double J) const {
        const double wr = m.polePairs * x[4], slipSpeed = we - wr;
        const double lqs = ls * x[0] + m.lm * x[2], lds = ls * x[1] + m.lm * x[3];
        const double lqr = m.lm * x[0] + lr * x[2], ldr = m.lm * x[1] + lr * x[3];
        const double eqs = vqs - m.rs * x[0] - we * lds;   // dλ_qs/dt
        const double eds = 0.0 - m.rs * x[1] + we * lqs;   // dλ_ds/dt
        const double eqr = -m.rr * x[2] - slipSpeed * ldr;  // dλ'_qr/dt
        const double edr = -m.rr * x[3] + slipSpeed * lqr;  // dλ'_dr/dt
        State d{};
        d[0] = (lr * eqs - m.lm * eqr) / det;
        d[2] = (ls * eqr - m.lm * eqs) / det;
        d[1] = (lr * eds - m.lm * edr) / det;
        d[3] = (ls * edr - m.lm * eds) / det;
        d[4] = (torque(x) - load(x[4])) / J;
        return d;
    }
};

State axpy(const State& x, double a, const State& k) {
    State y{};
    for (std::size_t i = 0; i < y.size(); ++i) y[i] = x[i] + a * k[i];
    return y;
}

}  // namespace

std::vector<DqSample> dqMachineStart(const DqMachine& machine, const DqSupply& supply, double J,
                                     const std::function<double(double)>& loadTorque, double h, double endTime,
                                     int sampleEvery) {
    if (!(h > 0) || !(endTime > 0) || sampleEvery < 1 || !(J > 0))
        throw std::invalid_argument("dqMachineStart: step, end time, sampling and inertia must be > 0");
    const double nSwitch = supply.switchTime / h;
    if (supply.kind == DqSupply::Kind::StarDelta && std::abs(nSwitch - std::round(nSwitch)) > 1e-6)
        throw std::invalid_argument("dqMachineStart: the star-delta switch must fall on a step boundary");
    if (supply.kind == DqSupply::Kind::SoftStart && !(supply.rampTime > 0))
        throw std::invalid_argument("dqMachineStart: a soft start needs a ramp time > 0");
    const Machine mc(machine);
    const double peak = std::sqrt(2.0) * machine.phaseVoltage;
    const auto steps = static_cast<long>(std::llround(endTime / h));
    std::vector<DqSample> out;
    State x{};
    auto sample = [&](double t, double vqs) {
        DqSample s;
        s.time = t;
        s.speed = x[4];
        s.torque = mc.torque(x);
        const double is2 = x[0] * x[0] + x[1] * x[1], ir2 = x[2] * x[2] + x[3] * x[3];
        s.statorCurrent = std::sqrt(is2 / 2);
        s.inputPower = 1.5 * vqs * x[0];
        s.copperLoss = 1.5 * (machine.rs * is2 + machine.rr * ir2);
        const double lqs = mc.ls * x[0] + machine.lm * x[2], lds = mc.ls * x[1] + machine.lm * x[3];
        const double lqr = machine.lm * x[0] + mc.lr * x[2], ldr = machine.lm * x[1] + mc.lr * x[3];
        s.fieldEnergy = 0.75 * (x[0] * lqs + x[1] * lds + x[2] * lqr + x[3] * ldr);
        out.push_back(s);
    };
    sample(0.0, peak * supply.factor(0.0, 0.0));
    for (long n = 0; n < steps; ++n) {
        const double t = static_cast<double>(n) * h;
        auto v = [&](double tt) { return peak * supply.factor(tt, t); };
        const State k1 = mc.rates(x, v(t), loadTorque, J);
        const State k2 = mc.rates(axpy(x, h / 2, k1), v(t + h / 2), loadTorque, J);
        const State k3 = mc.rates(axpy(x, h / 2, k2), v(t + h / 2), loadTorque, J);
        const State k4 = mc.rates(axpy(x, h, k3), v(t + h), loadTorque, J);
        for (std::size_t i = 0; i < x.size(); ++i) x[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
        if ((n + 1) % sampleEvery == 0) {
            const double tn = static_cast<double>(n + 1) * h;
            sample(tn, peak * supply.factor(tn, tn));
        }
    }
    return out;
}

DqHeldResponse dqHeldResponse(const DqMachine& machine, double slip, double u, double dudt) {
    using C = std::complex<double>;
    const double we = 2 * M_PI * machine.frequency;
    const double ls = machine.lls + machine.lm, lr = machine.llr + machine.lm, lm = machine.lm;
    // Z(0) and its inverse (2×2, Cramer).
    const C z11(machine.rs, we * ls), z12(0, we * lm), z21(0, slip * we * lm), z22(machine.rr, slip * we * lr);
    const C det = z11 * z22 - z12 * z21;
    auto solve = [&](C a, C b, C& x1, C& x2) {
        x1 = (z22 * a - z12 * b) / det;
        x2 = (z11 * b - z21 * a) / det;
    };
    C is0, ir0, is1, ir1;
    solve(C(std::sqrt(2.0) * machine.phaseVoltage, 0), C(0, 0), is0, ir0);
    solve(-(ls * is0 + lm * ir0), -(lm * is0 + lr * ir0), is1, ir1);
    const C is = u * is0 + dudt * is1, ir = u * ir0 + dudt * ir1;
    return {1.5 * machine.polePairs * lm * std::imag(std::conj(ir) * is), std::abs(is) / std::sqrt(2.0)};
}

double dqTimeToFraction(const std::vector<DqSample>& run, double fraction) {
    if (run.empty()) return std::numeric_limits<double>::quiet_NaN();
    const double target = fraction * run.back().speed;
    for (std::size_t i = 1; i < run.size(); ++i)
        if (run[i].speed >= target) {
            const DqSample &a = run[i - 1], &b = run[i];
            return a.time + (target - a.speed) / (b.speed - a.speed) * (b.time - a.time);
        }
    return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace milldyn::oracles

namespace milldyn::oracles {
namespace {

using C = std::complex<double>;

/// Inverse of a small real matrix (Gauss–Jordan with partial pivoting).
std::vector<std::vector<double>> inverse(std::vector<std::vector<double>> a) {
    const std::size_t n = a.size();
    std::vector<std::vector<double>> b(n, std::vector<double>(n, 0.0));
    for (std::size_t i = 0; i < n; ++i) b[i][i] = 1;
    for (std::size_t c = 0; c < n; ++c) {
        std::size_t piv = c;
        for (std::size_t r = c + 1; r < n; ++r)
            if (std::abs(a[r][c]) > std::abs(a[piv][c])) piv = r;
        std::swap(a[c], a[piv]);
        std::swap(b[c], b[piv]);
        const double d = a[c][c];
        for (std::size_t k = 0; k < n; ++k) a[c][k] /= d, b[c][k] /= d;
        for (std::size_t r = 0; r < n; ++r)
            if (r != c) {
                const double m = a[r][c];
                for (std::size_t k = 0; k < n; ++k) a[r][k] -= m * a[c][k], b[r][k] -= m * b[c][k];
            }
    }
    return b;
}

struct Extended {
    DqMachineExtended m;
    int n = 2;  // stator + cages
    double we = 0;
    explicit Extended(const DqMachineExtended& mm) : m(mm) {
        n = m.rr2 > 0 ? 3 : 2;
        we = 2 * M_PI * m.base.frequency;
    }
    /// Krause's inductance matrix (per axis), the stator's entry with the
    /// source's u²·L seen through the starter.
    std::vector<std::vector<double>> inductance(double u2) const {
        std::vector<std::vector<double>> L(n, std::vector<double>(n, m.base.lm));
        L[0][0] += m.base.lls + u2 * m.sourceL;
        L[1][1] += m.base.llr;
        if (n == 3) L[2][2] += m.llr2;
        return L;
    }
};

// State: the complex winding currents (q − j·d) in the frame turning with
// the supply, then the shaft speed.
struct XState {
    C i[3];
    double w = 0;
};

XState axpyX(const XState& x, double a, const XState& k, int n) {
    XState y = x;
    for (int j = 0; j < n; ++j) y.i[j] = x.i[j] + a * k.i[j];
    y.w = x.w + a * k.w;
    return y;
}

}  // namespace

std::vector<DqSampleExtended> dqMachineRun(const DqMachineExtended& machine, const DqSupplyExtended& supply, double J,
                                           const std::function<double(double)>& loadTorque, double h, double endTime,
                                           int sampleEvery) {
    if (!(h > 0) || !(endTime > 0) || sampleEvery < 1 || !(J > 0))
        throw std::invalid_argument("dqMachineRun: step, end time, sampling and inertia must be > 0");
    const Extended mc(machine);
    const int n = mc.n;
    const DqMachine& b = machine.base;
    const double peak = std::sqrt(2.0) * b.phaseVoltage;
    auto openAt = [&](double t) {
        for (const auto& [from, to] : supply.openIntervals)
            if (t >= from && t < to) return true;
        return false;
    };
    // Rates at time t (inside the step [t0, t0 + h]: step functions switch at its boundaries).
    struct Rates {
        XState d;
        C winding;  // the winding's voltage in the frame
        double dip = 0;
    };
    auto rates = [&](const XState& x, double t, bool open) {
        const double u = supply.voltage(t), f = supply.frequency(t), r = supply.rotorResistanceRatio(t);
        const double delta = t >= supply.phaseStepTime ? supply.phaseStep : 0.0;
        const double w = mc.we * f, wr = b.polePairs * x.w;
        const double u2 = u * u;
        std::vector<double> R = {b.rs + u2 * machine.sourceR, r * b.rr, machine.rr2};
        const auto L = mc.inductance(u2);
        Rates out;
        // Flux linkages and the frame's speed per winding (stator ω, rotor ω − ω_r).
        C lambda[3], rhs[3];
        for (int j = 0; j < n; ++j) {
            lambda[j] = 0;
            for (int k = 0; k < n; ++k) lambda[j] += L[j][k] * x.i[k];
        }
        const C v = open ? C(0) : u * std::polar(peak, delta);
        for (int j = 0; j < n; ++j) {
            const double frame = j == 0 ? w : w - wr;
            rhs[j] = (j == 0 ? v : C(0)) - R[j] * x.i[j] - C(0, frame) * lambda[j];
        }
        if (open) {
            // i_s = 0: the rotor block alone.
            std::vector<std::vector<double>> Lrr(n - 1, std::vector<double>(n - 1));
            for (int j = 1; j < n; ++j)
                for (int k = 1; k < n; ++k) Lrr[j - 1][k - 1] = L[j][k];
            const auto G = inverse(Lrr);
            out.d.i[0] = 0;
            for (int j = 1; j < n; ++j) {
                out.d.i[j] = 0;
                for (int k = 1; k < n; ++k) out.d.i[j] += G[j - 1][k - 1] * rhs[k];
            }
        } else {
            const auto G = inverse(L);
            for (int j = 0; j < n; ++j) {
                out.d.i[j] = 0;
                for (int k = 0; k < n; ++k) out.d.i[j] += G[j][k] * rhs[k];
            }
        }
        C rotor = 0;
        for (int j = 1; j < n; ++j) rotor += x.i[j];
        const double torque = 1.5 * b.polePairs * b.lm * std::imag(std::conj(rotor) * x.i[0]);
        out.d.w = (torque - loadTorque(x.w)) / J;
        // The source's drop u·(R·i + L·(di/dt + jω·i)) between the emf and the
        // supply point; the winding sees u times the supply point's voltage.
        const C drop = machine.sourceR * x.i[0] + machine.sourceL * (out.d.i[0] + C(0, w) * x.i[0]);
        const C pcc = open ? std::polar(peak, delta) : std::polar(peak, delta) - u * drop;
        out.winding = open ? C(0) : u * pcc;
        out.dip = (machine.sourceR > 0 || machine.sourceL > 0) && !open ? 1 - std::abs(pcc) / peak : 0.0;
        if (open) {
            // The open terminals' voltage: dλ_s/dt + jω·λ_s with i_s = 0.
            C dls = 0;
            for (int k = 1; k < n; ++k) dls += b.lm * out.d.i[k];
            out.winding = dls + C(0, w) * lambda[0];
        }
        return out;
    };
    const auto steps = static_cast<long>(std::llround(endTime / h));
    std::vector<DqSampleExtended> out;
    XState x;
    bool wasOpen = false;
    auto sample = [&](double t, bool open) {
        const Rates rr = rates(x, t, open);
        DqSampleExtended s;
        s.base.time = t;
        s.base.speed = x.w;
        C rotor = 0;
        for (int j = 1; j < n; ++j) rotor += x.i[j];
        s.base.torque = 1.5 * b.polePairs * b.lm * std::imag(std::conj(rotor) * x.i[0]);
        s.base.statorCurrent = std::abs(x.i[0]) / std::sqrt(2.0);
        s.base.inputPower = 1.5 * std::real(rr.winding * std::conj(x.i[0]));
        s.voltageDip = rr.dip;
        out.push_back(s);
    };
    sample(0.0, openAt(0.0));
    const double eps = 1e-9 * h;
    for (long k = 0; k < steps; ++k) {
        const double t = static_cast<double>(k) * h;
        const bool open = openAt(t + eps);
        if (open && !wasOpen) {
            // Opening: i_s → 0 with the rotor's flux linkages continuous.
            const double u = supply.voltage(t - eps);
            const auto L = mc.inductance(u * u);
            std::vector<std::vector<double>> Lrr(n - 1, std::vector<double>(n - 1));
            for (int j = 1; j < n; ++j)
                for (int q = 1; q < n; ++q) Lrr[j - 1][q - 1] = L[j][q];
            const auto G = inverse(Lrr);
            C lr[3];
            for (int j = 1; j < n; ++j) {
                lr[j] = 0;
                for (int q = 0; q < n; ++q) lr[j] += L[j][q] * x.i[q];
            }
            x.i[0] = 0;
            for (int j = 1; j < n; ++j) {
                x.i[j] = 0;
                for (int q = 1; q < n; ++q) x.i[j] += G[j - 1][q - 1] * lr[q];
            }
        }
        wasOpen = open;
        auto at = [&](double tt) { return std::min(std::max(tt, t + eps), t + h - eps); };
        const XState k1 = rates(x, at(t), open).d;
        const XState k2 = rates(axpyX(x, h / 2, k1, n), at(t + h / 2), open).d;
        const XState k3 = rates(axpyX(x, h / 2, k2, n), at(t + h / 2), open).d;
        const XState k4 = rates(axpyX(x, h, k3, n), at(t + h), open).d;
        for (int j = 0; j < n; ++j) x.i[j] += h / 6 * (k1.i[j] + 2.0 * k2.i[j] + 2.0 * k3.i[j] + k4.i[j]);
        x.w += h / 6 * (k1.w + 2 * k2.w + 2 * k3.w + k4.w);
        if ((k + 1) % sampleEvery == 0) {
            const double tn = static_cast<double>(k + 1) * h;
            sample(tn, openAt(tn + eps));
        }
    }
    return out;
}

DqHeldResponse dqHeldResponseExtended(const DqMachineExtended& machine, double slip) {
    // d/dt = 0 in the synchronous frame: V = (R + j·W·L)·I, W = diag(ω_e, s·ω_e, s·ω_e),
    // solved by complex Gauss elimination.
    const Extended mc(machine);
    const int n = mc.n;
    const DqMachine& b = machine.base;
    const auto L = mc.inductance(1.0);
    std::vector<double> R = {b.rs + machine.sourceR, b.rr, machine.rr2};
    std::vector<std::vector<C>> A(n, std::vector<C>(n + 1, C(0)));
    for (int j = 0; j < n; ++j) {
        const double frame = j == 0 ? mc.we : slip * mc.we;
        for (int k = 0; k < n; ++k) A[j][k] = C(j == k ? R[j] : 0.0, frame * L[j][k]);
    }
    A[0][n] = std::sqrt(2.0) * b.phaseVoltage;
    for (int c = 0; c < n; ++c) {
        for (int r = c + 1; r < n; ++r) {
            const C m = A[r][c] / A[c][c];
            for (int k = c; k <= n; ++k) A[r][k] -= m * A[c][k];
        }
    }
    C I[3];
    for (int r = n - 1; r >= 0; --r) {
        C acc = A[r][n];
        for (int k = r + 1; k < n; ++k) acc -= A[r][k] * I[k];
        I[r] = acc / A[r][r];
    }
    C rotor = 0;
    for (int j = 1; j < n; ++j) rotor += I[j];
    return {1.5 * b.polePairs * b.lm * std::imag(std::conj(rotor) * I[0]), std::abs(I[0]) / std::sqrt(2.0)};
}

}  // namespace milldyn::oracles

#include <Eigen/Dense>

namespace milldyn::oracles {
namespace {

/// The slip on the stable branch where the T circuit gives `torque`.
double slipForTorque(const DqMachine& m, double torque) {
    // Breakdown slip by a fine scan; bisection below it.
    double best = 0, sk = 1;
    for (int i = 1; i <= 4000; ++i) {
        const double s = i / 4000.0, t = dqHeldResponse(m, s, 1.0, 0.0).torque;
        if (t > best) best = t, sk = s;
    }
    if (!(torque < best)) throw std::invalid_argument("dqBeltChain: the load exceeds the breakdown torque");
    double lo = 0, hi = sk;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (dqHeldResponse(m, mid, 1.0, 0.0).torque < torque ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

std::vector<std::complex<double>> sortedEigenvalues(const Eigen::MatrixXd& A) {
    Eigen::EigenSolver<Eigen::MatrixXd> eig(A);
    std::vector<std::complex<double>> ev(eig.eigenvalues().data(), eig.eigenvalues().data() + A.rows());
    std::sort(ev.begin(), ev.end(), [](const auto& a, const auto& b) {
        if (std::abs(std::abs(a.imag()) - std::abs(b.imag())) > 1e-9 * (1 + std::abs(a)))
            return std::abs(a.imag()) < std::abs(b.imag());
        return a.real() > b.real();
    });
    return ev;
}

}  // namespace

static Eigen::MatrixXd dqBeltChainJacobian(const DqBeltChain& c) {
    const DqMachine& m = c.machine;
    const double we = 2 * M_PI * m.frequency, ls = m.lls + m.lm, lr = m.llr + m.lm, det = ls * lr - m.lm * m.lm;
    const double Te0 = c.loadTorque / c.ratio, s0 = slipForTorque(m, Te0);
    // Equilibrium currents: the synchronous-frame phasors (q − j·d) of the
    // circuit at s0, Z(0)·I = [√2·V; 0].
    using C = std::complex<double>;
    const C z11(m.rs, we * ls), z12(0, we * m.lm), z21(0, s0 * we * m.lm), z22(m.rr, s0 * we * lr);
    const C D = z11 * z22 - z12 * z21, V = std::sqrt(2.0) * m.phaseVoltage;
    const C Is = z22 * V / D, Ir = -z21 * V / D;
    // x = i_qs, i_ds, i'_qr, i'_dr, ω1, φ, ω2
    std::array<double, 7> x0 = {Is.real(), -Is.imag(), Ir.real(), -Ir.imag(), (1 - s0) * we / m.polePairs,
                                Te0 / c.stiffness, (1 - s0) * we / m.polePairs / c.ratio};
    auto rates = [&](const std::array<double, 7>& x) {
        const double wr = m.polePairs * x[4], slipSpeed = we - wr;
        const double lqs = ls * x[0] + m.lm * x[2], lds = ls * x[1] + m.lm * x[3];
        const double lqr = m.lm * x[0] + lr * x[2], ldr = m.lm * x[1] + lr * x[3];
        const double eqs = V.real() - m.rs * x[0] - we * lds, eds = -m.rs * x[1] + we * lqs;
        const double eqr = -m.rr * x[2] - slipSpeed * ldr, edr = -m.rr * x[3] + slipSpeed * lqr;
        const double Te = 1.5 * m.polePairs * m.lm * (x[0] * x[3] - x[1] * x[2]);
        const double belt = c.stiffness * x[5] + c.damping * (x[4] - c.ratio * x[6]);
        std::array<double, 7> d{};
        d[0] = (lr * eqs - m.lm * eqr) / det;
        d[2] = (ls * eqr - m.lm * eqs) / det;
        d[1] = (lr * eds - m.lm * edr) / det;
        d[3] = (ls * edr - m.lm * eds) / det;
        d[4] = (Te - belt) / c.motorInertia;
        d[5] = x[4] - c.ratio * x[6];
        d[6] = (c.ratio * belt - c.loadTorque) / c.flywheelInertia;
        return d;
    };
    Eigen::MatrixXd A(7, 7);
    for (int j = 0; j < 7; ++j) {
        const double h = 1e-6 * std::max(1.0, std::abs(x0[j]));
        auto xp = x0, xm = x0;
        xp[j] += h;
        xm[j] -= h;
        const auto fp = rates(xp), fm = rates(xm);
        for (int i = 0; i < 7; ++i) A(i, j) = (fp[i] - fm[i]) / (2 * h);
    }
    return A;
}

static Eigen::MatrixXd staticBeltChainMatrix(const DqBeltChain& c) {
    const DqMachine& m = c.machine;
    const double we = 2 * M_PI * m.frequency, ws = we / m.polePairs;
    const double s0 = slipForTorque(m, c.loadTorque / c.ratio), ds = 1e-6;
    // dT/dω = −(dT/ds)/ω_s: the static curve's damping.
    const double slope = -(dqHeldResponse(m, s0 + ds, 1.0, 0.0).torque - dqHeldResponse(m, s0 - ds, 1.0, 0.0).torque) /
                         (2 * ds) / ws;
    // x = ω1, φ, ω2
    Eigen::MatrixXd A(3, 3);
    A << (slope - c.damping) / c.motorInertia, -c.stiffness / c.motorInertia, c.damping * c.ratio / c.motorInertia,
        1, 0, -c.ratio,
        c.ratio * c.damping / c.flywheelInertia, c.ratio * c.stiffness / c.flywheelInertia,
        -c.ratio * c.ratio * c.damping / c.flywheelInertia;
    return A;
}

std::vector<std::complex<double>> dqBeltChainEigenvalues(const DqBeltChain& c) {
    return sortedEigenvalues(dqBeltChainJacobian(c));
}

std::vector<std::complex<double>> staticBeltChainEigenvalues(const DqBeltChain& c) {
    return sortedEigenvalues(staticBeltChainMatrix(c));
}

std::complex<double> dqBeltChainBeltResponse(const DqBeltChain& c, double P, std::complex<double> torque,
                                             bool staticSlope) {
    // States: fifth-order x = (i_qs, i_ds, i'_qr, i'_dr, ω1, φ, ω2); static
    // x = (ω1, φ, ω2). The forcing enters ω2's row as torque/J2.
    const Eigen::MatrixXd A = staticSlope ? staticBeltChainMatrix(c) : dqBeltChainJacobian(c);
    const int n = static_cast<int>(A.rows()), w1 = staticSlope ? 0 : 4;
    Eigen::VectorXcd b = Eigen::VectorXcd::Zero(n);
    b[w1 + 2] = torque / c.flywheelInertia;
    const Eigen::MatrixXcd Z = std::complex<double>(0, P) * Eigen::MatrixXcd::Identity(n, n) - A.cast<std::complex<double>>();
    const Eigen::VectorXcd x = Z.fullPivLu().solve(b);
    // Belt torque k·φ + c·(ω1 − n·ω2).
    return c.stiffness * x[w1 + 1] + c.damping * (x[w1] - c.ratio * x[w1 + 2]);
}

}  // namespace milldyn::oracles
