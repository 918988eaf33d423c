#include "driver/Units.h"

#include <algorithm>
#include <array>
#include <utility>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <system_error>

namespace milldyn::units {

namespace {

constexpr double kPi = 3.14159265358979323846;

struct UnitDef {
    const char* name;
    double scale;  // SI value of one unit
    Dimension dim;
};

// Dimension shorthands {kg, m, s, rad, A}.
constexpr Dimension kNone{0, 0, 0, 0, 0};
constexpr Dimension kMass{1, 0, 0, 0, 0};
constexpr Dimension kLength{0, 1, 0, 0, 0};
constexpr Dimension kTime{0, 0, 1, 0, 0};
constexpr Dimension kAngle{0, 0, 0, 1, 0};
constexpr Dimension kAngularSpeed{0, 0, -1, 1, 0};
constexpr Dimension kFrequency{0, 0, -1, 0, 0};
constexpr Dimension kForce{1, 1, -2, 0, 0};
constexpr Dimension kPressure{1, -1, -2, 0, 0};
constexpr Dimension kPower{1, 2, -3, 0, 0};
constexpr Dimension kEnergy{1, 2, -2, 0, 0};
constexpr Dimension kVolume{0, 3, 0, 0, 0};
constexpr Dimension kCurrent{0, 0, 0, 0, 1};
constexpr Dimension kVoltage{1, 2, -3, 0, -1};
constexpr Dimension kResistance{1, 2, -3, 0, -2};
constexpr Dimension kInductance{1, 2, -2, 0, -2};

const UnitDef kUnits[] = {
    {"kg", 1.0, kMass},
    {"g", 1e-3, kMass},
    {"t", 1e3, kMass},
    {"m", 1.0, kLength},
    {"mm", 1e-3, kLength},
    {"cm", 1e-2, kLength},
    {"um", 1e-6, kLength},
    {"km", 1e3, kLength},
    {"s", 1.0, kTime},
    {"ms", 1e-3, kTime},
    {"min", 60.0, kTime},
    {"h", 3600.0, kTime},
    {"rad", 1.0, kAngle},
    {"deg", kPi / 180.0, kAngle},
    {"rev", 2.0 * kPi, kAngle},
    {"rpm", 2.0 * kPi / 60.0, kAngularSpeed},
    {"Hz", 1.0, kFrequency},
    {"N", 1.0, kForce},
    {"kN", 1e3, kForce},
    {"MN", 1e6, kForce},
    {"Pa", 1.0, kPressure},
    {"kPa", 1e3, kPressure},
    {"MPa", 1e6, kPressure},
    {"GPa", 1e9, kPressure},
    {"W", 1.0, kPower},
    {"kW", 1e3, kPower},
    {"MW", 1e6, kPower},
    {"J", 1.0, kEnergy},
    {"kJ", 1e3, kEnergy},
    {"L", 1e-3, kVolume},
    {"%", 0.01, kNone},
    {"A", 1.0, kCurrent},
    {"kA", 1e3, kCurrent},
    {"V", 1.0, kVoltage},
    {"kV", 1e3, kVoltage},
    {"ohm", 1.0, kResistance},
    {"mohm", 1e-3, kResistance},
    {"H", 1.0, kInductance},
    {"mH", 1e-3, kInductance},
};

// Common spellings that are not units here, with the unit to suggest.
struct Hint {
    const char* spelling;  // compared case-insensitively
    const char* suggestion;
};
constexpr std::array<Hint, 17> kHints{{
    {"Nm", "N*m"},           {"kNm", "kN*m"},     {"sec", "s"},
    {"secs", "s"},           {"second", "s"},     {"seconds", "s"},
    {"hr", "h"},             {"hour", "h"},       {"hours", "h"},
    {"degree", "deg"},       {"degrees", "deg"},  {"radian", "rad"},
    {"radians", "rad"},      {"rps", "rev/s"},    {"tonne", "t"},
    {"meter", "m"},          {"kgm", "kg*m"},
}};

const UnitDef* findUnit(std::string_view name) {
    for (const UnitDef& u : kUnits) {
        if (name == u.name) return &u;
    }
    return nullptr;
}

char lower(char c) {
    return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
}

bool equalsIgnoreCase(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (lower(a[i]) != lower(b[i])) return false;
    }
    return true;
}

// Optimal-string-alignment distance in half-edits: a substitution that only
// changes letter case costs 1, every other edit (insert, delete, substitute,
// swap of two neighbours) costs 2. Inputs are short (unit names).
std::size_t editCost(std::string_view a, std::string_view b) {
    const std::size_t n = a.size(), m = b.size();
    std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1, 0));
    for (std::size_t i = 0; i <= n; ++i) d[i][0] = 2 * i;
    for (std::size_t j = 0; j <= m; ++j) d[0][j] = 2 * j;
    for (std::size_t i = 1; i <= n; ++i) {
        for (std::size_t j = 1; j <= m; ++j) {
            std::size_t sub = 0;
            if (a[i - 1] != b[j - 1]) sub = (lower(a[i - 1]) == lower(b[j - 1])) ? 1 : 2;
            std::size_t best = std::min({d[i - 1][j] + 2, d[i][j - 1] + 2, d[i - 1][j - 1] + sub});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
                best = std::min(best, d[i - 2][j - 2] + 2);
            }
            d[i][j] = best;
        }
    }
    return d[n][m];
}

std::string suggestionFor(std::string_view name) {
    if (name.size() > 32) return {};  // nothing sensible to suggest; bound the work
    for (const Hint& h : kHints) {
        if (equalsIgnoreCase(name, h.spelling)) return h.suggestion;
    }
    // One edit allowed for names of 2..4 characters, two for longer ones;
    // a single character only gets a case correction ("M" -> "m").
    std::size_t allowed = 1;
    if (name.size() >= 2) allowed = 2;
    if (name.size() >= 5) allowed = 4;
    std::size_t bestCost = std::numeric_limits<std::size_t>::max();
    const char* best = nullptr;
    for (const UnitDef& u : kUnits) {
        const std::size_t cost = editCost(name, u.name);
        if (cost < bestCost) {
            bestCost = cost;
            best = u.name;
        }
    }
    if (best != nullptr && bestCost <= allowed) return best;
    return {};
}

// Printable rendering of one character for error messages.
std::string describeChar(char c) {
    const auto uc = static_cast<unsigned char>(c);
    if (uc >= 0x20 && uc < 0x7f) return std::string("'") + c + "'";
    char buf[8];
    std::snprintf(buf, sizeof buf, "\\x%02X", static_cast<unsigned>(uc));
    return std::string("byte ") + buf;
}

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }
bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isLetter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }

struct Term {
    double scale = 1.0;
    Dimension dim{};
};

// acc *= t^power, with overflow and range checks.
void combine(Term& acc, const Term& t, int power, std::size_t column) {
    const long long exps[5][2] = {{acc.dim.kg, t.dim.kg}, {acc.dim.m, t.dim.m}, {acc.dim.s, t.dim.s},
                                  {acc.dim.rad, t.dim.rad}, {acc.dim.A, t.dim.A}};
    int out[5];
    for (int i = 0; i < 5; ++i) {
        const long long e = exps[i][0] + exps[i][1] * power;
        if (e > kMaxDimensionExponent || e < -kMaxDimensionExponent) {
            throw UnitError("unit exponent too large (at most " + std::to_string(kMaxDimensionExponent) +
                                " per base dimension)",
                            column);
        }
        out[i] = static_cast<int>(e);
    }
    const double scale = acc.scale * std::pow(t.scale, power);
    if (!std::isnormal(scale) || scale < 0.0) {
        throw UnitError("unit scale factor out of range", column);
    }
    acc.scale = scale;
    acc.dim = Dimension{out[0], out[1], out[2], out[3], out[4]};
}

// Recursive-descent parser over text[pos, end); columns are offsets in text.
class UnitParser {
public:
    UnitParser(std::string_view text, std::size_t begin, std::size_t end) : text_(text), pos_(begin), end_(end) {}

    // Parses the whole range as one unit expression.
    Term parseAll() {
        skipSpace();
        if (atEnd()) throw UnitError("empty unit", pos_);
        Term t = parseExpr(0);
        skipSpace();
        if (!atEnd()) {
            const char c = text_[pos_];
            if (c == ')') throw UnitError("unexpected ')' without matching '('", pos_);
            if (isLetter(c) || c == '%' || c == '(') {
                throw UnitError("expected '*' or '/' between units", pos_);
            }
            if (isDigit(c)) throw UnitError("unexpected number in unit; write exponents as 'm^2'", pos_);
            if (c == ',') throw UnitError("unexpected ','; use '.' as the decimal separator", pos_);
            throw UnitError("unexpected " + describeChar(c) + " in unit", pos_);
        }
        return t;
    }

    // True if the expression parsed was exactly the number "1".
    bool wasBareOne() const { return bareOne_; }

private:
    bool atEnd() const { return pos_ >= end_; }
    char peek() const { return atEnd() ? '\0' : text_[pos_]; }
    void skipSpace() {
        while (!atEnd() && isSpace(text_[pos_])) ++pos_;
    }

    Term parseExpr(int depth) {
        skipSpace();
        Term acc;
        const std::size_t exprStart = pos_;
        if (isDigit(peek())) {
            std::size_t p = pos_;
            while (p < end_ && isDigit(text_[p])) ++p;
            if (text_.substr(pos_, p - pos_) != "1") {
                throw UnitError("unexpected number in unit; write exponents as 'm^2'", pos_);
            }
            pos_ = p;
            skipSpace();
            if (atEnd() || peek() == ')') {
                if (depth == 0) bareOne_ = true;
                return acc;  // "1": dimensionless
            }
            if (peek() != '/') throw UnitError("'1' in a unit may only start a reciprocal like '1/s'", exprStart);
        } else {
            const Term f = parseFactor(depth);
            combine(acc, f, 1, exprStart);
        }
        for (;;) {
            skipSpace();
            const char op = peek();
            if (op != '*' && op != '/') break;
            ++pos_;
            skipSpace();
            const std::size_t factorStart = pos_;
            const Term f = parseFactor(depth);
            combine(acc, f, op == '*' ? 1 : -1, factorStart);
        }
        return acc;
    }

    Term parseFactor(int depth) {
        skipSpace();
        const std::size_t start = pos_;
        Term t;
        if (atEnd()) {
            throw UnitError("expected a unit name", pos_);
        }
        const char c = peek();
        if (c == '(') {
            if (depth + 1 > kMaxParenDepth) {
                throw UnitError("parentheses nested too deeply (at most " + std::to_string(kMaxParenDepth) + ")",
                                pos_);
            }
            ++pos_;
            t = parseExpr(depth + 1);
            skipSpace();
            if (peek() != ')') {
                if (atEnd()) throw UnitError("unbalanced '(': missing ')'", start);
                throw UnitError("expected ')' to close '(' at column " + std::to_string(start) + ", found " +
                                    describeChar(peek()),
                                pos_);
            }
            ++pos_;
        } else if (isLetter(c) || c == '%') {
            std::size_t p = pos_;
            if (c == '%') {
                ++p;
            } else {
                while (p < end_ && isLetter(text_[p])) ++p;
            }
            const std::string_view name = text_.substr(pos_, p - pos_);
            const UnitDef* def = findUnit(name);
            if (def == nullptr) {
                std::string msg = "unknown unit '" + std::string(name) + "'";
                const std::string hint = suggestionFor(name);
                if (!hint.empty()) msg += " (did you mean '" + hint + "'?)";
                throw UnitError(msg, pos_);
            }
            t.scale = def->scale;
            t.dim = def->dim;
            pos_ = p;
        } else if (c == ')') {
            throw UnitError("expected a unit name before ')'", pos_);
        } else if (isDigit(c)) {
            throw UnitError("unexpected number in unit; write exponents as 'm^2'", pos_);
        } else if (text_.substr(pos_, 2) == "\xC2\xB5" || text_.substr(pos_, 2) == "\xCE\xBC") {
            throw UnitError("unexpected micro sign; write 'um' for micrometres", pos_);
        } else {
            throw UnitError("expected a unit name, found " + describeChar(c), pos_);
        }

        skipSpace();
        if (peek() == '^') {
            ++pos_;
            skipSpace();
            const int power = parseExponent();
            Term powered;
            combine(powered, t, power, start);
            t = powered;
        }
        return t;
    }

    int parseExponent() {
        const std::size_t start = pos_;
        bool negative = false;
        if (peek() == '+' || peek() == '-') {
            negative = peek() == '-';
            ++pos_;
        }
        if (!isDigit(peek())) throw UnitError("expected an integer exponent after '^'", pos_);
        long long magnitude = 0;
        while (isDigit(peek())) {
            if (magnitude <= 1000) magnitude = magnitude * 10 + (peek() - '0');
            ++pos_;
        }
        if (peek() == '.') throw UnitError("exponent after '^' must be an integer", start);
        if (magnitude > kMaxWrittenExponent) {
            throw UnitError("exponent out of range (at most " + std::to_string(kMaxWrittenExponent) +
                                " in magnitude)",
                            start);
        }
        return static_cast<int>(negative ? -magnitude : magnitude);
    }

    std::string_view text_;
    std::size_t pos_;
    std::size_t end_;
    bool bareOne_ = false;
};

struct Span {
    std::size_t begin = 0, end = 0;
};

Span trimmed(std::string_view text) {
    Span s{0, text.size()};
    while (s.begin < s.end && isSpace(text[s.begin])) ++s.begin;
    while (s.end > s.begin && isSpace(text[s.end - 1])) --s.end;
    return s;
}

struct ParsedValue {
    double number = 0.0;
    std::size_t numberColumn = 0;
    bool hasUnit = false;
    Span unit;  // offsets into text, valid if hasUnit
    Term term;  // valid if hasUnit
};

ParsedValue parseValue(std::string_view text) {
    const Span all = trimmed(text);
    if (all.begin == all.end) throw UnitError("empty value: expected a number", 0);

    std::size_t p = all.begin;
    const std::size_t numStart = p;
    auto at = [&](std::size_t i) { return i < all.end ? text[i] : '\0'; };

    if (at(p) == '+' || at(p) == '-') ++p;
    const std::size_t afterSign = p;
    // Words strtod would read as numbers: reject them explicitly.
    {
        std::size_t w = p;
        while (w < all.end && isLetter(text[w])) ++w;
        const std::string_view word = text.substr(p, w - p);
        if (equalsIgnoreCase(word, "inf") || equalsIgnoreCase(word, "infinity") || equalsIgnoreCase(word, "nan")) {
            throw UnitError("'" + std::string(text.substr(numStart, w - numStart)) +
                                "' is not accepted: the number must be finite",
                            numStart);
        }
    }
    if (at(p) == '0' && (at(p + 1) == 'x' || at(p + 1) == 'X')) {
        throw UnitError("hexadecimal numbers are not accepted", numStart);
    }
    std::size_t mantissaDigits = 0;
    while (isDigit(at(p))) {
        ++p;
        ++mantissaDigits;
    }
    if (at(p) == '.') {
        ++p;
        while (isDigit(at(p))) {
            ++p;
            ++mantissaDigits;
        }
    }
    if (mantissaDigits == 0) {
        const char c = at(afterSign);
        if (isLetter(c) || c == '%' || c == '(') {
            throw UnitError("missing number: a value must start with a number, e.g. '2 kg'", afterSign);
        }
        throw UnitError("expected a number", afterSign);
    }
    if (at(p) == 'e' || at(p) == 'E') {
        std::size_t q = p + 1;
        if (at(q) == '+' || at(q) == '-') ++q;
        if (isDigit(at(q))) {
            while (isDigit(at(q))) ++q;
            p = q;
        } else if (!isLetter(at(p + 1))) {
            // No unit name starts with 'e': "1e", "1e+", "1e-x" are broken exponents.
            throw UnitError("malformed number: '" + std::string(1, at(p)) + "' must be followed by an integer exponent",
                            p);
        }
    }

    ParsedValue out;
    out.numberColumn = numStart;
    {
        const char* first = text.data() + numStart;
        if (*first == '+') ++first;  // from_chars does not take a leading '+'
        const char* last = text.data() + p;
        const auto res = std::from_chars(first, last, out.number, std::chars_format::general);
        if (res.ec == std::errc::result_out_of_range) {
            throw UnitError("number '" + std::string(text.substr(numStart, p - numStart)) + "' is out of range",
                            numStart);
        }
        if (res.ec != std::errc() || res.ptr != last || !std::isfinite(out.number)) {
            throw UnitError("malformed number '" + std::string(text.substr(numStart, p - numStart)) + "'",
                            numStart);
        }
    }

    while (p < all.end && isSpace(text[p])) ++p;
    if (p == all.end) return out;

    if (at(p) == ',') throw UnitError("unexpected ','; use '.' as the decimal separator", p);
    if (at(p) == '.') throw UnitError("malformed number: unexpected '.'", p);

    UnitParser parser(text, p, all.end);
    out.term = parser.parseAll();
    if (parser.wasBareOne()) {
        throw UnitError("unexpected number after the value; '1' is not a unit here", p);
    }
    out.hasUnit = true;
    out.unit = Span{p, all.end};
    return out;
}

double applyScale(const ParsedValue& v) {
    const double value = v.number * v.term.scale;
    if (!std::isfinite(value) || (value == 0.0 && v.number != 0.0)) {
        throw UnitError("value out of range after conversion to SI", v.numberColumn);
    }
    return value;
}

}  // namespace

// ---------------------------------------------------------------------------

bool Dimension::operator==(const Dimension& o) const {
    return kg == o.kg && m == o.m && s == o.s && rad == o.rad && A == o.A;
}

bool Dimension::operator!=(const Dimension& o) const { return !(*this == o); }

std::string Dimension::toString() const {
    const std::pair<const char*, int> parts[5] = {{"kg", kg}, {"m", m}, {"s", s}, {"rad", rad}, {"A", A}};
    std::string num, den;
    for (const auto& [name, e] : parts) {
        if (e > 0) {
            if (!num.empty()) num += '*';
            num += name;
            if (e != 1) num += "^" + std::to_string(e);
        } else if (e < 0) {
            den += '/';
            den += name;
            if (e != -1) den += "^" + std::to_string(-e);
        }
    }
    if (num.empty() && den.empty()) return "1";
    if (num.empty()) num = "1";
    return num + den;
}

UnitError::UnitError(const std::string& msg, std::size_t column) : std::runtime_error(msg), column_(column) {}

std::size_t UnitError::column() const { return column_; }

Dimension parseUnit(std::string_view unit) {
    UnitParser parser(unit, 0, unit.size());
    return parser.parseAll().dim;
}

Quantity parseQuantity(std::string_view text) {
    const ParsedValue v = parseValue(text);
    if (!v.hasUnit) return Quantity{v.number, Dimension{}};
    return Quantity{applyScale(v), v.term.dim};
}

double toSI(std::string_view text, std::string_view expectedUnit) {
    Term expected;
    try {
        UnitParser parser(expectedUnit, 0, expectedUnit.size());
        expected = parser.parseAll();
    } catch (const UnitError& e) {
        throw std::invalid_argument("toSI: invalid expected unit '" + std::string(expectedUnit) + "': " + e.what());
    }
    if (expected.scale != 1.0) {
        throw std::invalid_argument("toSI: expected unit '" + std::string(expectedUnit) +
                                    "' is not a coherent SI unit");
    }

    const ParsedValue v = parseValue(text);
    if (!v.hasUnit) return v.number;  // bare number: already SI
    if (v.term.dim != expected.dim) {
        const Span e = trimmed(expectedUnit);
        throw UnitError("incompatible unit '" + std::string(text.substr(v.unit.begin, v.unit.end - v.unit.begin)) +
                            "': expected a quantity in " + std::string(expectedUnit.substr(e.begin, e.end - e.begin)),
                        v.unit.begin);
    }
    return applyScale(v);
}

std::vector<std::string> suggestedUnits(std::string_view expectedUnit) {
    const Dimension d = parseUnit(expectedUnit);
    // Engineering units first where the SI unit is not what a drawing shows.
    static const std::vector<std::pair<std::string, std::vector<std::string>>> usual = {
        {"rad/s", {"rpm"}}, {"rad", {"deg"}}, {"m", {"mm"}}, {"W", {"kW"}}, {"N", {"kN"}}};
    std::vector<std::string> out;
    for (const auto& [unit, alternatives] : usual)
        if (parseUnit(unit) == d) out = alternatives;
    const Span e = trimmed(expectedUnit);
    out.emplace_back(expectedUnit.substr(e.begin, e.end - e.begin));
    return out;
}

double toSIRequiringUnit(std::string_view text, std::string_view expectedUnit) {
    const double v = toSI(text, expectedUnit);
    if (parseUnit(expectedUnit) == Dimension{}) return v;
    const ParsedValue parsed = parseValue(text);
    if (parsed.hasUnit || parsed.number == 0.0) return v;
    const Span t = trimmed(text);
    const std::string number(text.substr(t.begin, t.end - t.begin));
    std::string hint;
    const std::vector<std::string> units = suggestedUnits(expectedUnit);
    for (std::size_t i = 0; i < units.size(); ++i)
        hint += (i == 0 ? "" : (i + 1 == units.size() ? " or " : ", ")) + number + " " + units[i];
    throw UnitError(std::string(kBareNumberNeedsUnit) + " (did you mean " + hint + "?)", t.end);
}

std::vector<std::string> knownUnitNames() {
    std::vector<std::string> names;
    for (const UnitDef& u : kUnits) {
        names.emplace_back(u.name);
    }
    return names;
}

}  // namespace milldyn::units
