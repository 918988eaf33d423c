#include "driver/Units.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace milldyn::units {
namespace {

// Relative tolerance for conversions: a handful of double roundings.
constexpr double kRelTol = 1e-12;
constexpr double kPi = 3.14159265358979323846;

void expectNearRel(double expected, double actual) {
    EXPECT_NEAR(expected, actual, kRelTol * std::abs(expected)) << "expected " << expected << ", got " << actual;
}

// Returns the UnitError thrown by f, failing the test if none (or another type) is thrown.
template <class F>
UnitError captureUnitError(F f) {
    try {
        f();
    } catch (const UnitError& e) {
        return e;
    } catch (const std::exception& e) {
        ADD_FAILURE() << "expected UnitError, got std::exception: " << e.what();
        return UnitError("<wrong exception>", SIZE_MAX);
    }
    ADD_FAILURE() << "expected UnitError, nothing thrown";
    return UnitError("<nothing thrown>", SIZE_MAX);
}

const Dimension kDimless{};
const Dimension kRadPerS{0, 0, -1, 1};
const Dimension kTorque{1, 2, -2, 0};
const Dimension kTorsionalStiffness{1, 2, -2, -1};
const Dimension kTorsionalDamping{1, 2, -1, -1};
const Dimension kInertia{1, 2, 0, 0};
const Dimension kPower{1, 2, -3, 0};

// ---- the examples of the model-file format, against hand computations ----

TEST(UnitsConversion, RpmConvertsToRadPerSecond) {
    // 1446 rpm = 1446 * 2*pi / 60 rad/s = 151.42476590302803 rad/s
    const Quantity q = parseQuantity("1446 rpm");
    expectNearRel(151.42476590302803, q.value);
    EXPECT_EQ(kRadPerS, q.dim);
    expectNearRel(1446.0 * 2.0 * kPi / 60.0, toSI("1446 rpm", "rad/s"));
}

TEST(UnitsConversion, InertiaWithExponentNotationStaysInKgM2) {
    // 190.7e-4 kg*m^2 = 0.01907 kg*m^2 (kg and m are SI already)
    const Quantity q = parseQuantity("190.7e-4 kg*m^2");
    expectNearRel(0.01907, q.value);
    EXPECT_EQ(kInertia, q.dim);
    expectNearRel(0.01907, toSI("190.7e-4 kg*m^2", "kg*m^2"));
}

TEST(UnitsConversion, TorsionalStiffnessKeepsPerRadian) {
    // 537 N*m/rad = 537 kg*m^2/s^2/rad (all factors 1)
    const Quantity q = parseQuantity("537 N*m/rad");
    expectNearRel(537.0, q.value);
    EXPECT_EQ(kTorsionalStiffness, q.dim);
    expectNearRel(537.0, toSI("537 N*m/rad", "N*m/rad"));
    // 1e5 N*m/rad = 100000 N*m/rad
    expectNearRel(1e5, toSI("1e5 N*m/rad", "N*m/rad"));
}

TEST(UnitsConversion, DegreesConvertToRadians) {
    // 40 deg = 40 * pi/180 rad = 0.6981317007977318 rad
    expectNearRel(0.6981317007977318, toSI("40 deg", "rad"));
    // -40 deg: the sign is kept
    expectNearRel(-0.6981317007977318, toSI("-40 deg", "rad"));
}

TEST(UnitsConversion, MassFlowPerHourConvertsToPerSecond) {
    // 130 kg/h = 130 / 3600 kg/s = 0.036111... kg/s
    expectNearRel(0.03611111111111111, toSI("130 kg/h", "kg/s"));
}

TEST(UnitsConversion, TorsionalDampingDividesOnlyTheLastFactor) {
    // 6.428 N*m*s/rad = 6.428 kg*m^2/s/rad ('/' applies to rad only)
    const Quantity q = parseQuantity("6.428 N*m*s/rad");
    expectNearRel(6.428, q.value);
    EXPECT_EQ(kTorsionalDamping, q.dim);
    expectNearRel(6.428, toSI("6.428 N*m*s/rad", "kg*m^2/s/rad"));
}

TEST(UnitsConversion, MillimetresConvertToMetres) {
    // 200 mm = 200 * 1e-3 m = 0.2 m
    expectNearRel(0.2, toSI("200 mm", "m"));
    expectNearRel(0.2, toSI("200mm", "m"));  // the space is optional
}

TEST(UnitsConversion, KilowattsConvertToWatts) {
    // 5.5 kW = 5.5 * 1000 W = 5500 W
    const Quantity q = parseQuantity("5.5 kW");
    expectNearRel(5500.0, q.value);
    EXPECT_EQ(kPower, q.dim);
    expectNearRel(5500.0, toSI("5.5 kW", "W"));
}

TEST(UnitsConversion, BareNumberIsDimensionless) {
    // 2.5e-3 = 0.0025, no unit
    const Quantity q = parseQuantity("2.5e-3");
    expectNearRel(0.0025, q.value);
    EXPECT_EQ(kDimless, q.dim);
    expectNearRel(0.0025, toSI("2.5e-3", "1"));
}

TEST(UnitsConversion, SecondsStaySeconds) {
    // 0.6 s = 0.6 s
    expectNearRel(0.6, toSI("0.6 s", "s"));
}

TEST(UnitsConversion, OtherTableUnitsHaveTheirSiFactors) {
    expectNearRel(1.5e-3, toSI("1.5 g", "kg"));           // 1.5 * 1e-3
    expectNearRel(2000.0, toSI("2 t", "kg"));             // 2 * 1e3
    expectNearRel(0.05, toSI("5 cm", "m"));               // 5 * 1e-2
    expectNearRel(3e-6, toSI("3 um", "m"));               // 3 * 1e-6
    expectNearRel(4000.0, toSI("4 km", "m"));             // 4 * 1e3
    expectNearRel(0.25, toSI("250 ms", "s"));             // 250 * 1e-3
    expectNearRel(120.0, toSI("2 min", "s"));             // 2 * 60
    expectNearRel(5400.0, toSI("1.5 h", "s"));            // 1.5 * 3600
    expectNearRel(6.0 * kPi, toSI("3 rev", "rad"));       // 3 * 2*pi
    expectNearRel(50.0, toSI("50 Hz", "1/s"));            // Hz = 1/s
    expectNearRel(3e6, toSI("3 MN", "N"));                // 3 * 1e6
    expectNearRel(7e3, toSI("7 kN*m", "N*m"));            // 7 * 1e3
    expectNearRel(2.1e11, toSI("210 GPa", "Pa"));         // 210 * 1e9
    expectNearRel(1.2e6, toSI("1.2 MPa", "N/m^2"));       // Pa = N/m^2
    expectNearRel(1e5, toSI("100 kPa", "kg/m/s^2"));      // 100 * 1e3
    expectNearRel(2e6, toSI("2 MW", "W"));                // 2 * 1e6
    expectNearRel(4e3, toSI("4 kJ", "J"));                // 4 * 1e3
    expectNearRel(0.012, toSI("12 L", "m^3"));            // 12 * 1e-3 m^3
    expectNearRel(0.5, toSI("50 %", "1"));                // 50 * 0.01
    expectNearRel(2.0 * kPi / 60.0, toSI("1 rev/min", "rad/s"));  // 2*pi rad / 60 s
}

TEST(UnitsConversion, SurroundingWhitespaceIsIgnored) {
    expectNearRel(0.2, toSI("  \t200 mm \n", "m"));
    expectNearRel(0.2, toSI(" 0.2 ", "m"));
    expectNearRel(0.2, toSI("200 mm", " m "));
}

TEST(UnitsConversion, StrtodNumberFormsAreAccepted) {
    expectNearRel(0.5, toSI(".5", "1"));
    expectNearRel(5.0, toSI("5.", "1"));
    expectNearRel(5.0, toSI("+5", "1"));
    expectNearRel(1e-3, toSI("1E-3 m", "m"));
    EXPECT_EQ(0.0, toSI("0 rpm", "rad/s"));
}

// ---- dimensions ----

TEST(UnitsDimension, TorqueAndTorsionalStiffnessDiffer) {
    EXPECT_EQ(kTorque, parseUnit("N*m"));
    EXPECT_EQ(kTorsionalStiffness, parseUnit("N*m/rad"));
    EXPECT_NE(parseUnit("N*m"), parseUnit("N*m/rad"));
}

TEST(UnitsDimension, WattHasNoAngleSoTorqueTimesAngularSpeedDiffers) {
    // W = kg*m^2/s^3 (no angle); N*m * rad/s carries one rad more.
    EXPECT_EQ(kPower, parseUnit("W"));
    EXPECT_EQ(parseUnit("W"), parseUnit("N*m/s"));
    EXPECT_EQ(parseUnit("W"), parseUnit("J/s"));
    EXPECT_NE(parseUnit("W"), parseUnit("N*m*rad/s"));
    EXPECT_EQ((Dimension{1, 2, -3, 1, 0}), parseUnit("N*m*rad/s"));
}

TEST(UnitsDimension, HertzIsNotAnAngularSpeed) {
    EXPECT_EQ((Dimension{0, 0, -1, 0, 0}), parseUnit("Hz"));
    EXPECT_NE(parseUnit("Hz"), parseUnit("rad/s"));
    EXPECT_EQ(parseUnit("rpm"), parseUnit("rad/s"));
    EXPECT_EQ(parseUnit("rpm"), parseUnit("rev/min"));
}

TEST(UnitsDimension, SlashAppliesToTheNextFactorOnly) {
    EXPECT_EQ((Dimension{1, -1, -1, 0, 0}), parseUnit("kg/m/s"));
    EXPECT_EQ(kTorsionalDamping, parseUnit("N*m*s/rad"));
}

TEST(UnitsDimension, ReciprocalFormsAgree) {
    EXPECT_EQ(parseUnit("1/s"), parseUnit("s^-1"));
    EXPECT_EQ(parseUnit("1/s"), parseUnit("Hz"));
    EXPECT_EQ(parseUnit("1/(kg*m)"), parseUnit("kg^-1*m^-1"));
    EXPECT_EQ(kDimless, parseUnit("1"));
    EXPECT_EQ(kDimless, parseUnit("%"));
    EXPECT_EQ(kDimless, parseUnit("m/m"));
}

TEST(UnitsDimension, ParenthesesAndGroupExponents) {
    EXPECT_EQ((Dimension{0, 2, -2, 0, 0}), parseUnit("(m/s)^2"));
    EXPECT_EQ((Dimension{1, 0, 1, 0, 0}), parseUnit("kg/(1/s)"));
    EXPECT_EQ(kInertia, parseUnit(" kg * m ^ 2 "));
    expectNearRel(1e-6, toSI("1 mm^2", "m^2"));  // (1e-3)^2
}

TEST(UnitsDimension, ToStringIsCanonical) {
    EXPECT_EQ("kg*m^2/s^2/rad", parseUnit("N*m/rad").toString());
    EXPECT_EQ("rad/s", parseUnit("rpm").toString());
    EXPECT_EQ("1/s", parseUnit("Hz").toString());
    EXPECT_EQ("1", parseUnit("%").toString());
    EXPECT_EQ("kg*m^2/s^3", parseUnit("kW").toString());
    EXPECT_EQ("kg/m/s^2", parseUnit("Pa").toString());
    EXPECT_EQ("A", parseUnit("kA").toString());
    EXPECT_EQ((Dimension{0, 0, 0, 0, 1}), parseUnit("A"));
    EXPECT_EQ(parseUnit("V/A"), parseUnit("ohm"));
    EXPECT_EQ(parseUnit("V*s/A"), parseUnit("H"));
}

TEST(UnitsDimension, ToStringRoundTripsForEveryKnownUnit) {
    const std::vector<std::string> names = knownUnitNames();
    EXPECT_EQ(39u, names.size());  // A, kA, V, kV, ohm, mohm, H, mH: motors
    for (const std::string& name : names) {
        const Dimension d = parseUnit(name);
        EXPECT_EQ(d, parseUnit(d.toString())) << name << " -> " << d.toString();
        EXPECT_NO_THROW(parseQuantity("1 " + name)) << name;
    }
}

// ---- toSI at the model-file boundary ----

TEST(UnitsToSI, BareNumbersPassThroughUnchanged) {
    EXPECT_EQ(151.4, toSI("151.4", "rad/s"));
    EXPECT_EQ(537.0, toSI("537", "N*m/rad"));
    EXPECT_EQ(-2.5, toSI("-2.5", "1"));
}

TEST(UnitsToSI, IncompatibleUnitThrowsWithMessageAndColumn) {
    const UnitError e = captureUnitError([] { toSI("12 N*m", "rad/s"); });
    EXPECT_STREQ("incompatible unit 'N*m': expected a quantity in rad/s", e.what());
    EXPECT_EQ(3u, e.column());
}

TEST(UnitsToSI, TorqueIsRejectedWhereStiffnessIsExpected) {
    const UnitError e = captureUnitError([] { toSI("537 N*m", "N*m/rad"); });
    EXPECT_STREQ("incompatible unit 'N*m': expected a quantity in N*m/rad", e.what());
    EXPECT_EQ(4u, e.column());
}

TEST(UnitsToSI, HertzIsRejectedWhereAngularSpeedIsExpected) {
    const UnitError e = captureUnitError([] { toSI("50 Hz", "rad/s"); });
    EXPECT_STREQ("incompatible unit 'Hz': expected a quantity in rad/s", e.what());
    EXPECT_EQ(3u, e.column());
}

TEST(UnitsToSI, IncompatibleColumnCountsLeadingWhitespace) {
    const UnitError e = captureUnitError([] { toSI("  5.5 kW", "N*m"); });
    EXPECT_STREQ("incompatible unit 'kW': expected a quantity in N*m", e.what());
    EXPECT_EQ(6u, e.column());
}

TEST(UnitsToSI, UnknownUnitThrowsWithNameAndColumn) {
    const UnitError e = captureUnitError([] { toSI("3 xyz", "m"); });
    EXPECT_STREQ("unknown unit 'xyz'", e.what());
    EXPECT_EQ(2u, e.column());
}

TEST(UnitsToSI, UnknownUnitInsideExpressionReportsItsOwnColumn) {
    const UnitError e = captureUnitError([] { toSI("3 N*qq/rad", "N*m/rad"); });
    EXPECT_STREQ("unknown unit 'qq'", e.what());
    EXPECT_EQ(4u, e.column());
}

TEST(UnitsToSI, MisspelledUnitSuggestsNearestName) {
    const UnitError e = captureUnitError([] { toSI("1446 rmp", "rad/s"); });
    EXPECT_STREQ("unknown unit 'rmp' (did you mean 'rpm'?)", e.what());
    EXPECT_EQ(5u, e.column());
}

TEST(UnitsToSI, OtherNearMissesGetSuggestions) {
    EXPECT_STREQ("unknown unit 'KW' (did you mean 'kW'?)", captureUnitError([] { toSI("5 KW", "W"); }).what());
    EXPECT_STREQ("unknown unit 'hz' (did you mean 'Hz'?)", captureUnitError([] { toSI("5 hz", "1/s"); }).what());
    EXPECT_STREQ("unknown unit 'Nm' (did you mean 'N*m'?)", captureUnitError([] { toSI("5 Nm", "N*m"); }).what());
    EXPECT_STREQ("unknown unit 'degrees' (did you mean 'deg'?)",
                 captureUnitError([] { toSI("5 degrees", "rad"); }).what());
    EXPECT_STREQ("unknown unit 'kPaa' (did you mean 'kPa'?)", captureUnitError([] { toSI("5 kPaa", "Pa"); }).what());
    EXPECT_STREQ("unknown unit 'kgm' (did you mean 'kg*m'?)", captureUnitError([] { toSI("5 kgm", "kg*m"); }).what());
    EXPECT_STREQ("unknown unit 'mmm' (did you mean 'mm'?)", captureUnitError([] { toSI("5 mmm", "m"); }).what());
}

TEST(UnitsToSI, InvalidExpectedUnitIsAProgrammingError) {
    EXPECT_THROW(toSI("1", "furlong"), std::invalid_argument);
    EXPECT_THROW(toSI("1", "rpm"), std::invalid_argument);  // not coherent SI (scale != 1)
    EXPECT_THROW(toSI("1", ""), std::invalid_argument);
}

// ---- malformed input: always UnitError, never a crash ----

TEST(UnitsErrors, GarbageInputsThrowUnitError) {
    const std::vector<std::string> garbage = {
        "",        "   ",      "kg",      "rpm",     "1e999 m", "-1e999",  "1e-999",   "nan",      "-nan",
        "inf",     "+Infinity", "0x1p3",  "0X10",    "1 m^",    "1 m^-",   "1 m^2.5",  "1 (m",     "1 m))",
        "1 m)",    "1 ()",      "1 m^99", "1 m^-13", "1 m m",   "1 m*",    "1 m/",     "1 *m",     "1 /s",
        "1 2",     "1 1",       "1 1*m",  "1 2/s",   "1,5 m",   "1.5.3",   "1 m2",     "1 m^ 1 2", "- 5",
        "1 m^+",   "1e",        "1 e5",   "1 \x01",  "1 \xC2\xB5m", "1 (m/s)^13", "1e308 km", "1 km^12*km^12*km^12",
        "1 (((m^12)^12)^12)", "1 %%",
    };
    for (const std::string& text : garbage) {
        EXPECT_THROW(parseQuantity(text), UnitError) << "input: '" << text << "'";
        EXPECT_THROW(toSI(text, "m"), UnitError) << "input: '" << text << "'";
    }
}

TEST(UnitsErrors, SpecificMessagesAndColumns) {
    struct Case {
        const char* text;
        const char* message;
        std::size_t column;
    };
    const Case cases[] = {
        {"", "empty value: expected a number", 0},
        {"kg", "missing number: a value must start with a number, e.g. '2 kg'", 0},
        {"1e999 m", "number '1e999' is out of range", 0},
        {"nan", "'nan' is not accepted: the number must be finite", 0},
        {"0x10", "hexadecimal numbers are not accepted", 0},
        {"1 m^", "expected an integer exponent after '^'", 4},
        {"1 (m", "unbalanced '(': missing ')'", 2},
        {"1 m))", "unexpected ')' without matching '('", 3},
        {"1 m^99", "exponent out of range (at most 12 in magnitude)", 4},
        {"1 m m", "expected '*' or '/' between units", 4},
        {"1,5 m", "unexpected ','; use '.' as the decimal separator", 1},
        {"1 1", "unexpected number after the value; '1' is not a unit here", 2},
        {"1e308 km", "value out of range after conversion to SI", 0},
        {"1e", "malformed number: 'e' must be followed by an integer exponent", 1},
        {"2.5E+ m", "malformed number: 'E' must be followed by an integer exponent", 3},
        {"1 \xC2\xB5m", "unexpected micro sign; write 'um' for micrometres", 2},
    };
    for (const Case& c : cases) {
        const UnitError e = captureUnitError([&] { parseQuantity(c.text); });
        EXPECT_STREQ(c.message, e.what()) << "input: '" << c.text << "'";
        EXPECT_EQ(c.column, e.column()) << "input: '" << c.text << "'";
    }
}

TEST(UnitsErrors, ParenthesesUpToTheDepthCapAreAccepted) {
    const std::string ok = "1 " + std::string(kMaxParenDepth, '(') + "m" + std::string(kMaxParenDepth, ')');
    expectNearRel(1.0, toSI(ok, "m"));
}

TEST(UnitsErrors, DeeplyNestedParenthesesThrowInsteadOfRecursing) {
    const int depth = kMaxParenDepth + 1;
    const std::string tooDeep = "1 " + std::string(depth, '(') + "m" + std::string(depth, ')');
    const UnitError e = captureUnitError([&] { parseQuantity(tooDeep); });
    EXPECT_STREQ("parentheses nested too deeply (at most 16)", e.what());
    EXPECT_EQ(2u + kMaxParenDepth, e.column());

    const std::string huge = "1 " + std::string(1000000, '(');
    EXPECT_THROW(parseQuantity(huge), UnitError);
    EXPECT_THROW(parseUnit(std::string(1000000, '(')), UnitError);
}

TEST(UnitsErrors, ParseUnitRejectsMalformedUnits) {
    for (const char* unit : {"", " ", "*", "m*", "/s", "2/s", "1*m", "m^x", "(", ")", "m^13", "foo"}) {
        EXPECT_THROW(parseUnit(unit), UnitError) << "unit: '" << unit << "'";
    }
}

TEST(UnitsErrors, EmbeddedNulBytesAreRejected) {
    const std::string withNul("1 m\0m", 5);
    EXPECT_THROW(parseQuantity(withNul), UnitError);
    EXPECT_THROW(parseUnit(std::string_view("m\0", 2)), UnitError);
}

// Cheap deterministic fuzzing: random strings over the grammar's alphabet
// must either parse or throw UnitError (run under ASan/UBSan to check for UB).
TEST(UnitsErrors, RandomInputsEitherParseOrThrowUnitError) {
    const std::string alphabet = "0123456789.eE+-*/^() %kgmsradpHzNWJLPaMGtuhvx,\t";
    std::uint64_t state = 0x9E3779B97F4A7C15ull;
    auto next = [&state] {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        return state;
    };
    int parsed = 0;
    constexpr int kIterations = 20000;
    for (int i = 0; i < kIterations; ++i) {
        std::string text;
        const std::size_t len = next() % 24;
        for (std::size_t j = 0; j < len; ++j) text += alphabet[next() % alphabet.size()];
        if (i % 3 == 0) text = std::to_string(next() % 1000) + " " + text;
        try {
            parseQuantity(text);
            ++parsed;
        } catch (const UnitError&) {
        }
        try {
            toSI(text, "N*m/rad");
        } catch (const UnitError&) {
        }
    }
    EXPECT_GT(parsed, 0);
}

}  // namespace
}  // namespace milldyn::units

namespace milldyn::units {
namespace {

TEST(UnitsRequired, BareNumberOnADimensionalUnitIsRefusedWithTheUsualUnits) {
    try {
        toSIRequiringUnit("1490", "rad/s");
        ADD_FAILURE() << "a bare 1490 was accepted as rad/s";
    } catch (const UnitError& e) {
        EXPECT_EQ(std::string(e.what()), "a bare number needs a unit here (did you mean 1490 rpm or 1490 rad/s?)");
        EXPECT_EQ(e.column(), 4u);  // just after the number, where the unit goes
    }
    EXPECT_THROW(toSIRequiringUnit(" 2.5e-3 ", "m"), UnitError);
    EXPECT_THROW(toSIRequiringUnit("-40", "rad"), UnitError);
}

TEST(UnitsRequired, ZeroDimensionlessAndWrittenUnitsPass) {
    EXPECT_EQ(toSIRequiringUnit("0", "N*m/rad"), 0.0);
    EXPECT_EQ(toSIRequiringUnit("0.0", "m"), 0.0);
    EXPECT_EQ(toSIRequiringUnit("1e-7", "1"), 1e-7);
    EXPECT_NEAR(toSIRequiringUnit("1490 rpm", "rad/s"), 1490 * 2 * 3.14159265358979323846 / 60, 1e-12);
    EXPECT_EQ(toSIRequiringUnit("5 mm", "m"), 5e-3);
}

TEST(UnitsRequired, SuggestionsEndWithTheSiUnit) {
    EXPECT_EQ(suggestedUnits("rad/s"), (std::vector<std::string>{"rpm", "rad/s"}));
    EXPECT_EQ(suggestedUnits("kg*m^2"), (std::vector<std::string>{"kg*m^2"}));
    EXPECT_EQ(suggestedUnits("kg*m^2/s^3"), (std::vector<std::string>{"kW", "kg*m^2/s^3"}));
}

}  // namespace
}  // namespace milldyn::units
