// The belt-driven planetary mill's section of the validation report (seed
// 002): R_A(φ) of the Fig. 3 case (Cartesian and polar) against the rebuilt
// oracle and the printed equations, the maps of Figs 4-8, c → 1, and the
// Fig. 3 conclusion (level within reach, printed swing not).

#include "validation/cases/PlanetaryBeltCases.h"
#include "validation/report/ReportSection.h"

#include <cmath>
#include <map>
#include <string>

namespace milldyn {
namespace {

bool hasCase(const std::vector<ValidationRow>& rows, const std::string& name) {
    for (const auto& r : rows)
        if (r.caseName == name) return true;
    return false;
}

std::string kN(double newtons, int digits = 4) { return formatCell(newtons / 1000, digits); }

std::vector<ReportTable> tables(const std::vector<ValidationRow>& rows) {
    std::vector<ReportTable> out;
    const std::string fig3 = "planetary_belt_fig3_printed";
    if (hasCase(rows, fig3)) {
        ReportTable t;
        t.title = "Fig. 3 case (Ω = 30 rad/s, γ = 90°, k = 0.1, b = 1, c = 0.5, α = 50°): R_A over a turn";
        t.header = {"quantity", "multibody (= rebuilt oracle)", "(15)-(18) as printed", "printed in the paper"};
        struct Q {
            const char* label;
            const char* quantity;
            bool force;
        };
        for (const Q& q : {Q{"R_A,min [kN]", "R_A,min (model; printed 73 kN)", true},
                           Q{"R_A,max [kN]", "R_A,max (model; printed 82 kN)", true},
                           Q{"swing R_A,max − R_A,min [kN]", "swing R_A,max − R_A,min (printed 9 kN)", true},
                           Q{"carrier angle of R_A,max [deg]", "carrier angle of R_A,max (printed ≈ 330°)", false}}) {
            const ValidationRow* r = findRow(rows, fig3, q.quantity);
            if (!r) continue;
            auto cell = [&](double v) { return q.force ? kN(v) : formatCell(v, 3); };
            t.rows.push_back({q.label, r->multibody ? cell(*r->multibody) : "", cell(r->oracle),
                              r->paper ? cell(*r->paper) : ""});
        }
        if (const ValidationRow* b =
                findRow(rows, fig3, "model swing within the weight bound 2(G_b+G_z) + 6 G_z l_Ac/r_A")) {
            t.rows.push_back({"weight bound on the swing 2(G_b + G_z) + 6 G_z l_Ac/r_A [kN]",
                              b->multibody ? kN(*b->multibody) + " ≤ " + kN(b->oracle) : "", "", "9 (printed swing)"});
        }
        t.caption = "The level is within reach of the parameters the paper omits; the printed 9 kN swing is not: "
                    "over a turn only the weights change direction, which bounds the swing.";
        out.push_back(t);

        ReportTable s;
        s.title = "Fig. 3 case: sensitivity of R_A to the parameters the paper omits (37 angles)";
        s.header = {"change", "R_A,max multibody [kN]", "R_A,max (15)-(18) [kN]", "swing multibody [kN]",
                    "swing (15)-(18) [kN]"};
        std::vector<std::string> order;
        std::map<std::string, std::vector<std::string>> cells;
        for (const auto& r : rows) {
            if (r.caseName != fig3 || r.quantity.rfind("sensitivity ", 0) != 0) continue;
            const std::size_t colon = r.quantity.find(": ");
            const std::string what = r.quantity.substr(12, colon - 12);
            if (!cells.count(what)) {
                order.push_back(what);
                cells[what] = {what, "", "", "", ""};
            }
            const std::string rest = r.quantity.substr(colon + 2);
            if (rest.rfind("R_A,max", 0) == 0) {
                cells[what][1] = r.multibody ? kN(*r.multibody) : "";
                cells[what][2] = kN(r.oracle);
            } else if (rest.rfind("swing", 0) == 0) {
                cells[what][3] = r.multibody ? kN(*r.multibody, 3) : "";
                cells[what][4] = kN(r.oracle, 3);
            }
        }
        for (const auto& w : order) s.rows.push_back(cells[w]);
        s.caption = "Base: 73.35 kN, swing 2.23 kN. The masses and α move the level by about ±30 % (α = 55° puts it "
                    "inside 73–82 kN); no change moves the swing beyond 2.7 kN.";
        if (!s.rows.empty()) out.push_back(s);
    }

    const std::string c1 = "planetary_belt_c_to_1";
    if (hasCase(rows, c1)) {
        ReportTable t;
        t.title = "c → 1: the drum translates at c = 1 (ω = 0, l_AD = ∞); everything stays finite";
        t.header = {"c", "ω multibody [rad/s]", "ω = Ω(1 − r0/r_A)", "drum_turns", "1/l_AD multibody [1/m]",
                    "1/l_AD (4)", "R_A error vs oracle (13 angles)"};
        std::vector<std::string> order;
        std::map<std::string, std::vector<std::string>> cells;
        for (const auto& r : rows) {
            if (r.caseName != c1) continue;
            const std::size_t colon = r.quantity.find(": ");
            const std::string c = r.quantity.substr(4, colon - 4);  // "c = ..."
            if (!cells.count(c)) {
                order.push_back(c);
                cells[c] = {c, "", "", "", "", "", ""};
            }
            const std::string rest = r.quantity.substr(colon + 2);
            const std::string mb = r.multibody ? formatCell(*r.multibody, 6) : "";
            if (rest.rfind("drum absolute speed", 0) == 0) {
                cells[c][1] = mb;
                cells[c][2] = formatCell(r.oracle, 6);
            } else if (rest.rfind("drum_turns", 0) == 0) {
                cells[c][3] = mb;
            } else if (rest.rfind("1/l_AD", 0) == 0) {
                cells[c][4] = mb;
                cells[c][5] = formatCell(r.oracle, 6);
            } else if (rest.rfind("max R_A error", 0) == 0) {
                cells[c][6] = formatCell(r.relError, 2);
            }
        }
        for (const auto& c : order) t.rows.push_back(cells[c]);
        t.caption = "At c = 1 ± 1e-9 the drum turns at ∓3e-8 rad/s and l_AD is finite but huge; at c = 1 it "
                    "translates (drum_turns = 0). Relative to the carrier it still turns at −Ω, so the charge is "
                    "still dragged: R_A is continuous through c = 1. The printed jump (Fig. 8) does not follow.";
        out.push_back(t);
    }
    return out;
}

std::vector<ReportPlot> plots(const std::vector<ValidationRow>& rows) {
    std::vector<ReportPlot> out;
    if (hasCase(rows, "planetary_belt_fig3_printed") || hasCase(rows, "planetary_belt_fig3_turn_c_r0_over_rA")) {
        const PlanetaryBeltTurnCurves t = calcPlanetaryBeltFig3Turn(73);
        std::vector<double> deg, model, rebuilt, paper, tight, slack;
        for (std::size_t k = 0; k < t.angle.size(); ++k) {
            deg.push_back(t.angle[k] * 180 / M_PI);
            model.push_back(t.model[k] / 1000);
            rebuilt.push_back(t.rebuilt[k] / 1000);
            paper.push_back(t.paper[k] / 1000);
            tight.push_back(t.tight[k] / 1000);
            slack.push_back(t.slack[k] / 1000);
        }
        ReportPlot p;
        p.file = "planetary_belt_reaction";
        p.title = "Fig. 3 case: drum-axle reaction R_A over a carrier turn";
        p.xLabel = "carrier angle φ [deg]";
        p.yLabel = "R_A [kN]";
        p.series = {{"multibody (73 angles)", deg, model, ReportSeries::Style::Points, 2},
                    {"oracle: vector equilibrium (14), steady charge", deg, rebuilt, ReportSeries::Style::Lines, 1},
                    {"(15)-(18) as printed", deg, paper, ReportSeries::Style::DashedLines, 3},
                    {"printed band 73-82 kN", {0, 360}, {73, 73}, ReportSeries::Style::DashedLines, 7},
                    {"", {0, 360}, {82, 82}, ReportSeries::Style::DashedLines, 7}};
        p.caption = "Multibody and rebuilt oracle agree to 1e-15. The printed equations sit ~2 kN lower (their "
                    "split Φ_c + Φ_r, the weight's arm sin φ); the paper's curve spans 73-82 kN, a swing the "
                    "weights cannot produce.";
        out.push_back(p);

        ReportPlot polar;
        polar.file = "planetary_belt_reaction_polar";
        polar.title = "R_A(φ) in polar form [kN] (radius from 0, angle = carrier angle)";
        polar.xLabel = "R_A cos φ [kN]";
        polar.yLabel = "R_A sin φ [kN]";
        polar.equalAxes = true;
        auto polarSeries = [&](const std::string& label, const std::vector<double>& r, ReportSeries::Style st,
                               int colour) {
            ReportSeries s{label, {}, {}, st, colour};
            for (std::size_t k = 0; k < r.size(); ++k) {
                s.x.push_back(r[k] * std::cos(t.angle[k]));
                s.y.push_back(r[k] * std::sin(t.angle[k]));
            }
            return s;
        };
        polar.series.push_back(polarSeries("multibody", model, ReportSeries::Style::Lines, 2));
        polar.series.push_back(polarSeries("(15)-(18) as printed", paper, ReportSeries::Style::DashedLines, 3));
        for (double radius : {73.0, 82.0}) {
            ReportSeries band{radius < 80 ? "printed 73 and 82 kN" : "", {}, {}, ReportSeries::Style::DashedLines, 7};
            for (int k = 0; k <= 120; ++k) {
                band.x.push_back(radius * std::cos(2 * M_PI * k / 120));
                band.y.push_back(radius * std::sin(2 * M_PI * k / 120));
            }
            polar.series.push_back(band);
        }
        polar.caption = "Almost a circle: the centrifugal load turns with the carrier and dominates; only the "
                        "weights make it off-centre.";
        out.push_back(polar);

        ReportPlot ten;
        ten.file = "planetary_belt_tensions";
        ten.title = "Belt tensions over a carrier turn (rigid belt, T1 = 2 T2)";
        ten.xLabel = "carrier angle φ [deg]";
        ten.yLabel = "tension [kN]";
        ten.series = {{"tight span", deg, tight, ReportSeries::Style::Lines, 1},
                      {"slack span", deg, slack, ReportSeries::Style::Lines, 2}};
        ten.caption = "The tensions carry the torque that holds the charge at its lag; 3 T2 cos β enters R_A.";
        out.push_back(ten);
    }

    struct Map {
        const char* tag;
        const char* title;
        const char* xLabel;
        const char* claim;
    };
    const Map maps[] = {
        {"omega", "Fig. 4: R_A,max against the carrier speed Ω (γ 90°, k 0.1, b 1, c 0.5)", "Ω [rad/s]",
         "The paper: 6-8× growth over 30-80 rad/s; the model: ×7.02 (Ω² with a constant weight part). Reproduced."},
        {"gamma", "Fig. 5: R_A,max against the segment half-angle γ (Ω 30)", "γ [deg]",
         "The paper: grows with the filling; the model only above γ ≈ 60°: a larger charge raises T2, whose "
         "3 T2 cos β is subtracted in X_A."},
        {"k", "Fig. 6: R_A,max against k = r_A/(l_OA + r_A) (Ω 60, b 1, c 0.5)", "k",
         "Falls with k (a shorter carrier arm), as the paper says."},
        {"b", "Fig. 7: R_A,max against b = r_b/r_A (Ω 60, k 0.4, c 0.5)", "b",
         "Falls with b, as the paper says: at fixed r_b and k a larger b is a smaller r_A and a shorter arm."},
        {"c", "Fig. 8: R_A,max against c = r0/r_A (Ω 60, k 0.4, b 1)", "c",
         "The paper: up to 2300 kN at small c and a jump at c = 1; the model: within 8 %, continuous through "
         "c = 1. Not reproduced (see c → 1)."},
    };
    const std::vector<PlanetaryBeltMapPoint> points = planetaryBeltMapPoints();
    for (const Map& m : maps) {
        const std::string name = std::string("planetary_belt_map_") + m.tag;
        if (!hasCase(rows, name)) continue;
        ReportPlot p;
        p.file = name;
        p.title = m.title;
        p.xLabel = m.xLabel;
        p.yLabel = "R_A,max over a turn [kN]";
        ReportSeries model{"multibody (= rebuilt oracle)", {}, {}, ReportSeries::Style::Lines, 1};
        ReportSeries printed{"(15)-(18) as printed", {}, {}, ReportSeries::Style::DashedLines, 3};
        for (const auto& pt : points) {
            if (pt.map != m.tag) continue;
            const ValidationRow* r = findRow(rows, name, planetaryBeltMapQuantity(pt));
            if (!r) continue;
            model.x.push_back(pt.value);
            model.y.push_back(r->multibody ? *r->multibody / 1000 : NAN);
            printed.x.push_back(pt.value);
            printed.y.push_back(r->oracle / 1000);
        }
        ReportSeries marks = model;
        marks.label = "map points";
        marks.style = ReportSeries::Style::Points;
        p.series = {model, marks, printed};
        p.caption = m.claim;
        out.push_back(p);
    }
    return out;
}

}  // namespace

ReportSection planetaryBeltReportSection() {
    ReportSection s;
    s.machine = "planetary_belt";
    s.title = "Planetary mill with belt drive (seed 002)";
    s.paper = "Seed 002 (OCR-garbled; decoded in docs/oracles/planetary_belt.md): a carrier on a horizontal axis O, "
              "two drums on pins at A1, A2, each belted (open belt) to a sheave fixed on O, so the drum turns at "
              "ω = Ω(1 − r0/r_A); a charge held at the lag α; the drum-axle reaction R_A over a turn, and its "
              "maps over Ω, γ and the criteria k, b, c.";
    s.claims = "R_A from (15)-(18) with T1 = 2 T2; for the Fig. 3 case (0.2 x 1 m drum, Ω = 30 rad/s, γ = 90°, k = "
               "0.1, b = 1, c = 0.5) R_A swings between 73 and 82 kN with its maximum near 330°; Figs 4-8 map "
               "R_A,max (6-8× growth with Ω, up to 2300 kN at small c and a jump at c = 1).";
    s.oracle = "validation/oracles/PlanetaryBeltOracle: the printed (15)-(18) (both readings of c and of Φ in "
               "(15)), and the rebuilt vector equilibrium (14) of the drum with its held charge. The paper gives "
               "no masses: a steel drum full of steel balls is chosen and argued (docs/oracles/planetary_belt.md "
               "§6).";
    s.multibody = "Simbody: carrier, two drums on pins, BeltDrive (rigid: T1 = 2 T2 as a constraint whose "
                  "multiplier is the tension difference; elastic: spans with Euler-Eytelwein slip), SegmentCharge "
                  "held at the lag, JointReaction. The kinetostatic analysis realizes one state per carrier angle "
                  "(no integration); the start is integrated with the elastic belt.";
    s.differences = {
        "The multibody R_A is the rebuilt oracle's to ~1e-15 over every turn, map point and c. The printed "
        "equations differ where their assumptions do (flagged rows, docs/oracles/planetary_belt.md A5-A7): "
        "the paper splits the charge's inertia as Φ_c + Φ_r with ω² on the centroid offset, gives the weight "
        "the arm sin φ instead of sin(φ + α), and for r0 > r_A the belt term of (17) changes sign.",
        "Fig. 3: the level is within reach (the omitted masses and α move R_A,max by ±30 %; α = 55° gives "
        "76.4-78.8 kN), the shape is not: over a turn only the weights change direction, so the swing is at "
        "most 2(G_b + G_z) + 6 G_z l_Ac/r_A = 4.7 kN (the model: 2.2 kN). The printed 9 kN needs about nine "
        "times the weights of a steel drum full of steel, which would put the level far above 82 kN. The "
        "maximum is at 310° (model) or 269° (printed equations), not ≈ 330°.",
        "c → 1: c enters only through ω² = Ω²(1 − c)² and sin β, both smooth; at c = 1 the drum translates "
        "but still turns at −Ω relative to the carrier. R_A is continuous; the printed jump and 2300 kN (40× "
        "anything the equations give for this drum) do not follow.",
        "The Φ_r reading of (15) cannot be reproduced by any physical model: Φ_r acts along A→C and has no "
        "moment about A (flagged row, T2 at φ = 270°).",
        "The start with an elastic belt (not in the paper) overshoots the kinetostatic R_A and tensions; a "
        "flat belt (μ = 0.22) cannot hold T1 = 2 T2 and slips (flagged rows with their sizes)."};
    s.docs = "docs/planetary_belt.md (model, parameters, results, maps, start-up), docs/oracles/planetary_belt.md "
             "(decoding of the paper, misprints), validation/cases/PlanetaryBeltCases.cpp.";
    s.tables = tables;
    s.plots = plots;
    return s;
}

}  // namespace milldyn
