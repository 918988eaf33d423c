// The tumbling ball mill's section of the validation report (issue 19):
// the girth-gear drive's mesh forces and bearing loads against statics, the
// geared chain's natural frequencies against the ratio²-reduced chain, and
// the start's energy balance, as tables built from the case rows.

#include "validation/report/ReportSection.h"

#include <string>

namespace milldyn {
namespace {

/// One table row per validation row: quantity, multibody, oracle, error, status.
std::vector<std::string> cells(const ValidationRow& r) {
    return {r.quantity, r.multibody ? formatCell(*r.multibody, 10) : "", formatCell(r.oracle, 10),
            formatCell(r.relError, 2), r.status};
}

std::vector<ReportTable> tables(const std::vector<ValidationRow>& rows) {
    std::vector<ReportTable> out;
    for (const std::string variant : {"spur", "helical"}) {
        ReportTable t;
        const std::string name = "tumbling_mill_girth_gear_statics_" + variant;
        t.title = "Girth gear (" + variant + ") at steady running: model vs statics";
        t.header = {"quantity", "multibody [N]", "oracle [N]", "error", "status"};
        for (const auto& r : rows)
            if (r.caseName == name) t.rows.push_back(cells(r));
        t.caption = "Bearing forces are the forces of the bearings on the shaft, ground axes; errors of the "
                    "components relative to the shaft's largest load.";
        if (!t.rows.empty()) out.push_back(t);
    }
    ReportTable f;
    f.title = "Natural frequencies of the geared chain";
    f.header = {"mode", "linearize [rad/s]", "chain eigen, ratio^2 [rad/s]", "rel. error", "status"};
    for (const auto& r : rows)
        if (r.caseName == "tumbling_mill_chain_frequencies") f.rows.push_back(cells(r));
    f.caption = "Mesh stiffness along the transverse line of action, on gear 1's shaft k r_b1^2; inertias and "
                "couplings reduced to the motor shaft by the square of the total ratio.";
    if (!f.rows.empty()) out.push_back(f);
    return out;
}

}  // namespace

ReportSection tumblingMillReportSection() {
    ReportSection s;
    s.machine = "tumbling_mill";
    s.title = "Tumbling ball mill 3 m x 4 m with girth-gear drive (issue 19)";
    s.paper = "No paper: a user's mill (models/tumbling_ball_mill_3x4m.yaml, numbers argued in docs/own-mill.md).";
    s.claims = "A gear mesh acts at the pitch point along the line of action, so its tangential, radial "
               "(W_t tan a_n / cos b) and axial (W_t tan b) forces load both shafts' bearings; two bearings per "
               "shaft share the load as a beam on two supports; the geared chain vibrates as the chain reduced "
               "to one shaft with the square of the ratios.";
    s.oracle = "validation/oracles/GearPairOracle: the helical mesh force triangle (Shigley 13-16), a rigid shaft "
               "on two simple supports (moments about each support, axial forces' couples at the pitch radius), "
               "and the generalized eigenproblem of the chain reduced by ratio^2 (Eigen).";
    s.multibody = "GearPair (compliant mesh) for the reducer stage and the girth gear, TorsionalCoupling for the "
                  "couplings, ShaftBearings on the shell (trunnions) and the pinion, the model's gravity; steady "
                  "running by Newton, linearize, a transient start.";
    s.differences = {
        "The statics cases hold the torque-arm charge at a constant 40 deg (the shipped model's lag rises "
        "with speed through a table, which the oracle does not interpolate) and switch the bearing friction "
        "off, so the oracle's load m g r_c sin(alpha) is known exactly; the charge's weight rests on the shell's "
        "axis. With friction on, each bearing's friction is a further (small) torque on the shell, checked in "
        "tests/plugins/GearPairTest.cpp."};
    s.docs = "docs/own-mill.md (the model, its numbers, how to run it), validation/cases/TumblingMillCases.cpp.";
    s.tables = tables;
    return s;
}

}  // namespace milldyn
