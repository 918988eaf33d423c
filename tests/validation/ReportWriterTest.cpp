// The report writer (validation/report/ReportWriter) on made-up rows and
// sections: counts, which sections appear, where flagged and failed rows go,
// escaping, the plots it draws, and that it leaves no temporary file.

#include "tests/driver/ReadFile.h"
#include "validation/report/ReportWriter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace milldyn {
namespace {

namespace fs = std::filesystem;

std::string readAll(const fs::path& p) { return test::slurp(p); }

fs::path freshDirectory(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / (name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    return dir;
}

std::vector<ValidationRow> madeUpRows() {
    std::vector<ValidationRow> rows;
    rows.push_back(compareRow("alpha_steady", "speed", "rad/s", 1.0, 1.0, 1e-6, "same equations"));
    rows.push_back(paperRow("alpha_table", "Mc printed vs eq 14", "N*m", 18.1, 16.48, 0.003, RowPolicy::Misprint,
                            "the printed <t_v> & 1.10 s is a misprint for 1.00 s"));
    rows.push_back(asObservation(compareRow("alpha_start", "start time, another start", "s", 4.88, 4.83, 0.01),
                                 {4.7, 5.0, "between the bounds"}));
    rows.push_back(compareRow("alpha_broken", "torque", "N*m", 2.0, 1.0, 1e-6, "a regression"));
    rows.push_back(compareRow("zeta_unclaimed", "frequency", "rad/s", 3.0, 3.0, 1e-6));
    return rows;
}

struct Sections {
    bool betaCalled = false;
    std::vector<ReportSection> list;
};

void makeSections(Sections& s) {
    ReportSection alpha;
    alpha.machine = "alpha";
    alpha.title = "Alpha mill (seed 999)";
    alpha.claims = "Alpha claims things.";
    alpha.differences = {"A difference spanning rows, explained."};
    alpha.tables = [](const std::vector<ValidationRow>& rows) {
        ReportTable t;
        t.title = "Side by side";
        t.header = {"quantity", "paper"};
        for (const auto& r : rows)
            if (r.paper) t.rows.push_back({r.quantity, formatCell(*r.paper)});
        return std::vector<ReportTable>{t};
    };
    alpha.plots = [](const std::vector<ValidationRow>&) {
        ReportPlot lines;
        lines.file = "alpha_lines";
        lines.title = "Lines";
        lines.series = {{"model", {0, 1, 2}, {0, 1, 4}, ReportSeries::Style::Lines, 1},
                        {"oracle", {0, 1, 2}, {0, 1, 4}, ReportSeries::Style::Points, 1}};
        ReportPlot bars;
        bars.file = "alpha_bars";
        bars.title = "Bars";
        bars.categories = {"row 1", "row 2"};
        bars.series = {{"paper", {}, {1, 2}, ReportSeries::Style::Lines, 0},
                       {"oracle", {}, {1.1, NAN}, ReportSeries::Style::Lines, 0}};
        return std::vector<ReportPlot>{lines, bars};
    };
    ReportSection beta;
    beta.machine = "beta";
    beta.title = "Beta crusher";
    beta.plots = [&s](const std::vector<ValidationRow>&) {
        s.betaCalled = true;
        return std::vector<ReportPlot>{};
    };
    s.list = {alpha, beta};
}

TEST(ReportWriter, CountsSectionsMisprintsFailuresAndPlots) {
    const fs::path dir = freshDirectory("milldyn_report_writer");
    Sections sections;
    makeSections(sections);
    std::string warning;
    const auto files = writeValidationReport(dir.string(), madeUpRows(), sections.list, warning);
    EXPECT_EQ(warning, "");
    EXPECT_EQ(files.size(), 4u);
    for (const char* f : {"report.md", "report.html", "alpha_lines.png", "alpha_bars.png"})
        EXPECT_TRUE(fs::exists(dir / f)) << f;
    // Nothing else: no temporary file or gnuplot script left behind.
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 4);
    for (const char* png : {"alpha_lines.png", "alpha_bars.png"}) {
        const std::string bytes = readAll(dir / png);
        EXPECT_EQ(bytes.substr(1, 3), "PNG");
        EXPECT_GT(bytes.size(), 5000u) << png;
    }
    EXPECT_FALSE(sections.betaCalled) << "a section without rows must not compute its plots";

    const std::string md = readAll(dir / "report.md");
    EXPECT_NE(md.find("**Totals:** 2 pass, 1 flagged, 1 info, 1 fail (5 comparisons)."), std::string::npos);
    EXPECT_NE(md.find("## Alpha mill (seed 999): 1 pass, 1 flagged, 1 info, 1 fail"), std::string::npos);
    EXPECT_NE(md.find("## Other cases: 1 pass, 0 flagged, 0 info, 0 fail"), std::string::npos);
    EXPECT_NE(md.find("### Observations within their expected bands (1)"), std::string::npos);
    EXPECT_NE(md.find("expected \\[4.7, 5\\]: between the bounds"), std::string::npos);  // Markdown-escaped brackets
    EXPECT_EQ(md.find("Beta crusher"), std::string::npos);
    EXPECT_NE(md.find("### Flagged misprints (1)"), std::string::npos);
    EXPECT_NE(md.find("### FAILURES (1)"), std::string::npos);
    EXPECT_NE(md.find("![Lines](alpha_lines.png)"), std::string::npos);
    EXPECT_NE(md.find("A difference spanning rows, explained."), std::string::npos);

    const std::string html = readAll(dir / "report.html");
    EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
    EXPECT_NE(html.find("<img src=\"alpha_lines.png\""), std::string::npos);
    EXPECT_NE(html.find("<img src=\"alpha_bars.png\""), std::string::npos);
    // The note travels with the flagged row, escaped.
    EXPECT_NE(html.find("the printed &lt;t_v&gt; &amp; 1.10 s is a misprint for 1.00 s"), std::string::npos);
    EXPECT_EQ(html.find("<t_v>"), std::string::npos);
    EXPECT_NE(html.find("<td class=\"fail\">fail</td>"), std::string::npos);
    EXPECT_EQ(html.find("<script"), std::string::npos);
    EXPECT_EQ(html.find("http"), std::string::npos);
    fs::remove_all(dir);
}

TEST(ReportWriter, WithoutGnuplotTheReportIsWrittenAndSaysSo) {
    const fs::path dir = freshDirectory("milldyn_report_noplot");
    Sections sections;
    makeSections(sections);
    const std::string path = std::getenv("PATH") ? std::getenv("PATH") : "";
    ::setenv("PATH", "/nonexistent", 1);
    std::string warning;
    const auto files = writeValidationReport(dir.string(), madeUpRows(), sections.list, warning);
    ::setenv("PATH", path.c_str(), 1);
    EXPECT_NE(warning.find("gnuplot not found"), std::string::npos);
    EXPECT_EQ(files.size(), 2u);
    const std::string html = readAll(dir / "report.html");
    EXPECT_EQ(html.find("<img"), std::string::npos);
    EXPECT_NE(html.find("Plot not drawn:"), std::string::npos);
    fs::remove_all(dir);
}

}  // namespace
}  // namespace milldyn

namespace milldyn {
namespace {

TEST(ReportWriter, ZeroOracleRowsShowAnAbsoluteErrorWithTheirUnit) {
    const fs::path dir = freshDirectory("milldyn_report_zero_oracle");
    ValidationRow row = compareRow("gamma_balance", "net torque", "N*m", 2.9e-17, 0.0, 1e-9);
    std::string warning;
    writeValidationReport(dir.string(), {row, compareRow("gamma_balance", "speed", "rad/s", 1.5, 1.0, 1e-6)}, {},
                          warning);
    const std::string md = readAll(dir / "report.md");
    EXPECT_NE(md.find("abs. 2.9e-17 N\\*m"), std::string::npos) << md;  // markdown escapes the *
    EXPECT_EQ(md.find("e+299"), std::string::npos) << md;
    EXPECT_EQ(md.find("e+2"), std::string::npos) << "no huge relative error anywhere:\n" << md;
    fs::remove_all(dir);
}

}  // namespace
}  // namespace milldyn
