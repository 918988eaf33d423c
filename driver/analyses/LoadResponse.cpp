#include "driver/analyses/LoadResponse.h"

#include <cmath>

namespace milldyn {

LoadResponse::LoadResponse(const Scene& scene, const LinearModel& model, const PeriodicLoad& load)
    : m_scene(scene), m_model(model), m_load(load) {
    for (std::size_t p = 0; p < scene.probes().size(); ++p)
        if (scene.probes()[p].role == ProbeRole::CouplingTorque) m_outputs.push_back(static_cast<int>(p));
    // Far below every elastic mode and the motor's own root the response is
    // quasi-static to about (P/|λ|)²: 1e-6 of the slowest leaves 1e-12. The
    // rigid rotation grows as 1/P but cancels in a coupling's twist, costing
    // about eps·|λ|/P ≈ 1e-10 of round-off.
    double slowest = 0;
    const double scale = model.eigenvalues.cwiseAbs().maxCoeff();
    for (Eigen::Index i = 0; i < model.eigenvalues.size(); ++i) {
        const double mag = std::abs(model.eigenvalues[i]);
        if (mag > 1e-9 * scale) slowest = slowest == 0 ? mag : std::min(slowest, mag);
    }
    const double Ps = 1e-6 * (slowest > 0 ? slowest : 1.0);
    const Eigen::VectorXcd f = forcing(1, true);
    m_static.assign(scene.probes().size(), 0.0);
    for (int p : m_outputs) m_static[p] = std::abs(respond(Ps, f, p));
}

Eigen::VectorXcd LoadResponse::forcing(int k, bool inPhase) const {
    const int n = static_cast<int>(m_scene.bodies().size());
    Eigen::VectorXcd f = Eigen::VectorXcd::Zero(n);
    const auto& bodies = m_load.bodies();
    for (int r = 0; r < m_load.params().rows; ++r) {
        const SimTK::MobilizedBodyIndex target = bodies[m_load.bodyOfRow(r)].getMobilizedBodyIndex();
        const double phase = inPhase ? 0.0 : k * m_load.rowPhase(r);
        for (int j = 0; j < n; ++j)
            if (m_scene.bodies()[j].mobod.getMobilizedBodyIndex() == target)
                f[j] += -std::exp(std::complex<double>(0, phase));
    }
    return f;
}

std::complex<double> LoadResponse::respond(double P, const Eigen::VectorXcd& f, int probe) const {
    const Eigen::VectorXcd X = harmonicResponse(m_model, P, f);
    const std::complex<double> q = m_model.outputQ.row(probe).cast<std::complex<double>>() * X;
    const std::complex<double> u = m_model.outputU.row(probe).cast<std::complex<double>>() * X;
    return q + std::complex<double>(0, P) * u;
}

std::complex<double> LoadResponse::output(double P, int k, int probe) const {
    return respond(P, forcing(k, false), probe);
}

double LoadResponse::staticReference(int probe) const { return m_static[probe]; }

}  // namespace milldyn
