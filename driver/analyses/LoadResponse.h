#pragma once
// Harmonic response of a Scene's coupling torques to one load's periodic
// forcing (a HarmonicForcing: its harmonics on its terms), from the linear
// model: shared by frequency_response and resonance_map.
//
// Term t's load torque in harmonic k is w_kt·b·sin(P·τ + φ_kt) (applied as
// −that); a coupling torque responds as T̄ + A·b·sin(P·τ + ψ). output()
// gives A·e^{iψ} per unit b. staticReference() is, per output, the
// amplitude all terms in phase with weight 1 produce at a frequency far
// below every mode: the quasi-static torque the coupling carries. The
// dynamic factor is A over that reference.
//
// A shaft-angle load's terms on shafts turning at different steady speeds
// are at different frequencies for one harmonic: the terms are grouped by
// their speed ratio to the first term's shaft (group 0 holds the first), and
// each group responds at its own frequency ratio·P.

#include "driver/analyses/LinearModel.h"
#include "plugins/scene/HarmonicForcing.h"

#include <complex>
#include <vector>

namespace milldyn {

class LoadResponse {
public:
    /// `steady`: the state the model was linearized about (realized to
    /// Velocity), where a shaft-angle load reads its phases and speeds.
    LoadResponse(const Scene& scene, const LinearModel& model, const HarmonicForcing& load,
                 const SimTK::State& steady);

    /// Complex amplitude A·e^{iψ} of probe `probe` per unit harmonic
    /// amplitude, for the terms of group `group` of harmonic `k` at forcing
    /// frequency P [rad/s].
    std::complex<double> output(double P, int k, int probe, int group = 0) const;
    /// Quasi-static in-phase amplitude of probe `probe` per unit amplitude.
    double staticReference(int probe) const;
    /// |output(P, k, probe, group)| over the amplitude the same terms produce
    /// all in phase with weight 1 at the same P: how far the pattern cancels
    /// at this probe (0 when both vanish; infinite when only the in-phase
    /// one does).
    double patternRatio(double P, int k, int probe, int group = 0) const;
    /// At or below kCancelled the pattern's response is the round-off of a
    /// sum of phasors that cancels exactly (evenly staggered rows on one
    /// rigid body): summing n unit phasors at phases k·φ_r leaves about
    /// n·k·2π·ε (3e-12 for 100 rows, k = 20), far below 1e-10; a physical
    /// partial cancellation is larger (the 10-mass crusher's reducer passes
    /// 1.8e-5 at its first mode). Such an output has no response to report.
    static constexpr double kCancelled = 1e-10;
    bool cancels(double P, int k, int probe, int group = 0) const {
        return patternRatio(P, k, probe, group) <= kCancelled;
    }
    /// Indices of the probes that are coupling torques, in scene order.
    const std::vector<int>& couplingOutputs() const { return m_outputs; }
    /// Speed ratio of each group's shafts to the first term's shaft (|ω_t/ω_0|;
    /// 1 for a time clock, whose terms all share one frequency).
    const std::vector<double>& groupSpeedRatios() const { return m_groupRatio; }

private:
    Eigen::VectorXcd forcing(int k, bool inPhase, int group) const;
    std::complex<double> respond(double P, const Eigen::VectorXcd& f, int probe) const;

    const Scene& m_scene;
    const LinearModel& m_model;
    const HarmonicForcing& m_load;
    SimTK::State m_steady;
    std::vector<SimTK::MobilizedBody> m_terms;
    std::vector<int> m_groupOfTerm;
    std::vector<double> m_groupRatio;
    std::vector<int> m_outputs;
    std::vector<double> m_static;  // per probe index
};

}  // namespace milldyn
