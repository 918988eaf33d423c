#pragma once
// Harmonic response of a Scene's coupling torques to one PeriodicLoad, from
// the linear model: shared by frequency_response and resonance_map.
//
// Row r's load torque is b·sin(P·t + k·φ_r) (applied as −that); a coupling
// torque responds as T̄ + A·b·sin(P·t + ψ). output() gives A·e^{iψ} per
// unit b. staticReference() is, per output, the amplitude all rows in phase
// produce at a frequency far below every mode: the quasi-static torque the
// coupling carries. The dynamic factor is A over that reference.

#include "driver/analyses/LinearModel.h"
#include "plugins/loads/PeriodicLoad.h"

#include <complex>
#include <vector>

namespace milldyn {

class LoadResponse {
public:
    LoadResponse(const Scene& scene, const LinearModel& model, const PeriodicLoad& load);

    /// Complex amplitude A·e^{iψ} of probe `probe` per unit row amplitude,
    /// for harmonic `k` of the load at forcing frequency P [rad/s].
    std::complex<double> output(double P, int k, int probe) const;
    /// Quasi-static in-phase amplitude of probe `probe` per unit row amplitude.
    double staticReference(int probe) const;
    /// |output(P, k, probe)| over the amplitude the same rows produce all in
    /// phase at the same P: how far the row pattern cancels at this probe
    /// (0 when both vanish; infinite when only the in-phase one does).
    double patternRatio(double P, int k, int probe) const;
    /// At or below kCancelled the pattern's response is the round-off of a
    /// sum of phasors that cancels exactly (evenly staggered rows on one
    /// rigid body): summing n unit phasors at phases k·φ_r leaves about
    /// n·k·2π·ε (3e-12 for 100 rows, k = 20), far below 1e-10; a physical
    /// partial cancellation is larger (the 10-mass crusher's reducer passes
    /// 1.8e-5 at its first mode). Such an output has no response to report.
    static constexpr double kCancelled = 1e-10;
    bool cancels(double P, int k, int probe) const { return patternRatio(P, k, probe) <= kCancelled; }
    /// Indices of the probes that are coupling torques, in scene order.
    const std::vector<int>& couplingOutputs() const { return m_outputs; }

private:
    Eigen::VectorXcd forcing(int k, bool inPhase) const;
    std::complex<double> respond(double P, const Eigen::VectorXcd& f, int probe) const;

    const Scene& m_scene;
    const LinearModel& m_model;
    const PeriodicLoad& m_load;
    std::vector<int> m_outputs;
    std::vector<double> m_static;  // per probe index
};

}  // namespace milldyn
