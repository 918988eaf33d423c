// Closed-form oracle for tumbling mills (issue 19): the charge as a circular
// segment held at a lag (torque-arm power), the critical speed, the running
// speed of a Kloss motor driving the charge through a ratio, and the natural
// frequencies of a geared chain of inertias reduced to one shaft (ratio²).
//
// Standard library and Eigen only; its own parameter structs, written from
// textbook closed forms, so it cannot share a bug with the Simbody model.
// The charge part is the `charges` branch's; gear and bearing parts belong
// beside it (branch `gears`).
#pragma once

#include <vector>

namespace milldyn::oracles {

/// A circular segment of a drum's cross-section cut by a chord, described by
/// its full central angle θ (the chord subtends θ at the centre), the
/// textbook parametrization (θ = 2γ of the model's half-angle).
struct CircularSegmentCharge {
    double drumRadius;   ///< R [m] > 0
    double length;       ///< L [m] > 0, axial
    double bulkDensity;  ///< ρ [kg/m^3] > 0
    double fill;         ///< J [1] in (0, 1]: area / (π R²)
};

/// Full central angle θ [rad] of the segment of area fraction J: solves
/// θ − sin θ = 2πJ (Newton from a bracketing start).
double segmentCentralAngle(double fill);
/// Area [m^2]: A = R²(θ − sin θ)/2.
double segmentArea(const CircularSegmentCharge& c);
/// Centroid distance from the centre [m]: ȳ = 4 R sin³(θ/2) / (3 (θ − sin θ)).
double segmentCentroidDistance(const CircularSegmentCharge& c);
/// Polar moment of the segment about the drum axis [kg*m^2]: the sector's
/// ρL R⁴θ/4 less the triangle's ρL R⁴ sin θ (2 + cos θ)/12 (vertex formula
/// J_O = A (a·a + a·b + b·b)/6).
double segmentAxisInertia(const CircularSegmentCharge& c);
/// Mass [kg]: ρ L A.
double segmentMass(const CircularSegmentCharge& c);

/// Critical speed [rad/s] of a drum of inner diameter D: a particle on the
/// wall (radius neglected) is pressed to it at the top, ω_c = sqrt(2g/D).
double criticalSpeed(double drumDiameter, double g);

/// Torque-arm torque [N*m] of a charge whose centroid is at lag α from the
/// downward vertical: M = m g ȳ sin α (its power P = M ω).
double torqueArmTorque(const CircularSegmentCharge& c, double lag, double g);

/// Kloss induction motor: M(s) = 2 Mk / (s/s_k + s_k/s), Mk = λ Mn,
/// s = (ω_sync − ω)/ω_sync, s_k = s_n (λ + sqrt(λ² − 1)).
struct KlossMotor {
    double ratedTorque;        ///< Mn [N*m]
    double ratedSpeed;         ///< ω_n [rad/s]
    double synchronousSpeed;   ///< ω_sync [rad/s]
    double breakdownRatio;     ///< λ > 1
};
/// Running speed [rad/s] of the motor under a constant load torque T [N*m]
/// on its shaft: the stable root s = s_k (a − sqrt(a² − 1)), a = Mk/T, of
/// M(s) = T. Throws std::domain_error when T exceeds Mk (no running point).
double klossRunningSpeed(const KlossMotor& m, double loadTorque);

/// A chain of inertias J_0 … J_{n−1} joined by springs c_k from shaft k to
/// k+1 with ratio n_k = ω_k/ω_{k+1}, c_k referred to shaft k.
struct GearedChain {
    std::vector<double> inertias;    ///< [kg*m^2]
    std::vector<double> stiffnesses; ///< [N*m/rad], n−1 of them
    std::vector<double> ratios;      ///< [1], n−1 of them
};
/// The undamped natural frequencies [rad/s], ascending, rigid mode (0)
/// included: every shaft referred to shaft 0 (J_k/N_k², c_k/N_k² with
/// N_k the product of the ratios up to k), then K v = ω² M v.
std::vector<double> gearedChainFrequencies(const GearedChain& chain);
/// The mode shapes of the same eigenproblem in the referred angles θ_k
/// (columns in the order of the frequencies, each scaled to max |entry| = 1).
std::vector<std::vector<double>> gearedChainModeShapes(const GearedChain& chain);

}  // namespace milldyn::oracles
