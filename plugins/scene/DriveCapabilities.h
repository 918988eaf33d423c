#pragma once
// What a drive declares about itself so that generic analyses (the linear
// model, a transient's motor reports) ask what it can do instead of naming
// its type (issue 31 item 4). A drive implements these beside
// SimTK::Force::Custom::Implementation, as a load implements
// HarmonicForcing; the analyses find them with Scene::findElement<T> on the
// names of the scene's drives (Scene::drives()).

#include <Simbody.h>

#include <string>
#include <vector>

namespace milldyn {

/**
 * First-order states of the drive's own (a dq machine's flux linkages)
 * that a linear model can carry as states, hold frozen or eliminate at
 * their steady state (scenario.motor_model: dq_states, frozen_flux,
 * static_slope; driver/analyses/LinearModel.h). Steady running must be an
 * equilibrium of them in a frame turning at electricalFrameSpeed().
 */
class ElectricalStates {
public:
    virtual ~ElectricalStates() = default;
    /// Index in the State's z of the first of them (the rest follow).
    virtual int firstElectricalState(const SimTK::State& state) const = 0;
    virtual int electricalStateCount() const = 0;
    /// Name of state k < electricalStateCount(), appended to the element's
    /// name after a dot ("psi_s_alpha").
    virtual std::string electricalStateName(int k) const = 0;
    /// Speed of the frame their phasor pairs turn in during steady running
    /// (the supply's electrical angular frequency) [rad/s].
    virtual double electricalFrameSpeed() const = 0;
};

/**
 * A drive whose torque is a static function of its shaft speed (a torque–
 * speed curve, no states of its own): in a linear model it is its slope at
 * the operating point whatever scenario.motor_model says, and its peaks at
 * switch-on are the curve's, not an electrical transient's.
 */
class StaticTorqueSpeedCurve {
public:
    virtual ~StaticTorqueSpeedCurve() = default;
    /// Natural torque (rated supply, direct on line) at shaft speed ω [rad/s] [N*m].
    virtual double torqueAtSpeed(double omega) const = 0;
};

/**
 * A drive fed through a supply impedance, whose start dips the voltage at
 * its supply point; it keeps the largest dip over every accepted step.
 */
class SupplyVoltageDip {
public:
    virtual ~SupplyVoltageDip() = default;
    /// Whether a supply impedance is modelled (else there is no dip).
    virtual bool hasSupplyImpedance() const = 0;
    /// Largest dip 1 − |v|/|e| over the accepted steps up to `state` [-].
    virtual double getPeakVoltageDip(const SimTK::State& state) const = 0;
    /// The dip above which the drive's start is reported as too harsh [-]
    /// (+inf: none given).
    virtual double voltageDipLimit() const = 0;
    /// The supply in words for the report ("S_k = 40 MVA, X/R = 10").
    virtual std::string supplyDescription() const = 0;
};

/**
 * A motor on an electrical supply (its pole pairs, its synchronous speed)
 * whose operating point a frequency converter sets by scaling the supply:
 * the Campbell diagram's supply lines and its operating_point
 * supply_scaled, which scales the keys supplyFrequencyKeys() names by one
 * factor.
 */
class SupplyFedDrive {
public:
    virtual ~SupplyFedDrive() = default;
    /// Pole pairs p [1] on a supply of angular frequency `supply` [rad/s]
    /// (a law that knows only its synchronous speed takes p from it).
    /// Throws std::invalid_argument saying why the drive does not fit it.
    virtual double polePairsOn(double supply) const = 0;
    /// Synchronous speed at the rated supply [rad/s].
    virtual double ratedSynchronousSpeed() const = 0;
    /// The element's keys proportional to the supply frequency.
    virtual std::vector<std::string> supplyFrequencyKeys() const = 0;
    /// "" when scaling those keys scales the drive, else why not.
    virtual std::string whySupplyNotScalable() const = 0;
    /// Fed through a frequency converter (its starter).
    virtual bool converterFed() const = 0;
};

}  // namespace milldyn
