#include "plugins/loads/AngleLoad.h"

#include "plugins/loads/HarmonicSeries.h"
#include "plugins/scene/ElementRegistry.h"
#include "plugins/scene/Format.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>

namespace milldyn {

namespace {

constexpr double kTwoPi = 2 * 3.14159265358979323846;

/// ψ wrapped to [0, 2π).
double wrapCycle(double psi) {
    double u = std::fmod(psi, kTwoPi);
    if (u < 0) u += kTwoPi;
    return u >= kTwoPi ? 0.0 : u;
}

/// Trapezoid points over one cycle for the harmonics of a table or pulse.
constexpr int kQuadraturePoints = 1 << 16;

}  // namespace

AngleLoad::AngleLoad(const SimTK::GeneralForceSubsystem& forces, std::vector<SimTK::MobilizedBody> bodies,
                     const AngleLoadParams& p)
    : m_forces(forces), m_bodies(std::move(bodies)), m_params(p) {
    auto check = [](bool ok, const std::string& name, double v, const std::string& rule) {
        if (!ok) throw std::invalid_argument("AngleLoad: " + name + " = " + std::to_string(v) + " is invalid: " + rule);
    };
    auto allFinite = [](const std::vector<double>& v) {
        return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
    };
    using S = AngleLoadParams::Shape;
    check(!m_bodies.empty(), "bodies", 0, "give at least one body");
    check(p.cyclesPerRevolution >= 1, "cycles_per_revolution", p.cyclesPerRevolution, "must be a whole number >= 1");
    check(p.phases.empty() || p.phases.size() == m_bodies.size(), "phases", static_cast<double>(p.phases.size()),
          "give one phase per body");
    check(allFinite(p.phases), "phases", 0, "each must be finite");
    check(std::isfinite(p.smoothingSpeed) && p.smoothingSpeed > 0, "smoothing_speed", p.smoothingSpeed,
          "must be finite and > 0");
    check(p.listedHarmonics >= 1 && p.listedHarmonics <= kAngleLoadHarmonics, "listed_harmonics",
          p.listedHarmonics, "must be 1.." + std::to_string(kAngleLoadHarmonics));
    check(allFinite(p.springCosineAmplitudes) && allFinite(p.springSineAmplitudes), "spring amplitudes", 0,
          "each must be finite");
    switch (p.shape) {
    case S::Fourier:
        check(std::isfinite(p.meanTorque), "mean_torque", p.meanTorque, "must be finite");
        check(allFinite(p.cosineAmplitudes) && allFinite(p.sineAmplitudes), "amplitudes", 0, "each must be finite");
        break;
    case S::Table: {
        const auto& a = p.tableAngles;
        check(a.size() >= 2 && a.size() == p.tableTorques.size(), "table_torques",
              static_cast<double>(p.tableTorques.size()), "give one torque per angle, at least two");
        check(allFinite(a) && a.front() >= 0 && a.back() < kTwoPi, "table_angles", a.empty() ? 0 : a.back(),
              "must lie in [0, 2π) rad of the cycle");
        for (std::size_t i = 1; i < a.size(); ++i)
            check(a[i] > a[i - 1], "table_angles", a[i], "must increase strictly");
        for (double g : p.tableTorques) check(std::isfinite(g) && g >= 0, "table_torques", g, "each must be >= 0");
        break;
    }
    case S::HalfSinePulse:
    case S::ShapedPulse:
        check(std::isfinite(p.pulseStart), "pulse_start", p.pulseStart, "must be finite");
        check(std::isfinite(p.pulseWidth) && p.pulseWidth > 0 && p.pulseWidth <= kTwoPi, "pulse_width",
              p.pulseWidth, "must be in (0, 2π] rad of the cycle");
        if (p.shape == S::HalfSinePulse)
            check(std::isfinite(p.peakTorque) && p.peakTorque >= 0, "peak_torque", p.peakTorque, "must be >= 0");
        else {
            check(p.pulseTorques.size() >= 2, "pulse_torques", static_cast<double>(p.pulseTorques.size()),
                  "give at least two torques (the pulse's ends included)");
            for (double g : p.pulseTorques) check(std::isfinite(g) && g >= 0, "pulse_torques", g, "each must be >= 0");
        }
        break;
    }

    for (std::size_t k = 0; k < p.springSineAmplitudes.size(); ++k)
        m_potentialCos.push_back(-p.springSineAmplitudes[k] / double(k + 1));
    for (std::size_t k = 0; k < p.springCosineAmplitudes.size(); ++k)
        m_potentialSin.push_back(p.springCosineAmplitudes[k] / double(k + 1));

    // The harmonics of g: given (fourier) or by the trapezoidal rule.
    if (p.shape == S::Fourier) {
        m_mean = p.meanTorque;
        const std::size_t K = std::max(p.cosineAmplitudes.size(), p.sineAmplitudes.size());
        m_cos.assign(K, 0.0);
        m_sin.assign(K, 0.0);
        std::copy(p.cosineAmplitudes.begin(), p.cosineAmplitudes.end(), m_cos.begin());
        std::copy(p.sineAmplitudes.begin(), p.sineAmplitudes.end(), m_sin.begin());
    } else {
        const int K = kAngleLoadHarmonics;
        m_cos.assign(K, 0.0);
        m_sin.assign(K, 0.0);
        double sum = 0;
        const double h = kTwoPi / kQuadraturePoints;
        for (int i = 0; i < kQuadraturePoints; ++i) {
            const double psi = i * h;
            const double g = shapeValue(psi);
            if (g == 0) continue;
            sum += g;
            for (int k = 1; k <= K; ++k) {
                m_cos[k - 1] += g * std::cos(k * psi);
                m_sin[k - 1] += g * std::sin(k * psi);
            }
        }
        m_mean = sum / kQuadraturePoints;
        for (int k = 0; k < K; ++k) {
            m_cos[k] *= 2.0 / kQuadraturePoints;
            m_sin[k] *= 2.0 / kQuadraturePoints;
        }
    }
}

double AngleLoad::shapeValue(double psi) const {
    using S = AngleLoadParams::Shape;
    const AngleLoadParams& p = m_params;
    switch (p.shape) {
    case S::Fourier:
        return p.meanTorque + harmonicSeries(p.cosineAmplitudes, p.sineAmplitudes, psi);
    case S::Table: {
        const double u = wrapCycle(psi);
        const auto& a = p.tableAngles;
        const auto& g = p.tableTorques;
        // Segment [a_i, a_{i+1}); before the first point and after the last,
        // the wrap-around segment from the last point to the first + 2π.
        const auto it = std::upper_bound(a.begin(), a.end(), u);
        double a0, a1, g0, g1;
        if (it == a.begin() || it == a.end()) {
            a0 = a.back();
            a1 = a.front() + kTwoPi;
            g0 = g.back();
            g1 = g.front();
            const double uu = it == a.begin() ? u + kTwoPi : u;
            return g0 + (g1 - g0) * (uu - a0) / (a1 - a0);
        }
        const std::size_t i = static_cast<std::size_t>(it - a.begin()) - 1;
        a0 = a[i];
        a1 = a[i + 1];
        g0 = g[i];
        g1 = g[i + 1];
        return g0 + (g1 - g0) * (u - a0) / (a1 - a0);
    }
    case S::HalfSinePulse:
    case S::ShapedPulse: {
        const double u = wrapCycle(psi - p.pulseStart);
        if (u > p.pulseWidth) return 0.0;
        if (p.shape == S::HalfSinePulse) return p.peakTorque * std::sin(SimTK::Pi * u / p.pulseWidth);
        const auto& v = p.pulseTorques;
        const double x = u / p.pulseWidth * static_cast<double>(v.size() - 1);
        const std::size_t i = std::min(static_cast<std::size_t>(x), v.size() - 2);
        return v[i] + (v[i + 1] - v[i]) * (x - static_cast<double>(i));
    }
    }
    return 0.0;
}

double AngleLoad::crushingMagnitude(double psi) const { return shapeValue(psi); }

double AngleLoad::springTorque(double psi) const {
    return harmonicSeries(m_params.springCosineAmplitudes, m_params.springSineAmplitudes, psi);
}

double AngleLoad::springPotential(double psi) const {
    // V = (1/n)·Σ_k (p_k sin kψ − q_k cos kψ)/k: the series of −q_k/k and p_k/k.
    return harmonicSeries(m_potentialCos, m_potentialSin, psi) / m_params.cyclesPerRevolution;
}

double AngleLoad::bodyPhase(int body) const { return m_params.phases.empty() ? 0.0 : m_params.phases[body]; }

double AngleLoad::cycleAngle(int body, double theta) const {
    return m_params.cyclesPerRevolution * theta - bodyPhase(body);
}

double AngleLoad::cosineCoefficient(int k) const {
    return k >= 1 && k <= static_cast<int>(m_cos.size()) ? m_cos[k - 1] : 0.0;
}

double AngleLoad::sineCoefficient(int k) const {
    return k >= 1 && k <= static_cast<int>(m_sin.size()) ? m_sin[k - 1] : 0.0;
}

double AngleLoad::runningHarmonicAmplitude(int k) const {
    const auto& pc = m_params.springCosineAmplitudes;
    const auto& qs = m_params.springSineAmplitudes;
    const double p = k <= static_cast<int>(pc.size()) ? pc[k - 1] : 0.0;
    const double q = k <= static_cast<int>(qs.size()) ? qs[k - 1] : 0.0;
    return std::hypot(cosineCoefficient(k) + p, sineCoefficient(k) + q);
}

int AngleLoad::forcingHarmonicCount() const {
    const AngleLoadParams& p = m_params;
    std::size_t K = static_cast<std::size_t>(p.listedHarmonics);
    if (p.shape == AngleLoadParams::Shape::Fourier) K = std::max(K, m_cos.size());
    K = std::max({K, p.springCosineAmplitudes.size(), p.springSineAmplitudes.size()});
    return static_cast<int>(K);
}

ForcingPhasor AngleLoad::forcingPhasor(int k, int shaft, const SimTK::State& steady) const {
    const double B = runningHarmonicAmplitude(k);
    if (!(B > 0)) return {0.0, 0.0};
    const auto& pc = m_params.springCosineAmplitudes;
    const auto& qs = m_params.springSineAmplitudes;
    const double p = k <= static_cast<int>(pc.size()) ? pc[k - 1] : 0.0;
    const double q = k <= static_cast<int>(qs.size()) ? qs[k - 1] : 0.0;
    const SimTK::MobilizedBody& body = m_bodies[shaft];
    const double omega = body.getOneU(steady, SimTK::MobilizerUIndex(0));
    const double theta = body.getOneQ(steady, SimTK::MobilizerQIndex(0));
    const double sign = std::tanh(omega / m_params.smoothingSpeed);
    const double X = sign * cosineCoefficient(k) + p, Y = sign * sineCoefficient(k) + q;
    std::complex<double> C = std::complex<double>(Y, X) * std::polar(1.0, k * cycleAngle(shaft, theta));
    if (omega < 0) C = -std::conj(C);  // the angle runs backwards: the harmonic at +k·n·|ω|
    return {std::abs(C) / B, std::arg(C)};
}

std::string AngleLoad::forcingDescription() const {
    const std::size_t n = m_bodies.size();
    return std::to_string(n) + (n == 1 ? " shaft, " : " shafts, ") + std::to_string(m_params.cyclesPerRevolution) +
           " cycle(s) per revolution";
}

bool AngleLoad::isExcitationOn(const SimTK::State& s) const {
    return SimTK::Value<bool>::downcast(m_forces.getDiscreteVariable(s, m_excitationIndex));
}

void AngleLoad::setExcitationOn(SimTK::State& s, bool on) const {
    SimTK::Value<bool>::updDowncast(m_forces.updDiscreteVariable(s, m_excitationIndex)) = on;
}

void AngleLoad::calcValues(const SimTK::State& s, Values& out) const {
    const bool excited = isExcitationOn(s);
    const double scheduled = m_params.schedule.factorAt(s);
    const std::size_t n = m_bodies.size();
    out.torques.resize(n);
    out.psi.resize(n);
    out.totalTorque = out.totalPower = out.crushingPower = 0;
    for (std::size_t j = 0; j < n; ++j) {
        const double theta = m_bodies[j].getOneQ(s, SimTK::MobilizerQIndex(0));
        const double omega = m_bodies[j].getOneU(s, SimTK::MobilizerUIndex(0));
        const double psi = cycleAngle(static_cast<int>(j), theta);
        const double sign = std::tanh(omega / m_params.smoothingSpeed);
        const double crushing = scheduled * (excited ? shapeValue(psi) : m_mean) * sign;
        const double M = crushing + (excited ? springTorque(psi) : 0.0);
        out.psi[j] = wrapCycle(psi);
        out.torques[j] = M;
        out.totalTorque += M;
        out.totalPower += M * omega;
        out.crushingPower += crushing * omega;
    }
}

const AngleLoad::Values& AngleLoad::getValues(const SimTK::State& s) const {
    SimTK_STAGECHECK_GE_ALWAYS(m_forces.getStage(s), SimTK::Stage::Velocity, "AngleLoad::getValues()");
    auto& values = SimTK::Value<Values>::updDowncast(m_forces.updCacheEntry(s, m_valuesIndex));
    if (!m_forces.isCacheValueRealized(s, m_valuesIndex)) {
        calcValues(s, values);
        m_forces.markCacheValueRealized(s, m_valuesIndex);
    }
    return values;
}

void AngleLoad::calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>&, SimTK::Vector_<SimTK::Vec3>&,
                          SimTK::Vector& mobilityForces) const {
    const Values& v = getValues(s);
    for (std::size_t j = 0; j < m_bodies.size(); ++j)
        m_bodies[j].applyOneMobilityForce(s, SimTK::MobilizerUIndex(0), -v.torques[j], mobilityForces);
}

SimTK::Real AngleLoad::calcPotentialEnergy(const SimTK::State& s) const {
    if (m_params.springCosineAmplitudes.empty() && m_params.springSineAmplitudes.empty()) return 0;
    if (!isExcitationOn(s)) return 0;
    double V = 0;
    for (std::size_t j = 0; j < m_bodies.size(); ++j)
        V += springPotential(cycleAngle(static_cast<int>(j), m_bodies[j].getOneQ(s, SimTK::MobilizerQIndex(0))));
    return V;
}

void AngleLoad::realizeTopology(SimTK::State& s) const {
    m_excitationIndex = m_forces.allocateDiscreteVariable(s, SimTK::Stage::Dynamics, new SimTK::Value<bool>(true));
    // Valid from Velocity (angles and speeds) until one changes; the
    // excitation switch invalidates Dynamics only, so it is a prerequisite.
    const SimTK::SubsystemIndex subsystem = m_forces.getMySubsystemIndex();
    SimTK::Array_<SimTK::DiscreteVarKey> switches;
    switches.push_back(SimTK::DiscreteVarKey(subsystem, m_excitationIndex));
    m_valuesIndex = s.allocateCacheEntryWithPrerequisites(subsystem, SimTK::Stage::Velocity, SimTK::Stage::Infinity,
                                                          false, false, false, switches, {}, new SimTK::Value<Values>());
}

namespace {

AngleLoadParams::Shape shapeOf(const std::string& word) {
    if (word == "table") return AngleLoadParams::Shape::Table;
    if (word == "half_sine_pulse") return AngleLoadParams::Shape::HalfSinePulse;
    if (word == "shaped_pulse") return AngleLoadParams::Shape::ShapedPulse;
    return AngleLoadParams::Shape::Fourier;
}

void buildAngleLoad(const ElementSpec& spec, Scene& scene) {
    std::vector<SimTK::MobilizedBody> bodies;
    const std::vector<std::string>& bodyNames = spec.names("bodies");
    for (const auto& name : bodyNames) bodies.push_back(scene.findBody(name)->mobod);
    AngleLoadParams p;
    p.shape = shapeOf(spec.text("shape"));
    p.cyclesPerRevolution = static_cast<int>(spec.number("cycles_per_revolution"));
    if (spec.has("phases")) p.phases = spec.numbers("phases");
    p.meanTorque = spec.number("mean_torque");
    if (spec.has("cosine_amplitudes")) p.cosineAmplitudes = spec.numbers("cosine_amplitudes");
    if (spec.has("sine_amplitudes")) p.sineAmplitudes = spec.numbers("sine_amplitudes");
    if (spec.has("table_angles")) p.tableAngles = spec.numbers("table_angles");
    if (spec.has("table_torques")) p.tableTorques = spec.numbers("table_torques");
    p.peakTorque = spec.number("peak_torque");
    p.pulseStart = spec.number("pulse_start");
    p.pulseWidth = spec.number("pulse_width");
    if (spec.has("pulse_torques")) p.pulseTorques = spec.numbers("pulse_torques");
    if (spec.has("spring_cosine_amplitudes")) p.springCosineAmplitudes = spec.numbers("spring_cosine_amplitudes");
    if (spec.has("spring_sine_amplitudes")) p.springSineAmplitudes = spec.numbers("spring_sine_amplitudes");
    p.smoothingSpeed = spec.number("smoothing_speed");
    p.listedHarmonics = static_cast<int>(spec.number("listed_harmonics"));
    p.schedule = Schedule::fromSpec(spec);
    addScheduleBreakpoints(scene, p.schedule, spec.name);
    auto* impl = new AngleLoad(scene.forces(), bodies, p);
    SimTK::Force::Custom force(scene.forces(), impl);
    scene.addForce(spec.name, spec.type, force.getForceIndex(), impl);
    scene.addExcitation(spec.name, [impl](SimTK::State& s, bool on) { impl->setExcitationOn(s, on); });
    scene.addProbe({spec.name + ".torque", "N*m", ProbeRole::ResistanceTorque, SimTK::Stage::Velocity,
                    [impl](const SimTK::State& s) { return impl->getValues(s).totalTorque; },
                    "load torque, sum over its shafts, + opposing + rotation"});
    scene.addProbe({spec.name + ".power", "W", ProbeRole::ResistancePower, SimTK::Stage::Velocity,
                    [impl](const SimTK::State& s) { return impl->getValues(s).totalPower; },
                    "power into the load, crushing plus spring, Σ M_j·ω_j"});
    scene.addProbe({spec.name + ".crushing_power", "W", ProbeRole::Generic, SimTK::Stage::Velocity,
                    [impl](const SimTK::State& s) { return impl->getValues(s).crushingPower; },
                    "power dissipated by the crushing part, Σ g·tanh(ω/ωs)·ω"});
    for (std::size_t j = 0; j < bodies.size(); ++j)
        scene.addProbe({spec.name + (j == 0 ? std::string(".phase") : ".phase_" + bodyNames[j]), "rad",
                        ProbeRole::Generic, SimTK::Stage::Velocity,
                        [impl, j](const SimTK::State& s) { return impl->getValues(s).psi[j]; },
                        "cycle angle ψ = n·θ − φ of " + bodyNames[j] + ", wrapped to [0, 2π)"});
    scene.addEnergyFlow({spec.name, EnergyFlow::Kind::Load,
                         [impl](const SimTK::State& s) { return impl->getValues(s).crushingPower; },
                         "crushing work"});

    const int n = p.cyclesPerRevolution;
    scene.addDerivedValue({spec.name + ".mean_torque", impl->meanTorque(), "N*m",
                           "mean of the crushing magnitude g over a cycle, a0 (per shaft)"});
    double peak = 0;
    for (int i = 0; i < 4096; ++i) peak = std::max(peak, impl->crushingMagnitude(kTwoPi * i / 4096));
    scene.addDerivedValue({spec.name + ".peak_torque", peak, "N*m",
                           "largest crushing magnitude g over a cycle (4096 points), per shaft"});
    scene.addDerivedValue({spec.name + ".energy_per_cycle", kTwoPi * impl->meanTorque() / n, "J",
                           "crushing work per load cycle and shaft at running speed, 2π·a0/n"});
    scene.addDerivedValue({spec.name + ".energy_per_revolution", kTwoPi * impl->meanTorque(), "J",
                           "crushing work per revolution and shaft at running speed, 2π·a0"});
    double vMin = 0, vMax = 0;
    for (int i = 0; i < 4096; ++i) {
        const double v = impl->springPotential(kTwoPi * i / 4096);
        vMin = i == 0 ? v : std::min(vMin, v);
        vMax = i == 0 ? v : std::max(vMax, v);
    }
    scene.addDerivedValue({spec.name + ".spring_energy_swing", vMax - vMin, "J",
                           "range of the conservative part's potential over a cycle (4096 points), per shaft"});
    double largest = 0;
    for (int k = 1; k <= p.listedHarmonics; ++k) largest = std::max(largest, impl->runningHarmonicAmplitude(k));
    for (int k = 1; k <= p.listedHarmonics; ++k) {
        const double amplitude = impl->runningHarmonicAmplitude(k);
        scene.addDerivedValue({spec.name + ".harmonic_" + std::to_string(k) + "_amplitude", amplitude, "N*m",
                               "amplitude of harmonic " + std::to_string(k) + " of the cycle (order " +
                                   std::to_string(k * n) + " of the shaft speed) of the running load g + c"});
        // An order excitation per harmonic that is there (not round-off of
        // the quadrature: a half-sine over half a cycle has no odd k >= 3).
        if (!(amplitude > 1e-6 * largest)) continue;
        for (std::size_t j = 0; j < bodies.size(); ++j)
            scene.addOrderExcitation({spec.name + (bodies.size() == 1 ? std::string() : "." + bodyNames[j]) +
                                          ".order_" + std::to_string(k * n),
                                      bodyNames[j], double(k * n)});
    }
    scene.note("force " + spec.name + " (AngleLoad, " + spec.text("shape") + ", " + std::to_string(n) +
                   " cycle(s) per revolution)",
               "loads " + std::to_string(bodies.size()) + " bod" + (bodies.size() == 1 ? "y" : "ies") +
                   " by their angles; mean " + formatNumber(impl->meanTorque()) + " N*m");
}

}  // namespace

namespace {

/// The smallest value of a0 + Σ a_k cos kψ + b_k sin kψ over one cycle and
/// where it is: 64 samples per harmonic, then the root of the derivative
/// bracketed around the smallest sample, bisected to 1e-13 rad.
struct FourierMinimum {
    double value;
    double angle;
};
FourierMinimum fourierSeriesMinimum(double a0, const std::vector<double>& a, const std::vector<double>& b) {
    const std::size_t K = std::max(a.size(), b.size());
    auto at = [&](double psi, int derivative) {
        double g = derivative == 0 ? a0 : 0.0;
        for (std::size_t k = 1; k <= K; ++k) {
            const double ak = k <= a.size() ? a[k - 1] : 0.0, bk = k <= b.size() ? b[k - 1] : 0.0;
            const double c = std::cos(k * psi), s = std::sin(k * psi);
            g += derivative == 0 ? ak * c + bk * s : static_cast<double>(k) * (bk * c - ak * s);
        }
        return g;
    };
    const std::size_t n = 64 * std::max<std::size_t>(K, 1);
    const double h = kTwoPi / static_cast<double>(n);
    std::size_t best = 0;
    double bestValue = at(0, 0);
    for (std::size_t i = 1; i < n; ++i) {
        const double v = at(h * static_cast<double>(i), 0);
        if (v < bestValue) bestValue = v, best = i;
    }
    double lo = h * (static_cast<double>(best) - 1), hi = h * (static_cast<double>(best) + 1);
    if (at(lo, 1) < 0 && at(hi, 1) > 0) {
        for (int it = 0; it < 200 && hi - lo > 1e-13; ++it) {
            const double mid = 0.5 * (lo + hi);
            (at(mid, 1) < 0 ? lo : hi) = mid;
        }
        const double psi = 0.5 * (lo + hi);
        if (at(psi, 0) < bestValue) return {at(psi, 0), std::fmod(psi + kTwoPi, kTwoPi)};
    }
    return {bestValue, h * static_cast<double>(best)};
}

}  // namespace

void registerAngleLoad(ElementRegistry& registry) {
    using P = ParamSchema;
    ElementSchema s;
    s.type = "AngleLoad";
    s.doc = "Process load tied to a shaft's angle: crushing magnitude g(ψ), ψ = n·θ − φ (Fourier series, "
            "periodic table, or a half-sine or shaped pulse), opposing motion (× tanh(ω/ωs)), plus an "
            "optional conservative part c(ψ) with its potential.";
    s.params = {
        P::bodyList("bodies", 1, 1000, "shafts the load acts on, each by its own angle"),
        P::choice("shape", {"fourier", "table", "half_sine_pulse", "shaped_pulse"},
                  "how the crushing magnitude over one cycle is given"),
        P::quantity("cycles_per_revolution", "1", "n: load cycles per revolution of the shaft (whole)")
            .optional(1.0).atLeast(1).atMost(1000),
        P::quantityList("phases", "rad", 1, 1000, "φ_j of each shaft: ψ_j = n·θ_j − φ_j (default 0)")
            .optional(std::string()),
        P::quantity("mean_torque", "N*m", "fourier: a0").optional(0.0),
        P::quantityList("cosine_amplitudes", "N*m", 0, 1000, "fourier: a_1..a_K of cos kψ").optional(std::string()),
        P::quantityList("sine_amplitudes", "N*m", 0, 1000, "fourier: b_1..b_K of sin kψ").optional(std::string()),
        P::quantityList("table_angles", "rad", 2, 10000, "table: cycle angles ψ_i in [0, 2π), increasing")
            .optional(std::string()),
        P::quantityList("table_torques", "N*m", 2, 10000, "table: g at each angle (periodic, linear between)")
            .optional(std::string())
            .atLeast(0),
        P::quantity("peak_torque", "N*m", "half_sine_pulse: P, the pulse's peak").optional(0.0).atLeast(0),
        P::quantity("pulse_start", "rad", "pulses: ψ0, the cycle angle where the pulse begins").optional(0.0),
        P::quantity("pulse_width", "rad", "pulses: w, the pulse's width in cycle angle, (0, 2π]")
            .optional(0.0).atLeast(0).atMost(kTwoPi),
        P::quantityList("pulse_torques", "N*m", 2, 10000,
                        "shaped_pulse: g evenly over the width, ends included, linear between")
            .optional(std::string())
            .atLeast(0),
        P::quantityList("spring_cosine_amplitudes", "N*m", 0, 1000, "conservative part: p_k of cos kψ")
            .optional(std::string()),
        P::quantityList("spring_sine_amplitudes", "N*m", 0, 1000, "conservative part: q_k of sin kψ")
            .optional(std::string()),
        P::quantity("smoothing_speed", "rad/s", "ωs: width of the sign regularisation of the crushing part")
            .optional(0.01).above(0),
        P::quantity("listed_harmonics", "1", "harmonics reported and registered as excitation orders")
            .optional(6.0).atLeast(1).atMost(kAngleLoadHarmonics),
        scheduleParam("schedule", "f(t) multiplying the crushing part g: {ramp|step_recovery|sine|table: ...} (default 1)"),
    };
    s.crossCheck = [](const ElementSpec& e) {
        if (e.number("cycles_per_revolution") != std::floor(e.number("cycles_per_revolution")))
            throw e.error("cycles_per_revolution", "must be a whole number (the load repeats every revolution)");
        if (e.number("listed_harmonics") != std::floor(e.number("listed_harmonics")))
            throw e.error("listed_harmonics", "must be a whole number");
        const std::size_t bodies = e.names("bodies").size();
        if (e.has("phases") && e.params.at("phases").numbers.size() != bodies)
            throw e.error("phases", "give one phase per body (" + std::to_string(bodies) + "), got " +
                                        std::to_string(e.params.at("phases").numbers.size()));
        const std::string& shape = e.text("shape");
        // Keys of one shape only: a key of another shape is a mistake, not ignored.
        const std::vector<std::pair<std::string, std::string>> owner = {
            {"mean_torque", "fourier"},       {"cosine_amplitudes", "fourier"},  {"sine_amplitudes", "fourier"},
            {"table_angles", "table"},        {"table_torques", "table"},        {"peak_torque", "half_sine_pulse"},
            {"pulse_torques", "shaped_pulse"}};
        for (const auto& [key, of] : owner)
            if (e.has(key) && shape != of) throw e.error(key, "belongs to shape " + of + ", not " + shape);
        const bool pulse = shape == "half_sine_pulse" || shape == "shaped_pulse";
        for (const char* key : {"pulse_start", "pulse_width"})
            if (e.has(key) && !pulse) throw e.error(key, "belongs to the pulse shapes, not " + shape);
        if (shape == "table") {
            if (!e.has("table_angles")) throw e.error("table_angles", "shape table needs table_angles");
            if (!e.has("table_torques")) throw e.error("table_torques", "shape table needs table_torques");
            const auto& a = e.params.at("table_angles").numbers;
            if (e.params.at("table_torques").numbers.size() != a.size())
                throw e.error("table_torques", "give one torque per angle (" + std::to_string(a.size()) + ")");
            for (std::size_t i = 0; i < a.size(); ++i) {
                if (!(a[i] >= 0 && a[i] < kTwoPi)) throw e.error("table_angles", "must lie in [0, 2π) rad");
                if (i > 0 && !(a[i] > a[i - 1])) throw e.error("table_angles", "must increase strictly");
            }
        }
        if (shape == "fourier") {
            // The crushing part must oppose motion at every angle (g >= 0), as
            // the table and pulse shapes are held to: a series that dips below
            // 0 would drive the shaft over part of the cycle. Its minimum is
            // searched on 64 points per harmonic, then refined by bisection of
            // g' around the smallest sample.
            const double a0 = e.number("mean_torque");
            const std::vector<double> a = e.has("cosine_amplitudes") ? e.params.at("cosine_amplitudes").numbers
                                                                     : std::vector<double>{};
            const std::vector<double> b =
                e.has("sine_amplitudes") ? e.params.at("sine_amplitudes").numbers : std::vector<double>{};
            const FourierMinimum m = fourierSeriesMinimum(a0, a, b);
            double scale = std::abs(a0);
            for (double x : a) scale += std::abs(x);
            for (double x : b) scale += std::abs(x);
            if (m.value < -1e-12 * scale)
                throw e.error(
                    a0 < 0 || (a.empty() && b.empty()) ? "mean_torque"
                    : e.has("cosine_amplitudes")         ? "cosine_amplitudes"
                                                         : "sine_amplitudes",
                    "the crushing magnitude g(ψ) = a0 + Σ a_k cos kψ + b_k sin kψ falls to " +
                        formatNumber(m.value, 6) + " N*m at ψ = " + formatNumber(m.angle, 6) +
                        " rad: it must be >= 0 at every angle (the crushing part opposes motion; below 0 it "
                        "would drive the shaft). A series truncated from a pulse undershoots: give the pulse "
                        "itself (shape: half_sine_pulse, shaped_pulse or table); what returns energy goes in "
                        "the conservative part (spring_cosine_amplitudes, spring_sine_amplitudes)");
        }
        if (pulse && !(e.number("pulse_width") > 0)) throw e.error("pulse_width", "a pulse needs a width > 0");
        if (shape == "half_sine_pulse" && !e.has("peak_torque"))
            throw e.error("peak_torque", "shape half_sine_pulse needs peak_torque");
        if (shape == "shaped_pulse" && !e.has("pulse_torques"))
            throw e.error("pulse_torques", "shape shaped_pulse needs pulse_torques");
    };
    s.regularisationSpeedKey = "smoothing_speed";
    registry.add({std::move(s), buildAngleLoad});
}

}  // namespace milldyn
