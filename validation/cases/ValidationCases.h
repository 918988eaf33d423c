#pragma once
// Validation cases: each compares one quantity of the multibody model (or
// of the paper's printed data) with an oracle written from the paper's
// equations (validation/oracles, which know nothing of Simbody).

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace milldyn {

struct ValidationRow {
    std::string caseName;              ///< starts with the machine: burr_mill_...
    std::string quantity;
    std::string unit;
    std::optional<double> multibody;   ///< absent for paper-vs-oracle rows
    double oracle = 0;
    std::optional<double> paper;       ///< the printed value, where compared
    double relError = 0;
    double tolerance = 0;
    std::string status;                ///< pass | fail | flagged
    std::string note;
};

/// The value a row judges against its oracle: the multibody model's, else
/// the paper's (NaN if neither).
double judgedValue(const ValidationRow& r);

/// Compares `value` with `oracle`: relative error against |oracle|.
ValidationRow compareRow(std::string caseName, std::string quantity, std::string unit, double value,
                         double oracle, double tolerance, std::string note = "");

/// A group of cases (one machine); `filter` selects case names containing it.
using CaseGroup = std::function<std::vector<ValidationRow>(const std::string& filter)>;

/// Runs every case whose name contains `filter` (all when empty): the
/// built-in groups, then those plugins added.
std::vector<ValidationRow> runValidationCases(const std::string& filter);

/// Adds a group of cases from a plugin library, so that
/// `milldyn validate --plugin lib.so` runs them too (docs/new-layout.md).
void addValidationCaseGroup(CaseGroup group);

/// The JSON array `validate --json` prints.
std::string formatValidationJson(const std::vector<ValidationRow>& rows);
/// A table for people.
std::string formatValidationTable(const std::vector<ValidationRow>& rows);

/// `v` with every digit a double holds (%.17g), for --set overrides that
/// must reach the model exactly.
std::string formatExact(double v);

/// Where the shipped model files are: $MILLDYN_MODELS, else the source tree's models/.
std::string modelsDirectory();

std::vector<ValidationRow> burrMillCases(const std::string& filter);
std::vector<ValidationRow> rollCrusherCases(const std::string& filter);
std::vector<ValidationRow> planetaryGearCases(const std::string& filter);
std::vector<ValidationRow> planetaryBeltCases(const std::string& filter);
std::vector<ValidationRow> beadMillCases(const std::string& filter);
std::vector<ValidationRow> tumblingMillCases(const std::string& filter);
/// Issue 27: the charge's power correlations and the frozen charge (ChargePowerCases.cpp).
std::vector<ValidationRow> chargePowerCases(const std::string& filter);
/// Planetary stages and bevel pairs (issue 32, validation/cases/GearboxCases.cpp).
std::vector<ValidationRow> gearboxCases(const std::string& filter);
std::vector<ValidationRow> startCases(const std::string& filter);
/// The dynamic (dq) induction machine against an independent transient
/// oracle and its starters against the equivalent circuit
/// (validation/cases/DqStartCases.cpp).
std::vector<ValidationRow> dqStartCases(const std::string& filter);
/// Whole machines started by their motor: seed 000's planetary mill through
/// a slipping V-belt, the burr mill started loaded
/// (validation/cases/MachineStartCases.cpp).
std::vector<ValidationRow> machineStartCases(const std::string& filter);
/// The 900 x 600 mm jaw crusher (issue 27; validation/cases/JawCrusherCases.cpp).
std::vector<ValidationRow> jawCrusherCases(const std::string& filter);

}  // namespace milldyn
