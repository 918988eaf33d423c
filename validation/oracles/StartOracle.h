#pragma once
// StartOracle: textbook closed forms for starting a drive, written from the
// equations alone (standard library only; no Simbody, no milldyn element),
// so the multibody model's start can be checked against them.
//
// Sources: the equation of motion J·dω/dt = M − Mc; the Kloss formula
// M = 2·Mk/(s/sk + sk/s) (Kloss 1927; e.g. Fischer, "Elektrische
// Maschinen", §7; Chilikin, "Electric drive", ch. 3); the rotor circuit's
// heat P = M·ωc·s (air-gap power times slip); the induction machine's
// torque ∝ V² at constant frequency; star connection: phase voltage
// V/√3.

namespace milldyn::oracles {

/// Time to accelerate J [kg*m^2] from rest to ω [rad/s] under constant
/// motor torque M and constant load Mc [N*m]: t = J·ω/(M − Mc) [s].
double constantTorqueStartTime(double J, double omega, double M, double Mc);

/// The Kloss breakdown slip from the nameplate: sk = sn·(λ + √(λ² − 1)).
double klossBreakdownSlip(double ratedSlip, double breakdownRatio);
/// The Kloss torque 2·Mk·s·sk/(s² + sk²) [N*m].
double klossTorque(double slip, double breakdownTorque, double breakdownSlip);
/// The steady slip under a constant load Mc < Mk on the stable branch
/// (s < sk): s = sk·(Mk/Mc − √((Mk/Mc)² − 1)).
double klossSteadySlip(double loadTorque, double breakdownTorque, double breakdownSlip);
/// Time for a DOL Kloss start of a pure inertia J from rest (s = 1) to
/// slip s_e: t = J·ωc/(2·Mk)·[(1 − s_e²)/(2·sk) + sk·ln(1/s_e)] [s].
double klossInertiaStartTime(double J, double synchronousSpeed, double breakdownTorque, double breakdownSlip,
                             double endSlip);

/// The modified Kloss torque with the stator-resistance term (Chilikin,
/// "Electric drive", ch. 3; Kopylov, "Electrical machines"):
/// M = Mk·2(1 + a·sk)/(s/sk + sk/s + 2a·sk) [N*m], a = R1/R2'.
double modifiedKlossTorque(double slip, double breakdownTorque, double breakdownSlip, double asymmetry);
/// sk and a of the modified Kloss law through M(sn) = Mn and M(1) = μ·Mn
/// with maximum Mk = λ·Mn, solved by eliminating q = a·sk with the s = 1
/// equation, q(sk) = (μ·(sk + 1/sk) − 2λ)/(2(λ − μ)), and bisecting the
/// rated-point residual sn/sk + sk/sn − 2λ − 2(λ − 1)·q(sk) in sk between
/// the q = 0 root sn·(λ + √(λ² − 1)) and 1. Returns false when no root with
/// 0 <= q < 1 lies there.
bool modifiedKlossFit(double ratedSlip, double breakdownRatio, double startingRatio, double& breakdownSlip,
                      double& asymmetry);
/// Time for a DOL modified Kloss start of a pure inertia J from rest (s = 1)
/// to slip s_e, J·ωc·ds/dt = −M(s) integrated in closed form:
/// t = J·ωc/(2·Mk·(1 + q))·[(1 − s_e²)/(2·sk) + sk·ln(1/s_e) + 2q·(1 − s_e)] [s].
double modifiedKlossInertiaStartTime(double J, double synchronousSpeed, double breakdownTorque, double breakdownSlip,
                                     double asymmetry, double endSlip);

/// Line current [A] at slip s by the circle diagram (magnetising branch at
/// the terminals, stator resistance neglected; Fitzgerald & Kingsley,
/// "Electric Machinery"; Kostenko & Piotrovsky, "Electrical Machines")
/// through the catalogue's rated current I_N [A] at rated slip sn with
/// power factor c, and the locked-rotor current k·I_N at s = 1. Per unit of
/// V and I_N the rotor current is a circle through the origin of diameter D
/// on the −j axis, the stator current that circle shifted by −j·Iμ; a
/// point's slip is s = s_c·(−Im I2)/Re I2. Solved here in Iμ: the rated
/// point (c, −√(1 − c²)) on the circle gives, with w = √(1 − c²) − Iμ,
/// D = (c² + w²)/w (a chord through the origin) and s_c/sn = c/w; the
/// standstill point then fixes Iμ, bisected on [0, √(1 − c²) − c·sn].
/// NaN when no Iμ there fits.
double circleDiagramCurrent(double slip, double ratedSlip, double ratedCurrent, double powerFactor,
                            double lockedRotorRatio);
/// The slip [-] at which the circle-diagram current (the circle of
/// circleDiagramCurrent, same data) is `current` [A], in closed form: with
/// x = 1/(1 + ρ²) the circle gives |I|² = Iμ² + x·D·(D + 2Iμ) (per unit), so
/// x = (I² − Iμ²)/(D·(D + 2Iμ)) and s = s_c/√(1/x − 1). NaN outside the
/// circle's range. Under a converter at constant V/f this is the slip at
/// which a current limit holds (slip speed s·ωc).
double circleDiagramSlipAtCurrent(double current, double ratedSlip, double ratedCurrent, double powerFactor,
                                  double lockedRotorRatio);

/// Loss model of an induction motor from its rated efficiency η (the
/// split of IEC 60034-2-1's summation of losses, stray load loss lumped
/// with the stator copper loss): at rated load the input P_n/η is the
/// air-gap power Mn·ωc (shaft power Mn·ωn plus rotor copper loss
/// Mn·(ωc − ωn)), the stator copper loss and the no-load loss P0 [W]; so
/// P_Cu1,n = Mn·ωn/η − Mn·ωc − P0 [W].
double ratedStatorCopperLoss(double Mn, double ratedSpeed, double synchronousSpeed, double ratedEfficiency,
                             double noLoadLoss);
/// Electrical input [W] at rated voltage and frequency of a motor giving
/// torque M [N*m] with line current I [A]: the air-gap power M·ωc, the
/// stator copper loss P_Cu1,n·(I/I_N)² (∝ current², R1 constant) and the
/// no-load loss P0 (constant at rated voltage and frequency).
double electricalInputPower(double M, double synchronousSpeed, double statorCopperRated, double current,
                            double ratedCurrent, double noLoadLoss);

/// Line-current ratio of a star start to delta at the same slip: phase
/// current 1/√3, and a delta's line current is √3 its phase current: 1/3.
double starDeltaCurrentRatio();

/// Torque ratio of a star start to the delta connection: (1/√3)² = 1/3.
double starDeltaTorqueRatio();
/// Torque ratio of a reduced voltage v = V/V_rated at constant frequency: v².
double reducedVoltageTorqueRatio(double voltageRatio);

/// Heat in the rotor circuit of a DOL start of a pure inertia J from rest
/// to ω_e (no load, whatever the torque curve): ∫M·(ωc − ω)dt =
/// J·(ωc·ω_e − ω_e²/2); ½·J·ωc² when ω_e = ωc [J].
double rotorHeatInertiaStart(double J, double synchronousSpeed, double endSpeed);

/// Slip energy of a friction clutch of constant torque Mf [N*m] between a
/// driving inertia J1 (no drive torque) turning at ω0 and a driven J2 at
/// rest with a constant load Mc [N*m]: the slip speed falls at
/// a = Mf/J1 + (Mf − Mc)/J2, slips for t_s = ω0/a and heats
/// E = Mf·ω0·t_s/2 = ½·Mf·ω0²/a [J] (J1 → ∞: ½·J2·ω0²·Mf/(Mf − Mc)).
/// With Mc = 0 the heat is ½·ω0²·J1·J2/(J1 + J2) for any engagement ramp
/// Mf(t): E = ∫Mf·v dt and a(t)·dt = −dv give E = ∫v·(−dv)/(1/J1 + 1/J2).
double clutchSlipEnergy(double J1, double J2, double drivingSpeed, double frictionTorque, double loadTorque);

/// Speed of an inertia J [kg*m^2] from ω0 [rad/s] under a brake whose
/// torque rises linearly from 0 to Mb over Tr [s] from t = 0, and a
/// constant load Mc [N*m], until it stops:
/// ω(t) = ω0 − (Mc·t + Mb·(t²/(2Tr) for t < Tr, t − Tr/2 after))/J [rad/s].
double brakedSpeed(double J, double omega0, double brakeTorque, double loadTorque, double rampTime, double t);

/// A rigid (frozen) charge on a free drum is a physical pendulum: with the
/// moment m·g·r_c =: W [N*m] and the drum's and charge's inertia J
/// [kg*m^2] about the axis, energy conservation ½·J·ω² + W·(1 − cos α)
/// = const. The angle [rad] at which a drum at charge angle α0 (from the
/// downward vertical) turning at ω0 [rad/s] stops:
/// α_max = acos(cos α0 − J·ω0²/(2W)).
double pendulumTurningAngle(double J, double W, double alpha0, double omega0);
/// Its speed [rad/s] through the bottom (α = 0): √(2W·(1 − cos α_max)/J).
double pendulumBottomSpeed(double J, double W, double alphaMax);
/// The torque [N*m] that holds the charge at angle α: W·sin α.
double chargeHoldingTorque(double W, double alpha);

/// Steady torque [N*m] of an induction machine at slip s from its T
/// equivalent circuit per phase (Fitzgerald & Kingsley, "Electric
/// Machinery"): Z = Rs + jX_sσ + jX_m ∥ (Rr/s + jX_rσ), X = 2πf·L,
/// I_s = V/Z, I_r = I_s·jX_m/(Rr/s + j(X_rσ + X_m)),
/// T = 3·|I_r|²·(Rr/s)/(2πf/p). V the rms phase voltage [V], resistances
/// [ohm], inductances [H], f [Hz], p pole pairs.
double equivalentCircuitTorque(double slip, double Rs, double Rr, double Lss, double Lrs, double Lm, int p, double V,
                               double f);

}  // namespace milldyn::oracles
