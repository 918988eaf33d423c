#pragma once
// PeriodicLoad: the crushing torque of sprocket rows, a mean plus a Fourier
// series in time, with a phase per row.

#include "plugins/scene/HarmonicForcing.h"
#include "plugins/scene/Schedule.h"

#include <Simbody.h>

#include <vector>

namespace milldyn {

/// Parameters of a PeriodicLoad. All SI.
struct PeriodicLoadParams {
    /// Number of sprocket rows n >= 1 whose loads this element applies.
    int rows = 1;
    /// Mean crushing torque per row M̄ [N*m], >= 0, opposing rotation.
    double meanTorque = 0;
    /// Harmonic amplitudes per row b_1..b_K [N*m], each >= 0 (eq 27).
    std::vector<double> amplitudes;
    /// Fundamental frequency P_1 [rad/s], > 0; harmonic k has P_k = k·P_1.
    double fundamentalFrequency = 0;
    /// true: rows evenly staggered over one period of the fundamental
    /// (φ_r = 2πr/n, eq 13); false: all rows in phase.
    bool staggered = true;
    /// Fundamental phase of each row φ_r [rad] (any stagger); when not
    /// empty it holds one entry per row and replaces `staggered`.
    std::vector<double> phases;
    /// Width ωs of the regularisation of the mean near standstill [rad/s], > 0.
    double smoothingSpeed = 0.01;
    /// f(t) multiplying every row's torque (mean and harmonics).
    Schedule schedule;
};

/**
 * Crushing torque of n sprocket rows on one or several pin-jointed shafts.
 *
 * <pre>
 *   row r = 0..n−1:  M_r(t) = M̄·tanh(ω/ωs) + Σ_k b_k·sin(k·(P_1·t + φ_r))   (eqs 13, 27)
 *   φ_r = 2π·r/n (staggered), 0 (in phase), or as listed (`phases:`, one per row)
 *   body j gets −Σ_{rows r on j} M_r(t)
 *   rows on bodies: n bodies → one row each; one body → all n rows on it
 *   scheduled: every M_r(t) times f(t), the `schedule` (Schedule.h)
 * </pre>
 *
 * Eq (13) writes the row loads as time shifts of one another,
 * M_i(t) = M_2(t + φ_i); a shift by r/n of the fundamental period is the
 * phase k·2πr/n of harmonic k. Evenly staggered rows on one rigid body sum
 * to zero for every harmonic that is not a multiple of n — the 2-mass
 * model's cancellation, which the chain does not share. The mean is
 * smoothed at standstill like ResistanceTorque; the periodic part is a pure
 * function of time (a tooth-passing load at constant speed, as the paper
 * assumes). Not conservative; potential energy 0. With excitation off
 * (setExcitationOn(false)) only the mean acts: the operating point of the
 * steady-state solver and the linearization. Checked by PeriodicLoadTest
 * and, through the crusher model, by validation/oracles/RollCrusherOracle.
 *
 * Evaluated once per realization: the row torques, their sums per body, the
 * total and the absorbed power are kept in a lazy cache entry (Velocity
 * stage: time and speeds; the excitation switch is a prerequisite), which
 * calcForce, the probes and the energy meter's power flow all read
 * (getValues). Rows of equal phase share one Fourier sum and rows on one
 * body one tanh. The harmonics come from one sine and cosine per distinct
 * phase by the angle-addition recurrence (harmonicSeries, HarmonicSeries.h, shared
 * with AngleLoad)
 *
 * <pre>
 *   sin((k+1)θ) = sin kθ·cos θ + cos kθ·sin θ,   cos((k+1)θ) = cos kθ·cos θ − sin kθ·sin θ
 * </pre>
 *
 * whose rounding grows like k·ε (PeriodicLoadTest checks it against the
 * direct sum in long double: ≤ 1e-13 of Σ|b_k| up to 50 harmonics).
 *
 * As a HarmonicForcing (frequency_response, resonance_map): a time clock,
 * P_k = k·P_1; one term per row, weight 1 and phase k·φ_r; B_k = b_k.
 */
class PeriodicLoad : public SimTK::Force::Custom::Implementation, public HarmonicForcing {
public:
    /// `bodies` holds n bodies or one; throws std::invalid_argument naming
    /// the parameter that is out of range.
    PeriodicLoad(const SimTK::GeneralForceSubsystem& forces, std::vector<SimTK::MobilizedBody> bodies,
                 const PeriodicLoadParams& params);

    /// Fundamental phase φ_r of row r [rad].
    double rowPhase(int row) const;
    /// Periodic part of row r's torque at time t [N*m].
    double periodicPart(int row, double t) const;

    /// What one realization of the rows gives (the cache entry's value).
    struct Values {
        /// Torque of each row M_r [N*m] (opposing rotation when positive).
        std::vector<double> rowTorques;
        /// Σ M_r of the rows on each body [N*m], one entry per body given.
        std::vector<double> bodyTorques;
        /// Σ_r M_r [N*m].
        double totalTorque = 0;
        /// Σ_r M_r·ω_r [W].
        double absorbedPower = 0;
        /// Speed ω_j of each body [rad/s] and its smoothed mean M̄·tanh(ω_j/ωs) [N*m].
        std::vector<double> bodySpeeds, bodyMeans;
        /// Σ_k b_k·sin(k(P_1·t + φ_g)) of each distinct phase [N*m] (0 with excitation off).
        std::vector<double> phaseParts;
    };
    /// The row torques of this state, evaluated at most once per
    /// realization; needs Stage::Velocity.
    const Values& getValues(const SimTK::State& state) const;
    /// Total torque magnitude this element applies in this state [N*m].
    double getTotalTorque(const SimTK::State& state) const { return getValues(state).totalTorque; }
    /// Power the rows absorb, Σ M_r·ω [W].
    double getAbsorbedPower(const SimTK::State& state) const { return getValues(state).absorbedPower; }
    bool isExcitationOn(const SimTK::State& state) const;
    void setExcitationOn(SimTK::State& state, bool on) const;
    /// The body each row acts on (index into the bodies given).
    int bodyOfRow(int row) const;
    const PeriodicLoadParams& params() const { return m_params; }
    const std::vector<SimTK::MobilizedBody>& bodies() const { return m_bodies; }

    void calcForce(const SimTK::State& state, SimTK::Vector_<SimTK::SpatialVec>& bodyForces,
                   SimTK::Vector_<SimTK::Vec3>& particleForces, SimTK::Vector& mobilityForces) const override;
    SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }
    void realizeTopology(SimTK::State& state) const override;

    // HarmonicForcing
    Clock forcingClock() const override { return Clock::Time; }
    std::vector<SimTK::MobilizedBody> forcingBodies() const override;
    int forcingHarmonicCount() const override { return static_cast<int>(m_params.amplitudes.size()); }
    double forcingAmplitude(int k) const override;
    double forcingOrder(int k) const override { return k * m_params.fundamentalFrequency; }
    ForcingPhasor forcingPhasor(int k, int row, const SimTK::State&) const override { return {1.0, k * rowPhase(row)}; }
    std::string forcingDescription() const override;
    bool setTimeCheckForcing(ElementSpec& spec, int k, double P) const override;

private:
    /// Σ_k b_k·sin(k·θ) by the angle-addition recurrence [N*m].
    double calcSineSeries(double theta) const;
    void calcValues(const SimTK::State& state, Values& out) const;

    const SimTK::GeneralForceSubsystem& m_forces;
    std::vector<SimTK::MobilizedBody> m_bodies;
    PeriodicLoadParams m_params;
    /// The distinct row phases φ [rad], and each row's index into them.
    std::vector<double> m_phases;
    std::vector<int> m_phaseOfRow;
    mutable SimTK::DiscreteVariableIndex m_excitationIndex;
    mutable SimTK::CacheEntryIndex m_valuesIndex;
};

}  // namespace milldyn
