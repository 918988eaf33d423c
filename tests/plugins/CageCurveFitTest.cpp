// The circuit fit to a published torque and current curve, and a slip-ring
// (single-cage) motor fitted from its own datasheet (issue 28 item 2). The
// data are generated here by the textbook T equivalent circuit of a known
// machine, written in this file (per-phase impedances, the magnetising
// branch in parallel with each rotor branch R'/s + jX'; Fitzgerald &
// Kingsley, "Electric Machinery", ch. 6; the single cage's breakdown by
// Thevenin's closed form), independently of CageCircuitFit's own
// steady-state solution; the fit must recover the curve and the machine.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include "driver/ModelFile.h"
#include "driver/analyses/Analysis.h"
#include "plugins/motors/CageCircuitFit.h"

namespace milldyn {
namespace {

using C = std::complex<double>;

// A machine by its reactances at 50 Hz, per phase of the equivalent star.
struct Machine {
    double Rs, Xs, Xm;
    std::vector<double> Rr, Xr;  // per cage
};

struct Point {
    double torque, current, powerFactor, inputPower;
};

constexpr double kV = 6000 / 1.7320508075688772;  // phase voltage of a 6 kV machine
constexpr double kF = 50;
constexpr int kP = 2;
const double kWs = 2 * M_PI * kF / kP;  // synchronous speed [rad/s]

// Textbook T circuit at slip s: Z = Rs + jXs + (jXm ∥ Σ_k ∥ (Rr_k/s + jXr_k)),
// I = V/Z, E = V − (Rs + jXs)·I, I_k = E/(Rr_k/s + jXr_k),
// T = 3·Σ|I_k|²·Rr_k/s / ω_s, P_in = 3·Re(V·conj(I)).
Point textbook(const Machine& m, double s) {
    C Y = 1.0 / C(0, m.Xm);
    for (std::size_t k = 0; k < m.Rr.size(); ++k) Y += 1.0 / C(m.Rr[k] / s, m.Xr[k]);
    const C Zs(m.Rs, m.Xs);
    const C I = kV / (Zs + 1.0 / Y);
    const C E = kV - Zs * I;
    double airGap = 0;
    for (std::size_t k = 0; k < m.Rr.size(); ++k) airGap += 3 * std::norm(E / C(m.Rr[k] / s, m.Xr[k])) * m.Rr[k] / s;
    const double P = 3 * std::real(kV * std::conj(I));
    return {airGap / kWs, std::abs(I), P / (3 * kV * std::abs(I)), P};
}

// The largest torque over slip: a fine log scan and golden section (the
// double cage has no closed form).
double breakdownByScan(const Machine& m) {
    double best = 0, bestS = 1;
    for (int i = 0; i <= 4000; ++i) {
        const double s = std::pow(10.0, -4.0 + 4.0 * i / 4000);
        const double t = textbook(m, s).torque;
        if (t > best) best = t, bestS = s;
    }
    double a = bestS / 1.01, b = std::min(1.0, bestS * 1.01);
    const double g = 0.5 * (std::sqrt(5.0) - 1);
    for (int i = 0; i < 100; ++i) {
        const double x1 = b - g * (b - a), x2 = a + g * (b - a);
        if (textbook(m, x1).torque > textbook(m, x2).torque) b = x2;
        else a = x1;
    }
    return textbook(m, 0.5 * (a + b)).torque;
}

// Thevenin's closed form of a single cage's breakdown torque:
// V_th = V·jXm/(Rs + j(Xs + Xm)), Z_th = jXm·(Rs + jXs)/(Rs + j(Xs + Xm)),
// T_k = 3·|V_th|² / (2·ω_s·(R_th + √(R_th² + (X_th + Xr)²))).
double breakdownThevenin(const Machine& m) {
    const C Vth = kV * C(0, m.Xm) / C(m.Rs, m.Xs + m.Xm);
    const C Zth = C(0, m.Xm) * C(m.Rs, m.Xs) / C(m.Rs, m.Xs + m.Xm);
    const double R = Zth.real(), X = Zth.imag() + m.Xr[0];
    return 3 * std::norm(Vth) / (2 * kWs * (R + std::sqrt(R * R + X * X)));
}

// The datasheet of the known machine at rated speed `ratedRpm`.
MotorDatasheet datasheetOf(const Machine& m, double ratedRpm, double breakdownTorque) {
    const double wn = ratedRpm * M_PI / 30, sn = 1 - wn / kWs;
    const Point rated = textbook(m, sn), locked = textbook(m, 1.0);
    MotorDatasheet d;
    d.ratedSpeed = wn;
    d.ratedPower = rated.torque * wn;
    d.lineVoltage = 6000;
    d.ratedCurrent = rated.current;
    d.powerFactor = rated.powerFactor;
    d.efficiency = rated.torque * wn / rated.inputPower;  // the fit's η_n: P_n over the circuit's input
    d.lockedRotorTorqueRatio = locked.torque / rated.torque;
    d.breakdownTorqueRatio = breakdownTorque / rated.torque;
    d.lockedRotorCurrentRatio = locked.current / rated.current;
    d.frequency = kF;
    return d;
}

// A 1 MW 4-pole slip-ring motor (6 kV): Lsσ = Lrσ' (the fit's convention).
Machine slipRing() { return {0.35, 6.0, 250.0, {0.45}, {6.0}}; }

TEST(CageCurveFit, TextbookSingleCageBreakdownIsThevenins) {
    // The two textbook breakdowns agree: the scan used for the double cage
    // is the closed form's maximum.
    const Machine m = slipRing();
    EXPECT_NEAR(breakdownByScan(m), breakdownThevenin(m), 1e-9 * breakdownThevenin(m));
}

TEST(CageCurveFit, SlipRingMotorFromItsOwnDatasheetWithoutStartingValues) {
    // A slip-ring datasheet gives no shorted-ring Ma, Ia: the single cage is
    // fitted to Mn, I_n, cos φ_n, η_n and Mk and recovers the machine, whose
    // Ma and Ia then follow.
    const Machine m = slipRing();
    MotorDatasheet d = datasheetOf(m, 1485, breakdownThevenin(m));
    const double Ma = d.lockedRotorTorqueRatio, Ia = d.lockedRotorCurrentRatio;
    d.lockedRotorTorqueRatio = d.lockedRotorCurrentRatio = 0;
    EXPECT_EQ(checkDatasheet(d).key, "");
    const CageFitResult fit = fitCageCircuit(d, 1);
    ASSERT_EQ(fit.points.size(), 5u);  // Mn, I_n, cos φ_n, η_n, Mk
    for (const FitPoint& pt : fit.points) EXPECT_LT(std::abs(pt.residual), 1e-7) << pt.name;
    const double w = 2 * M_PI * kF;
    EXPECT_NEAR(fit.circuit.statorResistance, m.Rs, 1e-5 * m.Rs);
    EXPECT_NEAR(w * fit.circuit.statorLeakage, m.Xs, 1e-5 * m.Xs);
    EXPECT_NEAR(w * fit.circuit.mainInductance, m.Xm, 1e-5 * m.Xm);
    EXPECT_NEAR(fit.circuit.rotorResistances[0], m.Rr[0], 1e-5 * m.Rr[0]);
    const CagePoint locked = cageSteadyState(fit.circuit, fit.phaseVoltage, kF, fit.polePairs, 1.0);
    EXPECT_NEAR(locked.torque / (d.ratedPower / d.ratedSpeed), Ma, 1e-5 * Ma);
    EXPECT_NEAR(locked.current / d.ratedCurrent, Ia, 1e-5 * Ia);
    // A double cage is fitted to starting values: without them it is refused.
    EXPECT_THROW(fitCageCircuit(d, 2), std::invalid_argument);
}

TEST(CageCurveFit, SingleCageRecoversAPublishedCurrentCurve) {
    // The current curve at five speeds (and no Ma, Ia): fitted, each point's
    // residual reported, every one met, the machine recovered.
    const Machine m = slipRing();
    MotorDatasheet d = datasheetOf(m, 1485, breakdownThevenin(m));
    d.lockedRotorTorqueRatio = d.lockedRotorCurrentRatio = 0;
    for (double rpm : {0.0, 500.0, 1000.0, 1300.0, 1450.0}) {
        d.curveSpeeds.push_back(rpm * M_PI / 30);
        d.curveCurrents.push_back(textbook(m, 1 - rpm / 1500).current);
    }
    EXPECT_EQ(checkDatasheet(d).key, "");
    const CageFitResult fit = fitCageCircuit(d, 1);
    ASSERT_EQ(fit.points.size(), 10u);
    for (std::size_t i = 0; i < 5; ++i) {
        const FitPoint& pt = fit.points[5 + i];
        EXPECT_EQ(pt.key, "curve_currents");
        EXPECT_EQ(pt.unit, "A");
        EXPECT_EQ(pt.data, d.curveCurrents[i]);
        // The reported residual is the circuit's current at that speed.
        const CagePoint at = cageSteadyState(fit.circuit, fit.phaseVoltage, kF, fit.polePairs, 1 - d.curveSpeeds[i] / kWs);
        EXPECT_NEAR(pt.model, at.current, 1e-9 * at.current);
        EXPECT_LT(std::abs(pt.residual), 1e-7) << pt.name;
    }
    EXPECT_NEAR(fit.circuit.rotorResistances[0], m.Rr[0], 1e-5 * m.Rr[0]);
    EXPECT_NEAR(2 * M_PI * kF * fit.circuit.mainInductance, m.Xm, 1e-5 * m.Xm);
}

TEST(CageCurveFit, DoubleCageRecoversPublishedTorqueAndCurrentCurves) {
    // A double cage (Lsσ = Lrσ,2', the fit's convention) given by its
    // datasheet and both curves at six speeds: every point met.
    const Machine m = {0.30, 5.0, 220.0, {2.2, 0.42}, {2.0, 5.0}};
    MotorDatasheet d = datasheetOf(m, 1485, breakdownByScan(m));
    for (double rpm : {0.0, 300.0, 700.0, 1100.0, 1350.0, 1440.0}) {
        const Point pt = textbook(m, 1 - rpm / 1500);
        d.curveSpeeds.push_back(rpm * M_PI / 30);
        d.curveTorques.push_back(pt.torque);
        d.curveCurrents.push_back(pt.current);
    }
    EXPECT_EQ(checkDatasheet(d).key, "");
    const CageFitResult fit = fitCageCircuit(d, 2);
    ASSERT_EQ(fit.points.size(), 7u + 12u);
    for (const FitPoint& pt : fit.points) EXPECT_LT(std::abs(pt.residual), 1e-5) << pt.name;
    // Between the points too: the circuit is the machine.
    for (double rpm : {150.0, 900.0, 1400.0}) {
        const double s = 1 - rpm / 1500;
        const CagePoint at = cageSteadyState(fit.circuit, fit.phaseVoltage, kF, fit.polePairs, s);
        EXPECT_NEAR(at.torque, textbook(m, s).torque, 1e-4 * textbook(m, s).torque) << rpm;
        EXPECT_NEAR(at.current, textbook(m, s).current, 1e-4 * textbook(m, s).current) << rpm;
    }
}

TEST(CageCurveFit, ImpossibleCurvesAreRefusedWithTheReason) {
    const Machine m = slipRing();
    const MotorDatasheet base = datasheetOf(m, 1485, breakdownThevenin(m));
    const double Mn = base.ratedPower / base.ratedSpeed;
    auto with = [&](double rpm, double torque, double current) {
        MotorDatasheet d = base;
        d.curveSpeeds = {rpm * M_PI / 30};
        if (torque > 0) d.curveTorques = {torque};
        if (current > 0) d.curveCurrents = {current};
        return checkDatasheet(d);
    };
    // An air-gap power T·ω_s above √3·V·I: 1.5 Mn from a current that
    // carries 1 Mn at most.
    const double oneMnCurrent = Mn * kWs / (std::sqrt(3.0) * 6000);
    DatasheetProblem p = with(1000, 1.5 * Mn, oneMnCurrent);
    EXPECT_EQ(p.key, "curve_currents");
    EXPECT_NE(p.reason.find("exceeds the apparent input"), std::string::npos) << p.reason;
    // Driving torque at synchronous speed.
    EXPECT_EQ(with(1500, 0.5 * Mn, 0).key, "curve_speeds");
    // A torque above Mk.
    p = with(1400, 1.01 * base.breakdownTorqueRatio * Mn, 0);
    EXPECT_EQ(p.key, "curve_torques");
    EXPECT_NE(p.reason.find("exceeds the breakdown torque"), std::string::npos) << p.reason;
    // A standstill current 20 % off the datasheet's Ia, and a torque 20 % off Ma.
    const double Ia = base.lockedRotorCurrentRatio * base.ratedCurrent, Ma = base.lockedRotorTorqueRatio * Mn;
    p = with(0, 0, 1.2 * Ia);
    EXPECT_EQ(p.key, "curve_currents");
    EXPECT_NE(p.reason.find("differ by 20 %"), std::string::npos) << p.reason;
    EXPECT_EQ(with(0, 0.8 * Ma, 0).key, "curve_torques");
    // One current per speed; speeds without either curve.
    MotorDatasheet d = base;
    d.curveSpeeds = {0, 1000 * M_PI / 30};
    d.curveCurrents = {Ia};
    EXPECT_EQ(checkDatasheet(d).key, "curve_currents");
    d.curveCurrents.clear();
    EXPECT_EQ(checkDatasheet(d).key, "curve_speeds");
    // Consistent points pass, and the fit refuses what checkDatasheet refuses.
    EXPECT_EQ(with(0, Ma, Ia).key, "");
    d.curveCurrents = {Ia, 2 * Ia};
    d.curveTorques = {Ma, 3 * base.breakdownTorqueRatio * Mn};
    EXPECT_THROW(fitCageCircuit(d, 1), std::invalid_argument);
}

// The element: a slip-ring datasheet without its starting values builds and
// derives the circuit's; a cage motor's starting values on a single cage
// are refused with what one rotor circuit gives; curve_currents located.
std::string errorOf(const std::string& keys) {
    const std::string text =
        "format_version: 1\nname: t\nbodies:\n  - name: shaft\n    inertia: 100 kg*m^2\n"
        "    joint: {type: pin, parent: ground}\nelements:\n  - type: DqInductionMotor\n    name: motor\n    body: shaft\n" +
        keys + "scenario:\n  analysis: transient\n  end_time: 1 s\n";
    try {
        readModelText(text, "m.yaml", defaultModelReader());
    } catch (const SpecError& e) {
        return e.formatted();
    }
    return std::string();
}

const std::string kSlipRing =
    "    rated_power: 1000.2 kW\n    rated_speed: 1490 rpm\n    rated_voltage: 6000 V\n    rated_current: 115 A\n"
    "    rated_power_factor: 0.87\n    rated_efficiency: 0.962\n    breakdown_ratio: 2.2\n";

TEST(CageCurveFit, SlipRingElementFromItsDatasheetOrTheStartingValuesItHas) {
    EXPECT_EQ(errorOf(kSlipRing + "    cage: single\n    starter: liquid_resistance\n    ramp_time: 20 s\n"), "");
    // The double cage (default) needs the starting values.
    const std::string twin = errorOf(kSlipRing);
    EXPECT_NE(twin.find("m.yaml:"), std::string::npos) << twin;
    EXPECT_NE(twin.find("error: motor.rated_power: a datasheet needs locked_rotor_ratio"), std::string::npos) << twin;
    // A cage motor's Ma, Ia (0.5, 5) on one rotor circuit: refused, with the
    // values one circuit has at this rated point and Mk.
    const std::string cageValues =
        errorOf(kSlipRing + "    cage: single\n    locked_rotor_ratio: 0.5\n    locked_rotor_current_ratio: 5\n");
    EXPECT_NE(cageValues.find("error: motor.locked_rotor"), std::string::npos) << cageValues;
    EXPECT_NE(cageValues.find("one rotor circuit with this rated point and Mk has Ma/Mn = "), std::string::npos) << cageValues;
    EXPECT_NE(cageValues.find("use cage: double"), std::string::npos) << cageValues;
    EXPECT_EQ(std::count(cageValues.begin(), cageValues.end(), '\n'), 0) << cageValues;
    const std::string sizes =
        errorOf(kSlipRing + "    cage: single\n    curve_speeds: [0 rpm, 1000 rpm]\n    curve_currents: [400 A]\n");
    EXPECT_NE(sizes.find("error: motor.curve_currents: give one current per curve_speeds item (2)"), std::string::npos)
        << sizes;
    const std::string lone = errorOf(kSlipRing + "    cage: single\n    curve_speeds: [0 rpm]\n");
    EXPECT_NE(lone.find("error: motor.curve_speeds: give the curve's curve_torques, curve_currents or both"),
              std::string::npos)
        << lone;
    const std::string impossible =
        errorOf(kSlipRing + "    cage: single\n    curve_speeds: [1000 rpm]\n    curve_torques: [9000 N*m]\n"
                            "    curve_currents: [50 A]\n");
    EXPECT_NE(impossible.find("error: motor.curve_currents: the air-gap power"), std::string::npos) << impossible;
}

}  // namespace
}  // namespace milldyn
