// The validation report of the real machines, from the quicker cases of each
// (the full report takes minutes: ctest -L slow -R report_full). Writes
// MILLDYN_REPORT_CHECK_DIR, which the `report_render` test then opens in
// headless Chromium (tests/report/render_check.sh).

#include "tests/driver/ReadFile.h"
#include "driver/Cli.h"
#include "validation/report/ReportWriter.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace milldyn {
namespace {

namespace fs = std::filesystem;

std::string readAll(const fs::path& p) { return test::slurp(p); }

std::vector<ValidationRow> quickRows() {
    std::vector<ValidationRow> rows;
    auto add = [&rows](const std::vector<ValidationRow>& more) { rows.insert(rows.end(), more.begin(), more.end()); };
    add(burrMillCases("burr_mill_coastdown"));
    add(burrMillCases("burr_mill_table1_5p5kW_feed50_70"));  // the flagged row
    add(burrMillCases("burr_mill_table1_3p2kW_feed130_150"));
    for (const char* c : {"roll_crusher_2mass_roots", "roll_crusher_10mass_modes", "roll_crusher_stagger",
                          "roll_crusher_resonance_map", "roll_crusher_approximation_sweep"})
        add(rollCrusherCases(c));
    // The planetary mills' kinetostatic cases (no integrated start).
    for (const char* c : {"planetary_gear_100x200_fig10_initial_torque_vs_tp",
                          "planetary_gear_500x1000_fig10_initial_torque_vs_tp", "planetary_gear_100x200_start_up",
                          "planetary_gear_100x200_steady_held_lag"})
        add(planetaryGearCases(c));
    for (const char* c : {"planetary_belt_fig3_printed", "planetary_belt_c_to_1", "planetary_belt_map_omega",
                          "planetary_belt_map_c"})
        add(planetaryBeltCases(c));
    add(beadMillCases("bead_mill_static_5disc_0p1m"));
    add(beadMillCases("bead_mill_eq2_fit"));  // with flagged rows
    return rows;
}

TEST(ValidationReport, BothMachinesWithTable1PlotsAndFlaggedMisprints) {
    const fs::path dir = MILLDYN_REPORT_CHECK_DIR;
    fs::remove_all(dir);
    const auto rows = quickRows();
    const ReportCounts counts = countRows(rows);
    std::string warning;
    writeValidationReport(dir.string(), rows, reportSections(), warning);
    EXPECT_EQ(warning, "");
    for (const char* png : {"burr_mill_table1_Mc", "burr_mill_coastdown_5p5kW", "burr_mill_coastdown_3p2kW",
                            "burr_mill_coastdown_error", "roll_crusher_resonance_map", "roll_crusher_mode_shapes",
                            "bead_mill_deflection_line"})
        EXPECT_TRUE(fs::exists(dir / (std::string(png) + ".png"))) << png;
    for (const char* png : {"planetary_gear_fig10_a", "planetary_gear_holding_torque", "planetary_belt_reaction",
                            "planetary_belt_reaction_polar", "planetary_belt_tensions", "planetary_belt_map_omega",
                            "planetary_belt_map_c"})
        EXPECT_TRUE(fs::exists(dir / (std::string(png) + ".png"))) << png;
    // Not asked for: the start-history cases were left out, so no history plot.
    EXPECT_FALSE(fs::exists(dir / "planetary_gear_fig10_b_100x200.png"));
    // Not asked for: the response case was left out, so no response plot.
    EXPECT_FALSE(fs::exists(dir / "roll_crusher_response.png"));

    const std::string md = readAll(dir / "report.md");
    std::ostringstream totals;
    totals << "**Totals:** " << formatStatusCounts(counts);
    EXPECT_NE(md.find(totals.str()), std::string::npos) << totals.str();
    EXPECT_EQ(counts.fail, 0);
    EXPECT_GT(counts.flagged, 0);
    EXPECT_NE(md.find("## MMP-50 burr mill (seed 003)"), std::string::npos);
    EXPECT_NE(md.find("## Single-roll crusher (seed 004)"), std::string::npos);
    EXPECT_NE(md.find("## Horizontal planetary mill, external rolling (seed 000)"), std::string::npos);
    EXPECT_NE(md.find("## Planetary mill with belt drive (seed 002)"), std::string::npos);
    EXPECT_NE(md.find("## Horizontal bead mill rotor (seed 001)"), std::string::npos);
    EXPECT_NE(md.find("| d(5 discs, 0.1 m, L\\_p 0.15 m) | 16.5 | 16.64 | 23.47 (flagged) |"), std::string::npos);
    EXPECT_EQ(md.find("Other cases"), std::string::npos) << "every row belongs to a machine";
    // Fig. 10 (a) side by side: at t_p = 0.3 s the ratio 1/(1 − e^(−0.3)) =
    // 3.858 of both sizes, beside the paper's "≈ 4× at 0.3–0.4 s".
    const std::size_t fig10 = md.find("| 0.3 |", md.find("Fig. 10, reading (a)"));
    ASSERT_NE(fig10, std::string::npos);
    const std::string row = md.substr(fig10, md.find('\n', fig10) - fig10);
    EXPECT_NE(row.find("| 3.858 | 3.85"), std::string::npos) << row;
    EXPECT_NE(row.find("≈ 4× at 0.3–0.4 s"), std::string::npos) << row;
    // The J_pr misprint flagged with its explanation, and c → 1 tabled.
    EXPECT_NE(md.find("misprint: the carrier counted twice"), std::string::npos);
    // c = 1: ω = Ω(1 − 1) = 0 in model and oracle, drum_turns 0.
    EXPECT_NE(md.find("| 1 | 0 | 0 | 0 |", md.find("c → 1: the drum translates")), std::string::npos);
    // Table 1 side by side: the misprinted row flagged, its corrected reading
    // beside it, the untouched row with paper, oracle and multibody.
    EXPECT_NE(md.find("| 5.5 kW 50-70 kg/h | 1.1 | 18.1 (flagged) | 16.48"), std::string::npos);
    EXPECT_NE(md.find("| 5.5 kW 50-70 kg/h (t\\_v corrected) | 1.00 | 18.1 |"), std::string::npos);
    EXPECT_NE(md.find("| 3.2 kW 130-150 kg/h | 0.6 | 27 | 27.02 | 27.02 |"), std::string::npos);
    // The flagged rows carry their explanation (the case's note).
    EXPECT_NE(md.find("t\\_v = 1.10 s as printed gives these"), std::string::npos);
    EXPECT_NE(md.find("the approximation fails here"), std::string::npos);

    const std::string html = readAll(dir / "report.html");
    EXPECT_NE(html.find("<img src=\"burr_mill_table1_Mc.png\""), std::string::npos);
    EXPECT_NE(html.find("<img src=\"roll_crusher_resonance_map.png\""), std::string::npos);
}

TEST(ValidationReport, CommandLineWritesTheReportBesideTheTable) {
    const fs::path dir = fs::temp_directory_path() / ("milldyn_cli_report_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    std::ostringstream out, err;
    const int rc = runCli({"validate", "--filter", "roll_crusher_10mass_modes", "--report", dir.string()}, out, err);
    EXPECT_EQ(rc, 0) << err.str();
    EXPECT_NE(out.str().find("passed, 0 failed"), std::string::npos);
    EXPECT_NE(out.str().find("report.html"), std::string::npos);
    EXPECT_TRUE(fs::exists(dir / "report.html"));
    EXPECT_TRUE(fs::exists(dir / "report.md"));
    EXPECT_TRUE(fs::exists(dir / "roll_crusher_mode_shapes.png"));
    EXPECT_NE(readAll(dir / "report.md").find("## Single-roll crusher (seed 004)"), std::string::npos);
    // --json keeps stdout a JSON document.
    std::ostringstream jout, jerr;
    EXPECT_EQ(runCli({"validate", "--filter", "roll_crusher_10mass_modes", "--json", "--report", dir.string()}, jout,
                     jerr),
              0);
    EXPECT_EQ(jout.str().front(), '[');
    EXPECT_NE(jerr.str().find("report.html"), std::string::npos);
    std::ostringstream uout, uerr;
    EXPECT_EQ(runCli({"info", "model.yaml", "--report", dir.string()}, uout, uerr), 2);
    EXPECT_NE(uerr.str().find("--report goes with validate"), std::string::npos);
    fs::remove_all(dir);
}

}  // namespace
}  // namespace milldyn
