#include "plugins/scene/EnergyMeter.h"

#include <map>

namespace milldyn {

EnergyCategory energyCategory(EnergyFlow::Kind kind, const std::string& elementType) {
    if (kind == EnergyFlow::Kind::Source) return EnergyCategory::MotorInput;
    if (kind == EnergyFlow::Kind::Load) return EnergyCategory::Grinding;
    static const std::map<std::string, EnergyCategory> heat = {
        {"InductionMotor", EnergyCategory::MotorLoss},    {"DqInductionMotor", EnergyCategory::MotorLoss},
        {"JournalFriction", EnergyCategory::Friction},
        {"ShaftBearings", EnergyCategory::Friction},      {"Brake", EnergyCategory::Friction},
        {"Clutch", EnergyCategory::Friction},             {"TorsionalCoupling", EnergyCategory::Damping},
        {"BeltDrive", EnergyCategory::Damping},           {"GearPair", EnergyCategory::Damping},
        {"GearMesh", EnergyCategory::Damping},            {"FlexibleRotor", EnergyCategory::Damping},
    };
    const auto it = heat.find(elementType);
    return it == heat.end() ? EnergyCategory::OtherHeat : it->second;
}

std::string energyCategoryKey(EnergyCategory c) {
    switch (c) {
        case EnergyCategory::MotorInput: return "motor_input";
        case EnergyCategory::MotorLoss: return "motor_loss";
        case EnergyCategory::Grinding: return "grinding";
        case EnergyCategory::Friction: return "friction";
        case EnergyCategory::Damping: return "damping";
        case EnergyCategory::OtherHeat: break;
    }
    return "other_heat";
}

std::string energyCategoryLabel(EnergyCategory c) {
    switch (c) {
        case EnergyCategory::MotorInput:
            return "drive input: the motors' electrical input (their air-gap power where no rated_efficiency is "
                   "given), a prescribed drive's work, a torque source's (AppliedTorque) work";
        case EnergyCategory::MotorLoss:
            return "motor loss: heat in the motors (rotor copper loss; stator copper and no-load loss where a "
                   "rated_efficiency is given; a dq machine's stator and rotor copper loss)";
        case EnergyCategory::Grinding:
            return "grinding: work taken by the charges and loads (ResistanceTorque, PeriodicLoad, DiscDrag)";
        case EnergyCategory::Friction: return "friction heat: journals, bearings, brakes, clutch slip";
        case EnergyCategory::Damping: return "damping heat: couplings, belts, gear meshes, shaft material damping";
        case EnergyCategory::OtherHeat: break;
    }
    return "other heat: dissipation of elements of no listed type (plugins)";
}

EnergyMeter::EnergyMeter(const SimTK::GeneralForceSubsystem& forces, std::vector<EnergyFlow> flows,
                         const std::vector<std::string>& elementTypes)
    : m_forces(forces), m_flows(std::move(flows)) {
    for (std::size_t i = 0; i < m_flows.size(); ++i)
        m_categories.push_back(energyCategory(m_flows[i].kind, i < elementTypes.size() ? elementTypes[i] : ""));
}

std::string EnergyMeter::describe(std::size_t i) const {
    const EnergyFlow& f = m_flows.at(i);
    if (!f.what.empty()) return f.what;
    switch (m_categories.at(i)) {
        case EnergyCategory::MotorInput: return "work of the drive " + f.name;
        case EnergyCategory::MotorLoss: return "heat in the motor " + f.name;
        case EnergyCategory::Grinding: return "grinding work taken by " + f.name;
        case EnergyCategory::Friction: return "friction heat in " + f.name;
        case EnergyCategory::Damping: return "damping heat in " + f.name;
        case EnergyCategory::OtherHeat: break;
    }
    return "heat in " + f.name + " (a dissipation of no listed type)";
}

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

double EnergySplit::residual() const {
    double out = of(EnergyCategory::MotorInput) - of(EnergyCategory::MotorLoss) - stored();
    for (EnergyCategory c : {EnergyCategory::Grinding, EnergyCategory::Friction, EnergyCategory::Damping,
                             EnergyCategory::OtherHeat})
        out -= of(c);
    return out;
}

namespace {
double gravitationalEnergy(const SimTK::GeneralForceSubsystem& forces, const SimTK::State& s) {
    double e = 0;
    for (int i = 0; i < forces.getNumForces(); ++i) {
        const SimTK::Force& f = forces.getForce(SimTK::ForceIndex(i));
        if (SimTK::Force::UniformGravity::isInstanceOf(f) || SimTK::Force::Gravity::isInstanceOf(f))
            e += f.calcPotentialEnergyContribution(s);
    }
    return e;
}
}  // namespace

EnergySplit calcEnergySplit(const EnergyMeter& meter, const SimTK::MultibodySystem& system,
                            const SimTK::State& start, const SimTK::State& end) {
    const SimTK::GeneralForceSubsystem& forces = meter.forceSubsystem();
    EnergySplit out;
    for (std::size_t i = 0; i < meter.flows().size(); ++i)
        out.work[static_cast<int>(meter.category(i))] += meter.work(end, i) - meter.work(start, i);
    out.kinetic = system.calcKineticEnergy(end) - system.calcKineticEnergy(start);
    out.gravitational = gravitationalEnergy(forces, end) - gravitationalEnergy(forces, start);
    out.elastic = system.calcPotentialEnergy(end) - system.calcPotentialEnergy(start) - out.gravitational;
    return out;
}

}  // namespace milldyn
