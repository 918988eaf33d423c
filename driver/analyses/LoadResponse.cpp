#include "driver/analyses/LoadResponse.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace milldyn {

LoadResponse::LoadResponse(const Scene& scene, const LinearModel& model, const HarmonicForcing& load,
                           const SimTK::State& steady)
    : m_scene(scene), m_model(model), m_load(load), m_steady(steady), m_terms(load.forcingBodies()) {
    // Groups of equal speed ratio to the first term's shaft (a shaft-angle
    // clock only; a time clock's terms share one frequency).
    const bool angle = load.forcingClock() == HarmonicForcing::Clock::ShaftAngle;
    const double first = m_terms.empty() ? 0.0 : pinSpeed(steady, m_terms[0]);
    for (const auto& body : m_terms) {
        const double ratio = angle && first != 0 ? std::abs(pinSpeed(steady, body) / first) : 1.0;
        std::size_t g = 0;
        while (g < m_groupRatio.size() && std::abs(m_groupRatio[g] - ratio) > 1e-9 * std::max(1.0, ratio)) ++g;
        if (g == m_groupRatio.size()) m_groupRatio.push_back(ratio);
        m_groupOfTerm.push_back(static_cast<int>(g));
    }
    if (m_groupRatio.empty()) m_groupRatio.push_back(1.0);
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
    const Eigen::VectorXcd f = forcing(1, true, -1);
    m_static.assign(scene.probes().size(), 0.0);
    for (int p : m_outputs)
        m_static[p] = std::abs((4 * std::abs(respond(Ps, f, p)) - std::abs(respond(2 * Ps, f, p))) / 3);
}

// group < 0: every term (the quasi-static reference).
Eigen::VectorXcd LoadResponse::forcing(int k, bool inPhase, int group) const {
    const int n = static_cast<int>(m_scene.bodies().size());
    Eigen::VectorXcd f = Eigen::VectorXcd::Zero(n);
    for (std::size_t t = 0; t < m_terms.size(); ++t) {
        if (group >= 0 && m_groupOfTerm[t] != group) continue;
        const SimTK::MobilizedBodyIndex target = m_terms[t].getMobilizedBodyIndex();
        const ForcingPhasor w = inPhase ? ForcingPhasor{1.0, 0.0}
                                        : m_load.forcingPhasor(k, static_cast<int>(t), m_steady);
        for (int j = 0; j < n; ++j)
            if (m_scene.bodies()[j].mobod.getMobilizedBodyIndex() == target)
                f[j] += -(w.weight * std::exp(std::complex<double>(0, w.phase)));
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

std::complex<double> LoadResponse::output(double P, int k, int probe, int group) const {
    return respond(P, forcing(k, false, group), probe);
}

double LoadResponse::patternRatio(double P, int k, int probe, int group) const {
    const double pattern = std::abs(output(P, k, probe, group));
    const double inPhase = std::abs(respond(P, forcing(k, true, group), probe));
    if (inPhase > 0) return pattern / inPhase;
    return pattern > 0 ? std::numeric_limits<double>::infinity() : 0.0;
}

double LoadResponse::staticReference(int probe) const { return m_static[probe]; }

}  // namespace milldyn
