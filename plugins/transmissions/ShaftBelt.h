#pragma once
// ShaftBelt: an open (V-)belt between two parallel shafts on ground pins,
// e.g. a motor's sheave driving a mill's carrier (seed 000, Fig. 1). Its
// spans follow BeltDrive's elastic law (pretension, span stiffness and
// damping, Euler–Eytelwein slip with the slip as a state).

#include "plugins/scene/Scene.h"
#include "plugins/transmissions/BeltDrive.h"

#include <cmath>

namespace milldyn {

struct ShaftBeltParams {
    double driverSheaveRadius = 0;  ///< r1 [m] > 0, rigid with the driver shaft
    double drivenSheaveRadius = 0;  ///< r2 [m] > 0, rigid with the driven shaft
    double pretension = 0;          ///< T0 [N] >= 0 in each span at rest (all strands of a multi-belt set)
    double spanStiffness = 0;       ///< k_s [N/m] > 0 of each span (EA/span length, all strands)
    double spanDamping = 0;         ///< c_s [N*s/m] > 0 of each span
    double frictionCoefficient = 0; ///< μ [-] >= 0 (V-belt: effective μ/sin(half groove angle))
};

/**
 * Open belt between sheave 1 (radius r1, on the driver, centre C1) and
 * sheave 2 (r2, driven, C2), both shafts on pins on ground so the centres
 * and spans are fixed in ground (centre distance l = |C2 − C1|, the pins'
 * locations). Both sheaves turn the same way. With q1, q2 the pin angles
 * and s the slip (a state), the feed and the stretch are
 * <pre>
 *   x = r1·q1 − r2·q2 [m],   x_e = x − s
 *   wrap on the small sheave θ = π − 2·asin(|r1 − r2|/l),  grip E = e^(μθ)
 *   y = k_s·x_e + c_s·x' capped at ±y_max = ±T0 (E − 1)/(E + 1)   (BeltDrive's law)
 *   T_lead = T0 + y (the span x stretches),  T_trail = T0 − y
 *   torque on the driver −r1·2y, on the driven +r2·2y;  ratio i = r2/r1
 * </pre>
 * The span tensions act at the tangent points along the spans (the common
 * external tangents, calcBeltSpans), so the belt's pull T_lead + T_trail
 * loads both pins and shows in their Simbody reactions. Rigid-belt limit
 * (k_s → ∞, no slip): ω1 = i·ω2. Belt mass, centrifugal tension and creep
 * (the ~1 % elastic slip of a running V-belt) are neglected: below the
 * Euler–Eytelwein cap the belt sticks. Potential energy
 * calcBeltSpanEnergy(x_e); dissipation = damping + y_max·|s'|.
 */
class ShaftBelt : public SimTK::Force::Custom::Implementation {
public:
    ShaftBelt(const SimTK::GeneralForceSubsystem& forces, const SimTK::MobilizedBody& driver,
              const SimTK::MobilizedBody& driven, const ShaftBeltParams& p);

    struct Tensions {
        double lead = 0, trail = 0;  ///< [N] >= 0; lead = T0 + y
        BeltSpanForce span;
    };
    Tensions calcTensions(const SimTK::State& s) const;
    double calcFeed(const SimTK::State& s) const;      ///< x [m]
    double calcFeedRate(const SimTK::State& s) const;  ///< x' [m/s]
    double getSlip(const SimTK::State& s) const;       ///< s [m]
    void setSlip(SimTK::State& s, double slip) const;
    double calcStretch(const SimTK::State& s) const { return calcFeed(s) - getSlip(s); }
    double getGripRatio() const { return m_grip; }     ///< E = e^(μθ) [-]
    double getWrap() const { return m_wrap; }           ///< θ on the small sheave [rad]
    /// Pitch length of the open belt, L = r1·θ1 + r2·θ2 + 2·l·cos β [m].
    double getBeltLength() const {
        return m_p.driverSheaveRadius * m_spans.wrapFixed + m_p.drivenSheaveRadius * m_spans.wrapDrum +
               2 * m_spans.centreDistance * std::cos(m_spans.beta);
    }
    double calcDrivenTorque(const SimTK::State& s) const;  ///< on the driven shaft [N*m]
    double calcDriverTorque(const SimTK::State& s) const;  ///< the belt's resisting torque on the driver [N*m]
    double calcDissipatedPower(const SimTK::State& s) const;
    const ShaftBeltParams& params() const { return m_p; }

    void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& bodyForces, SimTK::Vector_<SimTK::Vec3>&,
                   SimTK::Vector&) const override;
    SimTK::Real calcPotentialEnergy(const SimTK::State& s) const override;
    void realizeTopology(SimTK::State& s) const override;
    void realizeAcceleration(const SimTK::State& s) const override;

private:
    const SimTK::GeneralForceSubsystem& m_forces;
    SimTK::MobilizedBody m_driver, m_driven;
    ShaftBeltParams m_p;
    BeltSpans m_spans;  // fixed in ground: driver = "fixed" sheave, driven = "drum" sheave of calcBeltSpans
    double m_wrap = 0, m_grip = 1;
    mutable SimTK::ZIndex m_slip;
};

}  // namespace milldyn
