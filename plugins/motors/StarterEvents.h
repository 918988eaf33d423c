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

/// A starter switched at speeds (closed transitions): its step is a value
/// kept between steps (`NAME.starter_step`), advanced at the first accepted
/// step end at or past each speed of `speeds` (rad/s, of `shaft`'s pin).
/// Motor: as above, with getStarterStep(const State&).
template <class Motor>
void addStarterSpeedSwitching(Scene& scene, const std::string& name, const SimTK::MobilizedBody& shaft,
                              const std::vector<double>& speeds, Motor* impl) {
    if (speeds.empty()) return;
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
