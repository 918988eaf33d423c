#include "plugins/ElementRegistry.h"

namespace milldyn {

void registerInductionMotor(ElementRegistry& registry);
void registerTorsionalCoupling(ElementRegistry& registry);
void registerResistanceTorque(ElementRegistry& registry);
void registerPeriodicLoad(ElementRegistry& registry);

void registerBuiltinElements(ElementRegistry& registry) {
    registerInductionMotor(registry);
    registerTorsionalCoupling(registry);
    registerResistanceTorque(registry);
    registerPeriodicLoad(registry);
}

}  // namespace milldyn
