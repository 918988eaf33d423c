#include "plugins/ElementRegistry.h"

namespace milldyn {

void registerInductionMotor(ElementRegistry& registry);
void registerTorsionalCoupling(ElementRegistry& registry);
void registerResistanceTorque(ElementRegistry& registry);
void registerPeriodicLoad(ElementRegistry& registry);
void registerDiscDrag(ElementRegistry& registry);
void registerFlexibleRotor(ElementRegistry& registry);

void registerBuiltinElements(ElementRegistry& registry) {
    registerInductionMotor(registry);
    registerTorsionalCoupling(registry);
    registerResistanceTorque(registry);
    registerPeriodicLoad(registry);
    registerDiscDrag(registry);
    registerFlexibleRotor(registry);
}

}  // namespace milldyn
