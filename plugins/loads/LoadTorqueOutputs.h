#pragma once
// The outputs every load torque registers, in one place (issue 27, D5).

#include "plugins/scene/Scene.h"

#include <functional>
#include <string>
#include <utility>

namespace milldyn {

/**
 * Registers a load's `NAME.torque` (ProbeRole::ResistanceTorque: the torque
 * the load takes from its shaft, + about +z, summed over its shafts),
 * `NAME.power` (ProbeRole::ResistancePower: the power it absorbs) and that
 * power as an EnergyFlow of kind Load. The summary's `resistance_torque`,
 * `power` and `mean_power.grinding` are built from these roles
 * (docs/model-format.md, "Signs of the torques in the summary").
 */
inline void addLoadTorqueOutputs(Scene& scene, const std::string& name,
                                 std::function<double(const SimTK::State&)> torque,
                                 std::function<double(const SimTK::State&)> power, std::string torqueLabel = {},
                                 std::string powerLabel = {}) {
    scene.addProbe({name + ".torque", "N*m", ProbeRole::ResistanceTorque, SimTK::Stage::Velocity, std::move(torque),
                    std::move(torqueLabel)});
    scene.addProbe({name + ".power", "W", ProbeRole::ResistancePower, SimTK::Stage::Velocity, power,
                    std::move(powerLabel)});
    scene.addEnergyFlow({name, EnergyFlow::Kind::Load, std::move(power)});
}

/// The same for a load on one pin-jointed shaft: power = torque × ω.
inline void addShaftLoadTorqueOutputs(Scene& scene, const std::string& name, const SimTK::MobilizedBody& shaft,
                                      std::function<double(const SimTK::State&)> torque) {
    auto power = [torque, shaft](const SimTK::State& s) { return torque(s) * pinSpeed(s, shaft); };
    addLoadTorqueOutputs(scene, name, std::move(torque), std::move(power));
}

}  // namespace milldyn
