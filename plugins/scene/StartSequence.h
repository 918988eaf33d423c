#pragma once
// StartSequenceState: where a starting sequence stands — a motor's starter
// (its ramp, its resistance steps, its star–delta switch) or a clutch's
// engagement. Plain C++ so that plain parts (Starter) can say it too.

#include <string>

namespace milldyn {

/// A start is complete only once every sequence has finished; the start
/// verdict (driver/analyses/Transient.cpp) reads these at its window's end.
struct StartSequenceState {
    bool finished = true;       ///< at its last step: full supply, rotor short-circuited, clutch fully engaged
    bool waitsOnShaft = false;  ///< advances only when its shaft speeds up (a switch at a speed, a converter
                                ///< ramp held at its torque limit), not with time alone
    std::string text;           ///< "liquid_resistance starter at R/R_rotor = 3.2, 40 % of its 20 s ramp"
};

}  // namespace milldyn
