// libFuzzer target: the model-file reader (YAML, units, schemas, --set).
// Any input must end in a ModelSpec or a SpecError (exit 2 in the driver);
// any other exception, a crash, a leak or a hang is a finding.

#include "driver/ModelFile.h"
#include "tests/fuzz/FuzzInput.h"
#include "driver/analyses/Analysis.h"

#include <cstdint>
#include <cstdlib>
#include <cstdio>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const milldyn::ModelFileReader reader = milldyn::defaultModelReader();
    std::string text(reinterpret_cast<const char*>(data), size);
    const std::vector<milldyn::Override> overrides = milldyn::fuzz::overridesFromInput(text);
    try {
        milldyn::readModelText(text, "fuzz.yaml", reader, overrides);
    } catch (const milldyn::SpecError& e) {
        // The diagnostic must be one line.
        if (e.formatted().find('\n') != std::string::npos) std::abort();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "unexpected exception: %s\n", e.what());
        std::abort();
    }
    return 0;
}
