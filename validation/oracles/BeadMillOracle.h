// Closed-form oracle for the horizontal bead mill rotor (seed 001: Kozlovsky,
// Petrov, Borovsky, "Calculation of the shaft diameter of a horizontal bead
// mill"). SI units throughout. Derivations, the reading of the garbled Table 1
// and what the paper's deflections imply are in docs/oracles/bead_mill.md.
//
// This file knows nothing of Simbody nor of ModelSpec on purpose: it takes its
// own parameter structs, so it cannot share a bug with the model it judges.
#pragma once

#include "papers/BeadMillTable1.h"

#include <limits>
#include <vector>

namespace milldyn::oracles {

// ---------------------------------------------------------------- disc drag

/// Rotational Reynolds number of a disc, Re = ω·r²/ν [-]. `omega` [rad/s]
/// > 0, `radius` r [m] > 0, `viscosity` ν [m^2/s] > 0.
double beadMillDiscReynolds(double omega, double radius, double viscosity);

/// Eq (1): power to turn k discs in fluid at rest, von Kármán's laminar
/// rotating disc wetted on both faces,
///   N = 0.616·π·ρ_c·ω²·r⁴·k·√(ν·ω)   [W]
/// i.e. per disc the torque 0.616·π·ρ·r⁴·√(ν·ω³) [N*m] (Schlichting's
/// C_M = 3.87/√Re with M = C_M·ρω²r⁵/2 for both faces). Valid for a laminar
/// boundary layer, Re below about 3e5. `density` ρ_c [kg/m^3] > 0.
double beadMillLaminarPower(double density, double viscosity, double omega, double radius, int discs);

/// The turbulent alternative (von Kármán's 1/7-power profile, Schlichting
/// C_M = 0.146·Re^(-1/5) for both faces together):
///   M = 0.073·ρ·ω²·r⁵·Re^(-1/5) per disc (both faces), N = k·M·ω   [W].
/// PHYSICS.md calls 0.073 "per face"; with Schlichting's definition
/// (2M_face = C_M·ρω²r⁵/2) it is the moment of both faces (see the doc).
double beadMillTurbulentPower(double density, double viscosity, double omega, double radius, int discs);

// ------------------------------------------------------ overhung shaft beam

/// A disc (or any rigid attachment) on the shaft.
struct BeadMillDisc {
    double position = 0;         ///< from the rear bearing A along the shaft [m]
    double mass = 0;             ///< [kg] >= 0
    double diametralInertia = 0; ///< about a diameter through its centre [kg*m^2] >= 0
    double polarInertia = 0;     ///< about the shaft axis [kg*m^2] >= 0 (whirl only)
    double unbalance = 0;        ///< m·e, all discs in phase [kg*m] >= 0 (whirl only)
};

/// Uniform solid shaft on two radial supports: rear bearing A at x = 0,
/// front bearing B at x = L_p, overhang to x = L_p + a carrying the discs.
/// Euler–Bernoulli, small deflection, one bending plane.
struct BeadMillShaft {
    double youngsModulus = 0;  ///< E [Pa] > 0
    double diameter = 0;       ///< d [m] > 0
    double density = 0;        ///< shaft material ρ [kg/m^3] >= 0 (0: massless shaft)
    double span = 0;           ///< L_p, bearing to bearing [m] > 0
    double overhang = 0;       ///< a, front bearing to the shaft end [m] >= 0
    /// Radial stiffness of each bearing [N/m] > 0; infinity: rigid support.
    double stiffnessA = std::numeric_limits<double>::infinity();
    double stiffnessB = std::numeric_limits<double>::infinity();
    std::vector<BeadMillDisc> discs;
};

/// A transverse point load [N] at `position` [m] (positive along gravity).
struct BeadMillPointLoad {
    double position = 0;
    double force = 0;
};

/// Static deflection and bending critical speeds of a BeadMillShaft.
/// Deflection w(x) is positive in the direction of positive loads.
class BeadMillBeam {
public:
    /// Throws std::invalid_argument naming the parameter out of range
    /// (discs must lie on the shaft, 0 <= position <= L_p + a).
    explicit BeadMillBeam(BeadMillShaft shaft);

    const BeadMillShaft& shaft() const { return m_shaft; }
    double getLength() const { return m_shaft.span + m_shaft.overhang; }  ///< L [m]
    double getSecondMoment() const;  ///< I = π d⁴/64 [m^4]
    double getMassPerLength() const; ///< ρ·π d²/4 [kg/m]

    /// Deflection at x [m] under point loads and a uniform load q [N/m] on
    /// the whole shaft, by the unit-load (Mohr) integral
    ///   w(x) = ∫ M(s)·m_x(s)/(EI) ds + R_A·r_A/k_A + R_B·r_B/k_B
    /// with M the bending moment of the loads, m_x that of a unit load at x,
    /// R and r the support reactions of each. The integrand is piecewise
    /// cubic, so Simpson's rule on the pieces is exact.
    double calcDeflection(double x, const std::vector<BeadMillPointLoad>& loads, double uniformLoad = 0) const;
    /// Deflection at x under gravity g [m/s^2]: disc weights plus shaft weight.
    double calcGravityDeflection(double x, double g) const;
    /// Influence coefficient α(x, c): deflection at x per unit load at c [m/N].
    double calcInfluence(double x, double c) const;

    /// Rayleigh's quotient with the static deflection curve as trial shape.
    /// `modeSigned` false: loads m·g all downwards (the textbook form, poor
    /// for an overhang, where the span bows the other way); true: loads m·g
    /// downwards on the overhang and upwards in the span (the shape of the
    /// first mode). ω² = Σ F·y / (Σ m y² + ∫ρA y²) with F the applied loads
    /// [rad/s]. Disc diametral inertia is ignored. Upper bound of the exact
    /// frequency without diametral inertia.
    double calcRayleighCriticalSpeed(bool modeSigned) const;
    /// Dunkerley: 1/ω² = Σ m_i α(x_i, x_i) + Σ_shaft-lumps m_j α(x_j, x_j),
    /// the shaft's mass in `shaftLumps` equal lumps [rad/s]. Lower bound.
    double calcDunkerleyCriticalSpeed(int shaftLumps = 400) const;
    /// Finite elements: `elements` Hermite-cubic beam elements (consistent
    /// mass), nodes at the bearings and every disc, discs as point masses
    /// with diametral inertia if `discInertia`, the shaft's rotary inertia
    /// ρI per length if `shaftRotaryInertia`; supports as springs. Returns
    /// the lowest `count` natural frequencies [rad/s], ascending.
    std::vector<double> calcFiniteElementFrequencies(int elements, bool discInertia, bool shaftRotaryInertia,
                                                     int count = 1) const;
    /// Forward synchronous critical speed [rad/s]: the lowest Ω with
    /// det(K − Ω²·M_Ω) = 0, where M_Ω has the translational mass and, per
    /// unit Ω², the gyroscopic-plus-centrifugal rotary terms of a forward
    /// synchronous whirl: I_d − I_p on each disc, ρI − 2ρI = −ρI per length
    /// of shaft (the thin disc's I_p ≈ 2·I_d stiffens the whirl).
    double calcForwardCriticalSpeed(int elements) const;
    /// Amplitude of the forward synchronous whirl at x [m] at speed Ω
    /// [rad/s] under the discs' unbalances (in phase): in the frame turning
    /// with the shaft a static problem, (K − Ω²·M_Ω)·y = Ω²·f, f the m·e at
    /// the discs. Undamped; infinite at the forward critical speed.
    double calcSynchronousWhirl(double x, double omega, int elements) const;
    /// Static deflection at x by the same finite elements under gravity
    /// (an independent check of calcGravityDeflection) [m].
    double calcFiniteElementGravityDeflection(double x, double g, int elements) const;

private:
    // Reactions (upward positive) [N] and bending moment (sagging positive)
    // [N*m] at s of point loads and a uniform load.
    void calcReactions(const std::vector<BeadMillPointLoad>& loads, double q, double& RA, double& RB) const;
    double calcMoment(double s, const std::vector<BeadMillPointLoad>& loads, double q, double RA, double RB) const;
    struct Mesh;
    Mesh buildMesh(int elements) const;

    BeadMillShaft m_shaft;
};

// -------------------------------------------------------- eq (2), Table 1

using papers::BeadMillTableReading;
using papers::beadMillTableCoefficient;

/// Eq (2): d = k1·L³ − k2·L² + k3·L + k4, with L = L_p [m], 0.15 <= L_p <= 0.5,
/// discs k in {5, 6, 7, 8}, D_d in {0.1, 0.17, 0.23, 0.3} m (tabulated values
/// only, within 1e-9). Returns the shaft diameter [m] (the table gives mm).
/// Throws std::invalid_argument for anything outside the table.
double beadMillShaftDiameter(int discs, double discDiameter, double span,
                             BeadMillTableReading reading = BeadMillTableReading::Resolved);

}  // namespace milldyn::oracles
