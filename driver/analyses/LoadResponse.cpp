#include "driver/analyses/LoadResponse.h"

#include <cmath>
#include <limits>

namespace milldyn {

LoadResponse::LoadResponse(const Scene& scene, const LinearModel& model, const PeriodicLoad& load)
    : m_scene(scene), m_model(model), m_load(load) {
    for (std::size_t p = 0; p < scene.probes().size(); ++p)
        if (scene.probes()[p].role == ProbeRole::CouplingTorque) m_outputs.push_back(static_cast<int>(p));
    // The quasi-static amplitude, the limit P -> 0 of |A(P)|, which is even
    // in P (A(−P) is A(P)'s conjugate): |A(P)| = A0 + a·P² + O(P⁴), so
    // Richardson's (4|A(P)| − |A(2P)|)/3 leaves (P/|λ|)⁴ = 1e-12 at P = 1e-3
    // of the slowest non-rigid eigenvalue. A rigid rotation grows as 1/P
    // (damped by a motor or a load) or 1/P² (free, undamped) and cancels in
    // a coupling's twist, costing eps·(|λ|/P)^(1 or 2): 2e-13 or 2e-10. One
    // evaluation at 1e-6 of the slowest (as before) costs eps·1e12 on a free
    // undamped pair: its dynamic factors came out 3.05e-5 off.
    double slowest = 0;
    for (Eigen::Index i = 0; i < model.eigenvalues.size(); ++i) {
        const double mag = std::abs(model.eigenvalues[i]);
        if (!isRigidEigenvalue(model, model.eigenvalues[i])) slowest = slowest == 0 ? mag : std::min(slowest, mag);
    }
    const double Ps = 1e-3 * (slowest > 0 ? slowest : 1.0);
    const Eigen::VectorXcd f = forcing(1, true);
    m_static.assign(scene.probes().size(), 0.0);
    for (int p : m_outputs)
        m_static[p] = std::abs((4 * std::abs(respond(Ps, f, p)) - std::abs(respond(2 * Ps, f, p))) / 3);
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
    // Reduced constraints: the generalized force on the independent
    // coordinates v (u = N·v) is Nᵀ·f.
    if (m_model.N.size()) return m_model.N.transpose().cast<std::complex<double>>() * f;
    return f;
}

std::complex<double> LoadResponse::respond(double P, const Eigen::VectorXcd& f, int probe) const {
    // The linear model's chosen motor model (with dq machines' flux states, their outputs too).
    return harmonicProbeResponse(m_model, P, f, probe);
}

std::complex<double> LoadResponse::output(double P, int k, int probe) const {
    return respond(P, forcing(k, false), probe);
}

double LoadResponse::patternRatio(double P, int k, int probe) const {
    const double pattern = std::abs(output(P, k, probe));
    const double inPhase = std::abs(respond(P, forcing(k, true), probe));
    if (inPhase > 0) return pattern / inPhase;
    return pattern > 0 ? std::numeric_limits<double>::infinity() : 0.0;
}

double LoadResponse::staticReference(int probe) const { return m_static[probe]; }

}  // namespace milldyn
