#pragma once
// HarmonicForcing: what a periodic load declares about its harmonics so that
// frequency_response and resonance_map can force the linear model with it
// without knowing the element's type (PeriodicLoad, AngleLoad, a plugin's).

#include <Simbody.h>

#include <string>
#include <vector>

namespace milldyn {

struct ElementSpec;

/// Term t's share of harmonic k, per unit of the harmonic's amplitude.
struct ForcingPhasor {
    double weight = 1;  ///< >= 0
    double phase = 0;   ///< [rad]
};

/**
 * A load's periodic part as harmonics 1..K, each acting on a fixed list of
 * terms (a PeriodicLoad's rows, an AngleLoad's shafts), each term on one
 * pin-jointed body.
 *
 * <pre>
 *   load torque of term t, harmonic k (> 0 opposes +ω; applied as −it):
 *     B_k·w_kt·sin(P_k·τ + φ_kt)                B_k = forcingAmplitude(k),
 *                                               (w_kt, φ_kt) = forcingPhasor(k, t, steady)
 *   P_k: Clock::Time        P_k = forcingOrder(k) [rad/s], the same for every term
 *        Clock::ShaftAngle  P_k = forcingOrder(k)·|ω_t|: forcingOrder(k) events per
 *                           revolution of term t's body, ω_t its steady speed
 * </pre>
 *
 * τ is the time from the steady state given (a time clock's phases are at
 * τ = t). The analyses linearize about steady running with the excitations
 * off and apply these harmonics as forcing along it (the angle's
 * dependence on the vibration itself, a parametric term, is neglected:
 * docs/elements/AngleLoad.md). A load implements it beside
 * SimTK::Force::Custom::Implementation; the analyses find it with
 * Scene::findElement<HarmonicForcing>.
 */
class HarmonicForcing {
public:
    enum class Clock { Time, ShaftAngle };
    virtual ~HarmonicForcing() = default;

    virtual Clock forcingClock() const = 0;
    /// The bodies of the terms, one entry per term (a body may repeat).
    virtual std::vector<SimTK::MobilizedBody> forcingBodies() const = 0;
    /// K: harmonics 1..K are declared.
    virtual int forcingHarmonicCount() const = 0;
    /// B_k [N*m], >= 0.
    virtual double forcingAmplitude(int k) const = 0;
    /// Time: P_k [rad/s]; ShaftAngle: events per revolution of a term's body.
    virtual double forcingOrder(int k) const = 0;
    /// Term t's weight and phase in harmonic k, in steady running `steady`
    /// (realized to Velocity: a shaft-angle load reads the angles and the
    /// direction of turning there).
    virtual ForcingPhasor forcingPhasor(int k, int term, const SimTK::State& steady) const = 0;
    /// What the terms are, plural ("rows", "shafts"), for messages.
    virtual std::string forcingTermName() const { return "rows"; }
    /// A few words on the pattern ("9 rows, staggered"), for the notes.
    virtual std::string forcingDescription() const = 0;
    /// frequency_response's time check: edits this element's `spec` so that
    /// its only periodic part is harmonic k at P [rad/s] with B_k = 1 N*m.
    /// false when the element cannot be forced so (a shaft-angle load: its
    /// frequency is its shaft's speed).
    virtual bool setTimeCheckForcing(ElementSpec& spec, int k, double P) const {
        (void)spec, (void)k, (void)P;
        return false;
    }
};

}  // namespace milldyn
