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
