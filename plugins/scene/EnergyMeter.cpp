#include "plugins/scene/EnergyMeter.h"

namespace milldyn {

EnergyMeter::EnergyMeter(const SimTK::GeneralForceSubsystem& forces, std::vector<EnergyFlow> flows)
    : m_forces(forces), m_flows(std::move(flows)) {}

void EnergyMeter::realizeTopology(SimTK::State& state) const {
    if (!m_flows.empty()) m_first = m_forces.allocateZ(state, SimTK::Vector(static_cast<int>(m_flows.size()), 0.0));
}

void EnergyMeter::realizeAcceleration(const SimTK::State& state) const {
    if (m_flows.empty()) return;
    SimTK::Vector& zdot = m_forces.updZDot(state);
    for (std::size_t i = 0; i < m_flows.size(); ++i) zdot[m_first + static_cast<int>(i)] = m_flows[i].power(state);
}

double EnergyMeter::work(const SimTK::State& state, std::size_t i) const {
    return m_forces.getZ(state)[m_first + static_cast<int>(i)];
}

}  // namespace milldyn
