// Issue 29 item 2: the Campbell diagram (analysis campbell), one numbering
// of modes in every output, and resonance_map for every coupling.
//
// Oracle (textbook, independent of the model): a free–free chain of three
// inertias J1–k1–J2–k2–J3 has the undamped natural frequencies ω² = 0 and
// the roots λ = ω² of
//   J1·J2·J3·λ² − [k1·J3·(J1 + J2) + k2·J1·(J2 + J3)]·λ + k1·k2·(J1 + J2 + J3) = 0
// (det(K − λM) = 0 divided by λ). An induction motor on J1 and a
// shaft-angle load on J3 add damping only (the motor's torque–speed slope,
// the load's smoothing): the undamped frequencies do not depend on the
// speed, so the line of order o (o events per revolution of J3, which
// turns with the chain) meets mode m at the running speed Ω = ω_m/o.
// A half-sine pulse over half a cycle has harmonics k = 1, 2, 4 of its
// listed 1..4 (no odd k >= 3): with n = 2 cycles per revolution the orders
// are 2, 4 and 8, and no order 6.
#include "driver/analyses/Analysis.h"
#include "driver/outputs/CampbellPlot.h"
#include "driver/outputs/Writers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace milldyn {
namespace {

constexpr double kJ1 = 0.5, kJ2 = 0.2, kJ3 = 0.3;  // [kg*m^2]
constexpr double kK1 = 8e4, kK2 = 5e4;              // [N*m/rad]

/// The chain's two elastic natural frequencies [rad/s], ascending.
std::vector<double> chainFrequencies() {
    const double a = kJ1 * kJ2 * kJ3;
    const double b = -(kK1 * kJ3 * (kJ1 + kJ2) + kK2 * kJ1 * (kJ2 + kJ3));
    const double c = kK1 * kK2 * (kJ1 + kJ2 + kJ3);
    const double d = std::sqrt(b * b - 4 * a * c);
    return {std::sqrt((-b - d) / (2 * a)), std::sqrt((-b + d) / (2 * a))};
}

std::string num(double v) {
    std::ostringstream s;
    s.precision(17);
    s << v;
    return s.str();
}

std::string chain(const std::string& scenario) {
    return "format_version: 1\nname: three-inertia chain\nbodies:\n"
           "  - {name: a, inertia: " + num(kJ1) + " kg*m^2, joint: {type: pin}}\n"
           "  - {name: b, inertia: " + num(kJ2) + " kg*m^2, joint: {type: pin}}\n"
           "  - {name: c, inertia: " + num(kJ3) + " kg*m^2, joint: {type: pin}}\n"
           "elements:\n"
           "  - {type: InductionMotor, name: motor, body: a, law: kloss, rated_torque: 100 N*m, rated_speed: 1440 rpm,"
           " synchronous_speed: 1500 rpm, breakdown_ratio: 2.5}\n"
           "  - {type: TorsionalCoupling, name: shaft1, bodies: [a, b], stiffness: " + num(kK1) +
           " N*m/rad, damping: 2 N*m*s/rad}\n"
           "  - {type: TorsionalCoupling, name: shaft2, bodies: [b, c], stiffness: " + num(kK2) +
           " N*m/rad, damping: 2 N*m*s/rad}\n"
           "  - {type: AngleLoad, name: crushing, bodies: [c], shape: half_sine_pulse, peak_torque: 100 N*m,"
           " pulse_start: 0 deg, pulse_width: 180 deg, cycles_per_revolution: 2, listed_harmonics: 4}\n"
           "scenario: {" + scenario + "}\n"
           "outputs: {plots: false}\n";
}

AnalysisResult run(const std::string& scenario) {
    return runAnalysis(readModelText(chain(scenario), "chain.yaml", defaultModelReader()));
}

const DataTable& table(const AnalysisResult& r, const std::string& name) {
    for (const auto& t : r.extraTables)
        if (t.name == name) return t;
    throw std::runtime_error("no table " + name);
}

std::size_t col(const std::vector<std::string>& names, const std::string& name) {
    for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == name) return i;
    throw std::runtime_error("no column " + name);
}

/// The crossing of mode `mode` with the line `line`, its speed [rad/s]; NaN if none.
double crossingSpeed(const AnalysisResult& r, int mode, const std::string& line) {
    const DataTable& t = table(r, "campbell_crossings");
    const std::vector<std::string> names = campbellLineNames(r);
    for (const auto& row : t.rows)
        if (int(row[col(t.columnNames, "mode")]) == mode && names.at(std::size_t(row[col(t.columnNames, "order")])) == line)
            return row[col(t.columnNames, "speed")];
    return std::nan("");
}

std::size_t crossingsOf(const AnalysisResult& r, const std::string& line) {
    const DataTable& t = table(r, "campbell_crossings");
    const std::vector<std::string> names = campbellLineNames(r);
    std::size_t n = 0;
    for (const auto& row : t.rows) n += names.at(std::size_t(row[col(t.columnNames, "order")])) == line;
    return n;
}

// The crossing speeds of the load's orders equal ω_m/o, located on the
// mode curve (not read off the 12-point grid, whose spacing is 15 rad/s).
void expectOracleCrossings(const AnalysisResult& r) {
    const std::vector<double> w = chainFrequencies();
    // Every grid speed: the modes are the chain's.
    ASSERT_EQ(r.find("elastic_modes")->value, 2.0);
    for (const auto& row : r.rows)
        for (int m = 0; m < 2; ++m)
            EXPECT_NEAR(row[r.findColumn("natural_frequency_" + std::to_string(m + 1) + "_rad_per_s")] / w[m], 1.0, 1e-8);
    const std::vector<std::pair<int, std::pair<int, double>>> expected = {
        {2, {1, w[0] / 2}}, {4, {1, w[0] / 4}}, {8, {1, w[0] / 8}}, {8, {2, w[1] / 8}}};
    for (const auto& [order, at] : expected) {
        const double speed = crossingSpeed(r, at.first, "crushing.order_" + std::to_string(order));
        ASSERT_TRUE(std::isfinite(speed)) << "order " << order << " mode " << at.first;
        EXPECT_NEAR(speed / at.second, 1.0, 1e-8) << "order " << order << " mode " << at.first;
    }
    // Orders 2 and 4 meet mode 2 above the range (450, 225 rad/s > 210).
    EXPECT_EQ(crossingsOf(r, "crushing.order_2"), 1u);
    EXPECT_EQ(crossingsOf(r, "crushing.order_4"), 1u);
    EXPECT_EQ(crossingsOf(r, "crushing.order_8"), 2u);
    // The half sine has no third harmonic: no order 6.
    EXPECT_EQ(r.findColumn("crushing.order_6_hz"), std::string::npos);
}

TEST(Campbell, ChainCrossingsEqualTheRootsOfTheCharacteristicPolynomialOverTheOrder) {
    const AnalysisResult r =
        run("analysis: campbell, operating_point: supply_scaled, speed_min: 40 rad/s, speed_max: 210 rad/s, points: 12");
    EXPECT_EQ(r.tableName, "campbell");
    EXPECT_NE(r.findColumn("supply_scale"), std::string::npos);
    expectOracleCrossings(r);
    // Frequencies carry their unit in the name; Hz is rad/s over 2π.
    const auto& row = r.rows.front();
    EXPECT_NEAR(row[r.findColumn("natural_frequency_1_hz")] * 2 * M_PI, row[r.findColumn("natural_frequency_1_rad_per_s")],
                1e-12 * row[r.findColumn("natural_frequency_1_rad_per_s")]);
    // The margin is to the model's steady speed (the only operating speed).
    const double w0 = r.find("operating_speed")->value;
    const double at = crossingSpeed(r, 1, "crushing.order_4");
    const DataTable& t = table(r, "campbell_crossings");
    bool found = false;
    for (const auto& x : t.rows)
        if (x[col(t.columnNames, "speed")] == at) {
            EXPECT_NEAR(x[col(t.columnNames, "margin")], (at - w0) / w0 * 100, 1e-9);
            found = true;
        }
    EXPECT_TRUE(found);
}

TEST(Campbell, ScaledStateGivesTheSameCrossingsAsTheScaledSupply) {
    // The undamped frequencies do not see the motor's slope: either way of
    // reaching a speed gives the oracle's crossings. auto takes
    // scaled_state for a direct-on-line motor (no supply_scale column).
    const AnalysisResult r = run("analysis: campbell, speed_min: 40 rad/s, speed_max: 210 rad/s, points: 12");
    EXPECT_EQ(r.findColumn("supply_scale"), std::string::npos);
    expectOracleCrossings(r);
}

TEST(Campbell, SupplyLineFollowsTheScaledSupply) {
    // A 4-pole motor (1500 rpm at 50 Hz: p = 2) fed at a·50 Hz: the supply
    // line is 2·a·ω_c; a constant load torque keeps the relative slip of a
    // curve scaled along the speed axis, so Ω = a·Ω0 and the line meets
    // mode 1 at Ω = ω_1·Ω0/(p·ω_c).
    const AnalysisResult r =
        run("analysis: campbell, operating_point: supply_scaled, speed_min: 40 rad/s, speed_max: 210 rad/s, points: 12");
    const double w0 = r.find("operating_speed")->value, wc = 1500 * 2 * M_PI / 60;
    const double speed = crossingSpeed(r, 1, "motor.supply_frequency");
    ASSERT_TRUE(std::isfinite(speed));
    EXPECT_NEAR(speed / (chainFrequencies()[0] * w0 / (2 * wc)), 1.0, 1e-8);
    // Fixed at 50 Hz when the state is scaled instead: no crossing below mode 1's 64 Hz.
    const AnalysisResult fixed =
        run("analysis: campbell, operating_point: scaled_state, speed_min: 40 rad/s, speed_max: 210 rad/s, points: 12");
    EXPECT_EQ(crossingsOf(fixed, "motor.supply_frequency"), 0u);
    EXPECT_NEAR(fixed.rows.front()[fixed.findColumn("motor.supply_frequency_hz")], 50.0, 1e-12);
}

TEST(Campbell, ExtraOrdersAndCrossingsCsvNameTheLine) {
    const AnalysisResult r =
        run("analysis: campbell, speed_min: 40 rad/s, speed_max: 210 rad/s, points: 12, extra_orders: [3]");
    const double speed = crossingSpeed(r, 1, "extra_order_3");
    EXPECT_NEAR(speed / (chainFrequencies()[0] / 3), 1.0, 1e-8);
    const std::string csv = formatCampbellCrossingsCsv(r, table(r, "campbell_crossings"));
    EXPECT_NE(csv.find("mode[1],order,order_per_rev[1],speed[rad/s]"), std::string::npos) << csv;
    EXPECT_NE(csv.find(",extra_order_3,"), std::string::npos) << csv;
    EXPECT_NE(csv.find(",crushing.order_8,"), std::string::npos) << csv;
    // The plot draws modes, lines and the crossings.
    const std::string plot = campbellPlotCommands(r, "campbell.csv");
    EXPECT_NE(plot.find("$crossings"), std::string::npos);
    EXPECT_NE(plot.find("natural_frequency_2"), std::string::npos);
}

// A ShaftBelt's passing frequency is an order of its driver: a point of
// the belt passes the driver's sheave 2π·r1/L times per driver revolution,
// L the open belt's pitch length (textbook): with l the pins' distance and
// sin β = |r2 − r1|/l, L = r_small·(π − 2β) + r_large·(π + 2β) + 2·l·cos β.
// Here r1 = 0.1 m, r2 = 0.3 m, l = 0.8 m: L = 2.90691 m. The line is the
// Campbell diagram's and resonance_map's alike (Scene's order excitations).
TEST(Campbell, BeltPassingIsAnOrderOfTheDriverFromTheBeltLength) {
    const std::string model =
        "format_version: 1\nname: belt\nbodies:\n"
        "  - {name: motor_shaft, inertia: 0.5 kg*m^2, joint: {type: pin, parent: ground}}\n"
        "  - {name: drum, inertia: 20 kg*m^2, joint: {type: pin, parent: ground, location: [0.8 m, 0 m, 0 m]}}\n"
        "elements:\n"
        "  - {type: InductionMotor, name: motor, body: motor_shaft, law: kloss, rated_torque: 100 N*m, "
        "rated_speed: 1440 rpm, synchronous_speed: 1500 rpm, breakdown_ratio: 2.5}\n"
        "  - {type: ShaftBelt, name: belt, driver: motor_shaft, driven: drum, driver_sheave_radius: 0.1 m, "
        "driven_sheave_radius: 0.3 m, pretension: 2000 N, span_stiffness: 2e5 N/m, span_damping: 50 N*s/m, "
        "friction_coefficient: 1.5}\n"
        "  - {type: ResistanceTorque, name: load, body: drum, constant_torque: 100 N*m}\n"
        "scenario: {SCENARIO}\noutputs: {plots: false}\n";
    auto withScenario = [&](const std::string& scenario) {
        std::string text = model;
        text.replace(text.find("SCENARIO"), 8, scenario);
        return runAnalysis(readModelText(text, "belt.yaml", defaultModelReader()));
    };
    const double r1 = 0.1, r2 = 0.3, l = 0.8;
    const double beta = std::asin(std::abs(r2 - r1) / l);
    const double length = std::min(r1, r2) * (M_PI - 2 * beta) + std::max(r1, r2) * (M_PI + 2 * beta) +
                          2 * l * std::cos(beta);
    const double order = 2 * M_PI * r1 / length;  // per revolution of the driver
    const AnalysisResult c = withScenario("analysis: campbell, speed_min: 20 rad/s, speed_max: 160 rad/s, points: 8");
    const ResultScalar* derived = nullptr;
    for (const auto& d : c.derived)
        if (d.name == "belt.belt_length") derived = &d;
    ASSERT_NE(derived, nullptr);
    EXPECT_NEAR(derived->value, length, 1e-12 * length);
    // The diagram's speed is the driver's (the motor shaft is its reference).
    for (const auto& row : c.rows)
        EXPECT_NEAR(row[c.findColumn("belt.belt_passing_rad_per_s")], order * row[c.findColumn("speed")],
                    1e-12 * order * row[c.findColumn("speed")]);
    const AnalysisResult m = withScenario("analysis: resonance_map, rotor: drum, speed_min: 5 rad/s, "
                                          "speed_max: 50 rad/s, points: 10");
    // resonance_map's rotor is the drum, which turns at 1/3 of the driver
    // (ω_driver/ω_drum = r2/r1 at steady running, creep aside).
    const ResultScalar* perRotor = m.find("belt.belt_passing.per_rotor_speed");
    ASSERT_NE(perRotor, nullptr);
    EXPECT_NEAR(perRotor->value, order * r2 / r1, 1e-3 * order * r2 / r1);
}

TEST(Campbell, RefusesASupplyToScaleWithoutAMotor) {
    const std::string text = chain("analysis: campbell, operating_point: supply_scaled, speed_min: 40 rad/s, "
                                   "speed_max: 210 rad/s");
    std::string noMotor = text;
    const std::size_t from = noMotor.find("  - {type: InductionMotor");
    noMotor.replace(from, noMotor.find('\n', from) - from + 1,
                    "  - {type: AppliedTorque, name: drive, body: a, torque: 30 N*m}\n");
    EXPECT_THROW(runAnalysis(readModelText(noMotor, "chain.yaml", defaultModelReader())), SpecError);
}

// 1500 rpm synchronous on 47 Hz is 1.88 pole pairs: the motor does not fit
// that supply, refused at scenario.supply_frequency naming the motor.
TEST(Campbell, RefusesASupplyTheMotorDoesNotFitAtSupplyFrequency) {
    try {
        run("analysis: campbell, supply_frequency: 47 Hz, speed_min: 40 rad/s, speed_max: 210 rad/s, points: 12");
        ADD_FAILURE() << "47 Hz accepted";
    } catch (const SpecError& e) {
        EXPECT_EQ(e.key(), "scenario.supply_frequency");
        EXPECT_NE(std::string(e.what()).find("'motor': synchronous speed 1500 rpm is not 47 Hz over a whole number"),
                  std::string::npos)
            << e.what();
    }
}

// Orders of another shaft are referred through the train's speed ratios.
// Motor shaft a (J1) –k– pinion b (Jb), a rigid gear pair (20/80 teeth,
// pitch radii 0.1/0.4 m: ω_c = −ω_b/4) to the wheel c (Jc) with the
// crushing load. Textbook: the wheel reduced to the pinion,
// J_eq = Jb + Jc/16, one elastic mode ω_n² = k(1/J1 + 1/J_eq). Against
// the speed Ω of a: the mesh (20 per revolution of b) meets it at ω_n/20,
// the load's order 4 (per revolution of c) at ω_n/(4/4) = ω_n.
TEST(Campbell, OrdersOfAGearedShaftAreReferredThroughTheRatio) {
    const double J1 = 0.5, Jb = 0.1, Jc = 3.2, k = 3e3;
    const double wn = std::sqrt(k * (1 / J1 + 1 / (Jb + Jc / 16)));
    const std::string text =
        "format_version: 1\nname: geared chain\nbodies:\n"
        "  - {name: a, inertia: " + num(J1) + " kg*m^2, joint: {type: pin}}\n"
        "  - {name: b, inertia: " + num(Jb) + " kg*m^2, joint: {type: pin}}\n"
        "  - {name: c, inertia: " + num(Jc) + " kg*m^2, joint: {type: pin, parent: ground, location: [0.5 m, 0 m, 0 m]}}\n"
        "elements:\n"
        "  - {type: InductionMotor, name: motor, body: a, law: kloss, rated_torque: 100 N*m, rated_speed: 1440 rpm,"
        " synchronous_speed: 1500 rpm, breakdown_ratio: 2.5}\n"
        "  - {type: TorsionalCoupling, name: shaft, bodies: [a, b], stiffness: " + num(k) +
        " N*m/rad, damping: 0.5 N*m*s/rad}\n"
        "  - {type: GearPair, name: mesh, bodies: [b, c], pitch_radii: [0.1 m, 0.4 m], teeth: [20, 80]}\n"
        "  - {type: AngleLoad, name: crushing, bodies: [c], shape: half_sine_pulse, peak_torque: 100 N*m,"
        " pulse_start: 0 deg, pulse_width: 180 deg, cycles_per_revolution: 1, listed_harmonics: 4}\n"
        "scenario: {analysis: campbell, reference_shaft: a, speed_min: 5 rad/s, speed_max: 200 rad/s, points: 9}\n"
        "outputs: {plots: false}\n";
    const AnalysisResult r = runAnalysis(readModelText(text, "geared.yaml", defaultModelReader()));
    ASSERT_EQ(r.find("elastic_modes")->value, 1.0);
    EXPECT_NEAR(r.rows.front()[r.findColumn("natural_frequency_1_rad_per_s")] / wn, 1.0, 1e-8);
    EXPECT_NEAR(crossingSpeed(r, 1, "mesh.mesh_frequency") / (wn / 20), 1.0, 1e-8);
    EXPECT_NEAR(crossingSpeed(r, 1, "crushing.order_4") / wn, 1.0, 1e-8);
    // Per revolution of a: the mesh 20, the load's order 4 of c is 1.
    const DataTable& t = table(r, "campbell_crossings");
    const std::vector<std::string> names = campbellLineNames(r);
    for (const auto& row : t.rows) {
        const std::string& line = names.at(std::size_t(row[col(t.columnNames, "order")]));
        const double perRev = row[col(t.columnNames, "order_per_rev")];
        if (line == "mesh.mesh_frequency") {
            EXPECT_NEAR(perRev, 20.0, 1e-9);
        }
        if (line == "crushing.order_4") {
            EXPECT_NEAR(perRev, 1.0, 1e-9);
        }
    }
}

// One numbering: the summary's natural_frequency_k is the mode_shapes row
// numbered k; the rigid rotation is mode 0.
TEST(ModeNumbering, LinearizeSummaryAndModeShapesAgree) {
    const AnalysisResult r = run("analysis: linearize");
    const std::vector<double> w = chainFrequencies();
    ASSERT_EQ(r.tableName, "mode_shapes");
    std::size_t rigid = 0;
    for (const auto& row : r.rows) {
        const int mode = int(row[0]);
        if (mode == 0) {
            ++rigid;
            EXPECT_LT(row[1], 1e-3);
            continue;
        }
        const ResultScalar* rad = r.find("natural_frequency_" + std::to_string(mode));
        const ResultScalar* hz = r.find("natural_frequency_" + std::to_string(mode) + "_hz");
        ASSERT_NE(rad, nullptr);
        ASSERT_NE(hz, nullptr);
        EXPECT_EQ(rad->unit, "rad/s");
        EXPECT_EQ(hz->unit, "Hz");
        EXPECT_NEAR(row[1], hz->value, 1e-12 * hz->value);
        EXPECT_NEAR(rad->value / w[mode - 1], 1.0, 1e-8);
    }
    EXPECT_EQ(rigid, 1u);
    EXPECT_EQ(r.rows.size(), 3u);
    // The modes table numbers them alike.
    const DataTable& modes = table(r, "modes");
    EXPECT_EQ(modes.rows[0][0], 0.0);
    EXPECT_EQ(modes.rows[1][0], 1.0);
    EXPECT_EQ(modes.rows[2][0], 2.0);
    // And the plot's titles.
    const auto bars = modeShapeBars(r);
    ASSERT_EQ(bars.size(), 3u);
    EXPECT_NE(bars[0].title.find("mode 0 (rigid body)"), std::string::npos) << bars[0].title;
    EXPECT_EQ(bars[1].title.rfind("mode 1:", 0), 0u) << bars[1].title;
}

TEST(ResonanceMap, ReportsEveryCoupling) {
    const AnalysisResult r = run("analysis: resonance_map, load: crushing, speed_min: 40 rad/s, speed_max: 210 rad/s, "
                                 "points: 200, threshold: 1.3");
    for (const std::string name : {"shaft1.torque", "shaft2.torque"}) {
        EXPECT_NE(r.findColumn(name + ".dynamic_factor"), std::string::npos) << name;
        for (int k = 1; k <= 4; ++k)
            EXPECT_NE(r.findColumn(name + ".dynamic_factor_k" + std::to_string(k)), std::string::npos) << name;
        ASSERT_NE(r.find(name + ".avoid_bands"), nullptr) << name;
        ASSERT_NE(r.find(name + ".peak_dynamic_factor"), nullptr) << name;
        // The peak always comes with its band or a note that there is none.
        const bool band = r.find(name + ".peak_band_from") != nullptr;
        bool note = false;
        for (const auto& n : r.notes) note = note || n.rfind(name + ": peak dynamic factor", 0) == 0;
        EXPECT_TRUE(note) << name;
        if (r.find(name + ".peak_dynamic_factor")->value > 1.3) {
            EXPECT_TRUE(band) << name;
            EXPECT_LE(r.find(name + ".peak_band_from")->value, r.find(name + ".peak_speed")->value);
            EXPECT_GE(r.find(name + ".peak_band_to")->value, r.find(name + ".peak_speed")->value);
        }
    }
    // Both couplings pass mode 1's resonance at Ω = ω_1/4 (order 4) with a
    // factor above the threshold: each has its own bands.
    EXPECT_GE(r.find("shaft1.torque.avoid_bands")->value, 1.0);
    EXPECT_GE(r.find("shaft2.torque.avoid_bands")->value, 1.0);
}

}  // namespace
}  // namespace milldyn
