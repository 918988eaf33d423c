#include "plugins/loads/PeriodicLoad.h"

#include "plugins/loads/HarmonicSeries.h"
#include "plugins/loads/LoadTorqueOutputs.h"
#include "plugins/scene/ElementRegistry.h"

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

namespace milldyn {

PeriodicLoad::PeriodicLoad(const SimTK::GeneralForceSubsystem& forces, std::vector<SimTK::MobilizedBody> bodies,
                           const PeriodicLoadParams& p)
    : m_forces(forces), m_bodies(std::move(bodies)), m_params(p) {
    auto check = [](bool ok, const std::string& name, double v, const std::string& rule) {
        if (!ok)
            throw std::invalid_argument("PeriodicLoad: " + name + " = " + std::to_string(v) + " is invalid: " + rule);
    };
    check(p.rows >= 1, "rows", p.rows, "must be >= 1");
    check(!m_bodies.empty() && (m_bodies.size() == 1 || static_cast<int>(m_bodies.size()) == p.rows), "bodies",
          static_cast<double>(m_bodies.size()), "give one body per row, or one body for all rows");
    check(std::isfinite(p.meanTorque) && p.meanTorque >= 0, "mean_torque", p.meanTorque, "must be finite and >= 0");
    for (double b : p.amplitudes) check(std::isfinite(b) && b >= 0, "amplitudes", b, "each must be finite and >= 0");
    check(std::isfinite(p.fundamentalFrequency) && p.fundamentalFrequency > 0, "fundamental_frequency",
          p.fundamentalFrequency, "must be finite and > 0");
    check(std::isfinite(p.smoothingSpeed) && p.smoothingSpeed > 0, "smoothing_speed", p.smoothingSpeed,
          "must be finite and > 0");
    check(p.phases.empty() || static_cast<int>(p.phases.size()) == p.rows, "phases",
          static_cast<double>(p.phases.size()), "give one phase per row");
    for (double phi : p.phases) check(std::isfinite(phi), "phases", phi, "each must be finite");
    // Rows of equal phase share one Fourier sum per realization.
    std::map<double, int> groupOfPhase;
    for (int r = 0; r < p.rows; ++r) {
        const double phi = rowPhase(r);
        const auto found = groupOfPhase.emplace(phi, static_cast<int>(m_phases.size()));
        if (found.second) m_phases.push_back(phi);
        m_phaseOfRow.push_back(found.first->second);
    }
}

double PeriodicLoad::rowPhase(int row) const {
    if (!m_params.phases.empty()) return m_params.phases[row];
    return m_params.staggered ? 2 * SimTK::Pi * row / m_params.rows : 0.0;
}

double PeriodicLoad::calcSineSeries(double theta) const {
    static const std::vector<double> kNoCosines;
    return harmonicSeries(kNoCosines, m_params.amplitudes, theta);
}

double PeriodicLoad::periodicPart(int row, double t) const {
    return calcSineSeries(m_params.fundamentalFrequency * t + rowPhase(row));
}

int PeriodicLoad::bodyOfRow(int row) const { return m_bodies.size() == 1 ? 0 : row; }

bool PeriodicLoad::isExcitationOn(const SimTK::State& s) const {
    return SimTK::Value<bool>::downcast(m_forces.getDiscreteVariable(s, m_excitationIndex));
}

void PeriodicLoad::setExcitationOn(SimTK::State& s, bool on) const {
    SimTK::Value<bool>::updDowncast(m_forces.updDiscreteVariable(s, m_excitationIndex)) = on;
}

void PeriodicLoad::calcValues(const SimTK::State& s, Values& out) const {
    const std::size_t bodies = m_bodies.size();
    // Scratch kept in the cache value: sized once, reused every realization.
    out.bodySpeeds.resize(bodies);
    out.bodyMeans.resize(bodies);
    out.bodyTorques.assign(bodies, 0.0);
    for (std::size_t j = 0; j < bodies; ++j) {
        out.bodySpeeds[j] = m_bodies[j].getOneU(s, SimTK::MobilizerUIndex(0));
        out.bodyMeans[j] = m_params.meanTorque * std::tanh(out.bodySpeeds[j] / m_params.smoothingSpeed);
    }
    const bool excited = isExcitationOn(s);
    out.phaseParts.assign(m_phases.size(), 0.0);
    if (excited)
        for (std::size_t g = 0; g < m_phases.size(); ++g)
            out.phaseParts[g] = calcSineSeries(m_params.fundamentalFrequency * s.getTime() + m_phases[g]);
    const double scheduled = m_params.schedule.factorAt(s);
    out.rowTorques.resize(m_params.rows);
    out.totalTorque = 0;
    out.absorbedPower = 0;
    for (int r = 0; r < m_params.rows; ++r) {
        const int j = bodyOfRow(r);
        double M = out.bodyMeans[j];
        if (excited) M += out.phaseParts[m_phaseOfRow[r]];
        M *= scheduled;
        out.rowTorques[r] = M;
        out.bodyTorques[j] += M;
        out.totalTorque += M;
        out.absorbedPower += M * out.bodySpeeds[j];
    }
}

const PeriodicLoad::Values& PeriodicLoad::getValues(const SimTK::State& s) const {
    SimTK_STAGECHECK_GE_ALWAYS(m_forces.getStage(s), SimTK::Stage::Velocity, "PeriodicLoad::getValues()");
    auto& values = SimTK::Value<Values>::updDowncast(m_forces.updCacheEntry(s, m_valuesIndex));
    if (!m_forces.isCacheValueRealized(s, m_valuesIndex)) {
        calcValues(s, values);
        m_forces.markCacheValueRealized(s, m_valuesIndex);
    }
    return values;
}

void PeriodicLoad::calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>&, SimTK::Vector_<SimTK::Vec3>&,
                             SimTK::Vector& mobilityForces) const {
    const Values& v = getValues(s);
    for (std::size_t j = 0; j < m_bodies.size(); ++j)
        m_bodies[j].applyOneMobilityForce(s, SimTK::MobilizerUIndex(0), -v.bodyTorques[j], mobilityForces);
}

void PeriodicLoad::realizeTopology(SimTK::State& s) const {
    m_excitationIndex =
        m_forces.allocateDiscreteVariable(s, SimTK::Stage::Dynamics, new SimTK::Value<bool>(true));
    // Valid from Velocity (time and speeds) until time, a speed or the
    // excitation switch changes; the switch invalidates Dynamics only, so it
    // is a prerequisite of its own.
    const SimTK::SubsystemIndex subsystem = m_forces.getMySubsystemIndex();
    SimTK::Array_<SimTK::DiscreteVarKey> switches;
    switches.push_back(SimTK::DiscreteVarKey(subsystem, m_excitationIndex));
    m_valuesIndex = s.allocateCacheEntryWithPrerequisites(subsystem, SimTK::Stage::Velocity, SimTK::Stage::Infinity,
                                                          false, false, false, switches, {}, new SimTK::Value<Values>());
}

std::vector<SimTK::MobilizedBody> PeriodicLoad::forcingBodies() const {
    std::vector<SimTK::MobilizedBody> rows;
    for (int r = 0; r < m_params.rows; ++r) rows.push_back(m_bodies[bodyOfRow(r)]);
    return rows;
}

double PeriodicLoad::forcingAmplitude(int k) const {
    return k >= 1 && k <= forcingHarmonicCount() ? m_params.amplitudes[k - 1] : 0.0;
}

std::string PeriodicLoad::forcingDescription() const {
    return std::to_string(m_params.rows) + " rows, " + (m_params.staggered ? "staggered" : "in phase");
}

bool PeriodicLoad::setTimeCheckForcing(ElementSpec& spec, int k, double P) const {
    // Harmonic k alone, b_k = 1 N*m, at P_1 = P/k.
    std::vector<double> amplitudes(k, 0.0);
    amplitudes[k - 1] = 1.0;
    spec.params["amplitudes"].numbers = amplitudes;
    spec.params["fundamental_frequency"].number = P / k;
    return true;
}

namespace {

void buildPeriodicLoad(const ElementSpec& spec, Scene& scene) {
    std::vector<SimTK::MobilizedBody> bodies;
    for (const auto& name : spec.names("bodies")) bodies.push_back(scene.findBody(name)->mobod);
    PeriodicLoadParams p;
    p.rows = static_cast<int>(spec.number("rows"));
    p.meanTorque = spec.number("mean_torque");
    p.amplitudes = spec.numbers("amplitudes");
    p.fundamentalFrequency = spec.number("fundamental_frequency");
    p.staggered = spec.text("arrangement") == "staggered";
    if (spec.has("phases")) p.phases = spec.numbers("phases");
    p.smoothingSpeed = spec.number("smoothing_speed");
    p.schedule = Schedule::fromSpec(spec);
    addScheduleBreakpoints(scene, p.schedule, spec.name);
    auto* impl = new PeriodicLoad(scene.forces(), bodies, p);
    SimTK::Force::Custom force(scene.forces(), impl);
    scene.addForce(spec.name, spec.type, force.getForceIndex(), impl);
    scene.addExcitation(spec.name, [impl](SimTK::State& s, bool on) { impl->setExcitationOn(s, on); });
    addLoadTorqueOutputs(
        scene, spec.name, [impl](const SimTK::State& s) { return impl->getTotalTorque(s); },
        [impl](const SimTK::State& s) { return impl->getAbsorbedPower(s); });
    scene.note("force " + spec.name + " (PeriodicLoad, " + std::to_string(p.rows) + " rows, " +
                   (p.phases.empty() ? spec.text("arrangement") : std::string("phases as listed")) + ")",
               "loads " + std::to_string(bodies.size()) + " bod" + (bodies.size() == 1 ? "y" : "ies"));
}

}  // namespace

void registerPeriodicLoad(ElementRegistry& registry) {
    using P = ParamSchema;
    ElementSchema s;
    s.type = "PeriodicLoad";
    s.doc = "Crushing torque of sprocket rows: mean plus Fourier series b_k·sin(k(P1·t + φ_r)) (seed 004 eqs 13, 27).";
    s.params = {
        P::bodyList("bodies", 1, 1000, "one body per row, or one body carrying all rows"),
        P::quantity("rows", "1", "number of sprocket rows n").above(0).atMost(1000),
        P::quantity("mean_torque", "N*m", "mean crushing torque per row").optional(0.0).atLeast(0),
        P::quantityList("amplitudes", "N*m", 0, 100, "harmonic amplitudes b_1..b_K per row").atLeast(0),
        P::quantity("fundamental_frequency", "rad/s", "P_1; harmonic k is at k·P_1").above(0),
        P::choice("arrangement", {"in_phase", "staggered"}, "row phases: all equal, or evenly staggered")
            .optional("staggered"),
        P::quantityList("phases", "rad", 1, 1000,
                        "fundamental phase of each row φ_r, one per row (any stagger); replaces arrangement")
            .optional(std::string()),
        P::quantity("smoothing_speed", "rad/s", "regularisation width of the mean at standstill")
            .optional(0.01).above(0),
        scheduleParam("schedule", "f(t) multiplying every row's torque: {ramp|step_recovery|sine|table: ...} (default 1)"),
    };
    s.crossCheck = [](const ElementSpec& e) {
        const double rows = e.number("rows");
        if (rows != std::floor(rows)) throw e.error("rows", "must be a whole number");
        const auto n = e.names("bodies").size();
        if (n != 1 && static_cast<double>(n) != rows)
            throw e.error("bodies", "give one body per row (" + std::to_string(static_cast<int>(rows)) +
                                        ") or one body for all rows, got " + std::to_string(n));
        if (!e.has("phases")) return;
        const ParamValue& phases = e.params.at("phases");
        if (static_cast<double>(phases.numbers.size()) != rows)
            throw e.error("phases", "give one phase per row (" + std::to_string(static_cast<int>(rows)) + "), got " +
                                        std::to_string(phases.numbers.size()));
        if (e.has("arrangement"))
            throw e.error("phases", "give phases or arrangement, not both");
    };
    s.regularisationSpeedKey = "smoothing_speed";
    registry.add({std::move(s), buildPeriodicLoad});
}

}  // namespace milldyn
