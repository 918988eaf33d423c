// The floor of any Simbody-based tool on a transient scene of
// bench/transient_scenes.h: the same two bodies on Pin mobilizers, ONE
// Force::Custom whose calcForce evaluates the hand-written equations
// (bench/burr_equations.h, bench/roll_equations.h), no milldyn Scene,
// probes or energy meter; integrated by the same Simbody integrators at the
// same accuracy and sampled like milldyn (realized to Acceleration at every
// sample). One JSON line per integrator.
//   bench_bare_simbody SCENE [TOL] [REPEATS]      SCENE: burr | roll

#include "transient_scenes.h"

#include "Simbody.h"

#include <cmath>
#include <cstdlib>
#include <memory>

using namespace SimTK;

namespace {

/// The hand-written right-hand side as mobility torques: torque_i = J_i ẇ_i,
/// so Simbody's accelerations are the header's.
class HandWrittenTorques : public Force::Custom::Implementation {
public:
    HandWrittenTorques(const bench::TransientScene& scene, const MobilizedBody& b1, const MobilizedBody& b2)
        : m_scene(scene), m_b1(b1), m_b2(b2) {}
    void calcForce(const State& s, Vector_<SpatialVec>&, Vector_<Vec3>&, Vector& mobilityForces) const override {
        const bench::Vec4 x = {m_b1.getOneQ(s, MobilizerQIndex(0)), m_b2.getOneQ(s, MobilizerQIndex(0)),
                               m_b1.getOneU(s, MobilizerUIndex(0)), m_b2.getOneU(s, MobilizerUIndex(0))};
        bench::Vec4 dx;
        m_scene.rhs(x, dx, s.getTime());
        m_b1.applyOneMobilityForce(s, MobilizerUIndex(0), m_scene.inertia[0] * dx[2], mobilityForces);
        m_b2.applyOneMobilityForce(s, MobilizerUIndex(0), m_scene.inertia[1] * dx[3], mobilityForces);
    }
    Real calcPotentialEnergy(const State&) const override { return 0; }

private:
    const bench::TransientScene& m_scene;
    const MobilizedBody& m_b1;
    const MobilizedBody& m_b2;
};

std::unique_ptr<Integrator> makeIntegrator(const System& system, const std::string& name) {
    // As driver/Simulation.cpp makes them.
    if (name == "RungeKuttaMerson") return std::make_unique<RungeKuttaMersonIntegrator>(system);
    if (name == "RungeKutta3") return std::make_unique<RungeKutta3Integrator>(system);
    if (name == "RungeKuttaFeldberg") return std::make_unique<RungeKuttaFeldbergIntegrator>(system);
    if (name == "CPodes") return std::make_unique<CPodesIntegrator>(system, CPodes::BDF, CPodes::Newton);
    throw std::invalid_argument("unknown integrator " + name);
}

/// Builds the system and integrates the scene once (building is timed too,
/// as milldyn's run builds its scene).
bench::RunOutcome runOnce(const bench::TransientScene& scene, const std::string& integrator, double accuracy) {
    MultibodySystem system;
    SimbodyMatterSubsystem matter(system);
    GeneralForceSubsystem forces(system);
    // A pin turns about its Z axis; 1 kg on the axis, as milldyn's shafts.
    MobilizedBody::Pin b1(matter.Ground(), Transform(), Body::Rigid(MassProperties(1, Vec3(0), Inertia(scene.inertia[0]))),
                          Transform());
    MobilizedBody::Pin b2(matter.Ground(), Transform(), Body::Rigid(MassProperties(1, Vec3(0), Inertia(scene.inertia[1]))),
                          Transform());
    Force::Custom(forces, new HandWrittenTorques(scene, b1, b2));
    State state = system.realizeTopology();
    const bench::Vec4 x0 = scene.start();
    b1.setOneQ(state, MobilizerQIndex(0), x0[0]);
    b2.setOneQ(state, MobilizerQIndex(0), x0[1]);
    b1.setOneU(state, MobilizerUIndex(0), x0[2]);
    b2.setOneU(state, MobilizerUIndex(0), x0[3]);

    const std::unique_ptr<Integrator> integ = makeIntegrator(system, integrator);
    integ->setAccuracy(accuracy);
    integ->initialize(state);
    const MobilizedBody& compared = scene.speedIndex == 2 ? static_cast<const MobilizedBody&>(b1) : b2;
    bench::RunOutcome out;
    std::size_t nextTime = 0;
    for (long k = 1;; ++k) {
        const double sample = std::min(k * scene.sampleInterval, scene.endTime);
        integ->stepTo(sample, scene.endTime);
        const State& s = integ->getState();
        system.realize(s, Stage::Acceleration);  // as milldyn realizes every sample
        if (nextTime < scene.times.size() && std::abs(s.getTime() - scene.times[nextTime]) < 1e-9) {
            out.values.push_back(compared.getOneU(s, MobilizerUIndex(0)));
            ++nextTime;
        }
        if (sample >= scene.endTime) break;
    }
    out.realizations = integ->getNumRealizations();
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    bench::BenchArgs args;
    if (!bench::parseBenchArgs(argc, argv, "bench_bare_simbody burr|roll [TOL] [REPEATS]", args)) return 2;
    const bench::TransientScene& scene = args.scene;
    const std::string& tol = args.tol;
    const int repeats = args.repeats;
    for (const std::string& integrator : bench::integrators())
        bench::timeAndPrint("simbody_" + integrator, tol, repeats,
                            [&] { return runOnce(scene, integrator, std::atof(tol.c_str())); });
    return 0;
}
