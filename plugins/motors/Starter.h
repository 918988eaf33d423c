#pragma once
// Starter: how an induction motor's supply changes during a start
// (direct-on-line, star–delta, soft start, frequency converter, slip-ring
// rotor resistances). Plain C++ (no Simbody): the InductionMotor element
// holds one and applies the supply state to its TorqueSpeedCurve.

#include "plugins/scene/StartSequence.h"

#include <limits>
#include <string>
#include <vector>

namespace milldyn {

struct StarterParams {
    enum class Kind { DirectOnLine, StarDelta, SoftStart, FrequencyConverter, RotorResistance, LiquidResistance };
    Kind kind = Kind::DirectOnLine;
    /// Star–delta: one switch; rotor_resistance: one per resistance step.
    /// Switch by time [s] (> 0) or by shaft speed [rad/s] (> 0), not both.
    std::vector<double> switchTimes, switchSpeeds;
    /// Rotor_resistance: total rotor resistance over the rotor's own,
    /// R/R_rotor [-] (> 1, decreasing), one per step before its switch;
    /// after the last switch the rotor is short-circuited (1).
    std::vector<double> resistanceRatios;
    /// Soft start: initial voltage over rated [-] in (0, 1].
    double initialVoltage = 0.3;
    /// Frequency converter: initial frequency over rated [-] in [0, 1).
    double initialFrequency = 0.0;
    /// Liquid resistance: initial R/R_rotor [-] (>= 1).
    double initialResistanceRatio = 10.0;
    /// Soft start, converter, liquid resistance: ramp time [s] (> 0).
    double rampTime = 0;
    /// Frequency converter: torque limit |M| <= M_lim [N*m]; +inf: none.
    double torqueLimit = std::numeric_limits<double>::infinity();
    /// Frequency converter: line current limit [A]; +inf: none (the
    /// InductionMotor holds the ramp where the current reaches it).
    double currentLimit = std::numeric_limits<double>::infinity();
};

/// The supply an InductionMotor sees at one instant.
struct SupplyState {
    double voltage = 1;     ///< V/V_rated [-]
    double frequency = 1;   ///< f/f_rated [-] (V/f constant: voltage is then this too, flux unchanged)
    double resistance = 1;  ///< total rotor resistance over the rotor's own [-]
    double connection = 1;  ///< torque factor of the winding connection: 1/3 in star, 1 in delta
    double torqueLimit = std::numeric_limits<double>::infinity();  ///< [N*m]
};

/**
 * The supply state of a start, from the time since switch-on and the
 * starter's step (a discrete state the motor keeps; 0 at switch-on, +1 at
 * every switch, each switch a Scene switch event at its time or at the
 * first step past its speed).
 *
 * <pre>
 *   direct-on-line:      V = 1, f = 1
 *   star–delta:          connection 1/3 before the switch (phase voltage 1/√3: torque ∝ V² → 1/3,
 *                        line current 1/3), 1 after
 *   soft start:          V(t) = V0 + (1 − V0)·min(t/T, 1)          (torque ∝ V², current ∝ V)
 *   frequency converter: f(t) = f0 + (1 − f0)·min(t/T, 1), V/f = const, |M| <= M_lim
 *                        (the ramp alone; the InductionMotor holds it at its
 *                        torque limit, see InductionMotor)
 *   rotor resistance:    R/R_rotor = r_i in step i, 1 after the last switch
 *   liquid resistance:   R/R_rotor = r0 + (1 − r0)·min(t/T, 1)     (electrodes lowered at a constant rate)
 * </pre>
 */
class Starter {
public:
    /// Throws std::invalid_argument naming the parameter.
    explicit Starter(const StarterParams& params);
    SupplyState supply(double time, int step) const;
    /// The supply once the sequence has ended: delta, full voltage, rated
    /// frequency (with the converter's torque limit), rotor short-circuited.
    SupplyState finalSupply() const { return supply(std::numeric_limits<double>::max(), switchCount()); }
    /// supply(time, step), or finalSupply() once the sequence was `ended`
    /// for good (steady running, whatever the time).
    SupplyState supply(double time, int step, bool ended) const { return ended ? finalSupply() : supply(time, step); }
    /// Frequency converter: the ramp generator's output [-] at `time` [s]
    /// when it (re)started from `fromFrequency` at `fromTime`:
    /// min(1, f_r + R·(t − t_r)), R = rampRate().
    double rampFrequency(double time, double fromFrequency, double fromTime) const;
    /// Frequency converter: the ramp's rate R = (1 − f0)/T [1/s].
    double rampRate() const { return (1 - m_params.initialFrequency) / m_params.rampTime; }
    /// Where the starting sequence stands at `time` [s] in step `step` (or
    /// `ended` for good: steady running), with the converter's output
    /// frequency f/f_rated [-], whether its ramp is held and whether the hold
    /// is the current limit's (else the torque limit's): finished once the
    /// supply is full (delta, full voltage, full frequency, rotor
    /// short-circuited); it waits on the shaft while a switch at a speed is
    /// pending or the ramp is held.
    StartSequenceState progress(double time, int step, bool ended, double frequency = 1, bool rampHeld = false,
                                bool heldByCurrent = false) const;
    /// Number of switches (steps after the first).
    int switchCount() const;
    bool switchesBySpeed() const { return !m_params.switchSpeeds.empty(); }
    const StarterParams& params() const { return m_params; }
    static std::string kindName(StarterParams::Kind kind);

private:
    StarterParams m_params;
};

}  // namespace milldyn
