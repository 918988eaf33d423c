#include "plugins/motors/Starter.h"

#include "plugins/scene/Format.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace milldyn {
namespace {

[[noreturn]] void badParameter(const std::string& name, double value, const std::string& rule) {
    throw std::invalid_argument("InductionMotor starter: " + name + " = " + std::to_string(value) +
                                " is invalid: " + rule);
}

double ramp(double from, double time, double rampTime) {
    return from + (1 - from) * std::min(std::max(time, 0.0) / rampTime, 1.0);
}

}  // namespace

Starter::Starter(const StarterParams& p) : m_params(p) {
    using K = StarterParams::Kind;
    if (!p.switchTimes.empty() && !p.switchSpeeds.empty())
        badParameter("switch_speeds", p.switchSpeeds.front(), "give switch_times or switch_speeds, not both");
    for (std::size_t i = 0; i < p.switchTimes.size(); ++i)
        if (!(std::isfinite(p.switchTimes[i]) && p.switchTimes[i] > 0) ||
            (i > 0 && !(p.switchTimes[i] > p.switchTimes[i - 1])))
            badParameter("switch_times", p.switchTimes[i], "must be finite, > 0 and increasing");
    for (std::size_t i = 0; i < p.switchSpeeds.size(); ++i)
        if (!(std::isfinite(p.switchSpeeds[i]) && p.switchSpeeds[i] > 0) ||
            (i > 0 && !(p.switchSpeeds[i] > p.switchSpeeds[i - 1])))
            badParameter("switch_speeds", p.switchSpeeds[i], "must be finite, > 0 and increasing");
    const std::size_t switches = p.switchTimes.size() + p.switchSpeeds.size();
    if (p.kind == K::StarDelta && switches != 1)
        badParameter("switch_times", static_cast<double>(switches), "star-delta switches once");
    if (p.kind == K::RotorResistance) {
        if (p.resistanceRatios.empty() || switches != p.resistanceRatios.size())
            badParameter("resistance_ratios", static_cast<double>(p.resistanceRatios.size()),
                         "give one ratio per switch (and at least one)");
        for (std::size_t i = 0; i < p.resistanceRatios.size(); ++i)
            if (!(std::isfinite(p.resistanceRatios[i]) && p.resistanceRatios[i] > 1) ||
                (i > 0 && !(p.resistanceRatios[i] < p.resistanceRatios[i - 1])))
                badParameter("resistance_ratios", p.resistanceRatios[i], "must be finite, > 1 and decreasing");
    }
    if ((p.kind == K::SoftStart || p.kind == K::FrequencyConverter || p.kind == K::LiquidResistance) &&
        !(std::isfinite(p.rampTime) && p.rampTime > 0))
        badParameter("ramp_time", p.rampTime, "must be finite and > 0");
    if (!(p.initialVoltage > 0 && p.initialVoltage <= 1)) badParameter("initial_voltage", p.initialVoltage, "must lie in (0, 1]");
    if (!(p.initialFrequency >= 0 && p.initialFrequency < 1))
        badParameter("initial_frequency", p.initialFrequency, "must lie in [0, 1)");
    if (!(std::isfinite(p.initialResistanceRatio) && p.initialResistanceRatio >= 1))
        badParameter("initial_resistance_ratio", p.initialResistanceRatio, "must be finite and >= 1");
    if (!(p.torqueLimit > 0)) badParameter("torque_limit", p.torqueLimit, "must be > 0");
    if (!(p.currentLimit > 0)) badParameter("current_limit", p.currentLimit, "must be > 0");
    if (std::isfinite(p.currentLimit) && p.kind != K::FrequencyConverter)
        badParameter("current_limit", p.currentLimit, "only a frequency converter limits the current");
}

int Starter::switchCount() const {
    return static_cast<int>(m_params.switchTimes.size() + m_params.switchSpeeds.size());
}

SupplyState Starter::supply(double t, int step) const {
    using K = StarterParams::Kind;
    SupplyState s;
    switch (m_params.kind) {
        case K::DirectOnLine: break;
        case K::StarDelta: s.connection = step == 0 ? 1.0 / 3.0 : 1.0; break;
        case K::SoftStart: s.voltage = ramp(m_params.initialVoltage, t, m_params.rampTime); break;
        case K::FrequencyConverter:
            s.frequency = ramp(m_params.initialFrequency, t, m_params.rampTime);
            s.torqueLimit = m_params.torqueLimit;
            break;
        case K::RotorResistance:
            s.resistance = step < static_cast<int>(m_params.resistanceRatios.size())
                               ? m_params.resistanceRatios[static_cast<std::size_t>(step)]
                               : 1.0;
            break;
        case K::LiquidResistance: s.resistance = ramp(m_params.initialResistanceRatio, t, m_params.rampTime); break;
    }
    return s;
}

StartSequenceState Starter::progress(double t, int step, bool ended, double frequency, bool rampHeld,
                                     bool heldByCurrent) const {
    using K = StarterParams::Kind;
    const StarterParams& p = m_params;
    StartSequenceState q;
    // Ended for good (a converter still holding below rated frequency is not).
    if (ended && frequency >= 1) {
        q.text = kindName(p.kind) + " starter ended (the run started from steady running)";
        return q;
    }
    const double rampDone = p.rampTime > 0 ? std::min(std::max(t, 0.0) / p.rampTime, 1.0) : 1.0;
    const auto rampText = [&] {
        return formatNumber(100 * rampDone, 3) + " % of its " + formatNumber(p.rampTime) + " s ramp";
    };
    // The pending switch of a stepped starter, by time or by the shaft's speed.
    const auto nextSwitch = [&]() -> std::string {
        const std::size_t i = static_cast<std::size_t>(step);
        if (switchesBySpeed())
            return i < p.switchSpeeds.size()
                       ? "waits for the shaft to reach " + formatNumber(p.switchSpeeds[i]) + " rad/s"
                       : "";
        return i < p.switchTimes.size() ? "switches at " + formatNumber(p.switchTimes[i]) + " s" : "";
    };
    switch (p.kind) {
        case K::DirectOnLine: q.text = "direct on line"; break;
        case K::StarDelta:
            q.finished = step >= 1;
            q.waitsOnShaft = !q.finished && switchesBySpeed();
            q.text = q.finished ? "star-delta starter switched to delta"
                                : "star-delta starter still in star (torque / 3); it " + nextSwitch();
            break;
        case K::SoftStart:
            q.finished = rampDone >= 1;
            q.text = q.finished ? "soft start at full voltage since " + formatNumber(p.rampTime) + " s"
                                : "soft start at V = " + formatNumber(ramp(p.initialVoltage, t, p.rampTime), 4) +
                                      " of rated, " + rampText();
            break;
        case K::FrequencyConverter:
            q.finished = frequency >= 1;
            q.waitsOnShaft = !q.finished && rampHeld;
            q.text = q.finished ? "frequency converter at rated frequency"
                                : "frequency converter at f = " + formatNumber(frequency, 4) + " of rated, " +
                                      (rampHeld ? std::string("its ramp held at the ") +
                                                      (heldByCurrent ? "current" : "torque") + " limit"
                                                : "ramping (" + formatNumber(rampRate() * 100, 4) + " % of rated per s)");
            break;
        case K::RotorResistance: {
            const int steps = static_cast<int>(p.resistanceRatios.size());
            q.finished = step >= steps;
            q.waitsOnShaft = !q.finished && switchesBySpeed();
            q.text = q.finished ? "rotor-resistance starter: rotor short-circuited"
                                : "rotor-resistance starter in step " + std::to_string(step + 1) + " of " +
                                      std::to_string(steps) + " (R/R_rotor = " +
                                      formatNumber(p.resistanceRatios[static_cast<std::size_t>(std::max(step, 0))], 4) +
                                      "); it " + nextSwitch();
            break;
        }
        case K::LiquidResistance:
            q.finished = rampDone >= 1;
            q.text = q.finished ? "liquid-resistance starter shorted since " + formatNumber(p.rampTime) + " s"
                                : "liquid-resistance starter at R/R_rotor = " +
                                      formatNumber(ramp(p.initialResistanceRatio, t, p.rampTime), 4) + ", " + rampText();
            break;
    }
    return q;
}

double Starter::rampFrequency(double t, double from, double fromTime) const {
    return std::min(1.0, from + rampRate() * std::max(t - fromTime, 0.0));
}

std::string Starter::kindName(StarterParams::Kind kind) {
    using K = StarterParams::Kind;
    switch (kind) {
        case K::DirectOnLine: return "direct_on_line";
        case K::StarDelta: return "star_delta";
        case K::SoftStart: return "soft_start";
        case K::FrequencyConverter: return "frequency_converter";
        case K::RotorResistance: return "rotor_resistance";
        case K::LiquidResistance: return "liquid_resistance";
    }
    return "";
}

}  // namespace milldyn
