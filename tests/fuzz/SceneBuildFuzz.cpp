// libFuzzer target: model file to Simbody scene. Whatever the reader accepts
// must build (issue 16: half_angle 1e-7 rad passed the reader and then
// failed inside the segment formulas). Any input must end in a SpecError
// from the reader, or in a scene realized to Stage::Instance; a Simbody
// refusal ("Simbody refused it": the reader let through what Simbody
// rejects), any other exception, a crash, a leak or a hang is a finding.

#include "driver/ModelFile.h"
#include "tests/fuzz/FuzzInput.h"
#include "driver/SceneBuilder.h"
#include "driver/analyses/Analysis.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const milldyn::ModelFileReader reader = milldyn::defaultModelReader();
    std::string text(reinterpret_cast<const char*>(data), size);
    const std::vector<milldyn::Override> overrides = milldyn::fuzz::overridesFromInput(text);
    milldyn::ModelSpec spec;
    try {
        spec = milldyn::readModelText(text, "fuzz.yaml", reader, overrides);
    } catch (const milldyn::SpecError&) {
        return 0;  // refused at the reader: the driver's exit 2
    } catch (const std::exception& e) {
        std::fprintf(stderr, "unexpected exception from the reader: %s\n", e.what());
        std::abort();
    }
    // Keep each input fast: very large scenes are the reader's business.
    if (spec.bodies.size() > 200 || spec.elements.size() > 400) return 0;
    try {
        auto scene = milldyn::buildScene(spec);
        const SimTK::State& s = scene->system().getDefaultState();
        scene->system().realize(s, SimTK::Stage::Instance);
    } catch (const milldyn::SpecError& e) {
        if (e.formatted().find('\n') != std::string::npos) std::abort();
        if (e.formatted().find("Simbody refused it") != std::string::npos) {
            std::fprintf(stderr, "the reader accepted what Simbody refused: %s\n", e.formatted().c_str());
            std::abort();
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "unexpected exception building the scene: %s\n", e.what());
        std::abort();
    }
    return 0;
}
