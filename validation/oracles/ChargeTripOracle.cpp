#include "validation/oracles/ChargeTripOracle.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace milldyn::oracles {
namespace {

using State = std::array<double, 3>;  // α, ω_c, ω_d

State derivative(const LiveChargeTrip& p, const State& x, bool held) {
    const double drag = p.wallDrag * (x[2] - x[1]);  // the wall's torque on the charge
    const double charge = (drag - p.chargeMoment * std::sin(x[0])) / p.chargeInertia;
    return {x[1], charge, held ? 0.0 : -drag / p.drumInertia};
}

State rk4(const LiveChargeTrip& p, const State& x, double h, bool held) {
    const auto add = [](const State& a, const State& k, double s) {
        return State{a[0] + s * k[0], a[1] + s * k[1], a[2] + s * k[2]};
    };
    const State k1 = derivative(p, x, held);
    const State k2 = derivative(p, add(x, k1, h / 2), held);
    const State k3 = derivative(p, add(x, k2, h / 2), held);
    const State k4 = derivative(p, add(x, k3, h), held);
    State y;
    for (int i = 0; i < 3; ++i) y[i] = x[i] + h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    return y;
}

}  // namespace

LiveChargeTripResult simulateLiveChargeTrip(const LiveChargeTrip& p, double duration, double dt) {
    if (!(p.drumInertia > 0 && p.chargeInertia > 0 && p.chargeMoment > 0 && p.wallDrag > 0 && p.drumSpeed > 0))
        throw std::invalid_argument("simulateLiveChargeTrip: inertias, moment, drag and speed must be > 0");
    const double s0 = p.wallDrag * p.drumSpeed / p.chargeMoment;
    if (s0 >= 1) throw std::invalid_argument("simulateLiveChargeTrip: the wall drag lifts the charge past 90 deg");
    LiveChargeTripResult r;
    r.lagAtTrip = std::asin(s0);
    State x{r.lagAtTrip, 0.0, p.drumSpeed};
    r.smallestLag = x[0];
    r.smallestDrumSpeed = x[2];
    bool held = false, stopped = false;
    double t = 0;
    while (t < duration) {
        const double h = std::min(dt, duration - t);
        State y = rk4(p, x, h, held);
        double step = h;
        if (!held && y[2] < 0 && x[2] >= 0) {
            // The drum reaches zero speed within the step: find where.
            double lo = 0, hi = h;
            for (int i = 0; i < 60; ++i) {
                const double mid = 0.5 * (lo + hi);
                (rk4(p, x, mid, false)[2] >= 0 ? lo : hi) = mid;
            }
            step = hi;
            y = rk4(p, x, step, false);
            if (!stopped) {
                r.drumStopTime = t + step;
                stopped = true;
            }
            if (p.backstop && y[1] < 0) {  // the drag pulls backwards: the backstop takes it
                y[2] = 0;
                held = true;
            }
        } else if (held && y[1] >= 0) {
            // The charge turns forwards again: the drag pulls the drum on and the backstop lets go.
            double lo = 0, hi = h;
            for (int i = 0; i < 60; ++i) {
                const double mid = 0.5 * (lo + hi);
                (rk4(p, x, mid, true)[1] < 0 ? lo : hi) = mid;
            }
            step = hi;
            y = rk4(p, x, step, true);
            held = false;
        }
        x = y;
        t += step;
        if (held) r.peakBackstopTorque = std::max(r.peakBackstopTorque, -p.wallDrag * x[1]);
        r.smallestLag = std::min(r.smallestLag, x[0]);
        r.smallestDrumSpeed = std::min(r.smallestDrumSpeed, x[2]);
        if (stopped) r.largestLaterDrumSpeed = std::max(r.largestLaterDrumSpeed, x[2]);
    }
    return r;
}

}  // namespace milldyn::oracles
