#include "report/report_page.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "common/atomic_file.h"
#include "common/markup_text.h"

namespace grainlab {
namespace fs = std::filesystem;
namespace {

/// Where the published values come from; docs/reproduction.md ("The reference study") gives the
/// same text.
constexpr const char* kPublishedStudy =
    "Published values: the two-dimensional DEM study of drained biaxial compression of 8450 "
    "ovals (aspect ratio 0.6) at 15, 25, 50 and 100 kPa that GrainLab's reference experiment "
    "reproduces, computed with the OVAL program (M. R. Kuhn, University of Portland).";

/// The comparison of one cell with the published value, in words.
std::string comparisonText(const Scatter& s, const PublishedValue& published, int digits) {
    if (s.count == 0) {
        return "–";
    }
    const Comparison c = compare(s, published);
    if (published.upperBound) {
        if (c.agrees) {
            return "below the bound";
        }
        if (s.count < 2) {
            return "above the bound (one run: no scatter to judge by)";
        }
        return c.beyondScatter ? "above the bound, beyond the scatter"
                               : "above the bound, within the scatter";
    }
    const std::string d = fmt::format("{:+.{}f}", c.difference, digits);
    if (s.count < 2) {
        return d + " (one run: no scatter to judge by)";
    }
    return d + (c.beyondScatter ? ", beyond the seed scatter (2σ)" : ", within the seed scatter");
}

int digitsOf(const std::string& unit, const std::string& key) {
    if (unit == "deg" || key.rfind("fit_", 0) == 0) {
        return 2;
    }
    return 3;
}

/// "25 kPa" for a drained test, "25 kPa constant volume" for another kind (its series name
/// after the sample's, "p025kPa-constant-volume").
std::string testColumnLabel(const HeadlineValue& v) {
    std::string label = fmt::format("{:g} kPa", v.pressure / 1e3);
    const std::size_t dash = v.test.find('-');
    if (dash != std::string::npos) {
        std::string kind = v.test.substr(dash + 1);
        std::replace(kind.begin(), kind.end(), '-', ' ');
        label += " " + kind;
    }
    return label;
}

struct Table {
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;
};

Table headlineRows(const ReportPage& page) {
    Table t;
    t.header.push_back("number");
    if (!page.headline.empty()) {
        for (const HeadlineValue& v : page.headline.front().values) {
            t.header.push_back(testColumnLabel(v));
        }
    }
    t.header.push_back("published");
    t.header.push_back("measured against published");
    for (const HeadlineRow& row : page.headline) {
        const int digits = digitsOf(row.unit, row.key);
        std::vector<std::string> r{row.unit == "-" ? row.label
                                                   : fmt::format("{} [{}]", row.label, row.unit)};
        std::string comparison;
        for (const HeadlineValue& v : row.values) {
            r.push_back(withScatter(v.value, digits));
            if (row.published) {
                comparison += (comparison.empty() ? "" : "; ") +
                              fmt::format("{}: {}", testColumnLabel(v),
                                          comparisonText(v.value, *row.published, digits));
            }
        }
        r.push_back(row.published ? row.published->text : "");
        r.push_back(comparison);
        t.rows.push_back(std::move(r));
    }
    return t;
}

std::string sourcesText(const ReportPage& page) {
    double wall = 0, cpu = 0;
    for (const ReportSource& s : page.sources) {
        wall += s.wallSeconds;
        cpu += s.cpuSeconds;
    }
    const ReportSource& first = page.sources.front();
    return fmt::format(
               "{} run(s) of the experiment `{}` ({} grains), seeds {}; {:.0f} s of run "
               "wall time in all ({:.0f} s of processor time).",
               page.sources.size(), first.experimentName, first.grains,
               [&] {
                   std::string seeds;
                   for (const ReportSource& s : page.sources) {
                       seeds += (seeds.empty() ? "" : ", ") + std::to_string(s.seed);
                   }
                   return seeds;
               }(),
               wall, cpu) +
           [&] {
               int unfinished = 0;
               for (const ReportSource& s : page.sources) {
                   unfinished += s.finished ? 0 : 1;
               }
               return unfinished == 0
                          ? std::string()
                          : fmt::format(" {} of them had not finished (no cost.json saying so): "
                                        "reported as far as they got.",
                                        unfinished);
           }();
}

std::string pooledText(const PooledFitScatter& p) {
    return fmt::format("Pooled over every shear record of every test, per run: Z̄ = {} N_v/N_vi "
                       "+ {} (R² {}); the published study states Z̄ = 3.45 N_v/N_vi + 2.1.",
                       withScatter(p.slope, 2), withScatter(p.intercept, 2), withScatter(p.r2, 3));
}

std::string figureCaption(const ReportFigure& f) {
    std::string c = f.title;
    if (f.fit) {
        c += ": " + (f.fitLabel.empty() ? fitEquation(*f.fit) + " (pooled fit)" : f.fitLabel);
    }
    if (!f.note.empty()) {
        c += " — " + f.note;
    }
    return c;
}

/// The figures in the page's order, with the void-cell pictures (figure 5) after figure 4.
std::vector<std::pair<std::string, std::string>> pageFigures(const ReportPage& page) {
    std::vector<std::pair<std::string, std::string>> out; // file stem, caption
    bool voids = false;
    for (const ReportFigure& f : page.figures) {
        if (!voids && f.name.rfind("06", 0) == 0) {
            voids = true;
            std::vector<std::string> tests;
            for (const ReportLine& l : page.figures.front().lines) {
                tests.push_back(l.test);
            }
            for (const std::string& stem : voidCellPictureNames(tests)) {
                if (fs::exists(fs::path(page.figureFolder) / (stem + ".png"))) {
                    out.emplace_back(stem, "Void cells coloured by valence: " + stem.substr(3));
                }
            }
        }
        out.emplace_back(f.name, figureCaption(f));
    }
    return out;
}

} // namespace

std::string criticalStateText(const CriticalStateSummary& cs) {
    const SteadyStateCriterion& c = cs.criterion;
    std::string text = fmt::format(
        "A test's end counts as steady when, over its last {:g} of axial strain, the least-squares "
        "slopes obey |dq/dε1| / p < {:g} and |dεv/dε1| < {:g}: {} of {} test ends are steady "
        "(critical_state.csv lists every end, with the reason when it is not).",
        c.window, c.maxStressSlope, c.maxVolumeSlope, cs.steadyCount(), cs.ends.size());
    if (cs.m.count == 0) {
        return text + " No steady end: no critical state stress ratio or line.";
    }
    text +=
        fmt::format(" M = q/p at the steady ends: {} ({} ends)", withScatter(cs.m, 3), cs.m.count);
    if (cs.mDrained.count > 0 && cs.mConstantVolume.count > 0) {
        text += fmt::format("; drained {} ({}), constant volume {} ({})",
                            withScatter(cs.mDrained, 3), cs.mDrained.count,
                            withScatter(cs.mConstantVolume, 3), cs.mConstantVolume.count);
        if (cs.mDrained.count >= 2 && cs.mConstantVolume.count >= 2) {
            // The difference of two means against its standard error.
            const double se =
                std::sqrt(cs.mDrained.sd * cs.mDrained.sd / cs.mDrained.count +
                          cs.mConstantVolume.sd * cs.mConstantVolume.sd / cs.mConstantVolume.count);
            const double d = cs.mDrained.mean - cs.mConstantVolume.mean;
            text += fmt::format(": they differ by {:.3f}, {} twice the standard error of the "
                                "difference ({:.3f})",
                                d, std::fabs(d) <= 2.0 * se ? "within" : "beyond", 2.0 * se);
        }
    }
    text += ".";
    if (cs.line) {
        text += fmt::format(" Critical state line through the steady ends: {} (R² = {:.3f}, {} "
                            "points).",
                            cs.line->equation(), cs.line->rSquared, cs.line->points);
    } else {
        text += " No critical state line: it needs steady ends at two different p′.";
    }
    return text;
}

std::string criticalStateCsv(const CriticalStateSummary& cs) {
    std::string out = "run,test,kind,pressure [Pa],steady,reason,q [Pa],p [Pa],e [-],"
                      "q_over_p [-],stress_slope [-],volume_slope [-]\n";
    const auto quoted = [](std::string s) {
        std::string q = "\"";
        for (char ch : s) {
            q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
        }
        return q + "\"";
    };
    for (const TestEndState& e : cs.ends) {
        out += fmt::format("{},{},{},{:.9g},{},{},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}\n",
                           quoted(e.run), e.test, e.kind, e.pressure,
                           e.steady.steady ? "yes" : "no", quoted(e.steady.reason), e.q, e.p, e.e,
                           e.stressRatio, e.steady.stressSlope, e.steady.volumeSlope);
    }
    return out;
}

std::string fitEquation(const LinearFit& fit) {
    return fmt::format("Z̄ = {:.2f} N_v/N_vi {} {:.2f} (R² = {:.3f}, {} records)", fit.slope,
                       fit.intercept < 0 ? "−" : "+", std::abs(fit.intercept), fit.r2, fit.count);
}

std::string withScatter(const Scatter& s, int digits) {
    if (s.count == 0) {
        return "–";
    }
    if (s.count < 2) {
        return fmt::format("{:.{}f}", s.mean, digits);
    }
    return fmt::format("{:.{}f} ± {:.{}f}", s.mean, digits, s.sd, digits);
}

std::vector<std::string> voidCellPictureNames(const std::vector<std::string>& tests) {
    std::vector<std::string> names;
    if (tests.empty()) {
        return names;
    }
    std::vector<std::string> ends{tests.front()};
    if (tests.size() > 1) {
        ends.push_back(tests.back());
    }
    for (const std::string& t : ends) {
        for (const char* at : {"start", "peak", "10pc"}) {
            names.push_back(fmt::format("05_{}_{}", t, at));
        }
    }
    return names;
}

std::string base64(const std::string& bytes) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    std::size_t k = 0;
    for (; k + 2 < bytes.size(); k += 3) {
        const unsigned v = (unsigned char)bytes[k] << 16 | (unsigned char)bytes[k + 1] << 8 |
                           (unsigned char)bytes[k + 2];
        out += table[v >> 18 & 63];
        out += table[v >> 12 & 63];
        out += table[v >> 6 & 63];
        out += table[v & 63];
    }
    if (k < bytes.size()) {
        const bool two = k + 1 < bytes.size();
        const unsigned v =
            (unsigned char)bytes[k] << 16 | (two ? (unsigned char)bytes[k + 1] << 8 : 0);
        out += table[v >> 18 & 63];
        out += table[v >> 12 & 63];
        out += two ? table[v >> 6 & 63] : '=';
        out += '=';
    }
    return out;
}

std::string reportMarkdown(const ReportPage& page) {
    std::string md = "# Report: biaxial compression of ovals\n\n" + sourcesText(page) + " " +
                     kPublishedStudy +
                     " Curves are means over the runs with a ±1σ band; numbers are mean ± "
                     "sample standard deviation over the runs.\n\n## Headline numbers\n\n";
    const Table t = headlineRows(page);
    const auto row = [](const std::vector<std::string>& cells) {
        std::string s = "|";
        for (const std::string& c : cells) {
            s += " " + c + " |";
        }
        return s + "\n";
    };
    md += row(t.header);
    md += row(std::vector<std::string>(t.header.size(), "---"));
    for (const auto& r : t.rows) {
        md += row(r);
    }
    md += "\n";
    md += pooledText(page.pooled); // appended, not "\n" + …: GCC 12 warns falsely (-Wrestrict)
    if (page.criticalState) {
        md += "\n\n## Critical state\n\n";
        md += criticalStateText(*page.criticalState);
    }
    md += "\n\n## Figures\n\n";
    const std::string folder = fs::path(page.figureFolder).filename().string();
    for (const auto& [stem, caption] : pageFigures(page)) {
        const bool png = fs::exists(fs::path(page.figureFolder) / (stem + ".png"));
        md += fmt::format("### {}\n\n", caption);
        if (png) {
            md += fmt::format("![{}]({}/{}.png)\n\n", stem, folder, stem);
        }
        if (fs::exists(fs::path(page.figureFolder) / (stem + ".csv"))) {
            md += fmt::format("Data: [{}/{}.csv]({}/{}.csv)\n\n", folder, stem, folder, stem);
        }
    }
    return md;
}

std::string reportHtml(const ReportPage& page) {
    std::string h =
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
        "<title>GrainLab report</title><style>"
        "body{font-family:sans-serif;max-width:1100px;margin:2em auto;color:#222}"
        "table{border-collapse:collapse;font-size:90%}td,th{border:1px solid #bbb;"
        "padding:3px 6px;text-align:left}th{background:#eee}"
        "figure{margin:1.5em 0}img{max-width:100%;border:1px solid #ddd}"
        "figcaption{font-style:italic}</style></head><body>\n"
        "<h1>Report: biaxial compression of ovals</h1>\n<p>" +
        markupEscaped(sourcesText(page)) + " " + markupEscaped(kPublishedStudy) +
        " Curves are means over the runs with a ±1σ band; numbers are mean ± sample standard "
        "deviation over the runs.</p>\n<h2>Headline numbers</h2>\n<table>\n<tr>";
    const Table t = headlineRows(page);
    for (const std::string& c : t.header) {
        h += "<th>" + markupEscaped(c) + "</th>";
    }
    h += "</tr>\n";
    for (const auto& r : t.rows) {
        h += "<tr>";
        for (const std::string& c : r) {
            h += "<td>" + markupEscaped(c) + "</td>";
        }
        h += "</tr>\n";
    }
    h += "</table>\n<p>" + markupEscaped(pooledText(page.pooled)) + "</p>\n";
    if (page.criticalState) {
        h += "<h2>Critical state</h2>\n<p>" +
             markupEscaped(criticalStateText(*page.criticalState)) + "</p>\n";
    }
    h += "<h2>Figures</h2>\n";
    for (const auto& [stem, caption] : pageFigures(page)) {
        const fs::path png = fs::path(page.figureFolder) / (stem + ".png");
        h += "<figure>";
        if (fs::exists(png)) {
            h += "<img alt=\"" + markupEscaped(stem) + "\" src=\"data:image/png;base64," +
                 base64(readWholeFile(png.string())) + "\">";
        }
        h += "<figcaption>" + markupEscaped(caption) + " (data: figures/" + markupEscaped(stem) +
             ".csv)</figcaption></figure>\n";
    }
    h += "</body></html>\n";
    return h;
}

} // namespace grainlab
