#include "plugins/shafts/FlexibleRotor.h"

#include "plugins/scene/ElementRegistry.h"
// eq (2)'s table is typed in once, in the oracle; the model only takes the
// fitted diameter from it as an input (validation judges deflections and
// frequencies, never d, so sharing it cannot hide a model bug).
#include "papers/BeadMillTable1.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace milldyn {
namespace {

void requirePositive(const std::string& name, double v) {
    if (!(v > 0) || !std::isfinite(v))
        throw std::invalid_argument("FlexibleRotor: " + name + " = " + std::to_string(v) +
                                    " is invalid: must be finite and > 0");
}
void requireNonNegative(const std::string& name, double v) {
    if (!(v >= 0) || !std::isfinite(v))
        throw std::invalid_argument("FlexibleRotor: " + name + " = " + std::to_string(v) +
                                    " is invalid: must be finite and >= 0");
}

}  // namespace

FlexibleRotor::FlexibleRotor(SimTK::SimbodyMatterSubsystem& matter, const SimTK::MobilizedBody& drive,
                             const FlexibleRotorParams& p)
    : m_params(p), m_drive(drive) {
    (void)matter;  // the bodies join it through their parent
    requirePositive("shaft_diameter", p.shaftDiameter);
    requirePositive("youngs_modulus", p.youngsModulus);
    requirePositive("shear_modulus", p.shearModulus);
    requirePositive("shaft_density", p.shaftDensity);
    requirePositive("span", p.span);
    requirePositive("overhang", p.overhang);
    requirePositive("disc_diameter", p.discDiameter);
    requirePositive("disc_thickness", p.discThickness);
    requirePositive("disc_density", p.discDensity);
    requirePositive("first_disc_offset", p.firstDiscOffset);
    requirePositive("disc_pitch", p.discPitch);
    requirePositive("seal_offset", p.sealOffset);
    requirePositive("bearing_stiffness", p.bearingStiffness);
    requireNonNegative("disc_unbalance", p.discUnbalance);
    requireNonNegative("bearing_damping", p.bearingDamping);
    requireNonNegative("stiffness_damping", p.stiffnessDamping);
    if (p.segments < 2) throw std::invalid_argument("FlexibleRotor: segments must be >= 2");
    if (p.discs < 0) throw std::invalid_argument("FlexibleRotor: discs must be >= 0");
    if (p.discs > 0 && getDiscPosition(p.discs - 1) > getLength() + 1e-12)
        throw std::invalid_argument("FlexibleRotor: overhang: the last disc (at " +
                                    std::to_string(getDiscPosition(p.discs - 1) - p.span) +
                                    " m from bearing B) lies beyond the shaft end");
    if (p.sealOffset >= p.overhang)
        throw std::invalid_argument("FlexibleRotor: seal_offset must be shorter than the overhang");
    if (!SimTK::MobilizedBody::Pin::isInstanceOf(drive) || !drive.getParentMobilizedBody().isGround())
        throw std::invalid_argument("FlexibleRotor: drive_body must be a pin on ground (the rotor's spin)");

    const double d = p.shaftDiameter, pi = M_PI;
    m_base = drive.getDefaultInboardFrame().p();
    // Nodes: the key points, each interval between them cut evenly.
    std::vector<double> keys = {0.0, p.span, getSealPosition(), getLength()};
    for (int j = 0; j < p.discs; ++j) keys.push_back(getDiscPosition(j));
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end(), [](double a, double b) { return std::abs(a - b) < 1e-12; }),
               keys.end());
    const double target = getLength() / p.segments;
    m_nodes = {0.0};
    for (std::size_t k = 0; k + 1 < keys.size(); ++k) {
        const int pieces = std::max(1, static_cast<int>(std::lround((keys[k + 1] - keys[k]) / target)));
        for (int j = 1; j <= pieces; ++j) m_nodes.push_back(keys[k] + (keys[k + 1] - keys[k]) * j / pieces);
    }
    const int n = getNumSegments();
    const double EI = p.youngsModulus * pi * std::pow(d, 4) / 64, GJ = p.shearModulus * pi * std::pow(d, 4) / 32;
    for (int i = 0; i < n; ++i) {
        const double h = m_nodes[i + 1] - m_nodes[i];
        const double hbar = i == 0 ? h / 2 : 0.5 * (m_nodes[i + 1] - m_nodes[i - 1]);
        m_bending.push_back(i == 0 ? 0.0 : EI / hbar);
        m_torsion.push_back(GJ / hbar);
    }

    const double mu = p.shaftDensity * pi * d * d / 4;
    const double md = getDiscMass(), Id = getDiscDiametralInertia(),
                 Ip = md * p.discDiameter * p.discDiameter / 8;
    const double e = md > 0 ? p.discUnbalance / md : 0;
    SimTK::MobilizedBody parent = drive;
    for (int i = 0; i < n; ++i) {
        const double h = m_nodes[i + 1] - m_nodes[i];
        const double ms = mu * h;
        double mass = ms;
        SimTK::Vec3 moment = ms * SimTK::Vec3(0, 0, h / 2);
        SimTK::Inertia inertia = SimTK::Inertia(ms * (h * h / 12 + d * d / 16), ms * (h * h / 12 + d * d / 16),
                                                ms * d * d / 8) +
                                 SimTK::Inertia::pointMassAt(SimTK::Vec3(0, 0, h / 2), ms);
        for (int j = 0; j < p.discs; ++j) {
            // A disc sits on a node. Half of it (mass, polar and diametral
            // inertia) goes to each segment meeting there, so that it turns
            // with the mean of their rotations, the beam's slope at the node
            // to O(h²). All on one segment would turn it with the slope h/2
            // away: an O(h) error in the frequency, of the size of the discs'
            // share in it (6 % on the 0.3 m rotor). Half a disc is still a
            // physical rigid body; the mass stays exactly at the node.
            double local = 0;
            const int at = segmentAt(getDiscPosition(j), local);
            const bool shared = at > 0 && local < 1e-12;
            const double part = shared ? 0.5 : 1.0;
            SimTK::Vec3 c;
            if (at == i) c = SimTK::Vec3(e, 0, local);
            else if (shared && at == i + 1) c = SimTK::Vec3(e, 0, h);
            else continue;
            mass += part * md;
            moment += part * md * c;
            inertia += SimTK::Inertia(part * Id, part * Id, part * Ip) + SimTK::Inertia::pointMassAt(c, part * md);
        }
        const SimTK::Vec3 com = moment / mass;
        const SimTK::Body::Rigid body(SimTK::MassProperties(mass, com, inertia));
        if (i == 0)
            m_segments.push_back(SimTK::MobilizedBody::Bushing(parent, SimTK::Transform(), body, SimTK::Transform()));
        else
            m_segments.push_back(SimTK::MobilizedBody::Gimbal(
                parent, SimTK::Transform(SimTK::Vec3(0, 0, m_nodes[i] - m_nodes[i - 1])), body, SimTK::Transform()));
        parent = m_segments.back();
    }
}

double FlexibleRotor::getDiscMass() const {
    return m_params.discDensity * M_PI * m_params.discDiameter * m_params.discDiameter / 4 * m_params.discThickness;
}

double FlexibleRotor::getDiscDiametralInertia() const {
    const double D = m_params.discDiameter, t = m_params.discThickness;
    return getDiscMass() * (3 * D * D / 4 + t * t) / 12;
}

double FlexibleRotor::getDiscPosition(int j) const {
    return m_params.span + m_params.firstDiscOffset + j * m_params.discPitch;
}

int FlexibleRotor::segmentAt(double z, double& local) const {
    // The last node at or below z (a node belongs to the segment it starts).
    int i = static_cast<int>(std::upper_bound(m_nodes.begin(), m_nodes.end(), z + 1e-12) - m_nodes.begin()) - 1;
    i = std::max(0, std::min(getNumSegments() - 1, i));
    local = z - m_nodes[i];
    return i;
}

SimTK::Vec3 FlexibleRotor::calcDisplacement(const SimTK::State& s, double z) const {
    double local = 0;
    const int i = segmentAt(z, local);
    const SimTK::Vec3 p = m_segments[i].findStationLocationInGround(s, SimTK::Vec3(0, 0, local));
    return p - (m_base + SimTK::Vec3(0, 0, z));
}

double FlexibleRotor::calcDeflection(const SimTK::State& s, double z) const { return -calcDisplacement(s, z)[1]; }

double FlexibleRotor::calcLateral(const SimTK::State& s, double z) const { return calcDisplacement(s, z)[0]; }

SimTK::Vec3 FlexibleRotor::bearingStretch(const SimTK::State& s, int bearing, SimTK::Vec3& velocity) const {
    const double z = bearing == 0 ? 0.0 : m_params.span;
    double local = 0;
    const int i = segmentAt(z, local);
    const SimTK::Vec3 station(0, 0, local);
    velocity = m_segments[i].findStationVelocityInGround(s, station);
    return m_segments[i].findStationLocationInGround(s, station) - (m_base + SimTK::Vec3(0, 0, z));
}

double FlexibleRotor::calcBearingForce(const SimTK::State& s, int bearing) const {
    SimTK::Vec3 v;
    const SimTK::Vec3 d = bearingStretch(s, bearing, v);
    const SimTK::Vec3 f = -m_params.bearingStiffness * SimTK::Vec3(d[0], d[1], 0) -
                          m_params.bearingDamping * SimTK::Vec3(v[0], v[1], 0);
    return f.norm();
}

void FlexibleRotor::calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& bodyForces,
                              SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector& mobilityForces) const {
    const double beta = m_params.stiffnessDamping;
    auto spring = [&](const SimTK::MobilizedBody& b, int j, double k) {
        const double q = b.getOneQ(s, SimTK::MobilizerQIndex(j)), u = b.getOneU(s, SimTK::MobilizerUIndex(j));
        b.applyOneMobilityForce(s, SimTK::MobilizerUIndex(j), -k * q - beta * k * u, mobilityForces);
    };
    for (int i = 0; i < getNumSegments(); ++i) {
        const auto& b = m_segments[i];
        if (i > 0) {
            spring(b, 0, m_bending[i]);
            spring(b, 1, m_bending[i]);
        }
        spring(b, 2, m_torsion[i]);
    }
    for (int bearing = 0; bearing < 2; ++bearing) {
        SimTK::Vec3 v;
        const SimTK::Vec3 d = bearingStretch(s, bearing, v);
        SimTK::Vec3 f = -m_params.bearingStiffness * SimTK::Vec3(d[0], d[1], bearing == 0 ? d[2] : 0) -
                        m_params.bearingDamping * SimTK::Vec3(v[0], v[1], 0);
        double local = 0;
        const int i = segmentAt(bearing == 0 ? 0.0 : m_params.span, local);
        m_segments[i].applyForceToBodyPoint(s, SimTK::Vec3(0, 0, local), f, bodyForces);
    }
}

SimTK::Real FlexibleRotor::calcPotentialEnergy(const SimTK::State& s) const {
    double pe = 0;
    for (int i = 0; i < getNumSegments(); ++i) {
        const auto& b = m_segments[i];
        if (i > 0)
            for (int j = 0; j < 2; ++j)
                pe += 0.5 * m_bending[i] * std::pow(b.getOneQ(s, SimTK::MobilizerQIndex(j)), 2);
        pe += 0.5 * m_torsion[i] * std::pow(b.getOneQ(s, SimTK::MobilizerQIndex(2)), 2);
    }
    for (int bearing = 0; bearing < 2; ++bearing) {
        SimTK::Vec3 v;
        const SimTK::Vec3 d = bearingStretch(s, bearing, v);
        pe += 0.5 * m_params.bearingStiffness * (d[0] * d[0] + d[1] * d[1] + (bearing == 0 ? d[2] * d[2] : 0));
    }
    return pe;
}

double FlexibleRotor::calcDissipation(const SimTK::State& s) const {
    double p = 0;
    const double beta = m_params.stiffnessDamping;
    for (int i = 0; i < getNumSegments(); ++i) {
        const auto& b = m_segments[i];
        if (i > 0)
            for (int j = 0; j < 2; ++j)
                p += beta * m_bending[i] * std::pow(b.getOneU(s, SimTK::MobilizerUIndex(j)), 2);
        p += beta * m_torsion[i] * std::pow(b.getOneU(s, SimTK::MobilizerUIndex(2)), 2);
    }
    for (int bearing = 0; bearing < 2; ++bearing) {
        SimTK::Vec3 v;
        bearingStretch(s, bearing, v);
        p += m_params.bearingDamping * (v[0] * v[0] + v[1] * v[1]);
    }
    return p;
}

namespace {

double fittedDiameter(const ElementSpec& spec) {
    const int k = static_cast<int>(spec.number("discs"));
    try {
        // Eq (2) under Table 1's resolved reading (papers/BeadMillTable1.h):
        // d = k1·L³ − k2·L² + k3·L + k4, d in mm, L = L_p in m.
        const double L = spec.number("span");
        if (!(L >= papers::kBeadMillTableSpanMin - 1e-12 && L <= papers::kBeadMillTableSpanMax + 1e-12))
            throw std::invalid_argument("span L_p must lie in [0.15, 0.5] m (eq 2)");
        const std::array<double, 4> c =
            papers::beadMillTableRow(k, spec.number("disc_diameter"), papers::BeadMillTableReading::Resolved);
        return 1e-3 * (c[0] * L * L * L - c[1] * L * L + c[2] * L + c[3]);
    } catch (const std::invalid_argument& err) {
        throw spec.error("shaft_diameter",
                         std::string("not given, and eq (2) has no fit here (") + err.what() +
                             "); give shaft_diameter");
    }
}

void buildFlexibleRotor(const ElementSpec& spec, Scene& scene) {
    // Copies: addBody below may move the scene's body list.
    const SceneBody drive = *scene.findBody(spec.text("drive_body"));
    FlexibleRotorParams p;
    p.shaftDiameter = spec.number("shaft_diameter") > 0 ? spec.number("shaft_diameter") : fittedDiameter(spec);
    scene.addDerivedValue({spec.name + ".shaft_diameter", p.shaftDiameter, "m",
                           spec.number("shaft_diameter") > 0
                               ? "shaft diameter d as given"
                               : "shaft diameter d from seed 001 eq (2), d = k1 L^3 - k2 L^2 + k3 L + k4 (Table 1, "
                                 "resolved reading)"});
    p.youngsModulus = spec.number("youngs_modulus");
    p.shearModulus = spec.number("shear_modulus");
    p.shaftDensity = spec.number("shaft_density");
    p.span = spec.number("span");
    p.segments = static_cast<int>(spec.number("segments"));
    p.discs = static_cast<int>(spec.number("discs"));
    p.discDiameter = spec.number("disc_diameter");
    p.discThickness = spec.number("disc_thickness");
    p.discDensity = spec.number("disc_density");
    p.firstDiscOffset = spec.number("first_disc_offset");
    p.discPitch = spec.number("disc_pitch");
    p.sealOffset = spec.number("seal_offset");
    p.overhang = spec.number("overhang") > 0
                     ? spec.number("overhang")
                     : p.firstDiscOffset + std::max(0, p.discs - 1) * p.discPitch + p.discPitch / 2;
    p.discUnbalance = spec.number("disc_unbalance");
    p.bearingStiffness = spec.number("bearing_stiffness");
    p.bearingDamping = spec.number("bearing_damping");
    p.stiffnessDamping = spec.number("stiffness_damping");
    if (p.discs > 0 && p.span + p.firstDiscOffset + (p.discs - 1) * p.discPitch > p.span + p.overhang + 1e-12)
        throw spec.error("overhang", "the last disc lies beyond the shaft end");
    auto* impl = new FlexibleRotor(scene.matter(), drive.mobod, p);
    SimTK::Force::Custom force(scene.forces(), impl);
    scene.addForce(spec.name, spec.type, force.getForceIndex(), impl);
    for (std::size_t i = 0; i < impl->segments().size(); ++i)
        scene.addBody(spec.name + ".segment" + std::to_string(i), impl->segments()[i]);

    const double zSeal = impl->getSealPosition(), zEnd = impl->getLength();
    auto addDeflection = [&](const std::string& what, double z) {
        scene.addProbe({spec.name + "." + what + "_deflection", "m", ProbeRole::Generic, SimTK::Stage::Position,
                        [impl, z](const SimTK::State& s) { return impl->calcDeflection(s, z); }});
        scene.addProbe({spec.name + "." + what + "_lateral", "m", ProbeRole::Generic, SimTK::Stage::Position,
                        [impl, z](const SimTK::State& s) { return impl->calcLateral(s, z); }});
    };
    addDeflection("seal", zSeal);
    addDeflection("end", zEnd);
    scene.addProbe({spec.name + ".bearing_A_force", "N", ProbeRole::Generic, SimTK::Stage::Velocity,
                    [impl](const SimTK::State& s) { return impl->calcBearingForce(s, 0); }});
    scene.addProbe({spec.name + ".bearing_B_force", "N", ProbeRole::Generic, SimTK::Stage::Velocity,
                    [impl](const SimTK::State& s) { return impl->calcBearingForce(s, 1); }});
    if (p.bearingDamping > 0 || p.stiffnessDamping > 0)
        scene.addEnergyFlow({spec.name + ".damping", EnergyFlow::Kind::Dissipation,
                             [impl](const SimTK::State& s) { return impl->calcDissipation(s); }});

    // Disc drag: one DiscDrag per segment carrying discs.
    if (spec.text("drag_law") != "none" && p.discs > 0) {
        DiscDragParams dp;
        dp.law = spec.text("drag_law") == "turbulent" ? DiscDragParams::Law::Turbulent : DiscDragParams::Law::Laminar;
        dp.density = spec.number("medium_density");
        dp.viscosity = spec.number("medium_viscosity");
        dp.radius = p.discDiameter / 2;
        std::vector<int> count(impl->getNumSegments(), 0);
        for (int j = 0; j < p.discs; ++j) {
            double local = 0;
            ++count[impl->segmentAt(impl->getDiscPosition(j), local)];
        }
        for (int i = 0; i < impl->getNumSegments(); ++i)
            if (count[i] > 0) {
                dp.discs = count[i];
                addDiscDrag(scene, spec.name + ".drag" + std::to_string(i), impl->segments()[i], dp);
            }
    }
    std::ostringstream why;
    why << impl->getNumSegments() << " segments on " << drive.name << ", d = " << p.shaftDiameter * 1e3 << " mm"
        << (spec.number("shaft_diameter") > 0 ? " (given)" : " (eq 2 fit)") << ", L_p = " << p.span
        << " m, overhang " << p.overhang << " m, " << p.discs << " discs of " << impl->getDiscMass() << " kg";
    scene.note("force " + spec.name + " (FlexibleRotor)", why.str());
}

}  // namespace

void registerFlexibleRotor(ElementRegistry& registry) {
    using P = ParamSchema;
    ElementSchema s;
    s.type = "FlexibleRotor";
    s.doc = "Overhung rotor shaft as a chain of rigid segments with bending (E·I) and torsion (G·J) "
            "springs, on two radial bearings, discs on the overhang, gravity (seed 001).";
    s.params = {
        P::body("drive_body", "pin on ground whose rotation is the rotor's spin (drive pulley at bearing A)"),
        P::quantity("shaft_diameter", "m", "d; 0: the eq (2) fit for discs, disc_diameter, span").optional(0.0)
            .atLeast(0),
        P::quantity("youngs_modulus", "Pa", "E of the shaft").optional(2.1e11).above(0),
        P::quantity("shear_modulus", "Pa", "G of the shaft").optional(8.1e10).above(0),
        P::quantity("shaft_density", "kg/m^3", "shaft material density").optional(7850.0).above(0),
        P::quantity("span", "m", "L_p, bearing A to bearing B").above(0).atMost(100),
        P::quantity("overhang", "m", "a, bearing B to the shaft end; 0: last disc + pitch/2").optional(0.0).atLeast(0),
        P::quantity("segments", "1", "rigid shaft segments over L_p + a").optional(24.0).atLeast(2).atMost(400),
        P::quantity("discs", "1", "k, discs on the overhang").optional(5.0).atLeast(0).atMost(50),
        P::quantity("disc_diameter", "m", "D_d").above(0),
        P::quantity("disc_thickness", "m", "disc thickness").optional(0.01).above(0),
        P::quantity("disc_density", "kg/m^3", "disc material density").optional(7850.0).above(0),
        P::quantity("first_disc_offset", "m", "first disc centre from bearing B").optional(0.08).above(0),
        P::quantity("disc_pitch", "m", "L_d, disc centre to centre").optional(0.04).above(0),
        P::quantity("seal_offset", "m", "L_y, mechanical seal from bearing B").optional(0.04).above(0),
        P::quantity("disc_unbalance", "kg*m", "m·e of every disc (in phase)").optional(0.0).atLeast(0),
        P::quantity("bearing_stiffness", "N/m", "radial stiffness of each bearing").optional(2e8).above(0),
        P::quantity("bearing_damping", "N*s/m", "radial viscous damping of each bearing").optional(0.0).atLeast(0),
        P::quantity("stiffness_damping", "s", "β: joint damping = β·joint stiffness").optional(0.0).atLeast(0),
        P::choice("drag_law", {"none", "laminar", "turbulent"}, "disc drag (DiscDrag on each disc)").optional("none"),
        P::quantity("medium_density", "kg/m^3", "ρ_c of the medium (drag)").optional(1000.0).above(0),
        P::quantity("medium_viscosity", "m^2/s", "ν of the medium (drag)").optional(1e-6).above(0),
    };
    s.crossCheck = [](const ElementSpec& e) {
        for (const char* key : {"segments", "discs"})
            if (e.number(key) != std::floor(e.number(key))) throw e.error(key, "must be a whole number");
    };
    registry.add({std::move(s), buildFlexibleRotor});
}

}  // namespace milldyn
