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
