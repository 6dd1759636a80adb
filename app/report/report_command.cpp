#include "report/report_command.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "common/atomic_file.h"
#include "common/run_cost.h"
#include "grainlab/csv_series.h"
#include "grainlab/measures.h"
#include "grainlab/run_file.h"
#include "report/report_page.h"
#include "study/study_command.h"
#include "study/study_files.h"

namespace grainlab {
namespace fs = std::filesystem;
namespace {

std::string unitOf(const std::string& column) {
    if (column == "pressure") {
        return "kPa";
    }
    for (const SeriesColumn& c : seriesColumns()) {
        if (c.name == column) {
            return c.unit;
        }
    }
    return "-";
}

std::string number(double v) {
    return fmt::format("{:.9g}", v);
}

/// The experiment without what may differ between the runs of one report (seed, name, text).
nlohmann::json comparable(nlohmann::json e) {
    for (const char* key : {"seed", "name", "description"}) {
        e.erase(key);
    }
    return e;
}

/// The first key (as a path) where two experiments differ, or "".
std::string firstDifference(const nlohmann::json& a, const nlohmann::json& b,
                            const std::string& at = "") {
    if (a.is_object() && b.is_object()) {
        for (const auto& [key, value] : a.items()) {
            const std::string path = at.empty() ? key : at + "." + key;
            if (!b.contains(key)) {
                return path;
            }
            if (std::string d = firstDifference(value, b[key], path); !d.empty()) {
                return d;
            }
        }
        for (const auto& [key, value] : b.items()) {
            if (!a.contains(key)) {
                return at.empty() ? key : at + "." + key;
            }
        }
        return "";
    }
    return a == b ? "" : (at.empty() ? std::string("(the whole experiment)") : at);
}

struct LoadedRuns {
    std::vector<ReportRun> runs;
    std::vector<ReportSource> sources;
};

/// Refuses a run folder given twice (under any spelling of its path): its copy would count as
/// a second seed with the same values, a standard deviation of 0 and a false agreement.
void refuseRepeatedRuns(const std::vector<std::string>& folders) {
    std::vector<fs::path> seen;
    for (const std::string& folder : folders) {
        fs::path path = fs::absolute(folder).lexically_normal();
        if (!path.has_filename()) {
            path = path.parent_path(); // "runs/seed1/" is "runs/seed1"
        }
        std::error_code ignored; // a missing folder is refused by name when it is read
        const fs::path canonical = fs::weakly_canonical(path, ignored);
        for (std::size_t k = 0; k < seen.size(); ++k) {
            if (seen[k] == canonical) {
                throw std::runtime_error(fmt::format(
                    "{}: this run is given twice (also as {}): a report averages different "
                    "runs (seeds) of one experiment; give each run once",
                    folder, folders[k]));
            }
        }
        seen.push_back(canonical);
    }
}

LoadedRuns loadRuns(const std::vector<std::string>& folders) {
    refuseRepeatedRuns(folders);
    LoadedRuns loaded;
    nlohmann::json first;
    for (std::size_t i = 0; i < folders.size(); ++i) {
        const std::string& folder = folders[i];
        const std::string runFile = (fs::path(folder) / "run.h5").string();
        if (!fs::exists(runFile)) {
            throw std::runtime_error(fmt::format("{}: no run.h5: not a run folder", folder));
        }
        // A run not finished (a window run has no cost.json; an interrupted one) is reported
        // as far as it got, and the page says so.
        std::optional<RunResult> result = readRunResult(folder, int(i));
        const bool finished = result.has_value();
        if (!result) {
            result = readRunSeries(folder, int(i));
        }
        const nlohmann::json experiment = nlohmann::json::parse(readExperimentText(runFile));
        if (i == 0) {
            first = experiment;
        } else if (const std::string d = firstDifference(comparable(first), comparable(experiment));
                   !d.empty()) {
            throw std::runtime_error(fmt::format(
                "{} and {} are runs of different experiments (they differ at `{}`): a report "
                "averages the seeds of one experiment",
                folders.front(), folder, d));
        }
        ReportRun run;
        run.name = fs::path(folder).filename().string();
        if (run.name.empty()) {
            run.name = fs::path(folder).parent_path().filename().string();
        }
        run.tests = std::move(result->tests);
        run.pressures = std::move(result->pressures);
        if (run.tests.empty()) {
            throw std::runtime_error(fmt::format("{}: the run has no shear test", folder));
        }
        ReportSource source;
        source.folder = folder;
        source.experimentName = experiment.value("name", std::string());
        source.seed = experiment.value("seed", 0);
        source.grains = experiment.contains("grains") ? experiment["grains"].value("count", 0) : 0;
        source.wallSeconds = result->cost.wallSeconds;
        source.cpuSeconds = result->cost.cpuSeconds;
        source.finished = finished;
        loaded.runs.push_back(std::move(run));
        loaded.sources.push_back(std::move(source));
    }
    return loaded;
}

} // namespace

std::string figureCsv(const ReportFigure& figure) {
    const std::string xUnit = unitOf(figure.xColumn), yUnit = unitOf(figure.yColumn);
    std::vector<std::string> header{"line", "test", "pressure [Pa]",
                                    fmt::format("{} [{}]", figure.xColumn, xUnit)};
    const bool xSd = !figure.lines.empty() && !figure.lines.front().xSd.empty();
    if (xSd) {
        header.push_back(fmt::format("{} sd [{}]", figure.xColumn, xUnit));
    }
    header.push_back(fmt::format("{} mean [{}]", figure.yColumn, yUnit));
    header.push_back(fmt::format("{} sd [{}]", figure.yColumn, yUnit));
    header.push_back("runs [-]");
    if (!figure.lines.empty()) {
        for (const auto& [name, values] : figure.lines.front().extra) {
            header.push_back(name);
        }
    }
    std::string out = csvLine(header);
    for (const ReportLine& line : figure.lines) {
        for (std::size_t k = 0; k < line.x.size(); ++k) {
            std::vector<std::string> row{line.label, line.test, number(line.pressure),
                                         number(line.x[k])};
            if (xSd) {
                row.push_back(k < line.xSd.size() ? number(line.xSd[k]) : "");
            }
            row.push_back(number(line.y[k]));
            row.push_back(number(line.sd[k]));
            row.push_back(std::to_string(line.runs[k]));
            for (const auto& [name, values] : line.extra) {
                row.push_back(k < values.size() ? number(values[k]) : "");
            }
            out += csvLine(row);
        }
    }
    if (figure.fit) {
        // The fitted line at the ends of the data, labelled with its equation.
        double lo = 0, hi = 0;
        bool any = false;
        for (const ReportLine& line : figure.lines) {
            for (double x : line.x) {
                lo = any ? std::min(lo, x) : x;
                hi = any ? std::max(hi, x) : x;
                any = true;
            }
        }
        const std::string label = fitEquation(*figure.fit);
        for (double x : {lo, hi}) {
            std::vector<std::string> row{label, "", "", number(x)};
            if (xSd) {
                row.push_back("");
            }
            row.push_back(number(figure.fit->slope * x + figure.fit->intercept));
            row.push_back("");
            row.push_back(std::to_string(figure.fit->count));
            row.resize(header.size());
            out += csvLine(row);
        }
    }
    return out;
}

std::string headlineCsv(const std::vector<HeadlineRow>& rows, const PooledFitScatter& pooled) {
    static constexpr const char* kOneRun = "one run: no scatter";
    std::string out = csvLine({"number", "label", "test", "pressure [Pa]", "unit", "mean", "sd",
                               "runs [-]", "published", "difference", "agrees", "beyond_scatter"});
    const auto line = [&](const std::string& key, const std::string& label, const std::string& test,
                          double pressure, const std::string& unit, const Scatter& s,
                          const std::optional<PublishedValue>& published) {
        std::vector<std::string> r{key,
                                   label,
                                   test,
                                   number(pressure),
                                   unit,
                                   s.count ? number(s.mean) : "",
                                   s.count ? number(s.sd) : "",
                                   std::to_string(s.count)};
        if (published && s.count) {
            const Comparison c = compare(s, *published);
            // One run has no scatter to judge by: a difference from a value (or a mean above a
            // bound) is then neither within nor beyond it, as the page says.
            const bool judged = s.count >= 2;
            const std::string agrees = published->upperBound || judged
                                           ? std::string(c.agrees ? "yes" : "no")
                                           : std::string(kOneRun);
            const std::string beyond =
                judged ? std::string(c.beyondScatter ? "yes" : "no") : std::string(kOneRun);
            r.insert(r.end(), {published->text, number(c.difference), agrees, beyond});
        } else {
            r.insert(r.end(), {published ? published->text : "", "", "", ""});
        }
        out += csvLine(r);
    };
    for (const HeadlineRow& row : rows) {
        for (const HeadlineValue& v : row.values) {
            line(row.key, row.label, v.test, v.pressure, row.unit, v.value, row.published);
        }
    }
    line("pooled_fit_slope", "slope of Z̄ on N_v/N_vi, every test pooled", "pooled", 0, "-",
         pooled.slope, publishedFitSlope());
    line("pooled_fit_intercept", "intercept of Z̄ on N_v/N_vi, every test pooled", "pooled", 0, "-",
         pooled.intercept, publishedFitIntercept());
    line("pooled_fit_r2", "R² of that fit", "pooled", 0, "-", pooled.r2, std::nullopt);
    return out;
}

int runReportCommand(const ReportCommandOptions& options) {
    if (options.runFolders.empty() || options.out.empty()) {
        fmt::print(stderr, "grainlab report: give one or more run folders and --out DIR\n");
        return 2;
    }
    try {
        const LoadedRuns loaded = loadRuns(options.runFolders);
        const std::vector<ReportFigure> figures = reportFigures(loaded.runs);
        const std::vector<HeadlineRow> headline = headlineTable(loaded.runs);
        const PooledFitScatter pooled = pooledFitOverRuns(loaded.runs);
        const fs::path out(options.out), figureFolder = out / "figures";
        fs::create_directories(figureFolder);
        for (const ReportFigure& f : figures) {
            writeFileAtomically((figureFolder / (f.name + ".csv")).string(), figureCsv(f));
        }
        writeFileAtomically((out / "headline.csv").string(), headlineCsv(headline, pooled));
        const CriticalStateSummary criticalState = criticalStateOf(loaded.runs);
        writeFileAtomically((out / "critical_state.csv").string(), criticalStateCsv(criticalState));
        if (options.figures) {
            if (const std::string error =
                    options.figures(figureFolder.string(), figures, loaded.sources);
                !error.empty()) {
                fmt::print(stderr, "grainlab report: figures: {}\n", error);
                return 1;
            }
        }
        const ReportPage page{
            figures, headline, pooled, loaded.sources, figureFolder.string(), &criticalState};
        writeFileAtomically((out / "report.md").string(), reportMarkdown(page));
        writeFileAtomically((out / "report.html").string(), reportHtml(page));
        if (!options.quiet) {
            fmt::print("grainlab report: {} run(s); wrote {}\n", loaded.runs.size(),
                       (out / "report.html").string());
        }
        return 0;
    } catch (const std::exception& e) {
        fmt::print(stderr, "grainlab report: {}\n", e.what());
        return 1;
    }
}

int runReproduceCommand(const ReproduceOptions& options) {
    if (options.out.empty()) {
        fmt::print(stderr, "grainlab reproduce: give --out DIR\n");
        return 2;
    }
    try {
        const fs::path out = fs::absolute(options.out);
        const nlohmann::json experiment = nlohmann::json::parse(readWholeFile(options.experiment));
        const int grains =
            options.grains > 0 ? options.grains : experiment.at("grains").at("count").get<int>();
        // The reference at K seeds: a study of one setting, run by the study's pool.
        nlohmann::json study{
            {"name", "reproduce"},
            {"description", fmt::format("the reference experiment at {} grains, {} seed(s)", grains,
                                        options.seeds)},
            {"base", fs::absolute(options.experiment).string()},
            {"knobs", {{"grain_count", {grains}}}},
            {"reference", {{"grain_count", grains}}},
            {"seeds", options.seeds}};
        fs::create_directories(out);
        const std::string studyFile = (out / "reproduce.json").string();
        const std::string text = study.dump(2) + "\n";
        if (fs::exists(studyFile) && readWholeFile(studyFile) != text) {
            throw std::runtime_error(
                fmt::format("{} holds a reproduction with other settings ({}); give another --out",
                            out.string(), studyFile));
        }
        writeFileAtomically(studyFile, text);
        StudyOptions s;
        s.studyFile = studyFile;
        s.out = (out / "study").string();
        s.jobs = options.jobs;
        s.quiet = options.quiet;
        s.grainlab = options.grainlab;
        const int status = runStudyCommand(s);
        std::vector<std::string> folders;
        for (int k = 1; k <= options.seeds; ++k) {
            const fs::path run = out / "study" / "runs" / fmt::format("ref-seed{}", k);
            if (readRunCost(run.string()).finished) {
                folders.push_back(run.string());
            }
        }
        if (folders.empty()) {
            fmt::print(stderr, "grainlab reproduce: no run finished; nothing to report\n");
            return status == 0 ? 1 : status;
        }
        ReportCommandOptions r;
        r.runFolders = folders;
        r.out = (out / "report").string();
        r.quiet = options.quiet;
        r.figures = options.figures;
        const int reported = runReportCommand(r);
        return status != 0 ? status : reported;
    } catch (const std::exception& e) {
        fmt::print(stderr, "grainlab reproduce: {}\n", e.what());
        return 1;
    }
}

} // namespace grainlab
