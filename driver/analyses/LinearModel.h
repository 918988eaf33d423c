#pragma once
// The linear model of a Scene about an operating point:
//   M·q̈ + C·q̇ + K·q = f      (q, q̇ deviations from the operating point)
// M from Simbody (calcM), C and K from central differences of the
// accelerations: K = −M·∂q̈/∂q, C = −M·∂q̈/∂q̇. Joints with q̇ = u only (pin,
// gimbal, bushing; not ball or free, whose q are quaternions).
//
// Kinematic constraints (a rigid GearPair or BeltDrive, a GearMesh) are
// reduced to independent coordinates v (with reduceConstraints): the
// constraint Jacobian G (Simbody's calcG, G·u = 0) gives a null-space basis
// N with G·N = 0, u = N·v, whose v are the velocities of the mobilities
// kept independent (the first in body order; the last ones a constraint
// determines are eliminated). The state is moved along N's columns only, so
// the constraints stay satisfied and u̇ stays in N's range; projecting
// M·u̇ + Gᵀλ = f on N removes the constraint forces:
//   M_r = Nᵀ·M·N,  K_r = −Nᵀ·M·∂u̇/∂v (q moved),  C_r = −Nᵀ·M·∂u̇/∂v (u moved).
// Assumption: the constraints are holonomic and linear in q at the point
// (G constant: gear and belt ratio constraints are r1·q1 ± r2·q2 = const),
// checked by moving the state ±0.01 along every column of N; nonholonomic,
// acceleration-only or non-linear constraints are refused, naming them.

#include "plugins/scene/Scene.h"

#include <Eigen/Dense>

#include <complex>
#include <string>
#include <vector>

namespace milldyn {

/// How a DqInductionMotor's fluxes enter a linear model (the static
/// InductionMotor is its torque–speed slope in all three):
///  - DqStates: the flux states are states of the linear model (Afull):
///    the electrical damping and stiffness the machine puts on the train,
///    and the machine's own electrical modes;
///  - FrozenFlux: the fluxes held at their operating-point values in the
///    stator frame (the mechanical rows only): no electrical damping;
///  - StaticSlope: the fluxes at their steady state for every speed (the
///    quasi-static reduction A_mm − A_mz·A_zz⁻¹·A_zm of Afull, the
///    frequency → 0 limit of the machine): the steady torque–speed slope of
///    the same machine, as a catalogue curve would give it.
enum class MotorModel { DqStates, FrozenFlux, StaticSlope };
/// "dq_states", "frozen_flux", "static_slope" (the scenario key's words).
const char* motorModelName(MotorModel model);
MotorModel motorModelFromName(const std::string& word);

struct LinearModel {
    /// The motor model the second-order matrices, `eigenvalues` and the
    /// harmonic response use (the same for all three without dq machines).
    MotorModel motorModel = MotorModel::FrozenFlux;
    /// [kg*m^2], [N*m*s/rad], [N*m/rad]: FrozenFlux and DqStates the
    /// mechanical system with the fluxes frozen (DqStates adds the states'
    /// coupling in Afull), StaticSlope with the quasi-static reduction.
    Eigen::MatrixXd M, C, K;
    Eigen::MatrixXd A;             ///< first-order state matrix [q; u] of M, C, K
    /// The chosen model's eigenvalues, sorted by |imag| then real [1/s]:
    /// of A, or of Afull with DqStates (and dq machines).
    Eigen::VectorXcd eigenvalues;
    Eigen::VectorXd naturalFrequencies;  ///< undamped, from K v = ω² M v [rad/s]
    /// Columns, one per mode, rows every mobility (bodyNames; u = N·v when
    /// constrained), max |entry| = 1.
    Eigen::MatrixXd modeShapes;
    std::vector<std::string> dofNames;   ///< the coordinates of M, C, K: independent mobilities' names
    std::vector<std::string> bodyNames;  ///< mobilityNames(): every mobility, the rows of modeShapes
    /// u = N·v (n × r) when constraints were reduced; empty without constraints (N = I).
    Eigen::MatrixXd N;
    std::vector<int> independent;  ///< mobilities kept as coordinates (indices into bodyNames)
    std::vector<int> eliminated;   ///< mobilities the constraints determine
    /// Natural frequencies up to this are the differencing's round-off, not
    /// stiffness [rad/s]: sqrt(100·ε·max|u̇|/h) over the evaluations (a
    /// 1-DOF train whose gravity stiffnesses cancel would otherwise report
    /// 1e-5 rad/s as an elastic mode).
    double frequencyFloor = 0;
    /// With elements' own continuous states (the fluxes of the scene's
    /// DqInductionMotor elements): the first-order matrix of [q; u; z] (z in the
    /// frame turning with each element's phasors: ∂ż/∂z − Ω), its
    /// eigenvalues sorted as `eigenvalues`, and the z states' names. Empty
    /// without such states; A and eigenvalues above are then the whole
    /// story, and with them they are the mechanical system with those
    /// states frozen.
    Eigen::MatrixXd Afull;
    Eigen::VectorXcd eigenvaluesFull;
    std::vector<std::string> stateNames;
    /// With such states, the first-order [q; u] matrices and eigenvalues of
    /// the other two motor models, for comparison (empty without them).
    Eigen::MatrixXd Afrozen, Astatic;
    Eigen::VectorXcd eigenvaluesFrozen, eigenvaluesStatic;
    /// Output rows: probe p's deviation ≈ outputQ.row(p)·q + outputU.row(p)·q̇
    /// (+ outputZ.row(p)·z̃ with DqStates; StaticSlope has z̃ eliminated in
    /// outputQ and outputU).
    Eigen::MatrixXd outputQ, outputU, outputZ;
    std::vector<std::string> outputNames, outputUnits;
};

/// Linearizes `scene` about `operatingPoint` (the excitations it carries are
/// switched off for the derivatives). Throws AnalysisError for joints whose
/// q̇ differs from u, and for enabled constraints unless `reduceConstraints`
/// (then M, C, K, A and the output rows are in the independent coordinates).
/// With `withModes` false only M, C, K, A and the output rows are filled
/// (no eigenproblems: what a static solve needs, at O(n²) instead of O(n³)).
/// `motorModel` chooses how dq machines' fluxes enter M, C, K, A, the
/// eigenvalues and the harmonic response (Afull is filled in every case).
LinearModel linearizeScene(const Scene& scene, const SimTK::State& operatingPoint, bool withModes = true,
                           bool reduceConstraints = false, MotorModel motorModel = MotorModel::FrozenFlux);

/// True when `lambda`, an eigenvalue of `model`, is a rigid-body mode's: zero
/// up to round-off, |λ| <= max(1e-9·max|λ|, frequencyFloor). A free
/// rotation is a double zero (a Jordan block), which round-off splits into
/// ±~1e-7 when the largest |λ| is ~75 1/s: above 1e-9·max|λ|, below the floor.
bool isRigidEigenvalue(const LinearModel& model, std::complex<double> lambda);

/// The elastic modes of `model`: indices into naturalFrequencies (ascending)
/// of the modes above max(1e-6·max ω, frequencyFloor); the others are
/// rigid-body modes (a free rotation, the differencing's round-off).
/// The one numbering of modes every analysis uses (linearize's summary,
/// mode_shapes.csv, modes.csv, resonance_map, campbell): elastic modes are
/// modes 1, 2, ... in ascending frequency; rigid-body modes are mode 0.
std::vector<int> elasticModes(const LinearModel& model);
/// Frequencies up to this [rad/s] are rigid-body modes (elasticModes' bound).
double rigidModeBound(const LinearModel& model);

/// Fills naturalFrequencies and modeShapes from K v = ω² M v (K's symmetric
/// part); linearizeScene does this unless told not to.
void calcUndampedModes(LinearModel& model);

/// Each mode's number (index as naturalFrequencies): elastic modes 1, 2, ...
/// ascending, rigid-body modes 0 (elasticModes).
std::vector<int> modeNumbers(const LinearModel& model);

struct AnalysisResult;
/// Adds M, C, K, A and the eigenvalue and mode tables to a result.
void addLinearModelOutputs(const LinearModel& model, AnalysisResult& result);

/// The DqInductionMotor elements of a scene (their flux states are the
/// elements' own states a linearization includes).
std::vector<std::string> dqMachineNames(const Scene& scene);

/// Which motor model a linear analysis's damping comes from, for its notes:
/// one note naming the model used and every motor, and per oscillating
/// mechanical mode its frequency and damping ratio under the three motor
/// models (modes matched by nearest eigenvalue to the frozen-flux ones).
/// Empty when the scene has no motor.
std::vector<std::string> motorDampingNotes(const Scene& scene, const LinearModel& model);

/// The table `mode_damping_by_motor_model`: per oscillating mode of the
/// frozen-flux model, the matched eigenvalue's frequency [Hz] and damping
/// ratio under each motor model. Empty name without dq machines.
struct DataTable;
DataTable modeDampingTable(const LinearModel& model);

/// Complex amplitudes of q for the forcing f·e^{iPt} (f on the independent
/// coordinates): (K − P²M + iP·C)·X = f, or with DqStates (and dq machines)
/// (iP − Afull)·[X; iP·X; Z] = [0; M⁻¹f; 0], whose z̃ rows are returned
/// after the r entries of X when `states` is given.
Eigen::VectorXcd harmonicResponse(const LinearModel& model, double P, const Eigen::VectorXcd& force,
                                  Eigen::VectorXcd* states = nullptr);
/// Complex amplitude of probe `probe` under that forcing:
/// outputQ·X + iP·outputU·X (+ outputZ·Z with DqStates).
std::complex<double> harmonicProbeResponse(const LinearModel& model, double P, const Eigen::VectorXcd& force,
                                           int probe);

}  // namespace milldyn
