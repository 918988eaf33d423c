// linearize: the linear model M·q̈ + C·q̇ + K·q = f of a model about steady
// running, against closed forms for two shafts and one coupling.
//
// The model (written as model-file text, read like any other): shaft a
// (J_a) driven by a motor on its linear branch M = M00 − γ·ω_a, shaft b
// (J_b) loaded by a constant torque M0, and a coupling c from a to b with
// stiffness c, damping b_c and ratio n: twist Δ = q_a − n·q_b, torque
// T = c·Δ + b_c·Δ̇, −T on a and +n·T on b.
//
// Equations of motion:
//   J_a·q̈_a = M00 − γ·q̇_a − c(q_a − n q_b) − b_c(q̇_a − n q̇_b)
//   J_b·q̈_b = −M0 + n·c(q_a − n q_b) + n·b_c(q̇_a − n q̇_b)
// (the load is M0·tanh(ω/ωs), flat at running speed: no damping from it). So
//   M = diag(J_a, J_b),
//   K = c·[[1, −n], [−n, n²]]   (the Hessian of V = ½c(q_a − n q_b)²),
//   C = diag(γ, 0) + b_c·[[1, −n], [−n, n²]].
//
// Undamped frequencies: det(K − ω²M) = (c − ω²J_a)(c n² − ω²J_b) − c²n²
//   = ω²·(ω²·J_a·J_b − c·(J_b + n²·J_a)) = 0, so besides the rigid rotation
// (ω = 0, q_a = n·q_b) there is one elastic mode
//   ω² = c·(J_b + n²·J_a)/(J_a·J_b) = c·(J_a + J_b/n²)/(J_a·J_b/n²),
// the 2-mass formula with b reflected to a (J_b/n²). For n = 1:
//   ω² = c·(J_a + J_b)/(J_a·J_b).

#include "driver/ModelFile.h"
#include "driver/SceneBuilder.h"
#include "driver/Simulation.h"
#include "driver/analyses/Analysis.h"
#include "driver/analyses/LinearModel.h"

#include "validation/oracles/TumblingMillOracle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <fstream>
#include <stdexcept>
#include <sstream>
#include <string>
#include <vector>

namespace milldyn {
namespace {

// The forces are linear in q and u near running speed, so the central
// differences are exact but for round-off: ~1e-16·(force)/(step) against
// entries of order c and γ, far below this tolerance.
constexpr double kLinearRelTol = 1e-9;
constexpr double kPi = 3.14159265358979323846;

struct TwoShafts {
    double Ja = 0.5;       // kg*m^2
    double Jb = 2.0;       // kg*m^2
    double c = 800;        // N*m/rad
    double bc = 0;         // N*m*s/rad
    double n = 1;          // ratio ω_a/ω_b
    double gamma = 12.5;   // N*m*s/rad, motor slope
    double M00 = 2000;     // N*m, motor torque at standstill (linear branch)
    double M0 = 50;        // N*m, load on b

    /// Steady running: γ·ω_a = M00 − T with T = M0/n (b's balance n·T = M0).
    double steadySpeedA() const { return (M00 - M0 / n) / gamma; }
    double elasticFrequency() const { return std::sqrt(c * (Jb + n * n * Ja) / (Ja * Jb)); }
};

std::string num(double v) {
    std::ostringstream s;
    s.precision(17);
    s << v;
    return s.str();
}

std::string modelText(const TwoShafts& m, const std::string& scenario = "scenario:\n  analysis: linearize\n") {
    return "format_version: 1\n"
           "name: two shafts\n"
           "bodies:\n"
           "  - name: a\n"
           "    inertia: " + num(m.Ja) + " kg*m^2\n"
           "    joint: {type: pin, parent: ground}\n"
           "  - name: b\n"
           "    inertia: " + num(m.Jb) + " kg*m^2\n"
           "    joint: {type: pin, parent: ground}\n"
           "elements:\n"
           "  - type: InductionMotor\n"
           "    name: drive\n"
           "    body: a\n"
           "    law: linear\n"
           "    rated_torque: 100 N*m\n"
           "    rated_speed: 1440 rpm\n"
           "    synchronous_speed: 1500 rpm\n"
           "    linear_stall_torque: " + num(m.M00) + " N*m\n"
           "    linear_slope: " + num(m.gamma) + " N*m*s/rad\n"
           "  - type: TorsionalCoupling\n"
           "    name: c\n"
           "    bodies: [a, b]\n"
           "    stiffness: " + num(m.c) + " N*m/rad\n"
           "    damping: " + num(m.bc) + " N*m*s/rad\n"
           "    ratio: " + num(m.n) + "\n"
           "  - type: ResistanceTorque\n"
           "    name: load\n"
           "    body: b\n"
           "    constant_torque: " + num(m.M0) + " N*m\n" +
           scenario;
}

ModelSpec readModel(const TwoShafts& m) {
    return readModelText(modelText(m), "linearize.yaml", defaultModelReader());
}

/// Builds, solves steady running and linearizes, as runLinearize does.
LinearModel linearModel(const TwoShafts& m, double* speedA = nullptr, double* speedB = nullptr) {
    const ModelSpec spec = readModel(m);
    auto scene = buildScene(spec);
    const SimTK::State steady = solveSteadyState(*scene, initialState(*scene, spec));
    if (speedA) *speedA = pinSpeed(steady, scene->findBody("a")->mobod);
    if (speedB) *speedB = pinSpeed(steady, scene->findBody("b")->mobod);
    return linearizeScene(*scene, steady);
}

/// |actual − expected| <= tol·scale for every entry.
void expectMatrixNear(const Eigen::MatrixXd& actual, const Eigen::MatrixXd& expected, double scale,
                      const std::string& what) {
    ASSERT_EQ(actual.rows(), expected.rows()) << what;
    ASSERT_EQ(actual.cols(), expected.cols()) << what;
    for (Eigen::Index i = 0; i < actual.rows(); ++i)
        for (Eigen::Index j = 0; j < actual.cols(); ++j)
            EXPECT_NEAR(actual(i, j), expected(i, j), kLinearRelTol * scale)
                << what << "(" << i << ", " << j << ")\n" << actual;
}

Eigen::MatrixXd couplingMatrix(double k, double n) {
    Eigen::MatrixXd m(2, 2);
    m << k, -n * k, -n * k, n * n * k;
    return m;
}

/// det(λ²M + λC + K) and the sum of the magnitudes of its terms (2×2).
std::pair<double, double> quadraticDet(const Eigen::MatrixXd& M, const Eigen::MatrixXd& C, const Eigen::MatrixXd& K,
                                       std::complex<double> l) {
    auto entry = [&](int i, int j) { return l * l * M(i, j) + l * C(i, j) + K(i, j); };
    auto size = [&](int i, int j) {
        return std::norm(l) * std::abs(M(i, j)) + std::abs(l) * std::abs(C(i, j)) + std::abs(K(i, j));
    };
    const std::complex<double> det = entry(0, 0) * entry(1, 1) - entry(0, 1) * entry(1, 0);
    const double scale = size(0, 0) * size(1, 1) + size(0, 1) * size(1, 0);
    return {std::abs(det), scale};
}

const DataTable* findTable(const AnalysisResult& r, const std::string& name) {
    for (const auto& t : r.extraTables)
        if (t.name == name) return &t;
    return nullptr;
}

const NamedMatrix* findMatrix(const AnalysisResult& r, const std::string& name) {
    for (const auto& m : r.matrices)
        if (m.name == name) return &m;
    return nullptr;
}

int outputRow(const LinearModel& lm, const std::string& name) {
    for (std::size_t i = 0; i < lm.outputNames.size(); ++i)
        if (lm.outputNames[i] == name) return static_cast<int>(i);
    ADD_FAILURE() << "no output " << name;
    return -1;
}

// ------------------------------------------------------------- direct ratio 1

TEST(LinearizeTwoShafts, MassStiffnessAndDampingMatricesAreTheClosedForms) {
    const TwoShafts m;  // n = 1, no coupling damping
    double wa = 0, wb = 0;
    const LinearModel lm = linearModel(m, &wa, &wb);
    // The operating point is steady running: γ·ω = M00 − M0 on both shafts.
    EXPECT_NEAR(wa, m.steadySpeedA(), 1e-9 * m.steadySpeedA());
    EXPECT_NEAR(wb, m.steadySpeedA(), 1e-9 * m.steadySpeedA());

    EXPECT_EQ(lm.dofNames, (std::vector<std::string>{"a", "b"}));
    Eigen::MatrixXd M = Eigen::MatrixXd::Zero(2, 2);
    M(0, 0) = m.Ja;
    M(1, 1) = m.Jb;
    expectMatrixNear(lm.M, M, m.Jb, "M");
    expectMatrixNear(lm.K, couplingMatrix(m.c, 1), m.c, "K");
    Eigen::MatrixXd C = Eigen::MatrixXd::Zero(2, 2);
    C(0, 0) = m.gamma;  // the motor's slope; the coupling is undamped, the load flat
    expectMatrixNear(lm.C, C, m.gamma, "C");

    // A = [[0, I], [−M⁻¹K, −M⁻¹C]].
    ASSERT_EQ(lm.A.rows(), 4);
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(4, 4);
    A.topRightCorner(2, 2) = Eigen::MatrixXd::Identity(2, 2);
    A.bottomLeftCorner(2, 2) = -M.inverse() * couplingMatrix(m.c, 1);
    A.bottomRightCorner(2, 2) = -M.inverse() * C;
    expectMatrixNear(lm.A, A, m.c / m.Ja, "A");
}

TEST(LinearizeTwoShafts, ElasticNaturalFrequencyIsTheTwoMassFormula) {
    const TwoShafts m;
    const LinearModel lm = linearModel(m);
    // sqrt(c (J1 + J2)/(J1 J2)) = sqrt(800 · 2.5/1) = sqrt(2000) rad/s.
    const double omega = std::sqrt(m.c * (m.Ja + m.Jb) / (m.Ja * m.Jb));
    EXPECT_NEAR(omega, std::sqrt(2000.0), 1e-12 * omega);
    ASSERT_EQ(lm.naturalFrequencies.size(), 2);
    EXPECT_LE(lm.naturalFrequencies[0], 1e-6 * omega);  // the rigid rotation
    EXPECT_NEAR(lm.naturalFrequencies[1], omega, kLinearRelTol * omega);
    // Elastic mode shape: (c − ω²J_a)·v_a = c·v_b, v_b/v_a = −J_a/J_b;
    // scaled so that the largest entry is 1.
    EXPECT_NEAR(lm.modeShapes(0, 1), 1.0, 1e-9);
    EXPECT_NEAR(lm.modeShapes(1, 1), -m.Ja / m.Jb, 1e-9);
    // The rigid rotation turns both shafts alike.
    EXPECT_NEAR(lm.modeShapes(0, 0), 1.0, 1e-9);
    EXPECT_NEAR(lm.modeShapes(1, 0), 1.0, 1e-9);
}

TEST(LinearizeTwoShafts, DampedEigenvaluesAreRootsOfTheCharacteristicPolynomial) {
    const TwoShafts m;
    const LinearModel lm = linearModel(m);
    ASSERT_EQ(lm.eigenvalues.size(), 4);
    // Closed form: det(λ²M + λC + K) = (J_a λ² + γ λ + c)(J_b λ² + c) − c²
    //   = J_a J_b λ⁴ + γ J_b λ³ + c (J_a + J_b) λ² + γ c λ.
    Eigen::MatrixXd M = Eigen::MatrixXd::Zero(2, 2), C = Eigen::MatrixXd::Zero(2, 2);
    M(0, 0) = m.Ja;
    M(1, 1) = m.Jb;
    C(0, 0) = m.gamma;
    const Eigen::MatrixXd K = couplingMatrix(m.c, 1);
    int nearZero = 0, complexCount = 0;
    for (Eigen::Index i = 0; i < lm.eigenvalues.size(); ++i) {
        const std::complex<double> l = lm.eigenvalues[i];
        SCOPED_TRACE("eigenvalue " + std::to_string(i) + " = " + num(l.real()) + " + " + num(l.imag()) + "i");
        // The numerical matrices and the closed-form ones.
        const auto numeric = quadraticDet(lm.M, lm.C, lm.K, l);
        EXPECT_LE(numeric.first, 1e-9 * numeric.second);
        const auto exact = quadraticDet(M, C, K, l);
        EXPECT_LE(exact.first, 1e-9 * exact.second);
        // The expanded polynomial, against the same scale (the size of the
        // products in the determinant: its c² terms cancel in the expansion).
        const std::complex<double> p = m.Ja * m.Jb * l * l * l * l + m.gamma * m.Jb * l * l * l +
                                       m.c * (m.Ja + m.Jb) * l * l + m.gamma * m.c * l;
        EXPECT_LE(std::abs(p), 1e-9 * exact.second);
        EXPECT_LE(l.real(), 1e-9 * std::abs(lm.eigenvalues[3]));  // nothing grows
        if (std::abs(l) <= 1e-9 * std::sqrt(m.c / m.Ja)) ++nearZero;
        if (l.imag() != 0) ++complexCount;
    }
    EXPECT_EQ(nearZero, 1);      // the angle of the rigid rotation
    EXPECT_EQ(complexCount, 2);  // one underdamped elastic pair
    // Sorted by |imag|: the two real ones first, then the conjugate pair.
    EXPECT_EQ(lm.eigenvalues[2], std::conj(lm.eigenvalues[3]));
}

// ----------------------------------------------------------- ratio coupling

TEST(LinearizeRatioCoupling, StiffnessIsTheHessianOfTheTwistEnergy) {
    TwoShafts m;
    m.n = 5;
    m.Jb = 20;  // J_b/n² = 0.8 kg*m^2 reflected to a
    double wa = 0, wb = 0;
    const LinearModel lm = linearModel(m, &wa, &wb);
    EXPECT_NEAR(wa, m.steadySpeedA(), 1e-9 * wa);
    EXPECT_NEAR(wb, m.steadySpeedA() / m.n, 1e-9 * wa);
    // V = ½c(q_a − n q_b)²: ∂²V/∂q_a² = c, ∂²V/∂q_a∂q_b = −n c, ∂²V/∂q_b² = n² c.
    expectMatrixNear(lm.K, couplingMatrix(m.c, m.n), m.c * m.n * m.n, "K");
    expectMatrixNear(lm.K, couplingMatrix(m.c, m.n), m.c, "K (relative to c)");
    Eigen::MatrixXd M = Eigen::MatrixXd::Zero(2, 2);
    M(0, 0) = m.Ja;
    M(1, 1) = m.Jb;
    expectMatrixNear(lm.M, M, m.Jb, "M");
}

TEST(LinearizeRatioCoupling, NaturalFrequencyReflectsTheDrivenInertiaThroughTheRatio) {
    TwoShafts m;
    m.n = 5;
    m.Jb = 20;
    const LinearModel lm = linearModel(m);
    // ω² = c·(J_a + J_b/n²)/(J_a·J_b/n²) = 800·(0.5 + 0.8)/(0.5·0.8) = 2600 (rad/s)².
    const double reflected = m.Jb / (m.n * m.n);
    const double omega = std::sqrt(m.c * (m.Ja + reflected) / (m.Ja * reflected));
    EXPECT_NEAR(omega * omega, 2600.0, 1e-9 * 2600);
    EXPECT_NEAR(m.elasticFrequency(), omega, 1e-12 * omega);
    ASSERT_EQ(lm.naturalFrequencies.size(), 2);
    EXPECT_LE(lm.naturalFrequencies[0], 1e-6 * omega);
    EXPECT_NEAR(lm.naturalFrequencies[1], omega, kLinearRelTol * omega);
    // The rigid rotation keeps the twist zero: q_a = n·q_b, shape [1, 1/n].
    EXPECT_NEAR(lm.modeShapes(0, 0), 1.0, 1e-9);
    EXPECT_NEAR(lm.modeShapes(1, 0), 1 / m.n, 1e-9);
}

TEST(LinearizeRatioCoupling, OutputRowsAreTheDerivativesOfTheProbes) {
    TwoShafts m;
    m.n = 5;
    m.Jb = 20;
    m.bc = 3;
    const LinearModel lm = linearModel(m);
    ASSERT_EQ(lm.outputQ.rows(), static_cast<Eigen::Index>(lm.outputNames.size()));
    ASSERT_EQ(lm.outputQ.cols(), 2);
    ASSERT_EQ(lm.outputU.cols(), 2);
    ASSERT_EQ(lm.outputUnits.size(), lm.outputNames.size());

    // T = c·Δ + b_c·Δ̇, Δ = q_a − n q_b: ∂T/∂q = c·[1, −n], ∂T/∂q̇ = b_c·[1, −n].
    const int torque = outputRow(lm, "c.torque");
    ASSERT_GE(torque, 0);
    EXPECT_EQ(lm.outputUnits[torque], "N*m");
    EXPECT_NEAR(lm.outputQ(torque, 0), m.c, kLinearRelTol * m.c);
    EXPECT_NEAR(lm.outputQ(torque, 1), -m.n * m.c, kLinearRelTol * m.n * m.c);
    EXPECT_NEAR(lm.outputU(torque, 0), m.bc, kLinearRelTol * m.bc);
    EXPECT_NEAR(lm.outputU(torque, 1), -m.n * m.bc, kLinearRelTol * m.n * m.bc);
    // The twist itself: [1, −n], no speed dependence.
    const int twist = outputRow(lm, "c.twist");
    ASSERT_GE(twist, 0);
    EXPECT_NEAR(lm.outputQ(twist, 0), 1.0, kLinearRelTol);
    EXPECT_NEAR(lm.outputQ(twist, 1), -m.n, kLinearRelTol * m.n);
    EXPECT_NEAR(lm.outputU(twist, 0), 0.0, kLinearRelTol);
    EXPECT_NEAR(lm.outputU(twist, 1), 0.0, kLinearRelTol);
    // The motor torque M00 − γ ω_a.
    const int drive = outputRow(lm, "drive.torque");
    ASSERT_GE(drive, 0);
    EXPECT_NEAR(lm.outputQ(drive, 0), 0.0, kLinearRelTol * m.gamma);
    EXPECT_NEAR(lm.outputU(drive, 0), -m.gamma, kLinearRelTol * m.gamma);
    EXPECT_NEAR(lm.outputU(drive, 1), 0.0, kLinearRelTol * m.gamma);

    // C = diag(γ, 0) + b_c·[[1, −n], [−n, n²]].
    Eigen::MatrixXd C = couplingMatrix(m.bc, m.n);
    C(0, 0) += m.gamma;
    expectMatrixNear(lm.C, C, m.gamma, "C");
    expectMatrixNear(lm.K, couplingMatrix(m.c, m.n), m.c, "K");
}

// -------------------------------------------------------- the analysis result

TEST(LinearizeAnalysis, ResultHasTheEigenvalueAndModeTablesAndTheElasticFrequency) {
    const TwoShafts m;
    const ModelSpec spec = readModel(m);
    ASSERT_EQ(spec.scenario.type, "linearize");
    const AnalysisResult r = runAnalysis(spec);
    EXPECT_EQ(r.analysis, "linearize");
    const int n = 2;
    const double omega = m.elasticFrequency();

    const ResultScalar* f1 = r.find("natural_frequency_1");
    ASSERT_NE(f1, nullptr);
    EXPECT_NEAR(f1->value, omega, kLinearRelTol * omega);
    EXPECT_EQ(f1->unit, "rad/s");
    EXPECT_EQ(r.find("natural_frequency_2"), nullptr);  // the rigid rotation is not reported
    const ResultScalar* dof = r.find("degrees_of_freedom");
    ASSERT_NE(dof, nullptr);
    EXPECT_EQ(dof->value, n);

    const DataTable* eig = findTable(r, "eigenvalues");
    ASSERT_NE(eig, nullptr);
    EXPECT_EQ(eig->columnNames, (std::vector<std::string>{"index", "real", "imag", "frequency", "damping_ratio"}));
    ASSERT_EQ(eig->rows.size(), static_cast<std::size_t>(2 * n));
    int rigid = 0;
    for (const auto& row : eig->rows) {
        ASSERT_EQ(row.size(), 5u);
        const std::complex<double> l(row[1], row[2]);
        EXPECT_NEAR(row[3], std::abs(l.imag()) / (2 * kPi), 1e-12 * omega);
        EXPECT_TRUE(std::isfinite(row[4]));
        if (std::abs(l) <= 1e-9 * omega) {
            ++rigid;
            EXPECT_EQ(row[4], 0.0) << "the rigid rotation's damping ratio, eigenvalue " << l;
        } else {
            EXPECT_NEAR(row[4], -l.real() / std::abs(l), 1e-12);
            EXPECT_GT(row[4], 0.0);
            EXPECT_LE(row[4], 1.0);
        }
    }
    EXPECT_EQ(rigid, 1);

    const DataTable* modes = findTable(r, "modes");
    ASSERT_NE(modes, nullptr);
    ASSERT_EQ(modes->rows.size(), static_cast<std::size_t>(n));
    EXPECT_LE(modes->rows[0][1], 1e-6 * omega);
    EXPECT_NEAR(modes->rows[1][1], omega, kLinearRelTol * omega);
    EXPECT_NEAR(modes->rows[1][2], omega / (2 * kPi), kLinearRelTol * omega);

    // The main table: one row per mode, one column per body, by name.
    EXPECT_EQ(r.tableName, "mode_shapes");
    EXPECT_EQ(r.columnNames, (std::vector<std::string>{"mode", "natural_frequency", "a", "b"}));
    ASSERT_EQ(r.rows.size(), static_cast<std::size_t>(n));
    EXPECT_NEAR(r.rows[1][1], omega / (2 * kPi), kLinearRelTol * omega);
    EXPECT_NEAR(r.rows[1][2], 1.0, 1e-9);
    EXPECT_NEAR(r.rows[1][3], -m.Ja / m.Jb, 1e-9);

    EXPECT_EQ(r.dofNames, (std::vector<std::string>{"a", "b"}));
    for (const char* name : {"M", "C", "K"}) {
        const NamedMatrix* mat = findMatrix(r, name);
        ASSERT_NE(mat, nullptr) << name;
        ASSERT_EQ(mat->rows.size(), static_cast<std::size_t>(n)) << name;
        EXPECT_EQ(mat->rows[0].size(), static_cast<std::size_t>(n)) << name;
    }
    const NamedMatrix* A = findMatrix(r, "A");
    ASSERT_NE(A, nullptr);
    EXPECT_EQ(A->rows.size(), static_cast<std::size_t>(2 * n));
    const NamedMatrix* K = findMatrix(r, "K");
    EXPECT_NEAR(K->rows[0][1], -m.c, kLinearRelTol * m.c);
}

TEST(LinearizeAnalysis, NamedLinearizeScenarioRunsThroughRunAnalysis) {
    // The same model with `linearize` as a named scenario next to a transient.
    TwoShafts m;
    m.n = 5;
    m.Jb = 20;
    const std::string text = modelText(m, "scenarios:\n  modes: {analysis: linearize}\n"
                                          "  run: {analysis: transient, end_time: 1 s}\nuse_scenario: run\n");
    const ModelSpec spec = readModelText(text, "linearize.yaml", defaultModelReader(), {{"use_scenario", "modes"}});
    ASSERT_EQ(spec.scenario.type, "linearize");
    const AnalysisResult r = runAnalysis(spec);
    const ResultScalar* f1 = r.find("natural_frequency_1");
    ASSERT_NE(f1, nullptr);
    EXPECT_NEAR(f1->value, m.elasticFrequency(), kLinearRelTol * m.elasticFrequency());
}

// ------------------------------------------------- kinematic constraints
//
// Shafts a and b joined by a rigid external gear pair (pitch radii r1, r2,
// i = r2/r1: q_b = −q_a/i), a coupling c from b to a third shaft d. By hand,
// with q_a and q_d as coordinates (b eliminated):
//   T = ½(J_a + J_b/i²)·q̇_a² + ½J_d·q̇_d²,  V = ½c·(−q_a/i − q_d)²,
//   M_r = diag(J_a + J_b/i², J_d),  K_r = c·[[1/i², 1/i], [1/i, 1]],
// and referred to b (J_b + i²J_a) the two-mass formula
//   ω² = c·(J_b + i²J_a + J_d)/((J_b + i²J_a)·J_d).
struct GearedThree {
    double Ja = 0.4, Jb = 3.0, Jd = 1.5;  // kg*m^2
    double r1 = 0.05, r2 = 0.2;           // m, i = 4
    double c = 2000;                      // N*m/rad
    double i() const { return r2 / r1; }
    double elasticFrequency() const {
        const double Jab = Jb + i() * i() * Ja;
        return std::sqrt(c * (Jab + Jd) / (Jab * Jd));
    }
    std::string text() const {
        return "format_version: 1\nname: geared three\nbodies:\n"
               "  - {name: a, inertia: " + num(Ja) + " kg*m^2, joint: {type: pin, parent: ground}}\n"
               "  - {name: b, inertia: " + num(Jb) + " kg*m^2, joint: {type: pin, parent: ground, location: [" +
               num(r1 + r2) + " m, 0 m, 0 m]}}\n"
               "  - {name: d, inertia: " + num(Jd) + " kg*m^2, joint: {type: pin, parent: ground, location: [1 m, 1 m, 0 m]}}\n"
               "elements:\n"
               "  - {type: GearPair, name: g, bodies: [a, b], pitch_radii: [" + num(r1) + " m, " + num(r2) + " m], law: rigid}\n"
               "  - {type: TorsionalCoupling, name: c, bodies: [b, d], stiffness: " + num(c) + " N*m/rad}\n"
               "scenario: {analysis: linearize, operating_point: file}\n";
    }
};

LinearModel linearizeText(const std::string& text, bool reduce = true) {
    const ModelSpec spec = readModelText(text, "linearize.yaml", defaultModelReader());
    auto scene = buildScene(spec);
    return linearizeScene(*scene, initialState(*scene, spec), true, reduce);
}

TEST(LinearizeConstraints, RigidGearPairReducesToTheIndependentShafts) {
    const GearedThree g;
    const LinearModel lm = linearizeText(g.text());
    EXPECT_EQ(lm.dofNames, (std::vector<std::string>{"a", "d"}));
    EXPECT_EQ(lm.bodyNames, (std::vector<std::string>{"a", "b", "d"}));
    EXPECT_EQ(lm.eliminated, (std::vector<int>{1}));
    Eigen::MatrixXd M(2, 2), K(2, 2);
    M << g.Ja + g.Jb / (g.i() * g.i()), 0, 0, g.Jd;
    K << g.c / (g.i() * g.i()), g.c / g.i(), g.c / g.i(), g.c;
    expectMatrixNear(lm.M, M, g.Jb, "M_r");
    expectMatrixNear(lm.K, K, g.c, "K_r");
    ASSERT_EQ(lm.naturalFrequencies.size(), 2);
    EXPECT_LE(lm.naturalFrequencies[0], 1e-6 * g.elasticFrequency());
    EXPECT_NEAR(lm.naturalFrequencies[1], g.elasticFrequency(), kLinearRelTol * g.elasticFrequency());
    // The shapes are expanded to every body: b turns −1/i times a.
    ASSERT_EQ(lm.modeShapes.rows(), 3);
    for (int m = 0; m < 2; ++m)
        EXPECT_NEAR(lm.modeShapes(1, m), -lm.modeShapes(0, m) / g.i(), 1e-12) << "mode " << m;
    // The damped eigenvalues of the undamped system: ±iω and the double 0.
    ASSERT_EQ(lm.eigenvalues.size(), 4);
    EXPECT_NEAR(std::abs(lm.eigenvalues[3].imag()), g.elasticFrequency(), 1e-6 * g.elasticFrequency());
}

TEST(LinearizeConstraints, AnalysesThatWorkInEveryMobilityStillRefuseConstraints) {
    const GearedThree g;
    try {
        linearizeText(g.text(), false);
        FAIL() << "no error";
    } catch (const AnalysisError& e) {
        EXPECT_NE(std::string(e.what()).find("between a and b"), std::string::npos) << e.what();
    }
}

TEST(LinearizeConstraints, AnalysisNamesTheEliminatedBodyAndTabulatesIt) {
    const GearedThree g;
    const AnalysisResult r = runAnalysis(readModelText(g.text(), "linearize.yaml", defaultModelReader()));
    EXPECT_EQ(r.dofNames, (std::vector<std::string>{"a", "d"}));
    EXPECT_EQ(r.columnNames, (std::vector<std::string>{"mode", "natural_frequency", "a", "b", "d"}));
    ASSERT_NE(r.find("natural_frequency_1"), nullptr);
    EXPECT_NEAR(r.find("natural_frequency_1")->value, g.elasticFrequency(), kLinearRelTol * g.elasticFrequency());
    EXPECT_EQ(r.find("degrees_of_freedom")->value, 2);
    bool noted = false;
    for (const auto& n : r.notes) noted = noted || n.find("b follow from the constraints") != std::string::npos;
    EXPECT_TRUE(noted);
}

// A planet (mass m_p, J_p) on a carrier (J_c) at a = R + r rolls outside a
// fixed gear R (GearMesh: ω_p,abs = ω_c (R + r)/r); a coupling c joins the
// carrier to a hub J_h. The carrier's reduced inertia is
//   J_red = J_c + m_p·a² + J_p·((R + r)/r)²
// and ω² = c·(J_red + J_h)/(J_red·J_h).
TEST(LinearizeConstraints, GearMeshPlanetIsCarriedInTheCarriersReducedInertia) {
    const double Jc = 0.02, mp = 3.0, Jp = 0.006, Jh = 0.05, R = 0.1, r = 0.05, c = 400;
    const std::string text =
        "format_version: 1\nname: planet\nbodies:\n"
        "  - {name: carrier, mass: 1 kg, inertia: " + num(Jc) + " kg*m^2, joint: {type: pin, parent: ground}}\n"
        "  - {name: planet, mass: " + num(mp) + " kg, inertia: " + num(Jp) +
        " kg*m^2, joint: {type: pin, parent: carrier, location: [" + num(R + r) + " m, 0 m, 0 m]}}\n"
        "  - {name: hub, inertia: " + num(Jh) + " kg*m^2, joint: {type: pin, parent: ground, location: [0 m, 0 m, 1 m]}}\n"
        "elements:\n"
        "  - {type: GearMesh, name: mesh, carrier: carrier, planet: planet, fixed_pitch_radius: " + num(R) +
        " m, planet_pitch_radius: " + num(r) + " m}\n"
        "  - {type: TorsionalCoupling, name: c, bodies: [carrier, hub], stiffness: " + num(c) + " N*m/rad}\n"
        "scenario: {analysis: linearize, operating_point: file}\n";
    const LinearModel lm = linearizeText(text);
    EXPECT_EQ(lm.dofNames, (std::vector<std::string>{"carrier", "hub"}));
    const double k = (R + r) / r;
    const double Jred = Jc + mp * (R + r) * (R + r) + Jp * k * k;
    EXPECT_NEAR(lm.M(0, 0), Jred, kLinearRelTol * Jred);
    const double w = std::sqrt(c * (Jred + Jh) / (Jred * Jh));
    ASSERT_EQ(lm.naturalFrequencies.size(), 2);
    EXPECT_NEAR(lm.naturalFrequencies[1], w, kLinearRelTol * w);
    // The planet turns relative to the carrier at ω_c·R/r.
    for (int m = 0; m < 2; ++m) EXPECT_NEAR(lm.modeShapes(1, m), lm.modeShapes(0, m) * R / r, 1e-12) << m;
}

// The shipped ball mill (models/tumbling_ball_mill_3x4m.yaml) with both
// gear stages rigid: 5 shafts, 3 independent (motor_shaft, reducer_input,
// pinion). Oracle: TumblingMillOracle's gearedChainFrequencies on the chain
// reduced by ratio² by hand — motor | reducer input + output referred to the
// output (J_ro + i_r²·J_ri) | pinion + shell and charge referred to the
// pinion (J_p + J_shell'/i_g²) — with the two couplings. It shares nothing
// with the model but the file's numbers.
struct MillVariants {
    ModelSpec rigid, compliant;
};

MillVariants readMillVariants() {
    const std::string path = std::string(MILLDYN_SOURCE_DIR) + "/models/tumbling_ball_mill_3x4m.yaml";
    std::ifstream in(path);
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::string text = buffer.str();
    // law: rigid admits no mesh keys: drop their lines.
    std::string rigid;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
        if (line.find("mesh_stiffness:") != std::string::npos || line.find("mesh_damping:") != std::string::npos)
            continue;
        const auto at = line.find("law: compliant");
        if (at != std::string::npos) line.replace(at, 14, "law: rigid");
        rigid += line + "\n";
    }
    return {readModelText(rigid, path, defaultModelReader()), readModelText(text, path, defaultModelReader())};
}

const ElementSpec& elementNamed(const ModelSpec& spec, const std::string& name) {
    for (const auto& e : spec.elements)
        if (e.name == name) return e;
    throw std::runtime_error("no element " + name);
}

double bodyInertia(const ModelSpec& spec, const std::string& name) {
    for (const auto& b : spec.bodies)
        if (b.name == name) return b.inertia;
    throw std::runtime_error("no body " + name);
}

LinearModel steadyLinearModel(const ModelSpec& spec) {
    auto scene = buildScene(spec);
    return linearizeScene(*scene, solveSteadyState(*scene, initialState(*scene, spec)), true, true);
}

TEST(LinearizeConstraints, RigidGearedMillIsTheRatioSquaredChain) {
    const MillVariants mill = readMillVariants();
    const ModelSpec& spec = mill.rigid;
    const LinearModel lm = steadyLinearModel(spec);
    EXPECT_EQ(lm.dofNames, (std::vector<std::string>{"motor_shaft", "reducer_input", "pinion"}));

    auto stage = [&](const char* name) {
        const auto r = elementNamed(spec, name).numbers("pitch_radii");
        return r[1] / r[0];
    };
    const double ir = stage("reducer"), ig = stage("girth_gear");
    const ElementSpec& charge = elementNamed(spec, "charge");
    const double shell = bodyInertia(spec, "shell") +
                         oracles::segmentAxisInertia({charge.number("drum_radius"), charge.number("length"),
                                                      charge.number("bulk_density"), charge.number("fill")});
    oracles::GearedChain chain;
    chain.inertias = {bodyInertia(spec, "motor_shaft"),
                      bodyInertia(spec, "reducer_output") + ir * ir * bodyInertia(spec, "reducer_input"),
                      bodyInertia(spec, "pinion") + shell / (ig * ig)};
    const ElementSpec& hs = elementNamed(spec, "hs_coupling");
    const ElementSpec& ls = elementNamed(spec, "ls_coupling");
    chain.stiffnesses = {hs.number("stiffness"), ls.number("stiffness")};
    chain.ratios = {hs.number("ratio") * ir, ls.number("ratio")};
    const std::vector<double> w = oracles::gearedChainFrequencies(chain);
    ASSERT_EQ(lm.naturalFrequencies.size(), 3);
    // The couplings are linear springs and the drive's and charge's torques
    // depend on speed only: the differences are exact up to round-off.
    EXPECT_LE(lm.naturalFrequencies[0], 1e-6 * w[2]);
    for (int k = 1; k < 3; ++k) EXPECT_NEAR(lm.naturalFrequencies[k], w[k], 1e-8 * w[k]) << "mode " << k;

    // The compliant meshes (torsional stiffness k r² cos²α: 5.1e7 N*m/rad
    // on the reducer input, 3.0e8 on the pinion) are 100 and 60 times
    // stiffer than the couplings they are in series with (5e5, 5e6), so
    // the compliant mill's two lowest elastic modes are the rigid ones
    // lowered by a little: a constraint only raises frequencies (Rayleigh),
    // by about half the mesh's share of the compliance in the mode (½/100 to
    // ½/60: 0.5-0.8 %). Measured: 56.18 vs 56.64 rad/s (0.81 %), 188.98 vs
    // 189.74 rad/s (0.40 %); the compliant mill's two further modes (3917,
    // 4378 rad/s) are the meshes' own, which the rigid mill does not have.
    const LinearModel soft = steadyLinearModel(mill.compliant);
    ASSERT_EQ(soft.naturalFrequencies.size(), 5);
    for (int k = 1; k < 3; ++k) {
        EXPECT_LE(soft.naturalFrequencies[k], lm.naturalFrequencies[k]) << "mode " << k;
        EXPECT_NEAR(soft.naturalFrequencies[k], lm.naturalFrequencies[k], 0.01 * lm.naturalFrequencies[k])
            << "mode " << k;
    }
}

// The shipped planetary mill (seed 000) at its start instant: the carrier
// is the only independent coordinate, the drums follow through their
// GearMesh at ω_rel = ω_c·R/r. Its charges hang in opposite phase (lag 0 on
// drum1, π on drum2), so the gravity stiffnesses of the two cancel and the
// one mode is the rigid rotation: no elastic frequency may be reported.
TEST(LinearizeConstraints, PlanetaryMillIsOneRigidDegreeOfFreedom) {
    const std::string path = std::string(MILLDYN_SOURCE_DIR) + "/models/planetary_gear_100x200.yaml";
    const ModelSpec spec = readModelFile(path, defaultModelReader(),
                                         {{"scenarios.modes.analysis", "linearize"},
                                          {"scenarios.modes.operating_point", "file"},
                                          {"use_scenario", "modes"}});
    const AnalysisResult r = runAnalysis(spec);
    EXPECT_EQ(r.find("degrees_of_freedom")->value, 1);
    EXPECT_EQ(r.dofNames, (std::vector<std::string>{"carrier"}));
    EXPECT_EQ(r.find("natural_frequency_1"), nullptr);
    const ElementSpec& mesh = elementNamed(spec, "mesh1");
    const double ratio = mesh.number("fixed_pitch_radius") / mesh.number("planet_pitch_radius");
    ASSERT_EQ(r.rows.size(), 1u);
    ASSERT_EQ(r.columnNames, (std::vector<std::string>{"mode", "natural_frequency", "carrier", "drum1", "drum2"}));
    EXPECT_NEAR(r.rows[0][3], ratio * r.rows[0][2], 1e-12);
    EXPECT_NEAR(r.rows[0][4], ratio * r.rows[0][2], 1e-12);
}

}  // namespace
}  // namespace milldyn
