#pragma once
// A Scene is one Simbody system built from a model, plus the handles the
// analyses need: bodies by name, the force elements, and the output probes
// (named scalar functions of the state). A Scene is never shared between
// threads; a sweep builds one per worker.

#include "plugins/scene/Sketch.h"
#include "plugins/scene/StartSequence.h"

#include <Simbody.h>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace milldyn {

class EnergyMeter;
class MobilizerReactions;

/// What a probe measures, so that analyses can find, for example, every
/// resistance torque without knowing the element types.
enum class ProbeRole {
    Generic,
    DriveTorque,       ///< torque a drive applies to its shaft [N*m]
    ResistanceTorque,  ///< magnitude of a load torque opposing rotation [N*m]
    ResistancePower,   ///< power a load absorbs [W]
    CouplingTorque,    ///< torque transmitted by a coupling [N*m]
    BodySpeed,         ///< angular speed of a body about its joint axis [rad/s]
};

/// A named scalar output, evaluated on a state realized to Stage::Dynamics
/// at least (Acceleration for probes that say so).
struct Probe {
    std::string name;   ///< "belt.torque"
    std::string unit;   ///< SI unit string, "N*m"
    ProbeRole role = ProbeRole::Generic;
    SimTK::Stage stage = SimTK::Stage::Dynamics;
    std::function<double(const SimTK::State&)> value;
    /// What the value is and its sign convention, for a plot's axis ("lag
    /// from the downward vertical, + in the +z sense"); empty: the name and
    /// unit say it.
    std::string label = {};
    /// The body it acts on or measures; empty: the SceneBuilder gives it
    /// the element's bodies (every body key's, joined by ", ") when the
    /// element's build ends (Scene::endElement).
    std::string shaft = {};
};

/// A power flow an element declares for the energy balance: a source feeds
/// the mechanical system (motor), a load takes useful work out (grinding),
/// a dissipation turns it into heat (damper). [W], at Stage::Velocity.
struct EnergyFlow {
    enum class Kind { Source, Load, Dissipation };
    std::string name;
    Kind kind;
    std::function<double(const SimTK::State&)> power;
    /// What the energy is, in words, for the summary ("heat in the rotor
    /// circuit", "journal friction heat"); empty: said from the kind.
    std::string what = {};
};

/// A body the scene holds: a shaft on a pin, rotating about its z axis.
struct SceneBody {
    std::string name;
    SimTK::MobilizedBody mobod;
};

/// A relation that is stationary in steady running (for example a
/// coupling's twist rate); the steady-state solver drives these to zero.
struct SteadyResidual {
    std::string name;
    std::function<double(const SimTK::State&)> value;  ///< at Stage::Velocity
};

/// A value an element derives from its parameters — a charge's mass, a
/// shaft diameter from a paper's fit, a motor law's coefficients — so a
/// user can read the intermediates a paper prints. Written to
/// summary.json's `derived` section and shown by `milldyn info`, at full
/// precision.
struct DerivedValue {
    std::string name;   ///< "element.quantity", e.g. "charge.mass"
    double value = 0;   ///< SI
    std::string unit;   ///< SI unit, "1" for a ratio
    std::string doc;    ///< what it is, with the paper's equation number
};

/// A starting sequence an element declares (see StartSequenceState).
struct StartSequence {
    std::string name;  ///< the element's name
    std::function<StartSequenceState(const SimTK::State&)> state;  ///< at Stage::Velocity
    /// Puts the sequence at its end in `state` (full supply, clutch
    /// engaged), for good: steady running (solveSteadyState) is the machine
    /// after its start, not in its starter's first step.
    std::function<void(SimTK::State&)> finish;
};

/// One thing an element registered with the scene (issue 31 item 1):
/// `milldyn info` lists them per element.
struct Contribution {
    enum class Kind {
        Drive, Probe, EnergyFlow, SwitchEvent, DerivedValue, StartSequence, StartHold, RegularisationSpeed,
        Excitation, KinetostaticUnknown, LaggedValue, SteadyResidual, OrderExcitation, PrescribedTrajectory,
        SpeedRelation
    };
    Kind kind;
    std::string name;    ///< as registered ("motor.torque")
    std::string shaft;   ///< the body it acts on or measures ("" if none)
    std::string detail;  ///< unit, role, time, value, in words
};
/// "probe", "energy flow", ... (the words `milldyn info` prints).
const char* contributionKindName(Contribution::Kind kind);

/// Everything one element registered, in the order it did.
struct ElementRecord {
    std::string element;
    std::string type;
    std::vector<Contribution> contributions;
    /// The contributions of one kind.
    std::vector<const Contribution*> of(Contribution::Kind kind) const;
};

/// One line of `milldyn info`: what was built and why.
struct BuildNote {
    std::string what;
    std::string why;
};

class Scene {
public:
    Scene();
    Scene(const Scene&) = delete;
    Scene& operator=(const Scene&) = delete;

    SimTK::MultibodySystem& system() { return m_system; }
    const SimTK::MultibodySystem& system() const { return m_system; }
    SimTK::SimbodyMatterSubsystem& matter() { return m_matter; }
    const SimTK::SimbodyMatterSubsystem& matter() const { return m_matter; }
    SimTK::GeneralForceSubsystem& forces() { return m_forces; }

    void addBody(const std::string& name, const SimTK::MobilizedBody& mobod);
    /// nullptr when no body has that name. addBody may move the list: do not
    /// keep the pointer across it.
    const SceneBody* findBody(const std::string& name) const;
    const std::vector<SceneBody>& bodies() const { return m_bodies; }

    /// The scene's shared cache of Simbody's mobilizer reactions, built on
    /// first use (before the system's topology is realized): every element
    /// that reads a joint reaction asks it, so one realization computes them
    /// once.
    const MobilizerReactions& mobilizerReactions();

    void addProbe(Probe probe) { m_probes.push_back(std::move(probe)); }
    /// Drops the probes `keep` rejects (outputs nobody asked for); returns
    /// how many were dropped.
    std::size_t retainProbes(const std::function<bool(const Probe&)>& keep);
    const std::vector<Probe>& probes() const { return m_probes; }

    void addEnergyFlow(EnergyFlow f) { m_energyFlows.push_back(std::move(f)); }
    /// The meter integrating the flows (built last by the SceneBuilder).
    void setEnergyMeter(const EnergyMeter* meter) { m_energyMeter = meter; }
    const EnergyMeter* energyMeter() const { return m_energyMeter; }
    const std::vector<EnergyFlow>& energyFlows() const { return m_energyFlows; }

    void addSteadyResidual(SteadyResidual r) { m_steadyResiduals.push_back(std::move(r)); }
    const std::vector<SteadyResidual>& steadyResiduals() const { return m_steadyResiduals; }

    /// Force elements by name, for analyses that need the handle or the
    /// element itself (Simbody owns `impl`; it lives as long as the system).
    void addForce(const std::string& name, const std::string& type, SimTK::ForceIndex index,
                  const SimTK::Force::Custom::Implementation* impl);
    SimTK::ForceIndex findForce(const std::string& name) const;
    /// The element named `name` if it is a T, else nullptr.
    template <class T>
    const T* findElement(const std::string& name) const {
        auto it = m_forceIndex.find(name);
        return it == m_forceIndex.end() ? nullptr : dynamic_cast<const T*>(it->second.impl);
    }

    /// Scheduled switchings (a motor switched off): the integrator stops
    /// exactly at `time`, `apply` changes the state, integration restarts.
    struct SwitchEvent {
        enum class Kind { DriveOff, LoadOn, StarterStep };
        Kind kind;
        double time;
        std::string what;
        std::function<void(SimTK::State&)> apply;
    };
    void addSwitchEvent(SwitchEvent e) { m_switchEvents.push_back(std::move(e)); }
    const std::vector<SwitchEvent>& switchEvents() const { return m_switchEvents; }

    /// A speed every steady-state search may start from for a body [rad/s]
    /// (a motor knows its shaft runs near synchronous speed).
    void addSpeedHint(const std::string& body, double omega) { m_speedHints[body] = omega; }
    /// Steady speed relations ω_from = ratio·ω_to (couplings), so hints
    /// reach bodies no motor drives.
    void addSpeedRelation(const std::string& from, const std::string& to, double ratio);
    /// Hinted speed of every body (0 where nothing reaches it).
    std::map<std::string, double> speedHints() const;

    /// What every drive (a motor, a prescribed drive) gives the scene, all
    /// in one facet (issue 31 item 1): the constructor takes every part, so
    /// a drive that forgets one does not compile, and addDrive refuses an
    /// empty or non-finite part when the model is built.
    struct Drive {
        Drive(std::string elementName, std::string shaftName, double hint, double offTime,
              std::function<void(SimTK::State&, bool)> onOff, std::string sequence)
            : element(std::move(elementName)), shaft(std::move(shaftName)), speedHint(hint),
              switchOffTime(offTime), setOn(std::move(onOff)), startingSequence(std::move(sequence)) {}
        std::string element;   ///< the drive's element name
        std::string shaft;     ///< the body it drives
        double speedHint;      ///< [rad/s] the speed its shaft runs near (steady-state searches start there)
        double switchOffTime;  ///< [s] when it is switched off (a DriveOff event); +inf: never
        /// On / off (a coast-down switches every drive off at t = 0). A
        /// drive that cannot be switched off throws std::invalid_argument
        /// saying why.
        std::function<void(SimTK::State&, bool)> setOn;
        std::string startingSequence;  ///< how it starts, in words ("direct_on_line", "prescribed ramp law")
    };
    /// Registers a drive: its on/off switch (addSwitchable), its switch-off
    /// event, its speed hint. Throws std::invalid_argument naming the part
    /// that is missing.
    void addDrive(Drive d);
    const std::vector<Drive>& drives() const { return m_drives; }

    /// Elements that can be told "you are off from now on" by an analysis
    /// (coast-down scenarios switch the drive off at t = 0); drives register
    /// through addDrive.
    void addSwitchable(const std::string& name, std::function<void(SimTK::State&, bool)> setOn);
    /// Switches every registered drive on or off in `state`.
    void setDrivesOn(SimTK::State& state, bool on) const;

    /// Time-periodic excitations (crushing loads) that the steady-state
    /// solver and the linearization switch off, so they work about the mean.
    void addExcitation(const std::string& name, std::function<void(SimTK::State&, bool)> setOn);
    /// Switches every registered excitation on or off in `state`.
    void setExcitationsOn(SimTK::State& state, bool on) const;

    /// Sets an element's part of the initial state (a gear's planet angle
    /// from its carrier, a charge's lag), after the bodies' own angles and
    /// speeds; run in the order the elements were built.
    void addInitializer(std::function<void(SimTK::State&)> f) { m_initializers.push_back(std::move(f)); }
    const std::vector<std::function<void(SimTK::State&)>>& initializers() const { return m_initializers; }

    /// A body whose motion is a known function of time (a drive prescribing
    /// its acceleration from the time alone). With every mobility either
    /// prescribed so or fixed by constraints and instant unknowns, a
    /// transient needs no integration (Simulation's replay).
    struct PrescribedTrajectory {
        std::string body;
        SimTK::MobilizedBody mobod;
        /// From speed u0 at time t0 to time t: {angle change [rad], speed at t [rad/s]}.
        std::function<std::pair<double, double>(double t0, double u0, double t)> advance;
    };
    void addPrescribedTrajectory(PrescribedTrajectory p) { m_trajectories.push_back(std::move(p)); }
    const std::vector<PrescribedTrajectory>& prescribedTrajectories() const { return m_trajectories; }

    /// Unknowns a kinetostatic analysis must solve for besides the
    /// accelerations: a torque whose value makes `residual` zero (a held
    /// charge's wall torque: residual = its acceleration in the carrier
    /// frame). `set` writes the torque into the state (a discrete variable).
    struct KinetostaticUnknown {
        std::string name;
        std::function<void(SimTK::State&, double)> set;
        std::function<double(const SimTK::State&)> get;
        std::function<double(const SimTK::State&)> residual;  ///< at Stage::Acceleration
    };
    void addKinetostaticUnknown(KinetostaticUnknown u) { m_kinetostaticUnknowns.push_back(std::move(u)); }
    const std::vector<KinetostaticUnknown>& kinetostaticUnknowns() const { return m_kinetostaticUnknowns; }

    /// A value an element keeps from the last accepted step (a journal's
    /// reaction). `current` reads what it should become from a state
    /// realized to Acceleration; `keep` stores that and returns the relative
    /// change. Kinetostatic analyses and replays iterate all of them to
    /// consistency at each instant, and so does the Simulation after every
    /// step for those with `eachStep` set (refreshLaggedValues: one
    /// realization per sweep over all of them).
    struct LaggedValue {
        std::string name;
        bool eachStep = false;
        std::function<double(const SimTK::State&)> current;
        std::function<double(SimTK::State&, double)> keep;
    };
    void addLaggedValue(LaggedValue v) { m_laggedValues.push_back(std::move(v)); }
    const std::vector<LaggedValue>& laggedValues() const { return m_laggedValues; }

    /// How an element draws itself in the schematic (`run --schematic`):
    /// called with a state realized to Stage::Acceleration.
    using SketchFn = std::function<void(const SimTK::State&, Sketch&)>;
    void addSketch(SketchFn f) { m_sketches.push_back(std::move(f)); }
    const std::vector<SketchFn>& sketches() const { return m_sketches; }

    /// An excitation whose frequency follows a body's speed: `eventsPerRevolution`
    /// events per turn of `body` relative to its parent (a gear's tooth-mesh
    /// frequency f_z = z·n). resonance_map reports where it meets the
    /// natural frequencies.
    struct OrderExcitation {
        std::string name;
        std::string body;
        double eventsPerRevolution = 0;
    };
    void addOrderExcitation(OrderExcitation e) { m_orderExcitations.push_back(std::move(e)); }
    const std::vector<OrderExcitation>& orderExcitations() const { return m_orderExcitations; }

    /// Starting sequences (starters, clutch engagements): a start is judged
    /// complete only once each has finished (see StartSequenceState).
    void addStartSequence(StartSequence q) { m_startSequences.push_back(std::move(q)); }
    const std::vector<StartSequence>& startSequences() const { return m_startSequences; }

    /// Sets an element's own continuous states (a dq machine's fluxes) to
    /// their steady running at the speeds and time in the state:
    /// solveSteadyState calls each at every trial state and on the state it
    /// returns, so steady running starts with its fields built up.
    void addSteadyInitializer(std::function<void(SimTK::State&)> f) { m_steadyInitializers.push_back(std::move(f)); }
    const std::vector<std::function<void(SimTK::State&)>>& steadyInitializers() const { return m_steadyInitializers; }

    /// What holds a start back (a breakaway not yet passed): `stallReason`
    /// says why a start stalled in the state at its end, "" when this hold
    /// was passed. The start verdict appends every non-empty reason.
    struct StartHold {
        std::string name;
        std::function<std::string(const SimTK::State&)> stallReason;
    };
    void addStartHold(StartHold h) { m_startHolds.push_back(std::move(h)); }
    const std::vector<StartHold>& startHolds() const { return m_startHolds; }

    /// A speed [rad/s] below which an element's law is regularised (the
    /// element type's ElementSchema::regularisationSpeedKey; registered by
    /// the SceneBuilder).
    struct RegularisationSpeed {
        std::string element;
        std::string key;  ///< "smoothing_speed"
        double speed = 0;
    };
    void addRegularisationSpeed(RegularisationSpeed r) { m_regularisationSpeeds.push_back(std::move(r)); }
    const std::vector<RegularisationSpeed>& regularisationSpeeds() const { return m_regularisationSpeeds; }

    /// Contribution records (issue 31 item 1): everything registered
    /// between beginElement and endElement is recorded under that element
    /// (the SceneBuilder opens and closes the record around each element's
    /// build). endElement gives the element's new probes without a shaft
    /// `defaultShaft`. Registrations outside a record are not recorded.
    void beginElement(const std::string& name, const std::string& type);
    void endElement(const std::string& defaultShaft);
    const std::vector<ElementRecord>& elementRecords() const { return m_records; }
    /// The record of element `name`; nullptr if it built nothing recorded.
    const ElementRecord* findRecord(const std::string& name) const;

    /// Values elements derive from their parameters (see DerivedValue).
    void addDerivedValue(DerivedValue v) { m_derived.push_back(std::move(v)); }
    const std::vector<DerivedValue>& derivedValues() const { return m_derived; }

    void note(const std::string& what, const std::string& why) { m_notes.push_back({what, why}); }
    const std::vector<BuildNote>& notes() const { return m_notes; }
    /// What the builder left out, and why (`milldyn info`'s "not built").
    void omit(const std::string& what, const std::string& why) { m_omitted.push_back({what, why}); }
    const std::vector<BuildNote>& omitted() const { return m_omitted; }

private:
    SimTK::MultibodySystem m_system;
    SimTK::SimbodyMatterSubsystem m_matter;
    SimTK::GeneralForceSubsystem m_forces;
    std::vector<SceneBody> m_bodies;
    std::vector<Probe> m_probes;
    std::vector<SteadyResidual> m_steadyResiduals;
    std::vector<EnergyFlow> m_energyFlows;
    const EnergyMeter* m_energyMeter = nullptr;
    const MobilizerReactions* m_reactions = nullptr;
    struct ForceEntry {
        std::string type;
        SimTK::ForceIndex index;
        const SimTK::Force::Custom::Implementation* impl;
    };
    std::map<std::string, ForceEntry> m_forceIndex;
    std::vector<SwitchEvent> m_switchEvents;
    std::vector<Drive> m_drives;
    std::vector<StartHold> m_startHolds;
    std::vector<RegularisationSpeed> m_regularisationSpeeds;
    std::vector<ElementRecord> m_records;
    /// The list sizes when the open record began (Scene.cpp's recordSince).
    struct RecordMarks;
    std::shared_ptr<RecordMarks> m_open;
    std::map<std::string, double> m_speedHints;
    struct SpeedRelation { std::string from, to; double ratio; };
    std::vector<SpeedRelation> m_speedRelations;
    std::vector<std::pair<std::string, std::function<void(SimTK::State&, bool)>>> m_switchables;
    std::vector<BuildNote> m_notes;
    std::vector<DerivedValue> m_derived;
    std::vector<OrderExcitation> m_orderExcitations;
    std::vector<BuildNote> m_omitted;
    std::vector<SketchFn> m_sketches;
    std::vector<std::function<void(SimTK::State&)>> m_initializers;
    std::vector<KinetostaticUnknown> m_kinetostaticUnknowns;
    std::vector<LaggedValue> m_laggedValues;
    std::vector<PrescribedTrajectory> m_trajectories;
    std::vector<std::pair<std::string, std::function<void(SimTK::State&, bool)>>> m_excitations;
    std::vector<StartSequence> m_startSequences;
    std::vector<std::function<void(SimTK::State&)>> m_steadyInitializers;
};

/// One fixed-point sweep over the scene's lagged values (only the eachStep
/// ones if `eachStepOnly`): realizes `state` to Acceleration once, reads
/// every current value, then keeps them all. Returns the largest relative
/// change (NaN if a value is not finite).
double refreshLaggedValues(const Scene& scene, SimTK::State& state, bool eachStepOnly = false);

/// The angular speed of a pin-jointed body about its axis [rad/s].
double pinSpeed(const SimTK::State& state, const SimTK::MobilizedBody& body);
/// The angle of a pin-jointed body about its axis [rad].
double pinAngle(const SimTK::State& state, const SimTK::MobilizedBody& body);

/// A name for every generalized speed u of the scene, in u order: the body's
/// name for a one-mobility body (a pin), "body.u<i>" for body mobilities
/// beyond one (gimbal, bushing). `state` must be realized to Model.
std::vector<std::string> mobilityNames(const Scene& scene, const SimTK::State& state);

}  // namespace milldyn
