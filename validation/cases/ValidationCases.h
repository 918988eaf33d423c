#pragma once
// Validation cases: each compares one quantity of the multibody model (or
// of the paper's printed data) with an oracle written from the paper's
// equations (validation/oracles, which know nothing of Simbody).

#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace milldyn {

/// What a row claims, and so how its status is decided (one policy for
/// every case, applyStatusPolicy; docs/validation.md "Status"):
enum class RowPolicy {
    /// The model (or the printed value) reproduces the oracle: `pass` within
    /// the tolerance, else `fail`.
    Judged,
    /// A known misprint or a known approximation of the paper: `flagged`
    /// while the two values disagree beyond the tolerance, `fail` if they
    /// agree (the explanation would then be wrong).
    Misprint,
    /// A value reported beside a reference it is not expected to equal
    /// (another start, the printed equations, the paper's first-order
    /// method): `info` while the judged value lies in its expected band,
    /// `fail` outside it. The band comes from the physics or the paper's
    /// stated accuracy, never from the run it judges.
    Observation,
};

/// Where an observation is expected, in the row's unit, and why.
struct ExpectedBand {
    double low = -INFINITY;
    double high = INFINITY;
    std::string why;
};

struct ValidationRow {
    std::string caseName;              ///< starts with the machine: burr_mill_...
    std::string quantity;
    std::string unit;
    std::optional<double> multibody;   ///< absent for paper-vs-oracle rows
    double oracle = 0;
    std::optional<double> paper;       ///< the printed value, where compared
    double relError = 0;
    double tolerance = 0;
    std::string status;                ///< pass | fail | flagged | info (applyStatusPolicy)
    std::string note;
    RowPolicy policy = RowPolicy::Judged;
    std::optional<ExpectedBand> band;  ///< observations only
};

/// The value a row judges against its oracle: the multibody model's, else
/// the paper's (NaN if neither).
double judgedValue(const ValidationRow& r);

/// Compares `value` with `oracle`: relative error against |oracle|; a
/// judged row (RowPolicy::Judged).
ValidationRow compareRow(std::string caseName, std::string quantity, std::string unit, double value,
                         double oracle, double tolerance, std::string note = "");

/// The one status policy: sets `row.status` from its policy, relError,
/// tolerance and band. Every row's status comes from here.
void applyStatusPolicy(ValidationRow& row);
/// `row` judged by an error measure its case computes (a vector error, an
/// error relative to a scale other than |oracle|): sets relError, then the
/// policy.
ValidationRow withError(ValidationRow row, double relError);
/// `row` as a known misprint / approximation (RowPolicy::Misprint).
ValidationRow asMisprint(ValidationRow row);
/// `row` as an observation expected in `band` (RowPolicy::Observation);
/// the band and its reason are appended to the note.
ValidationRow asObservation(ValidationRow row, ExpectedBand band);
/// A printed value against the oracle (no multibody value), relative error
/// against |oracle|: judged, or a known misprint, at `tolerance`.
ValidationRow paperRow(std::string caseName, std::string quantity, std::string unit, double printed,
                       double oracle, double tolerance, RowPolicy policy, std::string note);

/// Rows by status.
struct StatusCounts {
    int pass = 0, fail = 0, flagged = 0, info = 0;
    bool operator==(const StatusCounts& o) const {
        return pass == o.pass && fail == o.fail && flagged == o.flagged && info == o.info;
    }
};
StatusCounts countStatuses(const std::vector<ValidationRow>& rows);
/// "72 pass, 4 flagged, 3 info, 0 fail" — the form of docs/validation.md's
/// section headings and of the report.
std::string formatStatusCounts(const StatusCounts& c);

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
