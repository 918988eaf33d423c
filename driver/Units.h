// Unit parser used at the model-file boundary.
//
// Values in model files may carry a unit ("1446 rpm", "190.7e-4 kg*m^2",
// "537 N*m/rad", "5.5 kW", "2.5e-3"). They are converted to SI exactly once,
// here, so the rest of milldyn only ever sees SI numbers.
//
// Dimensions
// ----------
// Four base dimensions are tracked: mass (kg), length (m), time (s) and
// plane angle (rad). Tracking the angle is deliberate: it keeps a torque
// (N*m) apart from a torsional stiffness (N*m/rad), and refuses "50 Hz"
// (1/s, no angle) where an angular speed (rad/s) is expected.
//   rpm = 2*pi/60 rad/s    rev = 2*pi rad    deg = pi/180 rad    Hz = 1/s
//
// Consequence for power: W, kW, MW and J are kg*m^2/s^3 and kg*m^2/s^2
// (no angle), as in SI. A torque times an angular speed, N*m * rad/s, is
// therefore kg*m^2/s^3*rad -- one rad more than W. Code that computes a
// mechanical power from torque and speed must drop the radian explicitly,
// and a key that expects "W" does not accept "N*m*rad/s" (nor vice versa).
// Likewise "N*m" (torque) and "J" (energy) share one dimension.
//
// Unit table (explicit, no general prefix machinery):
//   mass    kg g t(tonne)          length  m mm cm um km      volume  L (1e-3 m^3)
//   time    s ms min h             angle   rad deg rev        speed   rpm
//   freq.   Hz                     force   N kN MN            pressure Pa kPa MPa GPa
//   power   W kW MW                energy  J kJ               ratio   % (0.01)
//
// Grammar (whitespace is allowed around numbers, operators and parentheses
// and is ignored at either end of the text):
//   value    := number [ unit ]
//   number   := decimal number as strtod reads it (sign, digits, '.', e/E
//               exponent); inf, nan, hex and trailing garbage are rejected
//   unit     := [ '1' '/' ] factor ( ('*' | '/') factor )*   |   '1'
//   factor   := ( name | '(' unit ')' ) [ '^' signed-integer ]
// '/' applies to the next factor only: "N*m*s/rad" = N*m*s*rad^-1 and
// "kg/m/s" = kg*m^-1*s^-1. "s^-1" and "1/s" are both accepted.
// A bare '1' unit is only accepted by parseUnit (as "dimensionless"), not
// after a number. Limits keep the parser safe on arbitrary input:
// parentheses nest at most kMaxParenDepth deep, an exponent written after
// '^' is at most kMaxWrittenExponent in magnitude, and a composed dimension
// exponent at most kMaxDimensionExponent.
//
// Every malformed input throws UnitError; nothing else is thrown for user
// text (toSI additionally throws std::invalid_argument for a bad
// expectedUnit, which is a programming error).
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace milldyn::units {

inline constexpr int kMaxParenDepth = 16;
inline constexpr int kMaxWrittenExponent = 12;
inline constexpr int kMaxDimensionExponent = 32;

// Exponents of the base dimensions kg, m, s, rad.
struct Dimension {
    int kg = 0, m = 0, s = 0, rad = 0, A = 0;  // A: electric current (motor currents)

    bool operator==(const Dimension& other) const;
    bool operator!=(const Dimension& other) const;

    // Canonical text: positive exponents first in the order kg, m, s, rad, A,
    // then each negative one as "/name^n", e.g. "kg*m^2/s^2/rad", "rad/s",
    // "1/s"; "1" for dimensionless. parseUnit(d.toString()) == d.
    std::string toString() const;
};

// A parsed value; `value` is in SI (coherent units of `dim`).
struct Quantity {
    double value = 0.0;
    Dimension dim{};
};

class UnitError : public std::runtime_error {
public:
    // column: 0-based offset in the parsed text where the problem is.
    UnitError(const std::string& msg, std::size_t column);
    std::size_t column() const;

private:
    std::size_t column_;
};

// The start of toSIRequiringUnit's refusal of a bare number (a sweep checks
// its grid values for it before any point runs).
inline constexpr char kBareNumberNeedsUnit[] = "a bare number needs a unit here";

// "N*m/rad" -> {kg 1, m 2, s -2, rad -1}. "1" -> dimensionless.
// The scale factor of the unit is discarded. Throws UnitError.
Dimension parseUnit(std::string_view unit);

// "1446 rpm" -> {151.4247..., rad/s}; a bare "2.5" -> {2.5, dimensionless}.
// Throws UnitError.
Quantity parseQuantity(std::string_view text);

// The model-file entry point. `text` is what the user wrote; `expectedUnit`
// is the coherent SI unit the key wants ("rad/s", "N*m/rad", "kg*m^2", "1"
// for dimensionless). Returns the value in that SI unit.
//  - A bare number is taken as already in SI and returned unchanged.
//  - A unit of another dimension throws UnitError
//    "incompatible unit 'N*m': expected a quantity in rad/s"
//    with column() at the start of the unit.
//  - An unknown unit name throws "unknown unit 'xyz'", with
//    " (did you mean 'rpm'?)" appended when a known name is close.
// Throws std::invalid_argument if expectedUnit does not parse or is not a
// coherent SI unit (scale != 1, e.g. "rpm" or "mm").
double toSI(std::string_view text, std::string_view expectedUnit);

// As toSI, but a bare number is refused where expectedUnit has a dimension
// (a bare 0 stays accepted: it is 0 in every unit), with the units people
// write for that quantity as the hint:
//   "a bare number needs a unit here (did you mean 1490 rpm or 1490 rad/s?)".
// A bare number keeps its meaning where expectedUnit is "1".
double toSIRequiringUnit(std::string_view text, std::string_view expectedUnit);

// Units people write for a quantity in the coherent SI unit `expectedUnit`,
// most common first, ending with expectedUnit itself ("rad/s" -> rpm, rad/s).
std::vector<std::string> suggestedUnits(std::string_view expectedUnit);

// The unit names of the table above, in table order.
std::vector<std::string> knownUnitNames();

}  // namespace milldyn::units
