// libFuzzer target: the unit parser. Any input must give a finite value or
// a UnitError.

#include "driver/Units.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const double v = milldyn::units::toSI(text, "N*m/rad");
        if (!std::isfinite(v)) std::abort();
    } catch (const milldyn::units::UnitError&) {
    }
    try {
        const auto q = milldyn::units::parseQuantity(text);
        if (!std::isfinite(q.value)) std::abort();
    } catch (const milldyn::units::UnitError&) {
    }
    return 0;
}
