#include "validation/report/ReportWriter.h"

#include "driver/outputs/AtomicFile.h"
#include "driver/outputs/Writers.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <map>
#include <sstream>

namespace milldyn {

ReportCounts countRows(const std::vector<ValidationRow>& rows) { return countStatuses(rows); }

namespace {

std::string countsText(const ReportCounts& c) { return formatStatusCounts(c); }

std::string relText(double v) {
    if (!std::isfinite(v)) return "—";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2g", v);
    return buf;
}

/// The error of a row: relative, or absolute (with its unit) where the
/// oracle is 0 and a relative error means nothing ("rel. 2.9e+299").
std::string errorText(const ValidationRow& r) {
    if (r.oracle != 0) return relText(r.relError);
    return "abs. " + relText(std::abs(judgedValue(r))) + (r.unit == "1" || r.unit.empty() ? "" : " " + r.unit);
}

/// The two output formats behind one interface, so both say the same.
class Doc {
public:
    virtual ~Doc() = default;
    virtual void heading(int level, const std::string& text, const std::string& anchor = "") = 0;
    /// A paragraph, optionally led by a bold label.
    virtual void paragraph(const std::string& label, const std::string& text) = 0;
    virtual void bullets(const std::vector<std::string>& items) = 0;
    virtual void table(const ReportTable& t) = 0;
    virtual void image(const std::string& file, const std::string& alt, const std::string& caption) = 0;
    /// A long part a reader may skip (HTML: <details>, Markdown: a heading).
    virtual void beginFold(const std::string& summary) = 0;
    virtual void endFold() = 0;
    virtual std::string finish(const std::string& title) = 0;
};


std::string escapeMarkdown(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '\\' || c == '*' || c == '_' || c == '|' || c == '<' || c == '`' || c == '[' || c == ']')
            out += '\\';
        out += c;
    }
    return out;
}

class MarkdownDoc : public Doc {
public:
    void heading(int level, const std::string& text, const std::string&) override {
        m_out << std::string(level, '#') << ' ' << escapeMarkdown(text) << "\n\n";
    }
    void paragraph(const std::string& label, const std::string& text) override {
        if (!label.empty()) m_out << "**" << escapeMarkdown(label) << "** ";
        m_out << escapeMarkdown(text) << "\n\n";
    }
    void bullets(const std::vector<std::string>& items) override {
        for (const auto& i : items) m_out << "- " << escapeMarkdown(i) << "\n";
        m_out << "\n";
    }
    void table(const ReportTable& t) override {
        if (!t.title.empty()) m_out << "*" << escapeMarkdown(t.title) << "*\n\n";
        m_out << "|";
        for (const auto& h : t.header) m_out << ' ' << escapeMarkdown(h) << " |";
        m_out << "\n|";
        for (std::size_t i = 0; i < t.header.size(); ++i) m_out << "---|";
        m_out << "\n";
        for (const auto& row : t.rows) {
            m_out << "|";
            for (const auto& cell : row) m_out << ' ' << escapeMarkdown(cell) << " |";
            m_out << "\n";
        }
        m_out << "\n";
        if (!t.caption.empty()) m_out << escapeMarkdown(t.caption) << "\n\n";
    }
    void image(const std::string& file, const std::string& alt, const std::string& caption) override {
        m_out << "![" << escapeMarkdown(alt) << "](" << file << ")\n\n";
        if (!caption.empty()) m_out << "*" << escapeMarkdown(caption) << "*\n\n";
    }
    void beginFold(const std::string& summary) override { m_out << "#### " << escapeMarkdown(summary) << "\n\n"; }
    void endFold() override {}
    std::string finish(const std::string&) override { return m_out.str(); }

private:
    std::ostringstream m_out;
};

class HtmlDoc : public Doc {
public:
    void heading(int level, const std::string& text, const std::string& anchor) override {
        m_out << "<h" << level << (anchor.empty() ? "" : " id=\"" + escapeMarkup(anchor) + "\"") << ">"
              << escapeMarkup(text) << "</h" << level << ">\n";
    }
    void paragraph(const std::string& label, const std::string& text) override {
        m_out << "<p>";
        if (!label.empty()) m_out << "<strong>" << escapeMarkup(label) << "</strong> ";
        m_out << escapeMarkup(text) << "</p>\n";
    }
    void bullets(const std::vector<std::string>& items) override {
        m_out << "<ul>\n";
        for (const auto& i : items) m_out << "<li>" << escapeMarkup(i) << "</li>\n";
        m_out << "</ul>\n";
    }
    void table(const ReportTable& t) override {
        m_out << "<div class=\"scroll\"><table>\n";
        if (!t.title.empty()) m_out << "<caption>" << escapeMarkup(t.title) << "</caption>\n";
        m_out << "<thead><tr>";
        for (const auto& h : t.header) m_out << "<th>" << escapeMarkup(h) << "</th>";
        m_out << "</tr></thead>\n<tbody>\n";
        for (const auto& row : t.rows) {
            m_out << "<tr>";
            for (const auto& cell : row) {
                const bool status = cell == "pass" || cell == "fail" || cell == "flagged" || cell == "info";
                m_out << (status ? "<td class=\"" + cell + "\">" : "<td>") << escapeMarkup(cell) << "</td>";
            }
            m_out << "</tr>\n";
        }
        m_out << "</tbody>\n</table></div>\n";
        if (!t.caption.empty()) m_out << "<p class=\"caption\">" << escapeMarkup(t.caption) << "</p>\n";
    }
    void image(const std::string& file, const std::string& alt, const std::string& caption) override {
        m_out << "<figure><img src=\"" << escapeMarkup(file) << "\" alt=\"" << escapeMarkup(alt) << "\">";
        if (!caption.empty()) m_out << "<figcaption>" << escapeMarkup(caption) << "</figcaption>";
        m_out << "</figure>\n";
    }
    void beginFold(const std::string& summary) override {
        m_out << "<details><summary>" << escapeMarkup(summary) << "</summary>\n";
    }
    void endFold() override { m_out << "</details>\n"; }
    std::string finish(const std::string& title) override {
        std::ostringstream page;
        page << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" << escapeMarkup(title)
             << "</title>\n<style>\n"
             << "body{font-family:'DejaVu Sans',sans-serif;max-width:1100px;margin:1em auto;padding:0 1em;"
                "color:#222;line-height:1.4}\n"
             << "table{border-collapse:collapse;margin:.6em 0;font-size:.85em}\n"
             << "th,td{border:1px solid #bbb;padding:2px 6px;text-align:left;vertical-align:top}\n"
             << "th{background:#eee}caption{font-weight:bold;text-align:left;padding:.3em 0}\n"
             << "td.pass{background:#dfd}td.flagged{background:#fe9}td.info{background:#def}td.fail{background:#f99}\n"
             << ".scroll{overflow-x:auto}\n"
             << "figure{margin:1em 0}img{max-width:100%;border:1px solid #ccc}\n"
             << "figcaption,.caption{font-size:.9em;color:#444}\n"
             << "details{margin:.6em 0}summary{cursor:pointer;font-weight:bold}\n"
             << "</style>\n</head>\n<body>\n"
             << m_out.str() << "</body>\n</html>\n";
        return page.str();
    }

private:
    std::ostringstream m_out;
};

/// The gnuplot commands of one report plot (data inline as datablocks).
std::string plotCommands(const ReportPlot& p) {
    std::ostringstream s;
    s << std::setprecision(10);
    s << "set title " << quoteForGnuplot(p.title) << "\nset xlabel " << quoteForGnuplot(p.xLabel)
      << "\nset ylabel " << quoteForGnuplot(p.yLabel) << "\nset grid\n"
      << (p.categories.empty() ? "set key below\n" : "set key top left\nset yrange [0:*]\n")
      << "set datafile missing '?'\n";
    if (p.logX) s << "set logscale x\n";
    if (p.logY) s << "set logscale y\n";
    if (p.equalAxes) s << "set size ratio -1\n";
    if (!p.xTicLabels.empty()) {
        s << "set xtics (";
        for (std::size_t i = 0; i < p.xTicLabels.size(); ++i)
            s << (i ? ", " : "") << quoteForGnuplot(p.xTicLabels[i]) << ' ' << i + 1;
        s << ")\n";
    }
    auto number = [](double v) {
        if (!std::isfinite(v)) return std::string("?");
        return formatDouble(v);
    };
    if (!p.categories.empty()) {
        s << "set style data histograms\nset style histogram clustered gap 1\n"
          << "set style fill solid 0.85 border -1\nset boxwidth 0.9\nset xtics rotate by -25\n"
          << "$bars << EOD\n";
        for (std::size_t c = 0; c < p.categories.size(); ++c) {
            std::string label = p.categories[c];
            std::replace(label.begin(), label.end(), '"', '\'');
            s << '"' << label << '"';
            for (const auto& ser : p.series) s << ' ' << (c < ser.y.size() ? number(ser.y[c]) : "?");
            s << "\n";
        }
        s << "EOD\nplot ";
        for (std::size_t k = 0; k < p.series.size(); ++k)
            s << (k ? ", " : "") << "$bars using " << k + 2 << (k == 0 ? ":xtic(1)" : "") << " title "
              << quoteForGnuplot(p.series[k].label);
        s << "\n";
        return s.str();
    }
    for (std::size_t k = 0; k < p.series.size(); ++k) {
        s << "$d" << k << " << EOD\n";
        const auto& ser = p.series[k];
        for (std::size_t i = 0; i < std::min(ser.x.size(), ser.y.size()); ++i)
            s << number(ser.x[i]) << ' ' << number(ser.y[i]) << "\n";
        s << "EOD\n";
    }
    s << "plot ";
    for (std::size_t k = 0; k < p.series.size(); ++k) {
        const char* style = "with lines lw 2";
        switch (p.series[k].style) {
            case ReportSeries::Style::Lines: style = "with lines lw 2"; break;
            case ReportSeries::Style::DashedLines: style = "with lines lw 2 dt 2"; break;
            case ReportSeries::Style::Points: style = "with points pt 7 ps 0.9"; break;
            case ReportSeries::Style::Impulses: style = "with impulses lw 1.5 dt 3"; break;
        }
        s << (k ? ", " : "") << "$d" << k << " using 1:2 " << style;
        if (p.series[k].colour > 0) s << " lc " << p.series[k].colour;
        s << " title "
          << quoteForGnuplot(p.series[k].label);
    }
    s << "\n";
    return s.str();
}

/// Per case: how many rows, by status, and the largest relative errors.
ReportTable caseSummary(const std::vector<ValidationRow>& rows) {
    struct Acc {
        ReportCounts counts;
        double worstModel = NAN, worstPaper = NAN;
    };
    std::vector<std::string> order;
    std::map<std::string, Acc> acc;
    for (const auto& r : rows) {
        if (!acc.count(r.caseName)) order.push_back(r.caseName);
        Acc& a = acc[r.caseName];
        (r.status == "pass" ? a.counts.pass : r.status == "flagged" ? a.counts.flagged
                                             : r.status == "info" ? a.counts.info : a.counts.fail)++;
        if (r.oracle == 0) continue;  // no relative error: its absolute one is in the row tables
        double& worst = r.multibody ? a.worstModel : a.worstPaper;
        worst = std::isnan(worst) ? r.relError : std::max(worst, r.relError);
    }
    ReportTable t;
    t.title = "Cases";
    t.header = {"case", "pass", "flagged", "info", "fail", "largest rel. error multibody vs oracle",
                "largest rel. error paper vs oracle"};
    for (const auto& name : order) {
        const Acc& a = acc[name];
        t.rows.push_back({name, std::to_string(a.counts.pass), std::to_string(a.counts.flagged),
                          std::to_string(a.counts.info), std::to_string(a.counts.fail), relText(a.worstModel), relText(a.worstPaper)});
    }
    t.caption = "Relative errors are |value − oracle|/|oracle| (phases: the wrapped difference); paper rows "
                "include the flagged and info ones. Where the oracle is 0 the row tables give the absolute error "
                "(abs.) instead; it is left out of these maxima.";
    return t;
}

ReportTable rowTable(const std::string& title, const std::vector<const ValidationRow*>& rows, bool withStatus) {
    ReportTable t;
    t.title = title;
    t.header = {"case", "quantity", "unit", "paper", "oracle", "multibody", "rel. error", "tolerance"};
    if (withStatus) t.header.push_back("status");
    t.header.push_back("explanation");
    for (const ValidationRow* r : rows) {
        std::vector<std::string> cells = {r->caseName,
                                          r->quantity,
                                          r->unit,
                                          r->paper ? formatCell(*r->paper, 8) : "",
                                          formatCell(r->oracle, 8),
                                          r->multibody ? formatCell(*r->multibody, 8) : "",
                                          errorText(*r),
                                          relText(r->tolerance)};
        if (withStatus) cells.push_back(r->status);
        cells.push_back(r->note);
        t.rows.push_back(cells);
    }
    return t;
}

struct RenderedPlot {
    ReportPlot plot;
    bool drawn = false;
};

void emitSection(Doc& doc, const ReportSection& s, const std::vector<ValidationRow>& rows,
                 const std::vector<ReportTable>& tables, const std::vector<RenderedPlot>& plots) {
    doc.heading(2, s.title + ": " + countsText(countRows(rows)), s.machine);
    if (!s.paper.empty()) doc.paragraph("Paper.", s.paper);
    if (!s.claims.empty()) doc.paragraph("What the paper claims.", s.claims);
    if (!s.oracle.empty()) doc.paragraph("What the oracle gives.", s.oracle);
    if (!s.multibody.empty()) doc.paragraph("What the multibody model gives.", s.multibody);
    doc.table(caseSummary(rows));
    for (const auto& t : tables) doc.table(t);
    for (const auto& p : plots) {
        if (p.drawn)
            doc.image(p.plot.file + ".png", p.plot.title, p.plot.caption);
        else
            doc.paragraph("Plot not drawn:", p.plot.title + " (gnuplot missing or failed).");
    }
    doc.heading(3, "Differences and their explanation");
    if (!s.differences.empty()) doc.bullets(s.differences);
    std::vector<const ValidationRow*> flagged, observed, failed;
    for (const auto& r : rows) {
        if (r.status == "flagged") flagged.push_back(&r);
        if (r.status == "info") observed.push_back(&r);
        if (r.status != "pass" && r.status != "flagged" && r.status != "info") failed.push_back(&r);
    }
    doc.heading(3, "Flagged misprints (" + std::to_string(flagged.size()) + ")");
    if (flagged.empty())
        doc.paragraph("", "None.");
    else
        doc.table(rowTable("", flagged, false));
    if (!observed.empty()) {
        // Each with its expected band and the band's reason (in the note).
        doc.heading(3, "Observations within their expected bands (" + std::to_string(observed.size()) + ")");
        doc.table(rowTable("", observed, true));  // with the note: the band and its reason
    }
    if (!failed.empty()) {
        doc.heading(3, "FAILURES (" + std::to_string(failed.size()) + ")");
        doc.table(rowTable("", failed, true));
    }
    if (!s.docs.empty()) doc.paragraph("Details:", s.docs);
    std::vector<const ValidationRow*> all;
    for (const auto& r : rows) all.push_back(&r);
    doc.beginFold("Every comparison of " + s.title + " (" + std::to_string(rows.size()) + ")");
    doc.table(rowTable("", all, true));
    doc.endFold();
}

}  // namespace

std::vector<std::string> writeValidationReport(const std::string& dir, const std::vector<ValidationRow>& rows,
                                               const std::vector<ReportSection>& sections, std::string& warning) {
    ensureDirectory(dir);
    std::vector<std::string> written;

    // Rows by section; the rest into "Other cases".
    std::vector<ReportSection> used;
    std::vector<std::vector<ValidationRow>> sectionRows;
    std::vector<bool> claimed(rows.size(), false);
    for (const auto& s : sections) {
        std::vector<ValidationRow> mine;
        for (std::size_t i = 0; i < rows.size(); ++i)
            if (!claimed[i] && rows[i].caseName.rfind(s.machine, 0) == 0) {
                mine.push_back(rows[i]);
                claimed[i] = true;
            }
        if (mine.empty()) continue;
        used.push_back(s);
        sectionRows.push_back(std::move(mine));
    }
    std::vector<ValidationRow> rest;
    for (std::size_t i = 0; i < rows.size(); ++i)
        if (!claimed[i]) rest.push_back(rows[i]);
    if (!rest.empty()) {
        ReportSection other;
        other.machine = "other";
        other.title = "Other cases";
        other.claims = "These cases have no report section yet (validation/report/ReportSections.cpp).";
        used.push_back(other);
        sectionRows.push_back(std::move(rest));
    }

    // Tables and plots first: images exist before the pages that show them.
    const bool canPlot = gnuplotAvailable();
    if (!canPlot) warning = "gnuplot not found: the report has no plots (scripts/install-deps.sh installs it)";
    std::vector<std::vector<ReportTable>> tables(used.size());
    std::vector<std::vector<RenderedPlot>> plots(used.size());
    for (std::size_t k = 0; k < used.size(); ++k) {
        if (used[k].tables) tables[k] = used[k].tables(sectionRows[k]);
        if (!used[k].plots) continue;
        for (auto& p : used[k].plots(sectionRows[k])) {
            RenderedPlot rp{std::move(p), false};
            if (canPlot) {
                const std::string png = dir + "/" + rp.plot.file + ".png";
                rp.drawn = renderGnuplotPng(png, plotCommands(rp.plot), 960, 540);
                if (rp.drawn)
                    written.push_back(png);
                else
                    warning = "gnuplot failed for " + rp.plot.file;
            }
            plots[k].push_back(std::move(rp));
        }
    }

    const std::string title = "milldyn validation report";
    const ReportCounts total = countRows(rows);
    MarkdownDoc md;
    HtmlDoc html;
    for (Doc* doc : {static_cast<Doc*>(&md), static_cast<Doc*>(&html)}) {
        doc->heading(1, title);
        doc->paragraph("Totals:", countsText(total) + " (" + std::to_string(rows.size()) + " comparisons).");
        ReportTable machines;
        machines.header = {"machine", "pass", "flagged", "info", "fail"};
        for (std::size_t k = 0; k < used.size(); ++k) {
            const ReportCounts c = countRows(sectionRows[k]);
            machines.rows.push_back(
                {used[k].title, std::to_string(c.pass), std::to_string(c.flagged), std::to_string(c.info),
                 std::to_string(c.fail)});
        }
        doc->table(machines);
        doc->paragraph(
            "How to read it.",
            "Each row compares one quantity of the multibody model (Simbody) or one number printed in the paper "
            "with an oracle written from the paper's equations, independently of the model (validation/oracles). "
            "pass: within tolerance; flagged: a known, explained disagreement with the paper (a misprint, or the "
            "paper's own approximation where it fails) - a flag whose disagreement vanishes counts as a failure; "
            "info: a value reported beside a reference it is not meant to equal (another start, the printed "
            "equations), inside the band the physics or the paper's accuracy allows - outside it, a failure; "
            "fail: anything else. Multibody vs oracle tolerances are those of the same equations solved two "
            "ways; paper vs oracle is half a unit in the last printed digit. Tolerances are never widened to hide "
            "a difference.");
        for (std::size_t k = 0; k < used.size(); ++k) emitSection(*doc, used[k], sectionRows[k], tables[k], plots[k]);
    }
    writeFileAtomically(dir + "/report.md", md.finish(title));
    written.push_back(dir + "/report.md");
    writeFileAtomically(dir + "/report.html", html.finish(title));
    written.push_back(dir + "/report.html");
    return written;
}

}  // namespace milldyn
