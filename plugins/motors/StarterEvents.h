#pragma once
// addStarterEvents: a motor's starter in a scene — one switch event per
// timed step and the starting sequence the start verdict reads — shared by
// InductionMotor and DqInductionMotor.

#include "plugins/motors/Starter.h"
#include "plugins/scene/Scene.h"

#include <cmath>
#include <string>
#include <vector>

namespace milldyn {

/// Motor: an element with setStarterStep(State&, int),
/// calcStarterProgress(const State&) and finishStarter(State&), owned by
/// Simbody (the scene's force) and alive as long as the scene.
template <class Motor>
void addStarterEvents(Scene& scene, const std::string& name, const StarterParams& starter, const Motor* impl) {
    const std::string starterName = Starter::kindName(starter.kind);
    for (std::size_t i = 0; i < starter.switchTimes.size(); ++i) {
        const int step = static_cast<int>(i) + 1;
        scene.addSwitchEvent({Scene::SwitchEvent::Kind::StarterStep, starter.switchTimes[i],
                              name + " " + starterName + " step " + std::to_string(step),
                              [impl, step](SimTK::State& s) { impl->setStarterStep(s, step); }});
    }
    // A start cut short while the starter is still in circuit is unfinished;
    // steady running is after the sequence.
    if (starter.kind != StarterParams::Kind::DirectOnLine)
        scene.addStartSequence({name, [impl](const SimTK::State& s) { return impl->calcStarterProgress(s); },
                                [impl](SimTK::State& s) { impl->finishStarter(s); }});
}

/// The next switch speed of a starter switched at speeds, as a Simbody
/// event: the witness ω − ω_k (ω the shaft's pin speed, ω_k the speed of
/// the step to come; −1 once every step is taken) rises through zero where
/// the shaft passes ω_k. The integrator localizes the sign change to a
/// window of kWindow s and returns the state at the window's start
/// (Integrator::ReachedEventTrigger, on the trajectory, still before the
/// switch); its next step end is the window's end, just past ω_k, where the
/// kept value `NAME.starter_step` advances (Simulation's consistency of the
/// kept values). So the switch is at the crossing to within the window
/// (|ω − ω_k| <= |dω/dt|·kWindow), whatever the integrator's steps and the
/// output rows, like a frozen charge's release (SegmentCharge). A
/// TimeStepper calls handleEvent, which advances the step as well.
template <class Motor>
class StarterSpeedTrigger : public SimTK::TriggeredEventHandler {
public:
    StarterSpeedTrigger(const Motor* motor, const SimTK::MobilizedBody& shaft, std::vector<double> speeds)
        : SimTK::TriggeredEventHandler(SimTK::Stage::Velocity), m_impl(motor), m_shaft(shaft),
          m_speeds(std::move(speeds)) {
        getTriggerInfo().setTriggerOnRisingSignTransition(true);
        getTriggerInfo().setTriggerOnFallingSignTransition(false);
        getTriggerInfo().setRequiredLocalizationTimeWindow(kWindow);
    }
    SimTK::Real getValue(const SimTK::State& s) const override {
        const int step = m_impl->getStarterStep(s);
        if (step >= static_cast<int>(m_speeds.size())) return -1.0;
        return pinSpeed(s, m_shaft) - m_speeds[static_cast<std::size_t>(step)];
    }
    void handleEvent(SimTK::State& s, SimTK::Real, bool& shouldTerminate) const override {
        int step = m_impl->getStarterStep(s);
        while (step < static_cast<int>(m_speeds.size()) &&
               pinSpeed(s, m_shaft) >= m_speeds[static_cast<std::size_t>(step)])
            ++step;
        m_impl->setStarterStep(s, step);
        shouldTerminate = false;
    }
    /// The localization window [s]: at 1e-6 s a shaft accelerating at
    /// 1000 rad/s² switches within 1e-3 rad/s of its switch speed.
    static constexpr double kWindow = 1e-6;

private:
    const Motor* m_impl;
    SimTK::MobilizedBody m_shaft;
    std::vector<double> m_speeds;
};

/// A starter switched at speeds (closed transitions): its step is a value
/// kept between steps (`NAME.starter_step`), advanced at the step end at or
/// past each speed of `speeds` (rad/s, of `shaft`'s pin); the crossing of
/// each speed is a located event (StarterSpeedTrigger), so that step end is
/// within the event's window of the crossing.
/// Motor: as above, with getStarterStep(const State&).
template <class Motor>
void addStarterSpeedSwitching(Scene& scene, const std::string& name, const SimTK::MobilizedBody& shaft,
                              const std::vector<double>& speeds, Motor* impl) {
    if (speeds.empty()) return;
    scene.system().addEventHandler(new StarterSpeedTrigger<Motor>(impl, shaft, speeds));
    scene.addLaggedValue({name + ".starter_step", true,
                          [impl, shaft, speeds](const SimTK::State& s) {
                              int step = impl->getStarterStep(s);
                              while (step < static_cast<int>(speeds.size()) &&
                                     pinSpeed(s, shaft) >= speeds[static_cast<std::size_t>(step)])
                                  ++step;
                              return static_cast<double>(step);
                          },
                          [impl](SimTK::State& s, double v) {
                              const int old = impl->getStarterStep(s);
                              impl->setStarterStep(s, static_cast<int>(v));
                              return std::abs(v - old);
                          }});
}

}  // namespace milldyn
