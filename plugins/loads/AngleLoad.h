#pragma once
// AngleLoad: a process load tied to a shaft's angle (a jaw crusher's
// crushing stroke, a piston machine's cylinders): its torque repeats every
// 1/n of a revolution of the shaft, whatever the speed.

#include "plugins/scene/HarmonicForcing.h"
#include "plugins/scene/Schedule.h"

#include <Simbody.h>

#include <vector>

namespace milldyn {

/// Parameters of an AngleLoad. All SI; angles of the cycle ψ in rad.
struct AngleLoadParams {
    /// How the crushing (dissipative) magnitude g(ψ) over one cycle is given.
    enum class Shape { Fourier, Table, HalfSinePulse, ShapedPulse };
    Shape shape = Shape::Fourier;
    /// Load cycles per revolution of the shaft n >= 1, whole (a potential
    /// must repeat after one revolution).
    int cyclesPerRevolution = 1;
    /// Phase φ_j of each shaft's cycle [rad of cycle], one per body (empty:
    /// 0 for every body).
    std::vector<double> phases;
    /// Fourier: g(ψ) = a0 + Σ_k (a_k·cos kψ + b_k·sin kψ) [N*m].
    double meanTorque = 0;
    std::vector<double> cosineAmplitudes, sineAmplitudes;
    /// Table: g at cycle angles ψ_i in [0, 2π), strictly increasing [rad],
    /// torques >= 0 [N*m]; periodic piecewise-linear interpolation.
    std::vector<double> tableAngles, tableTorques;
    /// Pulses: g = 0 outside [ψ0, ψ0 + w] (mod 2π); inside, a half-sine
    /// P·sin(π(ψ − ψ0)/w) or the torques listed evenly over the width,
    /// both ends included, linearly interpolated.
    double peakTorque = 0;
    double pulseStart = 0;
    double pulseWidth = 0;
    std::vector<double> pulseTorques;
    /// Conservative part c(ψ) = Σ_k (p_k·cos kψ + q_k·sin kψ) [N*m] (zero
    /// mean: lifting and lowering, a toggle spring).
    std::vector<double> springCosineAmplitudes, springSineAmplitudes;
    /// Width ωs of the sign regularisation of the dissipative part [rad/s], > 0.
    double smoothingSpeed = 0.01;
    /// Harmonics reported as derived values and as excitation orders.
    int listedHarmonics = 6;
    /// f(t) multiplying the crushing (dissipative) part; the conservative
    /// part is not scheduled (its potential stays a function of angle).
    Schedule schedule;
};

/**
 * A load torque on one or several pin-jointed shafts that is a periodic
 * function of each shaft's own angle.
 *
 * <pre>
 *   cycle angle of shaft j:  ψ_j = n·θ_j − φ_j        (θ_j its pin angle, + about +z)
 *   load on shaft j:         M_j = g(ψ_j)·tanh(ω_j/ωs) + c(ψ_j)      (> 0 opposes +ω)
 *   shaft j gets −M_j as a mobility force
 *   dissipative magnitude g(ψ), one of
 *     fourier:          a0 + Σ_k (a_k cos kψ + b_k sin kψ)
 *     table:            periodic piecewise-linear through (ψ_i, g_i), wrapping from
 *                       the last point to the first + 2π
 *     half_sine_pulse:  P·sin(π·u/w) for u = (ψ − ψ0) mod 2π in [0, w], else 0
 *     shaped_pulse:     the listed torques evenly over u in [0, w], linear, else 0
 *   conservative part   c(ψ) = Σ_k (p_k cos kψ + q_k sin kψ)
 *   potential energy    V = Σ_j (1/n)·Σ_k (p_k sin kψ_j − q_k cos kψ_j)/k,
 *                       so that dV/dθ_j = c(ψ_j): zero mean over a cycle
 *   scheduled           the dissipative part times f(t), the `schedule` (Schedule.h)
 * </pre>
 *
 * The dissipative part is crushing: it opposes the motion and at ω = 0 it
 * is zero, so it does no work on a standing shaft; tanh(ω/ωs) is the sign
 * regularised over ωs (|ω| ≫ ωs: the full g opposing the motion; |ω| ≪ ωs:
 * a stiff viscous torque g/ωs). Its power g·tanh(ω/ωs)·ω >= 0 where g >= 0
 * is the energy meter's load flow; the conservative part's work is in the
 * potential V (elastic energy of the balance). The cycle and its orders
 * follow the shaft: harmonic k of the cycle is order k·n of the shaft
 * speed, registered as order excitations (resonance_map). A time-based load
 * (the roll crusher's tooth passing) is PeriodicLoad.
 *
 * The harmonics of g (the table and the pulses) are computed once, by the
 * trapezoidal rule over 2^16 points of one cycle (exact for a
 * trigonometric polynomial of lower degree; for a kinked shape the error is
 * O(h²) ≈ 1e-8 of the peak). With excitation off (steady-state solver,
 * linearization) only the mean a0·tanh(ω/ωs) acts and c is off.
 *
 * As a HarmonicForcing (frequency_response, resonance_map): a shaft-angle
 * clock, harmonic k of the cycle at k·n events per revolution; one term per
 * shaft; B_k = runningHarmonicAmplitude(k); K = listed_harmonics (at least
 * the Fourier coefficients given). In steady running, θ_j = θ_j0 + ω_j·τ:
 *
 * <pre>
 *   X = s_j·a_k + p_k,  Y = s_j·b_k + q_k,  s_j = tanh(ω_j/ωs)
 *   harmonic k of M_j = X cos kψ_j + Y sin kψ_j = Im(C_j·e^{i·k·n·ω_j·τ}),
 *   C_j = (Y + iX)·e^{ik(n·θ_j0 − φ_j)};  ω_j < 0: Im(−conj(C_j)·e^{i·k·n·|ω_j|·τ})
 *   weight |C_j|/B_k, phase arg C_j (of −conj C_j when ω_j < 0)
 * </pre>
 */
class AngleLoad : public SimTK::Force::Custom::Implementation, public HarmonicForcing {
public:
    /// Throws std::invalid_argument naming the parameter that is out of range.
    AngleLoad(const SimTK::GeneralForceSubsystem& forces, std::vector<SimTK::MobilizedBody> bodies,
              const AngleLoadParams& params);

    /// Dissipative magnitude g(ψ) at cycle angle ψ [N*m].
    double crushingMagnitude(double psi) const;
    /// Conservative torque c(ψ) [N*m].
    double springTorque(double psi) const;
    /// Potential of the conservative part per shaft at cycle angle ψ, in
    /// energy per shaft [J] (1/n·Σ_k (p_k sin kψ − q_k cos kψ)/k).
    double springPotential(double psi) const;
    /// ψ_j of shaft j for shaft angle θ [rad].
    double cycleAngle(int body, double theta) const;
    /// Mean of g over a cycle a0 [N*m].
    double meanTorque() const { return m_mean; }
    /// Cosine and sine coefficients of harmonic k >= 1 of g (a_k, b_k) [N*m];
    /// 0 beyond the harmonics kept.
    double cosineCoefficient(int k) const;
    double sineCoefficient(int k) const;
    /// Amplitude of harmonic k of the running load g + c: |(a_k + p_k, b_k + q_k)| [N*m].
    double runningHarmonicAmplitude(int k) const;
    /// Phase of shaft j's cycle φ_j [rad].
    double bodyPhase(int body) const;
    int cyclesPerRevolution() const { return m_params.cyclesPerRevolution; }
    const AngleLoadParams& params() const { return m_params; }
    const std::vector<SimTK::MobilizedBody>& bodies() const { return m_bodies; }

    struct Values {
        std::vector<double> torques;   ///< M_j [N*m], > 0 opposing +ω
        std::vector<double> psi;       ///< ψ_j wrapped to [0, 2π) [rad]
        double totalTorque = 0;        ///< Σ M_j [N*m]
        double totalPower = 0;         ///< Σ M_j·ω_j [W]
        double crushingPower = 0;      ///< Σ g(ψ_j)·tanh(ω_j/ωs)·ω_j [W]
    };
    const Values& getValues(const SimTK::State& state) const;
    bool isExcitationOn(const SimTK::State& state) const;
    void setExcitationOn(SimTK::State& state, bool on) const;

    void calcForce(const SimTK::State& state, SimTK::Vector_<SimTK::SpatialVec>& bodyForces,
                   SimTK::Vector_<SimTK::Vec3>& particleForces, SimTK::Vector& mobilityForces) const override;
    SimTK::Real calcPotentialEnergy(const SimTK::State& state) const override;
    void realizeTopology(SimTK::State& state) const override;

    // HarmonicForcing
    Clock forcingClock() const override { return Clock::ShaftAngle; }
    std::vector<SimTK::MobilizedBody> forcingBodies() const override { return m_bodies; }
    int forcingHarmonicCount() const override;
    double forcingAmplitude(int k) const override { return runningHarmonicAmplitude(k); }
    double forcingOrder(int k) const override { return double(k) * m_params.cyclesPerRevolution; }
    ForcingPhasor forcingPhasor(int k, int shaft, const SimTK::State& steady) const override;
    std::string forcingTermName() const override { return "shafts"; }
    std::string forcingDescription() const override;

private:
    void calcValues(const SimTK::State& state, Values& out) const;
    double shapeValue(double psi) const;

    const SimTK::GeneralForceSubsystem& m_forces;
    std::vector<SimTK::MobilizedBody> m_bodies;
    AngleLoadParams m_params;
    double m_mean = 0;
    std::vector<double> m_cos, m_sin;  // a_k, b_k, k = 1..K
    std::vector<double> m_potentialCos, m_potentialSin;  // −q_k/k, p_k/k: the spring's potential series
    mutable SimTK::DiscreteVariableIndex m_excitationIndex;
    mutable SimTK::CacheEntryIndex m_valuesIndex;
};

/// The largest number of harmonics an AngleLoad computes for a table or a pulse.
constexpr int kAngleLoadHarmonics = 50;

}  // namespace milldyn
