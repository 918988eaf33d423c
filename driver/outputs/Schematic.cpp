#include "driver/outputs/Schematic.h"

#include "driver/analyses/AnalysisRegistry.h"

#include "driver/Units.h"
#include "driver/outputs/AtomicFile.h"
#include "driver/outputs/OutputSet.h"
#include "driver/outputs/Writers.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>

namespace milldyn {

SchematicRecorder::SchematicRecorder(std::vector<double> requested) {
    for (double r : requested) {
        SchematicFrame f;
        f.requested = r;
        m_frames.push_back(f);
    }
}

void SchematicRecorder::observe(const Scene& scene, const SimTK::State& state, double key) {
    for (auto& f : m_frames) {
        // Samples come in order: draw only when this one is nearer.
        if (f.drawn && !(std::abs(key - f.requested) < std::abs(f.key - f.requested))) continue;
        Sketch sketch;
        for (const auto& draw : scene.sketches()) draw(state, sketch);
        f.shapes = sketch.shapes();
        f.key = key;
        f.drawn = true;
    }
}

namespace {

constexpr double kDrawingPixels = 640;  // the larger side of the machine [px]
constexpr double kMargin = 60, kTitleHeight = 56, kLegendWidth = 300;


std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", v);
    return buf;
}

std::string shortNumber(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", v);
    return buf;
}

/// Same shape drawn twice (two meshes on one fixed gear): keep one.
bool sameShape(const Sketch::Shape& a, const Sketch::Shape& b) {
    auto close = [](double u, double v) { return std::abs(u - v) <= 1e-12 * std::max({1.0, std::abs(u), std::abs(v)}); };
    return a.kind == b.kind && a.role == b.role && a.label == b.label && close(a.x, b.x) && close(a.y, b.y) &&
           close(a.x2, b.x2) && close(a.y2, b.y2) && close(a.radius, b.radius) && close(a.direction, b.direction) &&
           close(a.halfAngle, b.halfAngle);
}

std::vector<Sketch::Shape> unique(const std::vector<Sketch::Shape>& shapes) {
    std::vector<Sketch::Shape> out;
    for (const auto& s : shapes)
        if (std::none_of(out.begin(), out.end(), [&](const Sketch::Shape& o) { return sameShape(o, s); }))
            out.push_back(s);
    return out;
}

struct Bounds {
    double xmin = std::numeric_limits<double>::infinity(), xmax = -xmin, ymin = xmin, ymax = -xmin;
    void add(double x, double y) {
        xmin = std::min(xmin, x);
        xmax = std::max(xmax, x);
        ymin = std::min(ymin, y);
        ymax = std::max(ymax, y);
    }
    bool valid() const { return xmin <= xmax && ymin <= ymax; }
    double extent() const { return std::max({xmax - xmin, ymax - ymin, 1e-9}); }
};

/// The machine's extent over every frame (arrows excluded).
Bounds geometryBounds(const std::vector<SchematicFrame>& frames) {
    Bounds b;
    for (const auto& f : frames)
        for (const auto& s : f.shapes) switch (s.kind) {
                case Sketch::Kind::Circle:
                case Sketch::Kind::Segment:
                    b.add(s.x - s.radius, s.y - s.radius);
                    b.add(s.x + s.radius, s.y + s.radius);
                    break;
                case Sketch::Kind::Line:
                    b.add(s.x, s.y);
                    b.add(s.x2, s.y2);
                    break;
                case Sketch::Kind::Arrow: b.add(s.x, s.y); break;
            }
    return b;
}

/// 1, 2 or 5 times a power of ten, the largest not above v.
double roundDown125(double v) {
    if (!(v > 0)) return 0;
    const double p = std::pow(10.0, std::floor(std::log10(v)));
    for (double m : {5.0, 2.0, 1.0})
        if (m * p <= v) return m * p;
    return p;
}

struct Style {
    const char* element;
    const char* attributes;
    const char* legend;
};

const std::map<std::string, Style>& styles() {
    static const std::map<std::string, Style> s = {
        {"fixed_gear", {"circle", "fill=\"#eeeeee\" stroke=\"#777\" stroke-width=\"1.5\" stroke-dasharray=\"6 4\"",
                        "fixed gear (pitch circle)"}},
        {"gear", {"circle", "fill=\"none\" stroke=\"#999\" stroke-width=\"1\" stroke-dasharray=\"2 3\"",
                  "drum gear (pitch circle)"}},
        {"drum", {"circle", "fill=\"none\" stroke=\"#222\" stroke-width=\"2.5\"", "drum wall"}},
        {"sheave", {"circle", "fill=\"none\" stroke=\"#888\" stroke-width=\"1.5\"", "sheave"}},
        {"charge", {"path", "fill=\"#c8955a\" fill-opacity=\"0.85\" stroke=\"#8a5a2b\" stroke-width=\"1\"",
                    "charge (segment at its lag)"}},
        {"carrier", {"line", "stroke=\"#555\" stroke-width=\"6\" stroke-linecap=\"round\" stroke-opacity=\"0.6\"",
                     "carrier"}},
        {"belt", {"line", "stroke=\"#1f5fbf\" stroke-width=\"3\"", "belt span (tension)"}},
    };
    return s;
}

const Style& styleOf(const std::string& role) {
    static const Style fallback{"", "fill=\"none\" stroke=\"#000\" stroke-width=\"1\"", ""};
    auto it = styles().find(role);
    return it == styles().end() ? fallback : it->second;
}

}  // namespace

bool labelBoxesOverlap(const LabelBox& a, const LabelBox& b) {
    return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
}

std::vector<LabelBox> placeLabels(const std::vector<LabelBox>& boxes) {
    std::vector<LabelBox> placed;
    auto free = [&](const LabelBox& b) {
        return std::none_of(placed.begin(), placed.end(), [&](const LabelBox& o) { return labelBoxesOverlap(b, o); });
    };
    for (const LabelBox& box : boxes) {
        LabelBox chosen = box;
        if (!free(box)) {
            bool found = false;
            for (int shift = 0; shift < 2 && !found; ++shift) {
                const double dx = shift * box.width;
                for (int k = 1; k <= 30 && !found; ++k)
                    for (int sign : {1, -1}) {
                        LabelBox c = box;
                        c.x += dx;
                        c.y += sign * k * (box.height + 2);
                        if (free(c)) {
                            chosen = c;
                            found = true;
                            break;
                        }
                    }
            }
        }
        placed.push_back(chosen);
    }
    return placed;
}

LabelBox textBox(const std::string& text, double x, double y, double size, bool middle) {
    std::size_t glyphs = 0;
    for (unsigned char c : text) glyphs += (c & 0xC0) != 0x80;  // UTF-8 lead bytes
    const double width = 0.62 * size * double(glyphs);
    return {middle ? x - width / 2 : x, y - 0.8 * size, width, size};
}

double schematicForceScale(const std::vector<SchematicFrame>& frames, double& referenceForce) {
    double largest = 0;
    for (const auto& f : frames)
        for (const auto& s : f.shapes)
            if (s.kind == Sketch::Kind::Arrow) largest = std::max(largest, std::hypot(s.x2, s.y2));
    referenceForce = roundDown125(largest / 2);
    if (!(largest > 0)) return 0;
    return 0.4 * geometryBounds(frames).extent() / largest;
}

std::string renderSchematicSvg(const SchematicFrame& frame, const std::string& title, const std::string& caption,
                               double metresPerNewton, double referenceForce) {
    const std::vector<Sketch::Shape> shapes = unique(frame.shapes);
    Bounds b = geometryBounds({frame});
    for (const auto& s : shapes)
        if (s.kind == Sketch::Kind::Arrow) b.add(s.x + s.x2 * metresPerNewton, s.y + s.y2 * metresPerNewton);
    if (!b.valid()) b.add(0, 0);
    const double pxPerM = kDrawingPixels / b.extent();
    const double drawW = (b.xmax - b.xmin) * pxPerM, drawH = (b.ymax - b.ymin) * pxPerM;
    const double width = drawW + 2 * kMargin + kLegendWidth;
    const double height = std::max(drawH + 2 * kMargin + kTitleHeight, 420.0);
    auto X = [&](double x) { return kMargin + (x - b.xmin) * pxPerM; };
    auto Y = [&](double y) { return kTitleHeight + kMargin + (b.ymax - y) * pxPerM; };  // y up

    std::ostringstream svg;
    svg << std::setprecision(10);  // arrow ends exact enough to check their lengths
    svg << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(width) << "\" height=\"" << num(height)
        << "\" viewBox=\"0 0 " << num(width) << ' ' << num(height) << "\" font-family=\"DejaVu Sans, sans-serif\""
        << " data-key=\"" << frame.key << "\" data-px-per-m=\"" << pxPerM << "\" data-m-per-n=\"" << metresPerNewton << "\">\n"
        << "<defs><marker id=\"head\" viewBox=\"0 0 10 10\" refX=\"10\" refY=\"5\" markerWidth=\"5\" "
           "markerHeight=\"5\" orient=\"auto\" markerUnits=\"strokeWidth\"><path d=\"M0,0 L10,5 L0,10 z\" "
           "fill=\"#d62728\"/></marker></defs>\n"
        << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
        << "<text x=\"" << num(kMargin / 2) << "\" y=\"24\" font-size=\"16\" font-weight=\"bold\">"
        << escapeMarkup(title) << "</text>\n"
        << "<text x=\"" << num(kMargin / 2) << "\" y=\"46\" font-size=\"13\">" << escapeMarkup(caption) << "</text>\n";

    // Labels: a first drawing collects where every label wants to go,
    // placeLabels moves those that would overprint an earlier one, and the
    // second drawing writes them where placed.
    std::vector<LabelBox> wanted, placed;
    bool collecting = true;
    std::size_t nextLabel = 0;
    auto labelAt = [&](const std::string& text, double x, double y, double size, bool middle) {
        const LabelBox box = textBox(text, x, y, size, middle);
        if (collecting) {
            LabelBox inside = box;  // no label starts left of the picture
            inside.x = std::max(inside.x, 2.0);
            wanted.push_back(inside);
            return "x=\"" + num(x) + "\" y=\"" + num(y) + "\"";
        }
        const LabelBox& p = placed.at(nextLabel++);
        return "x=\"" + num(x + p.x - box.x) + "\" y=\"" + num(y + p.y - box.y) + "\"";
    };
    std::ostringstream body;
    // Fills first, lines over them, arrows on top.
    auto pass = [&](std::ostringstream& out, Sketch::Kind kind) {
        for (const auto& s : shapes) {
            if (s.kind != kind) continue;
            const Style& st = styleOf(s.role);
            const std::string cls = escapeMarkup(s.role);
            switch (s.kind) {
                case Sketch::Kind::Circle:
                    out << "<circle class=\"" << cls << "\" cx=\"" << num(X(s.x)) << "\" cy=\"" << num(Y(s.y))
                        << "\" r=\"" << num(s.radius * pxPerM) << "\" " << st.attributes << "/>\n";
                    if (!s.label.empty())
                        out << "<text class=\"label\" "
                            << labelAt(s.label, X(s.x + 0.75 * s.radius), Y(s.y + 0.75 * s.radius) - 4, 11, false)
                            << " font-size=\"11\" fill=\"#333\">"
                            << escapeMarkup(s.label) << "</text>\n";
                    break;
                case Sketch::Kind::Segment: {
                    // Chord ends at direction ± γ; the arc runs through the
                    // direction, counter-clockwise in the world (y up).
                    const double a0 = s.direction - s.halfAngle, a1 = s.direction + s.halfAngle;
                    const double x0 = X(s.x + s.radius * std::cos(a0)), y0 = Y(s.y + s.radius * std::sin(a0));
                    const double x1 = X(s.x + s.radius * std::cos(a1)), y1 = Y(s.y + s.radius * std::sin(a1));
                    const double rpx = s.radius * pxPerM;
                    out << "<path class=\"" << cls << "\" d=\"M" << num(x0) << ',' << num(y0) << " A" << num(rpx)
                        << ',' << num(rpx) << " 0 " << (s.halfAngle > M_PI / 2 ? 1 : 0) << " 0 " << num(x1) << ','
                        << num(y1) << " Z\" " << st.attributes << "/>\n";
                    if (!s.label.empty()) {
                        const double lx = s.x + 0.45 * s.radius * std::cos(s.direction);
                        const double ly = s.y + 0.45 * s.radius * std::sin(s.direction);
                        out << "<text class=\"label\" " << labelAt(s.label, X(lx), Y(ly), 10, true)
                            << " font-size=\"10\" text-anchor=\"middle\" fill=\"#402000\">" << escapeMarkup(s.label)
                            << "</text>\n";
                    }
                    break;
                }
                case Sketch::Kind::Line:
                    out << "<line class=\"" << cls << "\" x1=\"" << num(X(s.x)) << "\" y1=\"" << num(Y(s.y))
                        << "\" x2=\"" << num(X(s.x2)) << "\" y2=\"" << num(Y(s.y2)) << "\" " << st.attributes
                        << "/>\n";
                    if (!s.label.empty())
                        out << "<text class=\"label\" "
                            << labelAt(s.label, X(0.5 * (s.x + s.x2)) + 4, Y(0.5 * (s.y + s.y2)) - 4, 11, false)
                            << " font-size=\"11\" fill=\"#1f5fbf\">"
                            << escapeMarkup(s.label) << "</text>\n";
                    break;
                case Sketch::Kind::Arrow: {
                    const double f = std::hypot(s.x2, s.y2);
                    const double ex = s.x + s.x2 * metresPerNewton, ey = s.y + s.y2 * metresPerNewton;
                    out << "<g class=\"arrow " << cls << "\" data-force=\"" << f << "\" data-name=\""
                        << escapeMarkup(s.label) << "\">"
                        << "<line class=\"arrow\" x1=\"" << X(s.x) << "\" y1=\"" << Y(s.y) << "\" x2=\"" << X(ex)
                        << "\" y2=\"" << Y(ey) << "\" stroke=\"#d62728\" stroke-width=\"3\" "
                        << "marker-end=\"url(#head)\"/>"
                        << "<circle cx=\"" << num(X(s.x)) << "\" cy=\"" << num(Y(s.y))
                        << "\" r=\"3\" fill=\"#d62728\"/>"
                        << "<text class=\"label\" "
                        << labelAt(s.label + " " + shortNumber(f / 1000) + " kN", X(ex) + 6, Y(ey) + 4, 11, false)
                        << " font-size=\"11\" fill=\"#a01010\">" << escapeMarkup(s.label) << ' '
                        << escapeMarkup(shortNumber(f / 1000)) << " kN</text></g>\n";
                    break;
                }
            }
        }
    };
    auto drawAll = [&](std::ostringstream& out) {
        out << std::setprecision(10);
        for (Sketch::Kind k : {Sketch::Kind::Circle, Sketch::Kind::Segment, Sketch::Kind::Line, Sketch::Kind::Arrow})
            pass(out, k);
    };
    drawAll(body);  // collects the labels' wanted boxes
    placed = placeLabels(wanted);
    collecting = false;
    body.str("");
    drawAll(body);
    svg << body.str();

    // Legend: the roles drawn, and the force scale.
    const double lx = width - kLegendWidth + 10;
    double ly = kTitleHeight + 20;
    svg << "<g class=\"legend\">\n<text x=\"" << num(lx) << "\" y=\"" << num(ly)
        << "\" font-size=\"13\" font-weight=\"bold\">Legend</text>\n";
    std::vector<std::string> roles;
    for (const auto& s : shapes)
        if (s.kind != Sketch::Kind::Arrow && std::find(roles.begin(), roles.end(), s.role) == roles.end())
            roles.push_back(s.role);
    for (const auto& role : roles) {
        ly += 22;
        const Style& st = styleOf(role);
        const std::string element = st.element;
        if (element == "line")
            svg << "<line x1=\"" << num(lx) << "\" y1=\"" << num(ly - 4) << "\" x2=\"" << num(lx + 28) << "\" y2=\""
                << num(ly - 4) << "\" " << st.attributes << "/>";
        else
            svg << "<rect x=\"" << num(lx) << "\" y=\"" << num(ly - 12) << "\" width=\"28\" height=\"14\" "
                << st.attributes << "/>";
        svg << "<text x=\"" << num(lx + 36) << "\" y=\"" << num(ly) << "\" font-size=\"12\">"
            << escapeMarkup(st.legend[0] ? st.legend : role) << "</text>\n";
    }
    if (metresPerNewton > 0 && referenceForce > 0) {
        ly += 34;
        const double len = referenceForce * metresPerNewton * pxPerM;
        svg << "<g class=\"legend-arrow\" data-force=\"" << referenceForce << "\"><line class=\"legend-arrow\" x1=\""
            << lx << "\" y1=\"" << num(ly) << "\" x2=\"" << lx + len << "\" y2=\"" << num(ly)
            << "\" stroke=\"#d62728\" stroke-width=\"3\" marker-end=\"url(#head)\"/>"
            << "<text x=\"" << num(lx) << "\" y=\"" << num(ly + 18) << "\" font-size=\"12\">"
            << escapeMarkup(shortNumber(referenceForce / 1000)) << " kN (one scale for every picture of this run)"
            << "</text></g>\n";
        ly += 40;
        for (const char* line : {"Arrows: force of the pin on the body at its", "axis (JointReaction); the bearing",
                                 "carries the opposite. Ground frame, y up."}) {
            svg << "<text x=\"" << num(lx) << "\" y=\"" << num(ly) << "\" font-size=\"11\" fill=\"#444\">" << line
                << "</text>\n";
            ly += 15;
        }
    }
    ly += 10;
    svg << "<text x=\"" << num(lx) << "\" y=\"" << num(ly) << "\" font-size=\"11\" fill=\"#444\">Scale: "
        << escapeMarkup(shortNumber(100 / pxPerM)) << " m per 100 px</text>\n</g>\n</svg>\n";
    return svg.str();
}

namespace {

bool rsvgAvailable() { return std::system("command -v rsvg-convert >/dev/null 2>&1") == 0; }

}  // namespace

std::vector<std::string> writeSchematics(const std::string& dir, const std::string& title,
                                         const std::vector<SchematicFrame>& frames, bool angles,
                                         std::string& warning) {
    ensureDirectory(dir);
    double reference = 0;
    const double scale = schematicForceScale(frames, reference);
    const bool png = rsvgAvailable();
    if (!png) warning = "rsvg-convert not found: schematics written as SVG only (scripts/install-deps.sh installs it)";
    std::vector<std::string> written;
    for (std::size_t i = 0; i < frames.size(); ++i) {
        const SchematicFrame& f = frames[i];
        std::string caption = angles ? "carrier angle " + shortNumber(f.key * 180 / M_PI) + " deg"
                                     : "t = " + shortNumber(f.key) + " s";
        if (std::abs(f.key - f.requested) > 1e-9 * std::max(1.0, std::abs(f.requested)))
            caption += " (the sample nearest to the " +
                       (angles ? shortNumber(f.requested * 180 / M_PI) + " deg" : shortNumber(f.requested) + " s") +
                       " asked for)";
        const std::string base = dir + "/schematic_" + std::to_string(i + 1);
        writeFileAtomically(base + ".svg", renderSchematicSvg(f, title, caption, scale, reference));
        written.push_back(base + ".svg");
        if (!png) continue;
        const std::string tmp = temporaryNameBeside(base + ".png");
        if (!runTool({"rsvg-convert", "-b", "white", "-o", tmp, base + ".svg"}) || !isCompletePng(tmp)) {
            discardTemporary(tmp);
            warning = "rsvg-convert failed for " + base + ".svg: SVG only";
            continue;
        }
        commitFile(tmp, base + ".png");
        written.push_back(base + ".png");
    }
    return written;
}

bool sceneHasSketches(const Scene& scene) { return !scene.sketches().empty(); }

std::vector<double> parseSchematicInstants(const ModelSpec& spec, const std::string& list, bool& angles) {
    const ElementSpec& sc = spec.scenario;
    const AnalysisKind* kind = findAnalysisKind(sc.type);
    if (!kind || !kind->schematicSpan) {
        std::string drawn;  // the kinds that span a schematic: "kinetostatic and transient"
        for (const AnalysisKind* k : analysisKindList())
            if (k->schematicSpan) drawn += (drawn.empty() ? "" : " and ") + k->schema.type;
        throw std::invalid_argument("--schematic draws " + drawn + " scenarios; this one is '" + sc.type + "'");
    }
    const SchematicSpan span = kind->schematicSpan(sc);
    angles = span.angles;
    const double from = span.from, to = span.to;
    if (list.empty()) return span.defaults;
    std::vector<double> out;
    const char* unit = angles ? "rad" : "s";
    const std::string what = angles ? "carrier angle" : "time";
    std::size_t start = 0;
    while (start <= list.size()) {
        const std::size_t comma = std::min(list.find(',', start), list.size());
        const std::string item = list.substr(start, comma - start);
        double v = 0;
        try {
            v = units::toSI(item, unit);
        } catch (const std::exception& e) {
            throw std::invalid_argument("--schematic-at: '" + item + "' is not a " + what + ": " + e.what());
        }
        const double slack = 1e-9 * std::max(1.0, std::abs(to - from));
        if (!(v >= from - slack && v <= to + slack)) {
            auto show = [&](double x) { return angles ? shortNumber(x * 180 / M_PI) + " deg" : shortNumber(x) + " s"; };
            throw std::invalid_argument("--schematic-at: " + what + " '" + item + "' is outside the run (" + show(from) +
                                        " to " + show(to) + ")");
        }
        out.push_back(v);
        start = comma + 1;
    }
    return out;
}

}  // namespace milldyn
