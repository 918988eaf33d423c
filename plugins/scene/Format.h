#pragma once
// formatNumber: a number for a message or a label, in the shortest form at
// a given number of significant digits (iostream's default notation).

#include <sstream>
#include <string>

namespace milldyn {

inline std::string formatNumber(double value, int significantDigits = 6) {
    if (value == 0) value = 0;  // "0", not "-0"
    std::ostringstream s;
    s.precision(significantDigits);
    s << value;
    return s.str();
}

}  // namespace milldyn
