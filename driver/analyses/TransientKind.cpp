// The transient's entry in the registry of analyses (AnalysisRegistry.h):
// its scenario keys and what generic code asks of it. Kept beside
// Transient.cpp (runTransient) rather than in it, to keep that long file
// to the run itself.

#include "driver/SceneBuilder.h"
#include "driver/Simulation.h"
#include "driver/analyses/AnalysisRegistry.h"

#include <string>

namespace milldyn {

AnalysisKind transientKind() {
    using P = ParamSchema;
    AnalysisKind kind;
    ElementSchema& transient = kind.schema;
    transient.type = "transient";
    transient.doc = "Time simulation: start, steady running, switch-off and run-out.";
    transient.params = {
        P::quantity("end_time", "s", "simulated time").above(0).atMost(1e6),
        P::choice("initial_state", {"rest", "steady", "file"},
                  "rest: all speeds 0; steady: solved steady running; file: the bodies' initial_* keys")
            .optional("rest"),
        P::body("speed_body", "body whose speed the summary reports (default: the first)").optional(""),
        P::body("runout_body", "body whose first stop after switch-off ends the run-out").optional(""),
        stopSpeedParam(),
        P::choice("zero_dof", {"replay", "integrate"},
                  "a scene without free degrees of freedom (every mobility prescribed or constrained): "
                  "replay: placed at each sample from the drives' time laws, no integration; "
                  "integrate: integrated like any other")
            .optional("replay"),
        P::quantity("start_tolerance", "1",
                    "start verdict: the speed is held when it stays within this fraction of the drive's "
                    "rated speed (referred to speed_body) of its final value")
            .optional(0.02).above(0).atMost(0.5),
        P::quantity("hold_time", "s", "start verdict: how long the speed must be held (0: a tenth of the "
                                      "time before switch-off)")
            .optional(0.0).atLeast(0),
        P::quantity("stall_fraction", "1", "start verdict: a speed held below this fraction of the rated speed "
                                           "(referred to speed_body) is a stall")
            .optional(0.8).above(0).below(1),
    };
    kind.run = runTransient;
    kind.timeIntegration = [](const ModelSpec& spec, const Scene& scene) -> std::string {
        const std::string why = whyNoReplay(scene, initialState(scene, spec));
        return spec.scenario.text("zero_dof") == "integrate" ? "integrated (zero_dof: integrate)"
               : why.empty() ? "none: no free degrees of freedom, the run is replayed at the samples"
                             : why;
    };
    kind.solvesEachInstant = true;  // a replayed run is solved sample by sample
    kind.carriesStepHistory = true;
    kind.keepsInitialState = [](const ElementSpec& sc) { return sc.text("initial_state") == "file"; };
    kind.reportsEnergyBalance = true;
    // Times from 0 to end_time; by default t = 0, 1/4, 1/2 and all of it.
    kind.schematicSpan = [](const ElementSpec& sc) {
        SchematicSpan span;
        span.to = sc.number("end_time");
        for (int k = 0; k < 4; ++k) span.defaults.push_back(span.to * (k < 3 ? k / 4.0 : 1.0));
        return span;
    };
    return kind;
}

}  // namespace milldyn
