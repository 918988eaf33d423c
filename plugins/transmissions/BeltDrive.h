#pragma once
// BeltDrive: an open belt from a sheave fixed on the carrier axis (on
// ground, not turning) to a sheave rigid with a drum on that carrier
// (seed 002: planetary mill with belt drive).

#include "plugins/scene/Scene.h"

namespace milldyn {

/// Common external tangents of two sheaves in the plane z = 0: the two belt
/// spans, recomputed from the current sheave centres.
struct BeltSpans {
    double centreDistance = 0;  ///< l = |p_A − p_O| [m]
    double sinBeta = 0;         ///< s = (r0 − r_A)/l, signed; sin β = |s| (seed 002 eq 5)
    double beta = 0;            ///< β = asin|s| [rad] >= 0
    double wrapFixed = 0;       ///< θ0 = π + 2 asin s [rad]: wrap on the fixed sheave
    double wrapDrum = 0;        ///< θ_A = π − 2 asin s [rad]: wrap on the drum sheave
    SimTK::Vec3 out;            ///< e = (p_A − p_O)/l
    SimTK::Vec3 leadPoint, trailPoint;          ///< tangent points on the drum sheave (ground)
    SimTK::Vec3 leadFixedPoint, trailFixedPoint;///< tangent points on the fixed sheave (ground)
    SimTK::Vec3 leadDir, trailDir;              ///< unit span directions from the drum toward O
};

/// Spans for sheave centres p_O (radius r0) and p_A (radius r_A). The lead
/// span is the one on the side A moves to for a counter-clockwise carrier
/// (+z × e), the trail span the other. Throws std::invalid_argument when
/// |r0 − r_A| > l (no open belt).
BeltSpans calcBeltSpans(const SimTK::Vec3& fixedCentre, double fixedRadius, const SimTK::Vec3& drumCentre,
                        double drumRadius);

/// Which tension law the belt follows.
enum class BeltLaw {
    Rigid,    ///< the paper's: inextensible, T_tight = 2·T_slack (a constraint)
    Elastic,  ///< pretension, span stiffness and damping, Euler–Eytelwein slip
};

/// The elastic span law shared by BeltDrive's Elastic law and ShaftBelt:
/// each span a spring-damper about the pretension T0, the tension change
/// y = k_s·x_e + c_s·x' capped by Euler–Eytelwein at
/// y_max = T0 (E − 1)/(E + 1) (E = e^(μθ) the grip ratio); beyond the cap
/// the belt slips at s' = x' − (±y_max − k_s x_e)/c_s [m/s].
struct BeltSpanForce {
    double y = 0;          ///< span force change [N]: one span T0 + y, the other T0 − y
    double slipSpeed = 0;  ///< s' [m/s]
    bool slipping = false;
};
BeltSpanForce calcBeltSpanForce(double pretension, double stiffness, double damping, double gripRatio, double stretch,
                                double feedRate);
/// Elastic energy of the two spans at stretch x_e, less its value at rest:
/// Σ max(0, T0 ± k x_e)²/(2k) − T0²/k [J].
double calcBeltSpanEnergy(double pretension, double stiffness, double stretch);
/// Power the belt turns into heat [W] >= 0: the power in, ΔT·x' (ΔT the
/// span tension difference that does work on the feed), less the rate of
/// the spans' elastic energy (damping plus y_max·|s'| when slipping).
double calcBeltDissipatedPower(double pretension, double stiffness, const BeltSpanForce& f, double stretch,
                               double feedRate);

struct BeltDriveParams {
    double fixedSheaveRadius = 0;  ///< r0 [m] > 0, on ground at the carrier axis
    double drumSheaveRadius = 0;   ///< r_A [m] > 0, rigid with the drum
    BeltLaw law = BeltLaw::Rigid;
    double tightToSlack = 2;       ///< Rigid: T_tight/T_slack [-] >= 1 (paper: 2)
    double pretension = 0;         ///< Elastic: T0 [N] >= 0 in each span at rest
    double spanStiffness = 0;      ///< Elastic: k_s [N/m] > 0 of each span (EA/length)
    double spanDamping = 0;        ///< Elastic: c_s [N*s/m] > 0 of each span
    double frictionCoefficient = 0;///< μ [-] >= 0 between belt and sheaves (V-belt: effective μ/sin(φ/2))
};

/**
 * Kinematics (seed 002 eqs 1–5). The carrier turns about O (its pin axis),
 * where the fixed sheave r0 sits on ground; the drum turns on a pin at A on
 * the carrier. Relative to the carrier the fixed sheave turns at −Ω, and an
 * inextensible belt passes that on, so with q1 the carrier's angle and q2
 * the drum's angle relative to the carrier
 * <pre>
 *   x = r0·q1 + r_A·q2 = 0   ⇒   ω = Ω + q2' = Ω(1 − r0/r_A)           (1)–(4)
 *   sin β = |r0 − r_A|/l_OA,  wraps θ0 = π + 2 asin s,  θ_A = π − 2 asin s,
 *   s = (r0 − r_A)/l_OA                                                   (5)
 * </pre>
 * x is the belt "fed" by the drum sheave less the belt fed by the fixed
 * sheave, in the carrier frame: the lead span lengthens by −x, the trail
 * span by +x. The spans are the common external tangents (calcBeltSpans),
 * recomputed from the current positions; span forces act at the tangent
 * points along the spans, so the pull loads the drum's pin and shows in its
 * Simbody reaction. A span force T has moment r_A·T about A and r0·T about O
 * (same sign), so only the tension difference ΔT = T_lead − T_trail does
 * work: Q_carrier = r0·ΔT, Q_drum = r_A·ΔT. The common part (T_lead + T_trail)/2
 * pulls A straight toward O: workless for every motion the pins allow.
 *
 * Rigid law (a), the paper's. A holonomic Constraint::Custom x = 0, like
 * GearMesh: its multiplier λ is the tension difference (ΔT = −λ, the
 * transmitted torque on the drum r_A·ΔT), exactly the unknown the drum's
 * moment equilibrium (14m)/(15) fixes. The paper's T1 = 2·T2 then sets the
 * common part: T_tight = 2|λ|, T_slack = |λ| (ratio `tight_to_slack`). The
 * tight span is whichever the torque demands (the trailing one when the
 * charge's moment about A is counter-clockwise). A constraint rather than a
 * kinetostatic unknown because the transmitted torque must also be right in
 * a time simulation, and the multiplier is what Simbody solves anyway; the
 * |λ|-dependent common part is workless, so it changes no acceleration (as
 * GearMesh's separating force). Valid while the centre distance is constant
 * (the drum on a rigid carrier): otherwise the common part would do work.
 *
 * Elastic law (b). Each span is a spring-damper about the pretension T0;
 * with the slip s (a state: belt slid over the sheaves) and x_e = x − s
 * <pre>
 *   y = k_s·x_e + c_s·x_e',     T_lead = max(0, T0 − y),  T_trail = max(0, T0 + y)
 *   Euler–Eytelwein: T_tight/T_slack <= E = e^(μ θ_min)  ⇔  |y| <= y_max = T0 (E − 1)/(E + 1)
 *   stick: s' = 0 while |k_s x_e + c_s x'| <= y_max
 *   slip:  y = ±y_max, x_e' = (±y_max − k_s x_e)/c_s, s' = x' − x_e'   (slip speed s' [m/s])
 * </pre>
 * (T_lead + T_trail = 2·T0 holds while both spans carry tension: a constant
 * centre distance, belt mass and centrifugal belt tension neglected). With
 * finite μ the cap keeps T_slack >= 2T0/(E + 1) > 0: the belt slips before
 * its slack span can go slack. Steady running at ω = Ω(1 − r0/r_A) comes out
 * of x_e' = 0. A kinetostatic analysis solves x_e for zero drum acceleration.
 * Potential energy Σ max(0, T0 ∓ k_s x_e)²/(2k_s) (less its value at rest);
 * dissipation = damping + y_max·|s'|.
 *
 * Restriction: the fixed sheave is on ground at the carrier's pin axis and
 * the drum is pinned to the carrier (the seed-002 mill); a belt between two
 * arbitrary bodies is not implemented.
 */
class BeltDrive {
public:
    BeltDrive(const SimTK::MobilizedBody& carrier, const SimTK::MobilizedBody& drum, const BeltDriveParams& p);

    const BeltDriveParams& params() const { return m_p; }
    /// Drum angle relative to the carrier that makes x = 0 [rad], and the speed.
    double calcDrumAngle(double carrierAngle) const;
    double calcDrumSpeed(double carrierSpeed) const;
    /// x = r0 q1 + r_A q2 [m] and x' [m/s].
    double calcFeed(const SimTK::State& s) const;
    double calcFeedRate(const SimTK::State& s) const;
    /// Centres of the fixed sheave (carrier axis O) and of the drum sheave
    /// (drum axis A) in ground [m] (Stage::Position).
    SimTK::Vec3 calcFixedCentre(const SimTK::State& s) const;
    SimTK::Vec3 calcDrumCentre(const SimTK::State& s) const;
    /// Spans in the current configuration (Stage::Position).
    BeltSpans calcSpans(const SimTK::State& s) const;
    /// e^(μ θ_min) [-]: the largest tension ratio the belt can hold.
    double calcGripRatio(const SimTK::State& s) const;
    /// Drum's absolute angular speed ω [rad/s] and 1/l_AD = (r0 − r_A)/(r_A l_OA) [1/m]
    /// (zero exactly when the drum translates: no instantaneous centre).
    double calcDrumAbsoluteSpeed(const SimTK::State& s) const;
    double calcInverseCentreOffset() const;

protected:
    SimTK::MobilizedBody m_carrier, m_drum;
    BeltDriveParams m_p;
    double m_nominalDistance;
};

/// Rigid law (a): the constraint. Tensions need Stage::Acceleration.
class RigidBeltConstraint : public SimTK::Constraint::Custom::Implementation, public BeltDrive {
public:
    RigidBeltConstraint(SimTK::SimbodyMatterSubsystem& matter, const SimTK::MobilizedBody& carrier,
                        const SimTK::MobilizedBody& drum, const BeltDriveParams& p);
    Implementation* clone() const override { return new RigidBeltConstraint(*this); }

    /// Span tensions [N] from the multiplier λ (ΔT = −λ).
    void calcTensions(double lambda, double& lead, double& trail) const;
    void calcTensions(const SimTK::State& s, const SimTK::Constraint& self, double& lead, double& trail) const;

    void calcPositionErrors(const SimTK::State& s, const SimTK::Array_<SimTK::Transform, SimTK::ConstrainedBodyIndex>&,
                            const SimTK::Array_<SimTK::Real, SimTK::ConstrainedQIndex>& q,
                            SimTK::Array_<SimTK::Real>& perr) const override;
    void calcPositionDotErrors(const SimTK::State& s, const SimTK::Array_<SimTK::SpatialVec, SimTK::ConstrainedBodyIndex>&,
                               const SimTK::Array_<SimTK::Real, SimTK::ConstrainedQIndex>& qdot,
                               SimTK::Array_<SimTK::Real>& pverr) const override;
    void calcPositionDotDotErrors(const SimTK::State& s,
                                  const SimTK::Array_<SimTK::SpatialVec, SimTK::ConstrainedBodyIndex>&,
                                  const SimTK::Array_<SimTK::Real, SimTK::ConstrainedQIndex>& qdotdot,
                                  SimTK::Array_<SimTK::Real>& paerr) const override;
    void addInPositionConstraintForces(const SimTK::State& s, const SimTK::Array_<SimTK::Real>& multipliers,
                                       SimTK::Array_<SimTK::SpatialVec, SimTK::ConstrainedBodyIndex>& bodyForcesInA,
                                       SimTK::Array_<SimTK::Real, SimTK::ConstrainedQIndex>& qForces) const override;

private:
    SimTK::ConstrainedBodyIndex m_groundBody, m_carrierBody, m_drumBody;
    SimTK::ConstrainedMobilizerIndex m_carrierMob, m_drumMob;
};

/// Elastic law (b): a force element with the slip s as a continuous state.
class ElasticBeltForce : public SimTK::Force::Custom::Implementation, public BeltDrive {
public:
    ElasticBeltForce(const SimTK::GeneralForceSubsystem& forces, const SimTK::MobilizedBody& carrier,
                     const SimTK::MobilizedBody& drum, const BeltDriveParams& p);

    /// The span law at one instant (Stage::Velocity).
    struct Tensions {
        double lead = 0, trail = 0;  ///< [N] >= 0
        double y = 0;                ///< span force change [N] (T_lead = T0 − y)
        double slipSpeed = 0;        ///< s' [m/s]
        bool slipping = false;
    };
    Tensions calcTensions(const SimTK::State& s) const;
    double getSlip(const SimTK::State& s) const;          ///< s [m]
    void setSlip(SimTK::State& s, double slip) const;
    double calcStretch(const SimTK::State& s) const { return calcFeed(s) - getSlip(s); }  ///< x_e [m]
    /// Sets s so that x_e = stretch (the kinetostatic unknown).
    void setStretch(SimTK::State& s, double stretch) const { setSlip(s, calcFeed(s) - stretch); }
    double calcDissipatedPower(const SimTK::State& s) const;  ///< [W] >= 0

    void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& bodyForces, SimTK::Vector_<SimTK::Vec3>&,
                   SimTK::Vector&) const override;
    SimTK::Real calcPotentialEnergy(const SimTK::State& s) const override;
    void realizeTopology(SimTK::State& s) const override;
    void realizeAcceleration(const SimTK::State& s) const override;

private:
    const SimTK::GeneralForceSubsystem& m_forces;
    mutable SimTK::ZIndex m_slip;
    double m_maxY;  // y_max at the nominal wraps
};

}  // namespace milldyn
