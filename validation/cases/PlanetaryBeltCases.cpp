// Validation of the planetary mill with belt drive (seed 002) against its
// kinetostatic oracle (validation/oracles/PlanetaryBeltOracle.h):
//  - R_A(φ) over a full turn from the multibody model (held charge, rigid
//    belt T1 = 2 T2; one realization per angle) vs the oracle's vector
//    equilibrium (14) (steady charge), in both readings of c;
//  - the charge welded to the drum at the instant its centroid is at α: the
//    paper's split (10)+(11) of its inertia, vs (15)–(18) as printed where
//    their assumptions hold (α = 0 with gravity; g = 0 at α = 50°; Φ_c and,
//    at α = 90°, g = 0, Φ_r too);
//  - c → 1: c = 1 − 1e-9, 1, 1 + 1e-9, 1.5 (drum turning the other way);
//  - the Fig. 3 case against the printed 73–82 kN, with the sensitivity of
//    R_A to every parameter the paper omits and the weight bound on the swing;
//  - maps of R_A,max over Ω, γ, k, b, c (Figs 4–8), multibody vs oracle, and
//    the paper's equations as printed;
//  - the elastic belt: kinetostatic drum torque vs the rigid belt's, and the
//    start from rest (overshoot of reaction and tensions, slack span, slip).
// The oracle's parameters are the stated free parameters (the oracle's
// suggestedSteelDrumMaterial and models/planetary_belt_200x1000.yaml); the
// geometry of a case enters the model file by --set and, for the arm l_OA
// and gravity (lists in the file), by replacing their text: written before
// --set took lists; it takes them now (the seed-002 test of
// tests/validation/NewParametersTest.cpp sets the arm through the joints'
// location), and the cases could do the same.

#include "driver/ModelFile.h"
#include "plugins/scene/Format.h"
#include "driver/analyses/Analysis.h"
#include "validation/cases/PlanetaryBeltCases.h"
#include "validation/cases/ValidationCases.h"
#include "validation/oracles/PlanetaryBeltOracle.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <fstream>
#include <functional>
#include <optional>
#include <sstream>
#include <string>

namespace milldyn {
namespace {

namespace oc = milldyn::oracles;

// Model and oracle solve the same rigid-body equations at one instant: they
// agree to round-off; 1e-6 is issue #4's bound.
constexpr double kTolerance = 1e-6;
constexpr double kDrumRadius = 0.1;  // r_b [m], the printed 0.2 m drum
const char* kModel = "/planetary_belt_200x1000.yaml";

/// Exact, for overrides.
std::string fmt(double v) { return formatExact(v); }

/// Short form for labels.
std::string num(double v) { return formatNumber(v); }

bool wanted(const std::string& name, const std::string& filter) {
    return filter.empty() || name.find(filter) != std::string::npos;
}

/// One load case, as the oracle sees it.
struct BeltCase {
    oc::PlanetaryBeltCriteria criteria{0.1, 1.0, 0.5};
    oc::CriterionCReading reading = oc::CriterionCReading::R0OverRA;
    double rate = 30;               // Ω [rad/s]
    double halfAngle = M_PI / 2;    // γ [rad]
    double lag = 50 * M_PI / 180;   // α [rad]
    oc::PlanetaryBeltMaterial material = oc::suggestedSteelDrumMaterial();
    oc::MomentForceReading moment = oc::MomentForceReading::TransportCharge;
};

oc::PlanetaryBeltParameters oracleParameters(const BeltCase& c) {
    oc::PlanetaryBeltParameters p;
    p.geometry = oc::geometryFromCriteria(c.criteria, kDrumRadius, c.reading);
    p.material = c.material;
    p.carrierRate = c.rate;
    p.segmentHalfAngle = c.halfAngle;
    p.chargeLag = c.lag;
    p.momentReading = c.moment;
    return p;
}

std::string replaceAll(std::string text, const std::string& from, const std::string& to) {
    std::size_t pos = 0, hits = 0;
    while ((pos = text.find(from, pos)) != std::string::npos) {
        text.replace(pos, from.size(), to);
        pos += to.size();
        ++hits;
    }
    if (hits == 0) throw std::runtime_error("planetary_belt cases: the model file no longer contains '" + from + "'");
    return text;
}

/// The model for case `c` at fidelity `level`, with extra overrides.
ModelSpec modelFor(const BeltCase& c, const std::string& level, std::vector<Override> extra = {}) {
    const oc::PlanetaryBeltOracle oracle(oracleParameters(c));
    const oc::PlanetaryBeltGeometry& g = oracle.getParameters().geometry;
    std::ifstream in(modelsDirectory() + kModel);
    std::stringstream text;
    text << in.rdbuf();
    std::string t = replaceAll(text.str(), "location: [0.9 m, 0 m, 0 m]", "location: [" + fmt(g.carrierArm) + " m, 0 m, 0 m]");
    t = replaceAll(t, "location: [-0.9 m, 0 m, 0 m]", "location: [" + fmt(-g.carrierArm) + " m, 0 m, 0 m]");
    t = replaceAll(t, "gravity: [0 m/s^2, -9.80665 m/s^2, 0 m/s^2]",
                   "gravity: [0 m/s^2, " + fmt(-c.material.gravity) + " m/s^2, 0 m/s^2]");
    const oc::PlanetaryBeltMasses& m = oracle.getMasses();
    // The default (kinetostatic) scenario's carrier speed, unless a named
    // scenario runs instead (a --set of scenario.KEY acts on the scenario
    // that runs, and the transient `start` has no carrier_speed).
    const bool namedScenario = std::any_of(extra.begin(), extra.end(),
                                           [](const Override& x) { return x.path == "use_scenario"; });
    std::vector<Override> o = {{"fidelity.level", level},
                               {"elements.drive.steady_speed", fmt(c.rate) + " rad/s"},
                               {"bodies.drum1.mass", fmt(m.drum) + " kg"},
                               {"bodies.drum2.mass", fmt(m.drum) + " kg"}};
    for (const char* belt : {"belt1", "belt2"}) {
        o.push_back({std::string("elements.") + belt + ".fixed_sheave_radius", fmt(g.fixedSheaveRadius) + " m"});
        o.push_back({std::string("elements.") + belt + ".drum_sheave_radius", fmt(g.drumSheaveRadius) + " m"});
    }
    const double bulk = c.material.chargeDensity * c.material.bulkFraction;
    for (const char* charge : {"charge1", "charge2"}) {
        o.push_back({std::string("elements.") + charge + ".half_angle", fmt(c.halfAngle) + " rad"});
        o.push_back({std::string("elements.") + charge + ".length", fmt(c.material.drumLength) + " m"});
        o.push_back({std::string("elements.") + charge + ".bulk_density", fmt(bulk) + " kg/m^3"});
    }
    if (level == "paper" || level == "elastic_held") {  // held charges (dynamic_lag refuses a lag)
        // SegmentCharge's lag is measured from the leading tangent (u = sin·e_out
        // + cos·e_t), the oracle's from the trailing one: lag = π − α.
        o.push_back({"elements.charge1.lag", fmt(M_PI - c.lag) + " rad"});
        o.push_back({"elements.charge2.lag", fmt(M_PI - c.lag) + " rad"});
    }
    if (!namedScenario) o.push_back({"scenario.carrier_speed", fmt(c.rate) + " rad/s"});
    o.insert(o.end(), extra.begin(), extra.end());
    return readModelText(t, modelsDirectory() + kModel, defaultModelReader(), o);
}

/// The axle's force on drum 1 in the carrier frame (x along O→A) at row k.
Eigen::Vector2d drumReaction(const AnalysisResult& r, std::size_t k) {
    const double phi = r.value(k, "carrier_angle");
    const double gx = r.value(k, "reaction_A1.on_drum1_at_axis_x_ground");
    const double gy = r.value(k, "reaction_A1.on_drum1_at_axis_y_ground");
    return {gx * std::cos(phi) + gy * std::sin(phi), -gx * std::sin(phi) + gy * std::cos(phi)};
}

ValidationRow judged(std::string name, std::string quantity, std::string unit, double value, double oracle,
                     double error, std::string note) {
    return withError(compareRow(std::move(name), std::move(quantity), std::move(unit), value, oracle, kTolerance,
                                std::move(note)),
                     error);
}

/// The model against (15)-(18) as printed (or the paper's printed value in
/// `paper`): the printed equations carry the errors A5-A7 of
/// docs/oracles/planetary_belt.md, so the two must differ beyond the
/// judged tolerance; a printed form that agrees fails (the explanation would
/// be wrong). The model itself is judged against the rebuilt oracle in the
/// neighbouring rows.
ValidationRow printedForm(std::string name, std::string quantity, std::string unit, double value, double printedEqs,
                          std::string note, std::optional<double> paper = std::nullopt) {
    ValidationRow row = compareRow(std::move(name), std::move(quantity), std::move(unit), value, printedEqs,
                                   kTolerance, std::move(note));
    row.paper = paper;
    return asMisprint(row);
}

/// A value reported beside a reference it is not meant to equal, expected
/// in `band` (RowPolicy::Observation).
ValidationRow observed(std::string name, std::string quantity, std::string unit, double value, double oracle,
                       std::string note, ExpectedBand band) {
    return asObservation(compareRow(std::move(name), std::move(quantity), std::move(unit), value, oracle, 0.0,
                                    std::move(note)),
                         std::move(band));
}

/// Over one kinetostatic turn: worst vector error of R_A against the
/// rebuilt oracle (steady charge), worst tension error, and the extremes.
struct TurnComparison {
    double worstReaction = 0, worstTension = 0;
    double modelMax = 0, modelMin = 1e300, oracleMax = 0, oracleMin = 1e300, angleAtMax = 0;
    double paperMax = 0, paperMin = 1e300;
};

TurnComparison compareTurn(const BeltCase& c, int points, const std::string& level = "paper") {
    const oc::PlanetaryBeltOracle oracle(oracleParameters(c));
    const AnalysisResult r = runAnalysis(modelFor(c, level, {{"scenario.angle_points", std::to_string(points)}}));
    TurnComparison t;
    for (int k = 0; k < points; ++k) {
        const double phi = r.value(k, "carrier_angle");
        const oc::RebuiltReaction o = oracle.calcRebuiltReaction(phi, oc::ChargeInertia::SteadyCentroid);
        const Eigen::Vector2d f = drumReaction(r, k);
        t.worstReaction = std::max(t.worstReaction, (f - Eigen::Vector2d(o.forceX, o.forceY)).norm() / o.rA);
        if (level == "paper") {
            const double tight = r.value(k, "belt1.tension_tight"), slack = r.value(k, "belt1.tension_slack");
            t.worstTension = std::max({t.worstTension, std::abs(tight - o.tightTension) / o.tightTension,
                                       std::abs(slack - o.slackTension) / o.tightTension});
        }
        if (f.norm() > t.modelMax) {
            t.modelMax = f.norm();
            t.angleAtMax = phi;
        }
        t.modelMin = std::min(t.modelMin, f.norm());
        t.oracleMax = std::max(t.oracleMax, o.rA);
        t.oracleMin = std::min(t.oracleMin, o.rA);
        const double paper = oracle.calcPaperReaction(phi).rA;
        t.paperMax = std::max(t.paperMax, paper);
        t.paperMin = std::min(t.paperMin, paper);
    }
    return t;
}

void turnCases(const std::string& filter, std::vector<ValidationRow>& rows) {
    struct Variant {
        std::string tag;
        oc::CriterionCReading reading;
    };
    for (const Variant& v : {Variant{"r0_over_rA", oc::CriterionCReading::R0OverRA},
                             Variant{"rA_over_r0", oc::CriterionCReading::RAOverR0}}) {
        const std::string name = "planetary_belt_fig3_turn_c_" + v.tag;
        if (!wanted(name, filter)) continue;
        BeltCase c;
        c.reading = v.reading;
        const TurnComparison t = compareTurn(c, 73);
        const std::string note = "Fig. 3 case, c = 0.5 read as " + std::string(v.tag == "r0_over_rA" ? "r0/r_A" : "r_A/r0") +
                                 "; 73 angles (5°), charge held at α = 50°, rigid belt T1 = 2 T2; oracle: vector "
                                 "equilibrium (14) with the steady charge";
        rows.push_back(judged(name, "max |R_A − oracle|/|oracle| over the turn (vector)", "1", t.worstReaction, 0.0,
                              t.worstReaction, note));
        rows.push_back(judged(name, "max tension error over the turn, rel. to T_tight", "1", t.worstTension, 0.0,
                              t.worstTension, note));
        rows.push_back(compareRow(name, "R_A,max over the turn", "N", t.modelMax, t.oracleMax, kTolerance, note));
        rows.push_back(compareRow(name, "R_A,min over the turn", "N", t.modelMin, t.oracleMin, kTolerance, note));
        rows.push_back(printedForm(name, "R_A,max: model vs (15)-(18) as printed (Φ_c)", "N", t.modelMax, t.paperMax,
                            "differs by A5-A7 of docs/oracles/planetary_belt.md (gravity arm sin(φ+α), Ω² vs ω² "
                            "on the centroid offset, the sign of the belt term for r0 > r_A)"));
    }
}

/// The welded charge at the instant its centroid is at α (carrier angle φ):
/// one kinetostatic point.
AnalysisResult weldedInstant(const BeltCase& c, double phi) {
    const oc::PlanetaryBeltOracle oracle(oracleParameters(c));
    const double ratio = oracle.getParameters().geometry.fixedSheaveRadius /
                         oracle.getParameters().geometry.drumSheaveRadius;
    // Absolute drum angle at φ is (1 − r0/r_A)φ; the centroid must point at
    // φ + α − 90° (drum 1) and φ + α + 90° (drum 2).
    const double d1 = ratio * phi + c.lag - M_PI / 2;
    return runAnalysis(modelFor(c, "rigid_charge",
                                {{"scenario.angle_points", "1"},
                                 {"scenario.angle_from", fmt(phi) + " rad"},
                                 {"elements.charge1.initial_direction", fmt(d1) + " rad"},
                                 {"elements.charge2.initial_direction", fmt(d1 + M_PI) + " rad"}}));
}

void paperFormCases(const std::string& filter, std::vector<ValidationRow>& rows) {
    struct Variant {
        std::string tag;
        double lag, gravity;
        oc::MomentForceReading moment;
        std::string note;
    };
    const Variant variants[] = {
        {"alpha0", 0.0, 9.80665, oc::MomentForceReading::TransportCharge,
         "α = 0, gravity on: (15)-(18) with Φ_c hold exactly (the weight's arm sin φ is right at α = 0)"},
        {"alpha50_g0", 50 * M_PI / 180, 0.0, oc::MomentForceReading::TransportCharge,
         "α = 50°, g = 0: (15)-(18) with Φ_c hold exactly"},
        {"alpha90_g0_phi_r", M_PI / 2, 0.0, oc::MomentForceReading::RelativeCharge,
         "α = 90°, g = 0: the Φ_r reading of (15) agrees (cos α = 0: no belt torque in either reading)"},
    };
    for (const Variant& v : variants) {
        const std::string name = "planetary_belt_paper_form_" + v.tag;
        if (!wanted(name, filter)) continue;
        BeltCase c;
        c.lag = v.lag;
        c.material.gravity = v.gravity;
        c.moment = v.moment;
        const oc::PlanetaryBeltOracle oracle(oracleParameters(c));
        double worst = 0, worstT = 0;
        for (int k = 0; k < 12; ++k) {
            const double phi = 2 * M_PI * k / 12;
            const AnalysisResult r = weldedInstant(c, phi);
            const oc::PaperReaction p = oracle.calcPaperReaction(phi);
            // (16)–(17): X_A = −F_x, Y_A = F_y.
            const Eigen::Vector2d f = drumReaction(r, 0);
            worst = std::max(worst, std::hypot(-f.x() - p.xA, f.y() - p.yA) / p.rA);
            const double slack = r.value(0, "belt1.tension_slack");
            worstT = std::max(worstT, std::abs(slack - std::abs(p.slackTension)) /
                                          std::max(std::abs(p.tightTension), 1e-3 * p.rA));
        }
        rows.push_back(judged(name, "max |(X_A, Y_A) − (16),(17)|/R_A over 12 angles", "1", worst, 0.0, worst,
                              "charge welded to the drum at the instant its centroid is at α (the paper's split "
                              "Φ_c + Φ_r); " + v.note));
        rows.push_back(judged(name, "max |T2 − (15)| rel. to max(T1, 1e-3 R_A) over 12 angles", "1", worstT, 0.0, worstT, v.note));
    }
    // The Φ_r reading where it is not the Φ_c one: flagged with its size.
    const std::string name = "planetary_belt_paper_form_phi_r_reading";
    if (wanted(name, filter)) {
        BeltCase c;
        c.moment = oc::MomentForceReading::RelativeCharge;
        const oc::PlanetaryBeltOracle literal(oracleParameters(c));
        const AnalysisResult r = weldedInstant(c, 3 * M_PI / 2);
        rows.push_back(printedForm(name, "T2 at φ = 270°, model vs (15) with Φ_r", "N", r.value(0, "belt1.tension_slack"),
                            literal.calcPaperReaction(3 * M_PI / 2).slackTension,
                            "Φ_r acts along A→C and has no moment about A; every physical model gives the Φ_c "
                            "moment, so the Φ_r reading cannot be reproduced (and gives T2 < 0 on part of the turn)"));
    }
}

void cToOneCases(const std::string& filter, std::vector<ValidationRow>& rows) {
    const std::string name = "planetary_belt_c_to_1";
    if (!wanted(name, filter)) return;
    for (double cValue : {1 - 1e-9, 1.0, 1 + 1e-9, 1.5}) {
        BeltCase c;
        c.criteria.c = cValue;
        const oc::PlanetaryBeltOracle oracle(oracleParameters(c));
        const TurnComparison t = compareTurn(c, 13);
        char label[32];
        std::snprintf(label, sizeof label, "c = %.10g", cValue);  // 1 ± 1e-9 stays distinct
        const std::string tag = label;
        rows.push_back(judged(name, tag + ": max R_A error over 13 angles (vector)", "1", t.worstReaction, 0.0,
                              t.worstReaction, "held charge, rigid belt; finite for every c"));
        const AnalysisResult r = runAnalysis(modelFor(c, "paper", {{"scenario.angle_points", "1"}}));
        const double omega = r.value(0, "belt1.drum_absolute_speed");
        const double expected = oracle.getKinematics().drumRate;
        ValidationRow w = compareRow(name, tag + ": drum absolute speed ω = Ω(1 − r0/r_A)", "rad/s", omega, expected,
                                     kTolerance, "absolute error judged against Ω");
        rows.push_back(withError(w, std::abs(omega - expected) / c.rate));
        const double turns = r.value(0, "belt1.drum_turns");
        ValidationRow flag = compareRow(name, tag + ": drum_turns flag (0: translates, l_AD = ∞)", "1", turns,
                                        oracle.getKinematics().hasInstantaneousCentre ? 1.0 : 0.0, 0.0);
        rows.push_back(withError(flag, std::abs(turns - flag.oracle)));
        const double inv = r.value(0, "belt1.inverse_centre_offset");
        ValidationRow io = compareRow(name, tag + ": 1/l_AD (4), finite form", "1/m", inv,
                                      oracle.getKinematics().inverseCentreOffset, kTolerance,
                                      "absolute error judged against 1/l_OA");
        rows.push_back(withError(io, std::abs(inv - io.oracle) * oracle.getParameters().geometry.carrierArm));
    }
}

void fig3Cases(const std::string& filter, std::vector<ValidationRow>& rows) {
    const std::string name = "planetary_belt_fig3_printed";
    if (!wanted(name, filter)) return;
    BeltCase base;
    const TurnComparison t = compareTurn(base, 73);
    const oc::PlanetaryBeltOracle oracle(oracleParameters(base));
    rows.push_back(printedForm(name, "R_A,max (model; printed 82 kN)", "N", t.modelMax, t.paperMax,
                               "oracle column: (15)-(18) as printed, Φ_c, α = 50°", 82e3));
    rows.push_back(printedForm(name, "R_A,min (model; printed 73 kN)", "N", t.modelMin, t.paperMin,
                               "oracle column: (15)-(18) as printed", 73e3));
    rows.push_back(printedForm(name, "swing R_A,max − R_A,min (printed 9 kN)", "N", t.modelMax - t.modelMin,
                               t.paperMax - t.paperMin, "the weights bound the swing; see the next row", 9e3));
    rows.push_back(printedForm(name, "carrier angle of R_A,max (printed ≈ 330°)", "deg", t.angleAtMax * 180 / M_PI,
                               oracle.calcPaperReactionExtremes().angleAtMax * 180 / M_PI,
                               "oracle column: (15)-(18) as printed", 330));
    // Physical bound: R_A is affine in (sin φ, cos φ) with weight
    // coefficients, so its swing is at most 2(G_b + G_z) + 6 G_z l_Ac/r_A.
    const double bound = 2 * (oracle.getDrumWeight() + oracle.getChargeWeight()) +
                         6 * oracle.getChargeWeight() * oracle.getChargeCentroidDistance() /
                             oracle.getParameters().geometry.drumSheaveRadius;
    // A bound: judged on swing/bound, which must not exceed 1.
    rows.push_back(withError(compareRow(name, "model swing within the weight bound 2(G_b+G_z) + 6 G_z l_Ac/r_A", "N",
                                        t.modelMax - t.modelMin, bound, 1.0,
                                        "pass when the swing is below the bound; 9 kN would need ~9x the physical "
                                        "weights"),
                             (t.modelMax - t.modelMin) / bound));

    // Sensitivity to every omitted parameter: the model's R_A range.
    struct Change {
        std::string what;
        std::function<void(BeltCase&)> apply;
    };
    const Change changes[] = {
        {"shell 6 mm", [](BeltCase& c) { c.material.shellThickness = 0.006; }},
        {"shell 15 mm", [](BeltCase& c) { c.material.shellThickness = 0.015; }},
        {"covers 25 mm", [](BeltCase& c) { c.material.coverThickness = 0.025; }},
        {"no sheave mass", [](BeltCase& c) { c.material.sheaveThickness = 0.0; }},
        {"sheave 100 mm", [](BeltCase& c) { c.material.sheaveThickness = 0.1; }},
        {"bulk fraction 0.5", [](BeltCase& c) { c.material.bulkFraction = 0.5; }},
        {"bulk fraction 0.65", [](BeltCase& c) { c.material.bulkFraction = 0.65; }},
        {"quartz charge 2700 kg/m^3", [](BeltCase& c) { c.material.chargeDensity = 2700; }},
        {"α = 40°", [](BeltCase& c) { c.lag = 40 * M_PI / 180; }},
        {"α = 60°", [](BeltCase& c) { c.lag = 60 * M_PI / 180; }},
    };
    for (const Change& ch : changes) {
        BeltCase c = base;
        ch.apply(c);
        const TurnComparison s = compareTurn(c, 37);
        rows.push_back(judged(name, "sensitivity " + ch.what + ": R_A error vs oracle", "1", s.worstReaction, 0.0,
                              s.worstReaction, "37 angles"));
        rows.push_back(printedForm(name, "sensitivity " + ch.what + ": R_A,max (oracle column: (15)-(18) as printed)",
                                   "N", s.modelMax, s.paperMax, "37 angles; base 73.35 kN (printed eqs 71.14 kN)"));
        rows.push_back(printedForm(name, "sensitivity " + ch.what + ": swing R_A,max − R_A,min", "N",
                                   s.modelMax - s.modelMin, s.paperMax - s.paperMin,
                                   "oracle column: (15)-(18) as printed; printed 9 kN", 9e3));
    }
}

struct MapPoint {
    std::string map;
    std::function<void(BeltCase&)> apply;
    std::string label;
    double value;
};

std::vector<MapPoint> mapPoints() {
    std::vector<MapPoint> points;
    for (double w : {30.0, 40.0, 50.0, 60.0, 70.0, 80.0})
        points.push_back({"omega", [w](BeltCase& c) { c.rate = w; }, "Ω = " + num(w) + " rad/s", w});
    for (double g : {30.0, 60.0, 90.0, 120.0})
        points.push_back({"gamma", [g](BeltCase& c) { c.halfAngle = g * M_PI / 180; }, "γ = " + num(g) + "°", g});
    for (double k : {0.1, 0.2, 0.3, 0.4})
        points.push_back({"k", [k](BeltCase& c) { c.rate = 60; c.criteria.k = k; }, "Ω = 60, k = " + num(k), k});
    for (double b : {0.6, 0.8, 1.0, 1.2, 1.4})
        points.push_back({"b", [b](BeltCase& c) { c.rate = 60; c.criteria = {0.4, b, 0.5}; },
                          "Ω = 60, k = 0.4, b = " + num(b), b});
    for (double cv : {0.2, 0.4, 0.6, 0.8, 1.0})
        points.push_back({"c", [cv](BeltCase& c) { c.rate = 60; c.criteria = {0.4, 1.0, cv}; },
                          "Ω = 60, k = 0.4, b = 1, c = " + num(cv), cv});
    return points;
}

void mapCases(const std::string& filter, std::vector<ValidationRow>& rows) {
    for (const MapPoint& p : mapPoints()) {
        const std::string name = "planetary_belt_map_" + p.map;
        if (!wanted(name, filter)) continue;
        BeltCase c;
        p.apply(c);
        const TurnComparison t = compareTurn(c, 37);
        rows.push_back(judged(name, p.label + ": max R_A error over 37 angles", "1", t.worstReaction, 0.0,
                              t.worstReaction, "held charge α = 50°, suggested steel drum"));
        const double printed = oc::calcPaperReactionExtremes(c.rate, c.halfAngle, c.criteria,
                                                             {kDrumRadius, c.material, c.lag, c.reading, c.moment})
                                   .max;
        rows.push_back(printedForm(name, planetaryBeltMapQuantity({p.map, p.value, p.label}), "N", t.modelMax,
                                   printed, "map point"));
    }
}

void elasticCases(const std::string& filter, std::vector<ValidationRow>& rows) {
    const std::string name = "planetary_belt_elastic_kinetostatic";
    if (!wanted(name, filter)) return;
    BeltCase c;
    const int points = 37;
    const AnalysisResult rigid = runAnalysis(modelFor(c, "paper", {{"scenario.angle_points", std::to_string(points)}}));
    const AnalysisResult elastic =
        runAnalysis(modelFor(c, "elastic_held", {{"scenario.angle_points", std::to_string(points)}}));
    double worstTorque = 0, maxRigid = 0, maxElastic = 0, minSlack = 1e300, maxRatio = 0;
    for (int k = 0; k < points; ++k) {
        const double a = rigid.value(k, "belt1.drum_torque"), b = elastic.value(k, "belt1.drum_torque");
        worstTorque = std::max(worstTorque, std::abs(a - b) / std::abs(a));
        maxRigid = std::max(maxRigid, drumReaction(rigid, k).norm());
        maxElastic = std::max(maxElastic, drumReaction(elastic, k).norm());
        minSlack = std::min(minSlack, elastic.value(k, "belt1.tension_slack"));
        maxRatio = std::max(maxRatio, elastic.value(k, "belt1.tension_tight") / elastic.value(k, "belt1.tension_slack"));
    }
    rows.push_back(judged(name, "max |drum torque elastic − rigid|/rigid over 37 angles", "1", worstTorque, 0.0,
                          worstTorque,
                          "the transmitted torque is fixed by the drum's equilibrium whatever the tension law"));
    // The two runs transmit the same torque M = (T1 − T2) r_A at each angle
    // (the judged row above); they differ in the tension sum only, 2 T0 for
    // the elastic belt and 3|M|/r_A for T1 = 2 T2, and each span pulls along
    // the same line in both: R_A moves by at most |2 T0 − 3|M|/r_A|.
    const double pretension = 24.4e3, rA = oc::PlanetaryBeltOracle(oracleParameters(c)).getParameters().geometry.drumSheaveRadius;
    double sumShift = 0;
    for (int k = 0; k < points; ++k)
        sumShift = std::max(sumShift, std::abs(2 * pretension - 3 * std::abs(rigid.value(k, "belt1.drum_torque")) / rA));
    rows.push_back(observed(name, "R_A,max elastic belt (oracle column: rigid T1 = 2 T2)", "N", maxElastic, maxRigid,
                            "pretension 24.4 kN: T1 = 2 T2 at the mean torque only; elsewhere T1 + T2 = 2 T0",
                            {maxRigid - sumShift, maxRigid + sumShift,
                             "the same torque, a tension sum of 2 T0 instead of 3|M|/r_A: R_A moves by at most "
                             "max |2 T0 − 3|M|/r_A| over the turn"}));
    const double grip = std::exp(0.77 * (M_PI - 2 * std::asin(0.05 / 0.9)));
    rows.push_back(observed(name, "largest T_tight/T_slack over the turn (oracle column: e^(μθ))", "1", maxRatio, grip,
                            "no slip while below",
                            {1.0, grip, "T_tight ≥ T_slack, and a belt that grips holds at most e^(μθ)"}));
    rows.push_back(observed(name, "smallest slack-span tension over the turn", "N", minSlack, 2 * pretension / 3,
                            "oracle column: T0·2/3, the slack tension at T1 = 2 T2",
                            {2 * pretension / (1 + grip), pretension,
                             "T1 + T2 = 2 T0 and T1 ≤ e^(μθ) T2: T_slack in [2 T0/(1 + e^(μθ)), T0], never slack"}));
}

void startUpCases(const std::string& filter, std::vector<ValidationRow>& rows) {
    const std::string name = "planetary_belt_start_up";
    if (!wanted(name, filter)) return;
    BeltCase c;
    const AnalysisResult run = runAnalysis(modelFor(c, "elastic", {{"use_scenario", "start"}}));
    // Every 20 ms of the run: the dynamic reaction and tensions, and the
    // kinetostatic ones at the same instant (carrier angle, speed and ε(t);
    // charge held at the dragged charge's current lag; belt stretch solved
    // so that it stays constant, as a rigid belt's would).
    double peakR = 0, peakKinR = 0, worstRatio = 0, tWorst = 0, peakTight = 0, peakKinTight = 0;
    double worstDiff = 0, worstTightRatio = 0, minSlack = 1e300, minKinSlack = 1e300, peakSlip = 0;
    const std::size_t n = run.rows.size();
    for (std::size_t k = 0; k < n; ++k) {
        peakSlip = std::max(peakSlip, std::abs(run.value(k, "belt1.slip_speed")));
        minSlack = std::min(minSlack, run.value(k, "belt1.tension_slack"));
        peakR = std::max(peakR, run.value(k, "reaction_A1.on_drum1_at_axis_magnitude"));
        peakTight = std::max(peakTight, run.value(k, "belt1.tension_tight"));
        if (k % 10 != 0) continue;
        const double t = run.rows[k][0];
        const AnalysisResult kin =
            runAnalysis(modelFor(c, "elastic_held",
                                 {{"scenario.angle_points", "1"},
                                  {"scenario.angle_from", fmt(run.value(k, "carrier.angle")) + " rad"},
                                  {"scenario.carrier_speed", fmt(run.value(k, "carrier.speed")) + " rad/s"},
                                  {"scenario.time", fmt(t) + " s"},
                                  {"elements.charge1.lag", fmt(run.value(k, "charge1.lag")) + " rad"},
                                  {"elements.charge2.lag", fmt(run.value(k, "charge2.lag")) + " rad"}}));
        const double rDyn = run.value(k, "reaction_A1.on_drum1_at_axis_magnitude");
        const double rKin = kin.value(0, "reaction_A1.on_drum1_at_axis_magnitude");
        peakKinR = std::max(peakKinR, rKin);
        worstDiff = std::max(worstDiff, std::abs(rDyn - rKin));
        if (rDyn / rKin > worstRatio) {
            worstRatio = rDyn / rKin;
            tWorst = t;
        }
        const double tightKin = kin.value(0, "belt1.tension_tight");
        peakKinTight = std::max(peakKinTight, tightKin);
        worstTightRatio = std::max(worstTightRatio, run.value(k, "belt1.tension_tight") / tightKin);
        minKinSlack = std::min(minKinSlack, kin.value(0, "belt1.tension_slack"));
    }
    for (const ResultScalar& r : run.results)
        if (r.name == "energy_balance_relative")
            rows.push_back(judged(name, "energy balance of the start (belt energy + damping + slip + grinding)", "1",
                                  std::abs(r.value), 0.0, std::abs(r.value),
                                  "ΔKE + ΔPE − (drive − grinding − belt dissipation), relative: checks the belt's "
                                  "potential energy and dissipated power against its forces"));
    const std::string note = "elastic belt, charge dragged by the wall; start ε = ε0 e^(−t), ω(4.6 s) = 30 rad/s, "
                             "8 s; oracle column: kinetostatics at the same instants";
    // The belt's own law bounds its tensions: T1 + T2 = 2 T0, and while it
    // grips |T1 − T2|/2 ≤ y_max = T0 (E − 1)/(E + 1) (BeltDrive, stick), so
    // each span stays in [2 T0/(1 + E), 2 T0 E/(1 + E)].
    const double pretension = 24.4e3;
    const double gripV = run.value(0, "belt1.grip_ratio");
    const double lowSpan = 2 * pretension / (1 + gripV), highSpan = 2 * pretension * gripV / (1 + gripV);
    const std::string spanWhy = "T1 + T2 = 2 T0 and |T1 − T2|/2 ≤ T0 (E − 1)/(E + 1), E = " + num(gripV);
    // The R_A comparisons (dynamic vs kinetostatic at the same instant) have
    // no band derived yet: they also differ by the dragged charge's lag rate,
    // which the held kinetostatic charge lacks. Reported with an open band:
    // they fail only on a value that is no number (docs/validation.md).
    const ExpectedBand openBand{-INFINITY, INFINITY, "no band derived yet (the charge's lag rate); finite only"};
    rows.push_back(observed(name, "peak R_A over the start", "N", peakR, peakKinR, note, openBand));
    rows.push_back(observed(name,
                            "largest R_A dynamic/kinetostatic (at t = " + num(std::round(tWorst * 1000) / 1000) + " s)",
                            "1", worstRatio, 1.0, note + "; every 20 ms", openBand));
    rows.push_back(observed(name, "peak tight-span tension", "N", peakTight, peakKinTight, note,
                            {pretension, highSpan, spanWhy}));
    rows.push_back(observed(name, "largest T_tight dynamic/kinetostatic", "1", worstTightRatio, 1.0,
                            note + "; every 20 ms",
                            {pretension / highSpan, highSpan / pretension,
                             "both tight spans lie in [T0, 2 T0 E/(1 + E)]"}));
    rows.push_back(observed(name, "smallest slack-span tension (0: the span went slack)", "N", minSlack, minKinSlack,
                            note, {lowSpan, pretension, spanWhy}));
    rows.push_back(observed(name, "peak belt slip speed", "m/s", peakSlip, 0.0, "0: the belt never slipped",
                            {0.0, 0.0,
                             "the span force stays below the grip cap (E = " + num(gripV) +
                                 " against the 2 the paper's T1 = 2 T2 needs): stick, s' = 0 exactly"}));
    rows.push_back(observed(name, "largest |R_A dynamic − kinetostatic|", "N", worstDiff, 0.0, note + "; every 20 ms",
                            openBand));
    rows.back() = withError(rows.back(), worstDiff / peakKinR);  // relative to the peak load
    // A flat belt (μ = 0.22, e^(μθ) = 1.95) cannot hold the paper's T1 = 2 T2:
    // does it slip during the start, and does its slack span go slack?
    const AnalysisResult flat = runAnalysis(modelFor(c, "elastic",
                                                     {{"use_scenario", "start"},
                                                      {"elements.belt1.friction_coefficient", "0.22"},
                                                      {"elements.belt2.friction_coefficient", "0.22"}}));
    double flatSlip = 0, flatSlack = 1e300, flatFirstSlip = -1;
    for (std::size_t k = 0; k < flat.rows.size(); ++k) {
        const double v = std::abs(flat.value(k, "belt1.slip_speed"));
        if (v > 0 && flatFirstSlip < 0) flatFirstSlip = flat.rows[k][0];
        flatSlip = std::max(flatSlip, v);
        flatSlack = std::min(flatSlack, flat.value(k, "belt1.tension_slack"));
    }
    const double grip = flat.value(0, "belt1.grip_ratio");
    const std::string flatNote = "flat belt μ = 0.22, grip e^(μθ) = " + num(grip);
    rows.push_back(observed(name, "flat belt: peak slip speed (first slip at t = " + num(flatFirstSlip) + " s)", "m/s",
                            flatSlip, 0.0, flatNote,
                            {std::numeric_limits<double>::min(), INFINITY,
                             "a grip of " + num(grip) + " < 2 cannot hold T1 = 2 T2: the belt must slip"}));
    rows.push_back(observed(name, "flat belt: accumulated slip at the end", "m",
                            flat.value(flat.rows.size() - 1, "belt1.slip"), 0.0, flatNote,
                            {-flatSlip * flat.rows.back()[0], flatSlip * flat.rows.back()[0],
                             "at most the peak slip speed times the run's length"}));
    rows.push_back(observed(name, "flat belt: smallest slack-span tension", "N", flatSlack, 2 * pretension / (1 + grip),
                            flatNote + "; oracle column: 2 T0/(1 + e^(μθ)), the floor while slipping",
                            {2 * pretension / (1 + grip) * (1 - 1e-9), pretension,
                             "T1 + T2 = 2 T0, T1 ≤ e^(μθ) T2 (round-off 1e-9 below the floor allowed)"}));
    // Without gravity the wall drag holds the lag where the centrifugal
    // moment m_z W² l_OA l_Ac cos α equals the drag's torque (the model file:
    // cos α = 0.643 at W = 30 rad/s); gravity's moment m_z g l_Ac sin(·) moves
    // cos α by at most g/(W² l_OA), and W ends between 30 and 30/(1 − e^−4.6).
    const double lag = run.value(n - 1, "charge1.lag");
    const double arm = oc::PlanetaryBeltOracle(oracleParameters(c)).getParameters().geometry.carrierArm;
    const double wLow = 30.0, wHigh = 30.0 / (1 - std::exp(-4.6)), cos50 = std::cos(50 * M_PI / 180);
    const double cosHigh = cos50 + 9.80665 / (wLow * wLow * arm), cosLow = cos50 * wLow / wHigh - 9.80665 / (wLow * wLow * arm);
    rows.push_back(observed(name, "settled lag α of the dragged charge", "deg", (M_PI - lag) * 180 / M_PI, 50.0,
                            "oracle column: the 50° the wall drag was chosen for (without gravity)",
                            {std::acos(cosHigh) * 180 / M_PI, std::acos(cosLow) * 180 / M_PI,
                             "cos α = 0.643·30/W ± g/(W² l_OA), W in [30, 30/(1 − e^−4.6)] rad/s"}));
}

}  // namespace

std::vector<PlanetaryBeltMapPoint> planetaryBeltMapPoints() {
    std::vector<PlanetaryBeltMapPoint> out;
    for (const MapPoint& p : mapPoints()) out.push_back({p.map, p.value, p.label});
    return out;
}

std::string planetaryBeltMapQuantity(const PlanetaryBeltMapPoint& p) {
    return p.label + ": R_A,max model (oracle column: (15)-(18) as printed)";
}

PlanetaryBeltTurnCurves calcPlanetaryBeltFig3Turn(int points) {
    const BeltCase c;
    const oc::PlanetaryBeltOracle oracle(oracleParameters(c));
    const AnalysisResult r = runAnalysis(modelFor(c, "paper", {{"scenario.angle_points", std::to_string(points)}}));
    PlanetaryBeltTurnCurves t;
    for (int k = 0; k < points; ++k) {
        const double phi = r.value(k, "carrier_angle");
        t.angle.push_back(phi);
        t.model.push_back(drumReaction(r, k).norm());
        t.rebuilt.push_back(oracle.calcRebuiltReaction(phi, oc::ChargeInertia::SteadyCentroid).rA);
        t.paper.push_back(oracle.calcPaperReaction(phi).rA);
        t.tight.push_back(r.value(k, "belt1.tension_tight"));
        t.slack.push_back(r.value(k, "belt1.tension_slack"));
    }
    return t;
}

std::vector<ValidationRow> planetaryBeltCases(const std::string& filter) {
    std::vector<ValidationRow> rows;
    turnCases(filter, rows);
    paperFormCases(filter, rows);
    cToOneCases(filter, rows);
    fig3Cases(filter, rows);
    mapCases(filter, rows);
    elasticCases(filter, rows);
    startUpCases(filter, rows);
    return rows;
}

}  // namespace milldyn
