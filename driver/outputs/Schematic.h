#pragma once
// The 2-D schematic of a machine (`milldyn run MODEL --schematic`): what
// every element draws of itself (Scene::addSketch, plugins/scene/Sketch.h) at
// chosen instants of a run, written as SVG (and PNG when rsvg-convert is
// installed). Reaction arrows share one force scale across all pictures of
// a run, with a reference arrow in the legend, so lengths compare.
//
// docs/schematic.md describes the command and the picture.

#include "driver/ModelSpec.h"
#include "plugins/scene/Scene.h"

#include <string>
#include <vector>

namespace milldyn {

/// One picture: the shapes every element drew at one sample.
struct SchematicFrame {
    double requested = 0;  ///< the instant asked for: time [s] or carrier angle [rad]
    double key = 0;        ///< the sample drawn (the nearest one): its table row's first column
    bool drawn = false;
    std::vector<Sketch::Shape> shapes;
};

/// Keeps, for every requested instant, the drawing of the nearest sample a
/// run passes (an analysis' SampleObserver).
class SchematicRecorder {
public:
    explicit SchematicRecorder(std::vector<double> requested);
    void observe(const Scene& scene, const SimTK::State& state, double key);
    const std::vector<SchematicFrame>& frames() const { return m_frames; }

private:
    std::vector<SchematicFrame> m_frames;
};

/// The instants to draw for `spec`'s scenario from `list` ("t1,t2,..."; each
/// a time for a transient, a carrier angle for a kinetostatic scenario; a
/// bare number is SI: s or rad; units allowed: "0.5 s", "90 deg"). An empty
/// list gives the defaults: the first angle and three more a quarter of the
/// range apart (one angle when the scenario has one), or t = 0, 1/4, 1/2 and
/// all of end_time. `angles` says which. Throws std::invalid_argument (one
/// line) for another analysis, a bad value or one outside the run.
std::vector<double> parseSchematicInstants(const ModelSpec& spec, const std::string& list, bool& angles);

/// Whether `scene` has anything to draw.
bool sceneHasSketches(const Scene& scene);

/// The SVG of `frame`: `title` on top, `caption` (the instant) below it.
/// `metresPerNewton` scales every arrow (0: no arrows to scale).
std::string renderSchematicSvg(const SchematicFrame& frame, const std::string& title, const std::string& caption,
                               double metresPerNewton, double referenceForce);

/// Writes DIR/schematic_<i>.svg (and .png when rsvg-convert is on the
/// PATH) for every frame, atomically. `angles`: the keys are carrier angles
/// (kinetostatic), else times. Returns the files written; `warning` says
/// when no PNG could be made. Throws OutputError.
std::vector<std::string> writeSchematics(const std::string& dir, const std::string& title,
                                         const std::vector<SchematicFrame>& frames, bool angles,
                                         std::string& warning);

/// A text label's box in picture pixels (x right, y down): its top-left
/// corner and size.
struct LabelBox {
    double x = 0, y = 0, width = 0, height = 0;
};

/// Whether two boxes overlap (touching edges do not).
bool labelBoxesOverlap(const LabelBox& a, const LabelBox& b);

/// Label placement: each box in turn keeps its place unless it overlaps an
/// earlier (already placed) one; then it moves to the nearest free place
/// found by stepping one box height (plus 2 px) down, then up, alternately,
/// up to 30 steps each way, and failing that one box width right. Returns
/// the placed boxes, in order.
std::vector<LabelBox> placeLabels(const std::vector<LabelBox>& boxes);

/// The box of `text` at font size `size` [px] drawn at (x, y), the baseline
/// point (`middle`: text-anchor middle, else start), estimated with an
/// average glyph width of 0.62 em.
LabelBox textBox(const std::string& text, double x, double y, double size, bool middle);

/// The common arrow scale of `frames`: the largest force is drawn 0.4 of the
/// drawing's extent long [m/N] (0 when there is no force); `referenceForce`
/// [N] receives a round force near half the largest for the legend.
double schematicForceScale(const std::vector<SchematicFrame>& frames, double& referenceForce);

}  // namespace milldyn
