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

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
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

}  // namespace
}  // namespace milldyn
