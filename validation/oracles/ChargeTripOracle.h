// Oracle for a tumbling drum that trips with a live charge: the drum and its
// charge as two bodies on one axis, coupled by the wall's viscous drag, the
// charge a pendulum under gravity, with or without an ideal backstop on the
// drum. Written from Newton's law for two rotors (no Simbody), integrated by
// its own fixed-step RK4 with the backstop's lock and release located by
// bisection within a step.
#pragma once

namespace milldyn::oracles {

struct LiveChargeTrip {
    double drumInertia = 0;    ///< J_d [kg*m^2]: the shell alone
    double chargeInertia = 0;  ///< J_c [kg*m^2]: the charge about the drum axis
    double chargeMoment = 0;   ///< W = m·g·r_c [N*m]: the charge's weight times its centroid distance
    double wallDrag = 0;       ///< c_w [N*m*s/rad]
    double drumSpeed = 0;      ///< ω0 [rad/s] > 0: steady drum speed at the trip
    bool backstop = false;     ///< an ideal backstop: the drum never turns backwards
};

/// What the trip does. The running state at the trip has the charge at rest
/// at its lag α0 = asin(c_w·ω0/W) (the wall drag's torque c_w·ω0 balances
/// the weight's moment W·sin α0). After the trip, with α the charge's lag
/// from the downward vertical (+ in the drum's running sense) and ω_c = dα/dt:
/// <pre>
///   J_c·dω_c/dt = c_w·(ω_d − ω_c) − W·sin α
///   J_d·dω_d/dt = −c_w·(ω_d − ω_c) + T_b
///   T_b = c_w·(ω_d − ω_c) while the backstop holds the drum at ω_d = 0
///         (from ω_d reaching 0 while the drag pulls it backwards, ω_c < 0,
///         until the drag turns forwards, ω_c >= 0); 0 otherwise
/// </pre>
struct LiveChargeTripResult {
    double lagAtTrip = 0;         ///< α0 [rad]
    double drumStopTime = 0;      ///< first ω_d = 0 after the trip [s from the trip]
    double peakBackstopTorque = 0;///< largest T_b [N*m] (backstop only)
    double smallestLag = 0;       ///< the charge's furthest back-swing, min α [rad]
    double smallestDrumSpeed = 0; ///< min ω_d [rad/s]: < 0 is a roll-back (no backstop)
    double largestLaterDrumSpeed = 0;  ///< max ω_d after the first stop [rad/s]
};

/// Integrates `duration` [s] after the trip with step `dt` [s].
LiveChargeTripResult simulateLiveChargeTrip(const LiveChargeTrip& p, double duration, double dt);

}  // namespace milldyn::oracles
