#pragma once
// Oracle for seed 000's planetary mill started by an induction motor through
// a V-belt (docs/will-it-start.md): written from textbook formulas and the
// published catalogue points alone (standard library and the kinetostatic
// PlanetaryGearOracle; no Simbody, no milldyn element), so it cannot share a
// bug with the model it judges.
//
//  - the catalogue torque curve: monotone piecewise-cubic Hermite
//    interpolation (Fritsch & Carlson, SIAM J. Numer. Anal. 17 (1980)
//    238-246) through (0, Mst), (ω_pu, Mpu), (ω_k, Mk), (ω_n, Mn), (ω_c, 0),
//    ω_k from Kloss's sk = sn·(λ + √(λ² − 1)) when the catalogue gives none;
//  - Euler–Eytelwein: a belt of pretension T0 per span transmits at most
//    ΔT = T1 − T2 = 2·T0·(E − 1)/(E + 1), E = e^(μθ), with T1 + T2 = 2·T0
//    (constant-length elastic belt), θ the wrap on the small sheave
//    π − 2·asin(|r2 − r1|/C);
//  - the start time of a rigid drive, t = ∫ J_red dω/(M_motor(ω) − M_load(ω)),
//    by the composite Simpson rule on the motor shaft.

#include "validation/oracles/PlanetaryGearOracle.h"

#include <functional>
#include <vector>

namespace milldyn::oracles {

/// Catalogue points of an induction motor (SI).
struct CatalogueMotor {
    double ratedTorque = 0;        ///< Mn [N*m]
    double ratedSpeed = 0;         ///< ω_n [rad/s]
    double synchronousSpeed = 0;   ///< ω_c [rad/s]
    double lockedRotorRatio = 0;   ///< Mst/Mn
    double pullUpRatio = 0;        ///< Mpu/Mn (0: no point)
    double pullUpSpeed = 0;        ///< [rad/s]
    double breakdownRatio = 0;     ///< Mk/Mn
    double breakdownSpeed = 0;     ///< [rad/s]; 0: from Kloss's sk
};

/// The catalogue curve M(ω) [N*m] (Fritsch–Carlson through the points;
/// below 0 it holds Mst, above ω_c it continues with the end tangent).
class CatalogueCurve {
public:
    explicit CatalogueCurve(const CatalogueMotor& m);
    double operator()(double omega) const;

private:
    std::vector<double> m_x, m_y, m_m;
};

/// Time [s] for a rigid drive of constant inertia J [kg*m^2] (referred to
/// the motor shaft) to go from rest to `endSpeed` [rad/s]:
/// ∫ J dω/(M(ω) − Mc(ω)), composite Simpson with `intervals` (made even).
double calcRigidStartTime(double inertia, const std::function<double(double)>& driveTorque,
                          const std::function<double(double)>& loadTorque, double endSpeed, int intervals);
/// The speed in [lo, hi] where `excess` (drive − load torque) changes sign
/// from + to −, by bisection [rad/s]; throws when it does not.
double calcSteadySpeed(const std::function<double(double)>& excess, double lo, double hi);

/// V-belt between two sheaves on fixed centres (SI).
struct VBelt {
    double driverRadius = 0;      ///< r1 [m]
    double drivenRadius = 0;      ///< r2 [m]
    double centreDistance = 0;    ///< C [m]
    double pretension = 0;        ///< T0 [N] per span
    double frictionCoefficient = 0;  ///< effective μ' [-]
    double lineAngle = -1.5707963267948966;  ///< direction of the motor's axis seen from A in G [rad] (below: −π/2)
};
/// Wrap on the small sheave θ = π − 2·asin(|r2 − r1|/C) [rad].
double calcSmallWrap(const VBelt& b);
/// Euler–Eytelwein: the largest tension difference 2·T0·(E − 1)/(E + 1) [N].
double calcBeltCapacity(const VBelt& b);
/// Tight-span tension when the belt slips, 2·T0·E/(E + 1) [N].
double calcSlippingTightTension(const VBelt& b);

/// The running mill's journal loads and carrier torque at one carrier angle
/// (SI, vectors in G: ground on carrier at A, carrier pin on drum at B1, B2).
struct PlanetaryRunningLoads {
    double driveTorque = 0;  ///< belt torque on the carrier, friction (21) included [N*m]
    Eigen::Vector2d journalA{Eigen::Vector2d::Zero()};   ///< R_A with the belt's pull [N]
    Eigen::Vector2d journalB1{Eigen::Vector2d::Zero()};  ///< R_B1 [N]
    Eigen::Vector2d journalB2{Eigen::Vector2d::Zero()};  ///< R_B2 [N]
};

/// The mill on the carrier, as a load for the motor: the PlanetaryGearOracle's
/// steady kinetostatics (charges turning with the drums, ε = 0) averaged
/// over a carrier turn, with the belt's pull on the carrier's journal A.
class PlanetaryMotorStartOracle {
public:
    PlanetaryMotorStartOracle(const PlanetaryGearParameters& mill, const CatalogueMotor& motor, const VBelt& belt,
                              double motorInertia);
    double calcRatio() const { return m_belt.drivenRadius / m_belt.driverRadius; }  ///< i = r2/r1
    /// Reduced inertia of the mill on the carrier [kg*m^2]: J_pr with both
    /// charges turning with their drums (their lags differ by π, so the sum
    /// is constant: calcReducedInertia at α = 0 and α = π averaged).
    double calcMillInertia() const;
    /// Mean drive torque on the carrier at carrier speed ω [rad/s] over a
    /// carrier turn [N*m]: friction (21) with the journal A carrying the
    /// belt's pull (T1 + T2 = 2·T0, T1 − T2 = M/r2, solved by fixed point);
    /// the frictionless part averages to zero.
    double calcCarrierLoadTorque(double carrierSpeed) const;
    /// Steady running (ε = 0) at carrier speed ω [rad/s] and carrier angle φ
    /// [rad] (A→B2 from +x), the drums and the charges rigid with them
    /// turned by κφ from hanging at φ = 0: the journal loads of
    /// PlanetaryGearOracle::calcLoads (frictionless reactions, the paper's
    /// first-order method) with the belt's pull taken by the ground at A,
    /// and the drive torque (20) with A's friction from that load.
    PlanetaryRunningLoads calcRunningLoads(double carrierSpeed, double carrierAngle) const;
    /// Steady motor speed where M_motor(ω) = M_load(ω/i)/i [rad/s].
    double calcSteadyMotorSpeed() const;
    /// Time [s] for the carrier to reach `fraction` of its steady speed from
    /// rest, rigid belt: ∫ (J_m + J_pr/i²) dω/(M_motor(ω) − M_load(ω/i)/i)
    /// (Simpson, `intervals` even).
    double calcStartTime(double fraction, int intervals) const;

private:
    PlanetaryGearOracle m_mill;
    CatalogueCurve m_motor;
    CatalogueMotor m_catalogue;
    VBelt m_belt;
    double m_motorInertia;
};

}  // namespace milldyn::oracles
