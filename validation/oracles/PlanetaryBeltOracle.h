#pragma once
// Closed-form kinetostatic oracle for the planetary mill with belt drive
// (seed 002; PHYSICS.md "002"; docs/oracles/planetary_belt.md).
//
// Standard library only: this oracle must not share code, and so bugs, with
// the multibody model it judges.

#include <limits>

namespace milldyn::oracles {

/// Which ratio the garbled criterion (8) denotes. The printed numerator is
/// unreadable; R0OverRA is the reading the rest of the paper's text supports
/// (see the doc), RAOverR0 fits the trend of its Fig. 8 somewhat better.
enum class CriterionCReading {
    R0OverRA,  ///< c = r0/r_A (default)
    RAOverR0,  ///< c = r_A/r0
};

/// Which inertial force multiplies l_Ac·cos α in the moment equation (14c)
/// and in (15); its subscript is lost in the OCR.
enum class MomentForceReading {
    /// Φ_c (10): physically consistent. Φ_c is the part of the charge's
    /// centrifugal force parallel to O→A; applied at the charge centroid its
    /// arm about A is l_Ac·cos α.
    TransportCharge,
    /// Φ_r (11): the literal-looking reading. Φ_r acts along A→centroid and
    /// has no moment about A, so this reading is kept only to reproduce what
    /// the paper may have computed.
    RelativeCharge,
};

/// How the vector rebuild forms the charge's inertial force.
enum class ChargeInertia {
    /// m_z·Ω²·p_OC applied at the centroid C. Exact when the charge's
    /// centroid is at rest in the carrier frame (the paper's "stable
    /// position"): the relative and Coriolis terms of the circulating
    /// material then sum to zero, in force and in moment about A.
    SteadyCentroid,
    /// The paper's split (10)+(11): Φ_c along O→A plus Φ_r = m_z·ω²·l_Ac
    /// along A→C, both applied at C. Differs from SteadyCentroid only by
    /// m_z·(Ω² − ω²)·l_Ac along A→C.
    PaperSplit,
};

/// Dimensionless criteria (6)–(8).
struct PlanetaryBeltCriteria {
    double k = std::numeric_limits<double>::quiet_NaN();  ///< (6) r_A/(l_OA + r_A), (0, 1)
    double b = std::numeric_limits<double>::quiet_NaN();  ///< (7) r_b/r_A, (0, ∞)
    double c = std::numeric_limits<double>::quiet_NaN();  ///< (8) r0/r_A or r_A/r0, (0, ∞)
};

/// Geometry of one drum and its belt, Fig. 1. Unset fields are NaN so that a
/// forgotten one is rejected rather than silently zero.
struct PlanetaryBeltGeometry {
    double drumRadius = std::numeric_limits<double>::quiet_NaN();         ///< r_b [m], inner, (0, ∞)
    double drumSheaveRadius = std::numeric_limits<double>::quiet_NaN();   ///< r_A [m], (0, ∞)
    double fixedSheaveRadius = std::numeric_limits<double>::quiet_NaN();  ///< r0 [m], (0, ∞)
    /// l_OA [m], (0, ∞), and |r0 − r_A| ≤ l_OA so that (5) has a belt angle.
    double carrierArm = std::numeric_limits<double>::quiet_NaN();
};

/// What the paper leaves out: the data that turn geometry into masses and
/// weights. suggestedSteelDrumMaterial() gives the values argued in the doc.
struct PlanetaryBeltMaterial {
    double drumLength = std::numeric_limits<double>::quiet_NaN();  ///< L [m], (0, ∞)
    /// δ [m], (0, ∞): shell wall, outside r_b.
    double shellThickness = std::numeric_limits<double>::quiet_NaN();
    /// δ_c [m], [0, ∞): each of two covers of radius r_b + δ.
    double coverThickness = std::numeric_limits<double>::quiet_NaN();
    /// h_s [m], [0, ∞): the sheave taken as a full disc of radius r_A.
    double sheaveThickness = std::numeric_limits<double>::quiet_NaN();
    /// ρ_b [kg/m³], (0, ∞): shell, covers and sheave.
    double drumDensity = std::numeric_limits<double>::quiet_NaN();
    /// ρ_z [kg/m³], (0, ∞): solid density of the charge.
    double chargeDensity = std::numeric_limits<double>::quiet_NaN();
    /// [-], (0, 1]: solid share of the segment's volume.
    double bulkFraction = std::numeric_limits<double>::quiet_NaN();
    double gravity = std::numeric_limits<double>::quiet_NaN();  ///< g [m/s²], [0, ∞)
};

/// Steel drum 0.2 m × 1 m with steel-ball charge; reasoning in the doc.
PlanetaryBeltMaterial suggestedSteelDrumMaterial();

/// Throws std::invalid_argument naming the field and its value; also
/// rejects sin β = |r0 − r_A|/l_OA > 1 (5).
void validate(const PlanetaryBeltGeometry& geometry);
void validate(const PlanetaryBeltMaterial& material);

/// (6)–(8) from geometry. Throws as validate(geometry).
PlanetaryBeltCriteria criteriaFromGeometry(const PlanetaryBeltGeometry& geometry,
                                           CriterionCReading reading = CriterionCReading::R0OverRA);

/// Inverse of (6)–(8) for a given drum radius r_b [m]:
/// r_A = r_b/b, l_OA = r_A(1 − k)/k, r0 = c·r_A or r_A/c. Throws for k ∉ (0, 1),
/// b or c ∉ (0, ∞), r_b ∉ (0, ∞), or a result with sin β > 1.
PlanetaryBeltGeometry geometryFromCriteria(const PlanetaryBeltCriteria& criteria, double drumRadius,
                                           CriterionCReading reading = CriterionCReading::R0OverRA);

/// sin β = |r0 − r_A|/l_OA (5), in [0, 1]. Throws as validate(geometry).
double calcSinBeltAngle(const PlanetaryBeltGeometry& geometry);

/// Drum kinematics (1)–(4) at carrier rate Ω. Signs: positive rotation is
/// the carrier's sense; x is along O→A.
struct PlanetaryBeltKinematics {
    double carrierSpeedAtA = 0;  ///< v_A = Ω·l_OA (2) [m/s]
    /// ω = Ω(1 − r0/r_A) [rad/s], absolute. Zero at r0 = r_A (translation)
    /// and negative beyond: the drum turns against the carrier.
    double drumRate = 0;
    /// ω − Ω = −Ω·r0/r_A [rad/s]: the drum as seen from the carrier, which
    /// is what drags the charge. Never zero for Ω ≠ 0, even at r0 = r_A.
    double relativeRate = 0;
    /// 1/l_AD = (r0 − r_A)/(r_A·l_OA) [1/m]: the finite, signed form of (4);
    /// zero exactly when the drum translates.
    double inverseCentreOffset = 0;
    /// False when the drum translates (r0 = r_A): then there is no
    /// instantaneous centre and centreOffsetFromA is meaningless (set to 0).
    /// Depends on geometry only, like (4): at Ω = 0 it is the limit Ω → 0.
    bool hasInstantaneousCentre = false;
    /// l_AD of (4), signed as the coordinate of D minus that of A along O→A
    /// [m]: > 0 beyond A (r0 > r_A), < 0 on the far side of O (r0 < r_A).
    /// (3)–(4) are printed for the first case; for r0 < r_A they give this
    /// negative value, whose magnitude is the true distance.
    double centreOffsetFromA = 0;
};

/// Throws for bad geometry or Ω not finite.
PlanetaryBeltKinematics calcKinematics(const PlanetaryBeltGeometry& geometry, double carrierRate);

/// Segment of a circle of radius r_b [m] cut by a chord, of half-angle
/// γ [rad] ∈ (0, π) (the charge, (12)–(13)). All throw std::invalid_argument
/// naming the argument if it is out of range.
/// S = ½·r_b²·(2γ − sin 2γ) (13) [m²].
double calcSegmentArea(double drumRadius, double halfAngle);
/// l_Ac = 4·r_b·sin³γ / (3·(2γ − sin 2γ)) (12) [m]: r_b as γ → 0,
/// 2·r_b·(π − γ)³/(3π) as γ → π.
double calcSegmentCentroidDistance(double drumRadius, double halfAngle);
/// S/(π·r_b²) = (2γ − sin 2γ)/(2π) ∈ (0, 1).
double calcFillDegree(double halfAngle);
/// γ with calcFillDegree(γ) = fill, fill ∈ (0, 1).
double calcHalfAngleFromFill(double fill);
/// Below this half-angle 2γ − sin 2γ is summed as a series: the direct
/// difference loses about log10(6/(2γ)²) digits to cancellation.
inline constexpr double kSegmentSeriesHalfAngle = 0.5;

/// Masses [kg]. Drum = shell + covers + sheave (the paper: "the body with its
/// covers and the sheave rigid with it").
struct PlanetaryBeltMasses {
    double shell = 0;   ///< ρ_b·π·((r_b + δ)² − r_b²)·L
    double covers = 0;  ///< 2·ρ_b·π·(r_b + δ)²·δ_c
    double sheave = 0;  ///< ρ_b·π·r_A²·h_s
    double drum = 0;    ///< m_b, the sum of the three
    double charge = 0;  ///< m_z = ρ_z·S·L·bulkFraction
};

/// Throws for bad geometry, material or γ.
PlanetaryBeltMasses calcMasses(const PlanetaryBeltGeometry& geometry, const PlanetaryBeltMaterial& material,
                               double segmentHalfAngle);

/// (9)–(11) [N].
struct PlanetaryBeltInertialForces {
    double drumTransport = 0;   ///< Φ_A = m_b·Ω²·l_OA (9)
    double chargeTransport = 0; ///< Φ_c = m_z·Ω²·l_OA (10)
    double chargeRelative = 0;  ///< Φ_r = m_z·ω²·l_Ac (11)
};

/// Everything that defines one load case.
struct PlanetaryBeltParameters {
    PlanetaryBeltGeometry geometry;
    PlanetaryBeltMaterial material;
    double carrierRate = std::numeric_limits<double>::quiet_NaN();       ///< Ω [rad/s], [0, ∞), counter-clockwise
    double segmentHalfAngle = std::numeric_limits<double>::quiet_NaN();  ///< γ [rad], (0, π)
    /// α [rad], [0, π]; paper: 40°–60°. Measured at A from the trailing
    /// tangent −y towards the outward radial +x, so the centroid is at
    /// l_Ac·(sin α, −cos α): the placement that (16)–(17) imply.
    double chargeLag = std::numeric_limits<double>::quiet_NaN();
    MomentForceReading momentReading = MomentForceReading::TransportCharge;
};

/// The paper's oracle, (15)–(18), at one carrier angle. Reaction signs as in
/// (14): the axle pushes the drum with (−X_A, +Y_A).
struct PaperReaction {
    double slackTension = 0;  ///< T2 (15) [N]; < 0 means the belt model fails
    double tightTension = 0;  ///< T1 = 2·T2 [N]
    double xA = 0;            ///< X_A (16) [N]
    double yA = 0;            ///< Y_A (17) [N]
    double rA = 0;            ///< R_A (18) [N]
};

/// The rebuilt oracle: vector equilibrium of the drum in the carrier frame.
struct RebuiltReaction {
    double forceX = 0;  ///< axle on drum, along O→A [N]
    double forceY = 0;  ///< axle on drum, along the carrier's motion at A [N]
    double xA = 0;      ///< −forceX: (16)'s sign convention [N]
    double yA = 0;      ///< forceY: (17)'s sign convention [N]
    double rA = 0;      ///< |force| [N]
    double tightTension = 0;  ///< [N], ≥ 0
    double slackTension = 0;  ///< [N], ≥ 0, tight/2
    /// The tight span is on the trailing (−y) side when the charge's moment
    /// about A is counter-clockwise, as the fixed sheave's drive requires.
    bool trailingSpanTight = true;
    double chargeMomentAboutA = 0;  ///< of the charge's inertia and weight [N·m], CCW +
};

/// Extremes of R_A over one carrier turn.
struct ReactionExtremes {
    double max = 0;          ///< [N]
    double angleAtMax = 0;   ///< φ [rad], [0, 2π)
    double min = 0;          ///< [N]
    double angleAtMin = 0;   ///< φ [rad], [0, 2π)
};

/// Kinetostatic oracle for one drum of the planetary mill with belt drive
/// (seed 002: "The influence of constructive and technological parameters
/// on dynamic loads in elements of a planetary mill with a belt drive").
///
/// System: a carrier of arm l_OA turns at constant Ω about O. The drum
/// (inner radius r_b, length L) turns on its axle at A; a sheave r_A rigid
/// with it is belted (open belt) to a sheave r0 that is fixed, not turning,
/// on the carrier axis. The charge is a circular segment of half-angle γ at
/// rest in the carrier frame, its centroid lagging by α.
///
/// Frame: rotating with the carrier, origin O, x along O→A, y = z × x (the
/// direction A moves for Ω > 0). φ is the carrier angle from the horizontal,
/// counter-clockwise, so gravity is g·(−sin φ, −cos φ) in this frame.
/// <pre>
///   ω = Ω(1 − r0/r_A)                                (1)–(4)
///   sin β = |r0 − r_A|/l_OA                          (5)
///   l_Ac = 4 r_b sin³γ/(3(2γ − sin 2γ))              (12)
///   Φ_A = m_b Ω² l_OA,  Φ_c = m_z Ω² l_OA,  Φ_r = m_z ω² l_Ac   (9)–(11)
///   T2 = (Φ·l_Ac cos α − G_z l_Ac sin φ)/r_A,  T1 = 2 T2     (15)
///   X_A = Φ_A + Φ_c + Φ_r sin α − (G_b+G_z) sin φ − 3 T2 cos β   (16)
///   Y_A = Φ_r cos α + (G_b+G_z) cos φ − T2 sin β                 (17)
///   R_A = √(X_A² + Y_A²)                                         (18)
/// </pre>
/// Φ in (15) is Φ_c or Φ_r per MomentForceReading.
///
/// Assumptions: constant Ω and ω (no angular inertia terms); quasi-static
/// charge (Ω²·l_OA ≫ g); T1 = 2·T2 with the tight span on the trailing side;
/// drum, covers and sheave symmetric about A. Units SI throughout.
///
/// calcRebuiltReaction() writes the same equilibrium with vectors: charge
/// force at its centroid, exact belt tangents, gravity moment of the charge
/// at its true arm. It agrees with (15)–(17) for r0 ≤ r_A, the Φ_c reading,
/// ChargeInertia::PaperSplit and either α = 0 or g = 0; the doc lists every
/// difference outside that case.
class PlanetaryBeltOracle {
public:
    /// The tight-to-slack tension ratio the paper fixes (T1 = 2·T2).
    static constexpr double kTightToSlackRatio = 2.0;

    /// Throws std::invalid_argument naming the offending field and value.
    explicit PlanetaryBeltOracle(const PlanetaryBeltParameters& parameters);

    const PlanetaryBeltParameters& getParameters() const { return m_parameters; }
    const PlanetaryBeltKinematics& getKinematics() const { return m_kinematics; }
    const PlanetaryBeltMasses& getMasses() const { return m_masses; }
    const PlanetaryBeltInertialForces& getInertialForces() const { return m_inertialForces; }
    double getChargeCentroidDistance() const { return m_chargeCentroidDistance; }  ///< l_Ac [m]
    double getSinBeltAngle() const { return m_sinBeltAngle; }                      ///< sin β
    double getDrumWeight() const;    ///< G_b = m_b·g [N]
    double getChargeWeight() const;  ///< G_z = m_z·g [N]

    /// (15)–(18) at carrier angle φ [rad] (any finite value).
    PaperReaction calcPaperReaction(double carrierAngle) const;

    /// Vector equilibrium at carrier angle φ [rad]. Ignores momentReading:
    /// its moment is always the one of the actual forces.
    RebuiltReaction calcRebuiltReaction(double carrierAngle,
                                        ChargeInertia chargeInertia = ChargeInertia::SteadyCentroid) const;

    /// max and min of the paper's R_A over φ ∈ [0, 2π).
    ReactionExtremes calcPaperReactionExtremes() const;

private:
    PlanetaryBeltParameters m_parameters;
    PlanetaryBeltKinematics m_kinematics;
    PlanetaryBeltMasses m_masses;
    PlanetaryBeltInertialForces m_inertialForces;
    double m_chargeCentroidDistance = 0;
    double m_sinBeltAngle = 0;
};

/// Everything a map of R_A,max over (Ω, γ, k, b, c) keeps fixed.
struct PlanetaryBeltMapSettings {
    double drumRadius = std::numeric_limits<double>::quiet_NaN();  ///< r_b [m], (0, ∞)
    PlanetaryBeltMaterial material;
    double chargeLag = std::numeric_limits<double>::quiet_NaN();   ///< α [rad], [0, π]
    CriterionCReading cReading = CriterionCReading::R0OverRA;
    MomentForceReading momentReading = MomentForceReading::TransportCharge;
};

/// Extremes of the paper's R_A over a turn for one point of Figs. 4–8.
/// Throws as the constructor does, e.g. when (k, c) give sin β > 1.
ReactionExtremes calcPaperReactionExtremes(double carrierRate, double segmentHalfAngle,
                                           const PlanetaryBeltCriteria& criteria,
                                           const PlanetaryBeltMapSettings& settings);

}  // namespace milldyn::oracles
