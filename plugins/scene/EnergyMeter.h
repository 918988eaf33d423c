#pragma once
// EnergyMeter: integrates every energy flow the scene's elements declare,
// so a run can close its energy balance, and says what each flow is (one
// classification for the energy balance and the power split).

#include "plugins/scene/Scene.h"

#include <string>
#include <vector>

namespace milldyn {

/**
 * What an energy flow is, for the energy and power accounting of a run.
 * An element declares the kind of its flow (EnergyFlow::Kind: source, load
 * or dissipation); the element type refines a dissipation into what heats:
 * <pre>
 *   MotorInput  every Source: a motor's electrical input (its air-gap power
 *               when no efficiency is given), a prescribed drive's work
 *   MotorLoss   InductionMotor's rotor heat (rotor copper loss, s·P_airgap)
 *               and stator heat (stator copper and no-load loss)
 *   Grinding    every Load: SegmentCharge, ResistanceTorque, PeriodicLoad,
 *               DiscDrag (the work the machine exists to do)
 *   Friction    JournalFriction, ShaftBearings, Brake, Clutch (slip)
 *   Damping     TorsionalCoupling, BeltDrive (creep and hysteresis),
 *               GearPair mesh damping, FlexibleRotor material damping
 *   OtherHeat   a dissipation of an element type not listed (a plugin)
 * </pre>
 * The mechanical power balance of any window [t1, t2] then reads
 * <pre>
 *   MotorInput − MotorLoss = Grinding + Friction + Damping + OtherHeat
 *                            + d(E_kinetic + E_gravity + E_elastic)/dt
 * </pre>
 */
enum class EnergyCategory { MotorInput, MotorLoss, Grinding, Friction, Damping, OtherHeat };
constexpr int kEnergyCategories = 6;

/// The category of a flow that an element of type `elementType` declared.
EnergyCategory energyCategory(EnergyFlow::Kind kind, const std::string& elementType);
/// Short name for result keys: "motor_input", "motor_loss", "grinding",
/// "friction", "damping", "other_heat".
std::string energyCategoryKey(EnergyCategory c);
/// What the category is, in words ("friction heat: journals, bearings, brakes, clutch slip").
std::string energyCategoryLabel(EnergyCategory c);

/**
 * Applies no force. Allocates one auxiliary state z_i per EnergyFlow of the
 * scene and sets ż_i = P_i (its power), so the integrator carries the work
 * integrals W_i = ∫ P_i dt at its own accuracy — no quadrature over
 * samples. With them
 * <pre>
 *   ΔKE + ΔPE = W_sources − W_loads − W_dissipated       (exact, per run)
 * </pre>
 * and the residual of that identity measures the integration error. Built
 * by the SceneBuilder after every element, so it sees all their flows;
 * `elementTypes[i]` is the type of the element that declared flow i.
 */
class EnergyMeter : public SimTK::Force::Custom::Implementation {
public:
    EnergyMeter(const SimTK::GeneralForceSubsystem& forces, std::vector<EnergyFlow> flows,
                const std::vector<std::string>& elementTypes);

    /// Work done by flow i since the start of the run [J].
    double work(const SimTK::State& state, std::size_t i) const;
    const std::vector<EnergyFlow>& flows() const { return m_flows; }
    /// The force subsystem the meter (and gravity) belong to.
    const SimTK::GeneralForceSubsystem& forceSubsystem() const { return m_forces; }
    /// What flow i is (energyCategory of its kind and element type).
    EnergyCategory category(std::size_t i) const { return m_categories.at(i); }
    /// What flow i is, in words: the element's own description if it gave
    /// one, else its category's.
    std::string describe(std::size_t i) const;

    void calcForce(const SimTK::State&, SimTK::Vector_<SimTK::SpatialVec>&, SimTK::Vector_<SimTK::Vec3>&,
                   SimTK::Vector&) const override {}
    SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }
    void realizeTopology(SimTK::State& state) const override;
    void realizeAcceleration(const SimTK::State& state) const override;

private:
    const SimTK::GeneralForceSubsystem& m_forces;
    std::vector<EnergyFlow> m_flows;
    std::vector<EnergyCategory> m_categories;
    mutable SimTK::ZIndex m_first;
};

/**
 * Work of each category between two states of one run, and the changes
 * of stored energy: kinetic, gravitational (every UniformGravity force:
 * lifted bodies and a charge's lift) and elastic (every other potential:
 * coupling, belt and shaft strain). Both states realized to Dynamics.
 */
struct EnergySplit {
    double work[kEnergyCategories] = {};  ///< by EnergyCategory [J]
    double kinetic = 0, gravitational = 0, elastic = 0;  ///< end minus start [J]
    double stored() const { return kinetic + gravitational + elastic; }
    /// Mechanical input (MotorInput − MotorLoss) less what the split
    /// accounts for: the integration error [J].
    double residual() const;
    double of(EnergyCategory c) const { return work[static_cast<int>(c)]; }
};
EnergySplit calcEnergySplit(const EnergyMeter& meter, const SimTK::MultibodySystem& system,
                            const SimTK::State& start, const SimTK::State& end);

}  // namespace milldyn
