#include "validation/cases/ValidationCases.h"

#include <cstdio>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <mutex>
#include <sstream>

namespace milldyn {

ValidationRow compareRow(std::string caseName, std::string quantity, std::string unit, double value,
                         double oracle, double tolerance, std::string note) {
    ValidationRow r;
    r.caseName = std::move(caseName);
    r.quantity = std::move(quantity);
    r.unit = std::move(unit);
    r.multibody = value;
    r.oracle = oracle;
    r.relError = std::abs(value - oracle) / std::max(std::abs(oracle), 1e-300);
    r.tolerance = tolerance;
    r.note = std::move(note);
    applyStatusPolicy(r);
    return r;
}

void applyStatusPolicy(ValidationRow& row) {
    const bool within = std::isfinite(row.relError) && row.relError <= row.tolerance;
    switch (row.policy) {
    case RowPolicy::Judged:
        row.status = within ? "pass" : "fail";
        return;
    case RowPolicy::Misprint:
        // A disagreement that vanished, or a value that is no number,
        // disproves the explanation.
        row.status = std::isfinite(row.relError) && !within ? "flagged" : "fail";
        return;
    case RowPolicy::Observation: {
        const double v = judgedValue(row);
        const bool inBand = row.band && std::isfinite(v) && v >= row.band->low && v <= row.band->high;
        row.status = inBand ? "info" : "fail";
        return;
    }
    }
    row.status = "fail";
}

ValidationRow withError(ValidationRow row, double relError) {
    row.relError = relError;
    applyStatusPolicy(row);
    return row;
}

ValidationRow asMisprint(ValidationRow row) {
    row.policy = RowPolicy::Misprint;
    applyStatusPolicy(row);
    return row;
}

namespace {
std::string bandText(const ExpectedBand& b) {
    auto num = [](double v) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.6g", v);
        return std::string(buf);
    };
    std::string range = std::isinf(b.low) ? "≤ " + num(b.high)
                        : std::isinf(b.high) ? "≥ " + num(b.low)
                                             : "[" + num(b.low) + ", " + num(b.high) + "]";
    return "expected " + range + (b.why.empty() ? "" : ": " + b.why);
}
}  // namespace

ValidationRow asObservation(ValidationRow row, ExpectedBand band) {
    row.policy = RowPolicy::Observation;
    row.note += (row.note.empty() ? "" : "; ") + bandText(band);
    row.band = std::move(band);
    applyStatusPolicy(row);
    return row;
}

ValidationRow paperRow(std::string caseName, std::string quantity, std::string unit, double printed, double oracle,
                       double tolerance, RowPolicy policy, std::string note) {
    ValidationRow r;
    r.caseName = std::move(caseName);
    r.quantity = std::move(quantity);
    r.unit = std::move(unit);
    r.paper = printed;
    r.oracle = oracle;
    r.relError = std::abs(printed - oracle) / std::abs(oracle);
    r.tolerance = tolerance;
    r.note = std::move(note);
    r.policy = policy;
    applyStatusPolicy(r);
    return r;
}

StatusCounts countStatuses(const std::vector<ValidationRow>& rows) {
    StatusCounts c;
    for (const auto& r : rows)
        (r.status == "pass" ? c.pass : r.status == "flagged" ? c.flagged : r.status == "info" ? c.info : c.fail)++;
    return c;
}

std::string formatStatusCounts(const StatusCounts& c) {
    return std::to_string(c.pass) + " pass, " + std::to_string(c.flagged) + " flagged, " + std::to_string(c.info) +
           " info, " + std::to_string(c.fail) + " fail";
}

std::string formatExact(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

namespace {
std::mutex g_pluginGroupsMutex;
std::vector<CaseGroup>& pluginGroups() {
    static std::vector<CaseGroup> groups;
    return groups;
}
}  // namespace

void addValidationCaseGroup(CaseGroup group) {
    const std::lock_guard<std::mutex> lock(g_pluginGroupsMutex);
    pluginGroups().push_back(std::move(group));
}

std::vector<ValidationRow> runValidationCases(const std::string& filter) {
    std::vector<CaseGroup> groups = {CaseGroup(burrMillCases), CaseGroup(rollCrusherCases),
                                     CaseGroup(planetaryGearCases), CaseGroup(planetaryBeltCases),
                                     CaseGroup(beadMillCases), CaseGroup(tumblingMillCases), CaseGroup(startCases), CaseGroup(dqStartCases),
                                     CaseGroup(machineStartCases), CaseGroup(chargePowerCases),
                                     CaseGroup(gearboxCases), CaseGroup(jawCrusherCases)};
    {
        const std::lock_guard<std::mutex> lock(g_pluginGroupsMutex);
        groups.insert(groups.end(), pluginGroups().begin(), pluginGroups().end());
    }
    std::vector<ValidationRow> all;
    for (const CaseGroup& group : groups) {
        auto rows = group(filter);
        all.insert(all.end(), rows.begin(), rows.end());
    }
    return all;
}

double judgedValue(const ValidationRow& r) { return r.multibody ? *r.multibody : r.paper ? *r.paper : NAN; }

std::string formatValidationJson(const std::vector<ValidationRow>& rows) {
    nlohmann::ordered_json array = nlohmann::ordered_json::array();
    for (const auto& r : rows) {
        nlohmann::ordered_json j;
        j["case"] = r.caseName;
        j["quantity"] = r.quantity;
        j["unit"] = r.unit;
        j["multibody"] = r.multibody ? nlohmann::ordered_json(*r.multibody) : nlohmann::ordered_json();
        j["oracle"] = r.oracle;
        if (r.paper) j["paper"] = *r.paper;
        // Where the oracle is 0 a relative error means nothing (1e+299):
        // null, and the absolute one says how far the value is from 0.
        j["rel_error"] = r.oracle == 0 ? nlohmann::ordered_json() : nlohmann::ordered_json(r.relError);
        if (r.oracle == 0) j["abs_error"] = std::abs(judgedValue(r) - r.oracle);
        j["tolerance"] = r.tolerance;
        j["status"] = r.status;
        if (r.band) {
            // JSON has no infinity: an open side is null.
            auto side = [](double v) { return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(); };
            j["band"] = {side(r.band->low), side(r.band->high)};
        }
        if (!r.note.empty()) j["note"] = r.note;
        array.push_back(j);
    }
    return array.dump(2) + "\n";
}

std::string formatValidationTable(const std::vector<ValidationRow>& rows) {
    std::ostringstream out;
    for (const auto& r : rows) {
        out << std::left << std::setw(8) << r.status << std::setw(38) << r.caseName << std::setw(52) << r.quantity
            << std::setprecision(8) << std::setw(16) << judgedValue(r) << " vs "
            << std::setw(16) << r.oracle << r.unit << "  ";
        if (r.oracle == 0)
            out << "abs " << std::setprecision(2) << std::abs(judgedValue(r)) << (r.unit == "1" ? "" : " " + r.unit);
        else
            out << "rel " << std::setprecision(2) << r.relError;
        out << " (tol " << r.tolerance << ")\n";
        if (!r.note.empty() && r.status != "pass") out << "        note: " << r.note << "\n";
    }
    const StatusCounts c = countStatuses(rows);
    out << c.pass << " passed, " << c.fail << " failed, " << c.flagged << " flagged";
    if (c.info > 0) out << ", " << c.info << " info";  // (docs/new-layout.md quotes the line without)
    out << "\n";
    return out.str();
}

std::string modelsDirectory() {
    if (const char* env = std::getenv("MILLDYN_MODELS")) return env;
    return MILLDYN_SOURCE_DIR "/models";
}

}  // namespace milldyn
