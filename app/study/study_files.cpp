#include "study/study_files.h"

#include <cmath>
#include <filesystem>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "common/atomic_file.h"
#include "common/run_cost.h"
#include "grainlab/csv_series.h"
#include "grainlab/run_file.h"

namespace grainlab {

namespace fs = std::filesystem;

namespace {

/// A number with round-trip precision; an empty cell for a missing value (never NaN).
std::string cell(const std::optional<double>& v) {
    return v && std::isfinite(*v) ? fmt::format("{:.17g}", *v) : std::string();
}

/// The knobs of the study, in file order, as CSV header cells and as one setting's cells.
std::vector<std::string> knobHeader(const StudySpec& spec) {
    std::vector<std::string> out;
    for (const Knob& k : spec.knobs) {
        out.push_back(knobName(k.kind) + " [-]");
    }
    return out;
}

std::vector<std::string> knobCells(const StudySpec& spec, const StudySetting& setting) {
    std::vector<std::string> out;
    for (const Knob& k : spec.knobs) {
        const auto it = setting.levels.find(k.kind);
        out.push_back(it == setting.levels.end() ? "base" : it->second.label());
    }
    return out;
}

std::string yesNo(bool b) {
    return b ? "yes" : "no";
}

} // namespace

RunResult readRunSeries(const std::string& runFolder, int runIndex) {
    const std::string runFile = (fs::path(runFolder) / "run.h5").string();
    RunResult r;
    r.run = runIndex;
    // Every test but the compaction's, with the confining pressure its rows carry.
    for (const std::string& test : listTests(runFile)) {
        SeriesTable t = readSeries(runFile, test);
        if (t.stageKinds.empty() || t.stageKinds.front() == "compaction") {
            continue;
        }
        r.pressures.push_back(t.stagePressures.front());
        r.tests.push_back(std::move(t));
    }
    return r;
}

std::optional<RunResult> readRunResult(const std::string& runFolder, int runIndex) {
    const RunCostRecord cost = readRunCost(runFolder);
    if (!cost.finished) {
        return std::nullopt;
    }
    RunResult r = readRunSeries(runFolder, runIndex);
    r.cost.wallSeconds = cost.wallSeconds;
    r.cost.cpuSeconds = cost.cpuSeconds;
    r.cost.steps = cost.steps;
    r.cost.grainSteps = cost.grainSteps;
    r.cost.threads = cost.threads;
    return r;
}

void writeStudyCsv(const std::string& path, const StudySpec& spec, const StudyPlan& plan,
                   const std::vector<RunResult>& results, const StudySummary& summary) {
    std::vector<std::string> header{"run", "setting", "seed [-]"};
    for (const std::string& k : knobHeader(spec)) {
        header.push_back(k);
    }
    // Metric columns: every test.metric any run has, in the summary's order.
    std::vector<std::pair<std::string, std::string>> metricColumns;
    if (!summary.settings.empty()) {
        for (const MetricSummary& m : summary.settings.front().metrics) {
            metricColumns.emplace_back(m.test + "." + m.metric, m.unit);
        }
    }
    for (const auto& [name, unit] : metricColumns) {
        header.push_back(fmt::format("{} [{}]", name, unit));
    }
    for (const char* c :
         {"wall_seconds [s]", "cpu_seconds [s]", "steps [-]", "grain_steps [-]", "threads [-]"}) {
        header.push_back(c);
    }
    std::string text = csvLine(header);
    for (std::size_t i = 0; i < results.size(); ++i) {
        const RunResult& r = results[i];
        const StudyRun& run = plan.runs.at(std::size_t(r.run));
        const StudySetting& setting = plan.settings.at(std::size_t(run.setting));
        std::vector<std::string> row{run.id, setting.id, fmt::format("{}", run.seed)};
        for (const std::string& c : knobCells(spec, setting)) {
            row.push_back(c);
        }
        for (const auto& [name, unit] : metricColumns) {
            const auto& m = summary.perRun.at(i);
            const auto it = m.find(name);
            row.push_back(it == m.end() ? std::string() : cell(it->second));
        }
        row.push_back(cell(r.cost.wallSeconds));
        row.push_back(cell(r.cost.cpuSeconds));
        row.push_back(fmt::format("{}", r.cost.steps));
        row.push_back(fmt::format("{}", r.cost.grainSteps));
        row.push_back(fmt::format("{}", r.cost.threads));
        text += csvLine(row);
    }
    writeFileAtomically(path, text);
}

void writeSummaryCsv(const std::string& path, const StudySpec& spec, const StudyPlan& plan,
                     const StudySummary& summary) {
    std::vector<std::string> header{"setting", "reference", "recommended", "valid", "runs [-]"};
    for (const std::string& k : knobHeader(spec)) {
        header.push_back(k);
    }
    for (const char* c : {"test", "metric", "unit", "mean", "sd", "error", "noise", "within_noise",
                          "tolerance", "within_tolerance", "deciding"}) {
        header.push_back(c);
    }
    std::string text = csvLine(header);
    for (const SettingSummary& s : summary.settings) {
        const StudySetting& setting = plan.settings.at(std::size_t(s.setting));
        std::vector<std::string> front{setting.id, yesNo(setting.isReference),
                                       yesNo(summary.recommended == s.setting), yesNo(s.valid),
                                       fmt::format("{}", s.runsDone)};
        for (const std::string& c : knobCells(spec, setting)) {
            front.push_back(c);
        }
        const auto addRow = [&](const std::vector<std::string>& rest) {
            std::vector<std::string> row = front;
            row.insert(row.end(), rest.begin(), rest.end());
            text += csvLine(row);
        };
        for (const MetricSummary& m : s.metrics) {
            const auto tol = spec.tolerances.find(m.metric);
            const bool deciding = std::find(spec.deciding.begin(), spec.deciding.end(), m.metric) !=
                                  spec.deciding.end();
            addRow(
                {m.test, m.metric, m.unit,
                 m.scatter.count > 0 ? cell(m.scatter.mean) : std::string(),
                 m.scatter.count > 0 ? cell(m.scatter.sd) : std::string(), cell(m.error),
                 cell(m.noise), m.error && m.noise ? yesNo(m.withinNoise) : std::string(),
                 tol == spec.tolerances.end()
                     ? std::string()
                     : fmt::format("{}{}", tol->second.value, tol->second.relative ? " rel" : ""),
                 m.withinTolerance ? yesNo(*m.withinTolerance) : std::string(), yesNo(deciding)});
        }
        // The cost of the setting, as rows of their own ("test" = "cost").
        const auto costRow = [&](const char* metric, const char* unit, const Scatter& sc) {
            addRow({"cost", metric, unit, sc.count ? cell(sc.mean) : "",
                    sc.count ? cell(sc.sd) : "", "", "", "", "", "", "no"});
        };
        costRow("wall_seconds", "s", s.wallSeconds);
        costRow("cpu_seconds", "s", s.cpuSeconds);
        addRow({"cost", "speed_up", "-", cell(s.speedUp), "", "", "", "", "", "", "no"});
    }
    writeFileAtomically(path, text);
}

std::string recommendedExperiment(const StudySpec& spec, const StudyPlan& plan, int setting) {
    const auto base = nlohmann::json::parse(spec.baseExperiment);
    const std::uint64_t seed = base.contains("seed") ? base["seed"].get<std::uint64_t>() : 1;
    return applySetting(spec.baseExperiment, spec.baseSource,
                        plan.settings.at(std::size_t(setting)).levels, seed);
}

} // namespace grainlab
