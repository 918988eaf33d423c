#include "plugins/scene/ElementRegistry.h"

namespace milldyn {

void registerInductionMotor(ElementRegistry& registry);
void registerDqInductionMotor(ElementRegistry& registry);
void registerTorsionalCoupling(ElementRegistry& registry);
void registerResistanceTorque(ElementRegistry& registry);
void registerPeriodicLoad(ElementRegistry& registry);
void registerGearMesh(ElementRegistry& registry);
void registerSegmentCharge(ElementRegistry& registry);
void registerCarrierDrive(ElementRegistry& registry);
void registerJournalFriction(ElementRegistry& registry);
void registerJointReaction(ElementRegistry& registry);
void registerBeltDrive(ElementRegistry& registry);
void registerShaftBelt(ElementRegistry& registry);
void registerDiscDrag(ElementRegistry& registry);
void registerFlexibleRotor(ElementRegistry& registry);
void registerGearPair(ElementRegistry& registry);
void registerPlanetaryGearSet(ElementRegistry& registry);
void registerBevelGearPair(ElementRegistry& registry);
void registerShaftBearings(ElementRegistry& registry);
void registerClutch(ElementRegistry& registry);
void registerBrake(ElementRegistry& registry);
void registerAngleLoad(ElementRegistry& registry);
void registerBreakawayResistance(ElementRegistry& registry);
void registerAppliedTorque(ElementRegistry& registry);

void registerBuiltinElements(ElementRegistry& registry) {
    registerInductionMotor(registry);
    registerDqInductionMotor(registry);
    registerTorsionalCoupling(registry);
    registerResistanceTorque(registry);
    registerPeriodicLoad(registry);
    registerGearMesh(registry);
    registerSegmentCharge(registry);
    registerCarrierDrive(registry);
    registerJournalFriction(registry);
    registerJointReaction(registry);
    registerBeltDrive(registry);
    registerShaftBelt(registry);
    registerDiscDrag(registry);
    registerFlexibleRotor(registry);
    registerGearPair(registry);
    registerPlanetaryGearSet(registry);
    registerBevelGearPair(registry);
    registerShaftBearings(registry);
    registerClutch(registry);
    registerBrake(registry);
    registerAngleLoad(registry);
    registerBreakawayResistance(registry);
    registerAppliedTorque(registry);
}

}  // namespace milldyn
