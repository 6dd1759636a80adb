#include "study/study_command.h"

#include <algorithm>
#include <filesystem>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "common/atomic_file.h"
#include "common/job_list.h"
#include "common/pool_command.h"
#include "common/run_cost.h"
#include "grainlab/experiment_file.h"
#include "grainlab/experiment_runner.h"
#include "grainlab/study_file.h"
#include "study/study_files.h"

namespace grainlab {

namespace fs = std::filesystem;

namespace {

/// The engine threads run `run` uses.
int threadsOf(const StudyRun& run) {
    return engineThreads(parseExperimentText(run.experimentText, run.id));
}

/// Creates the study folder, or checks that an existing one holds this very study. Writes
/// study.json and each run's experiment file (unless there already, identical).
void prepareFolder(const fs::path& dir, const StudySpec& spec, const StudyPlan& plan) {
    preparePoolFolder({dir, "study.json", "study", "study", {"experiments", "runs", "logs"}},
                      spec.sourceText, spec.sourcePath);
    for (const StudyRun& r : plan.runs) {
        const fs::path file = dir / "experiments" / (r.id + ".json");
        if (fs::exists(file)) {
            if (readWholeFile(file.string()) != r.experimentText) {
                throw std::runtime_error(fmt::format(
                    "{}: differs from what the study makes of this run; the study folder was "
                    "changed by hand",
                    file.string()));
            }
            continue;
        }
        writeFileAtomically(file.string(), r.experimentText);
    }
}

/// Summarises the finished runs into study.csv, summary.csv and recommended.json; prints the
/// recommendation. Returns how many runs had results.
std::size_t summarise(const fs::path& dir, const StudySpec& spec, const StudyPlan& plan, bool quiet,
                      const StudyFigureWriter& figures) {
    std::vector<RunResult> results;
    for (std::size_t i = 0; i < plan.runs.size(); ++i) {
        if (auto r = readRunResult((dir / "runs" / plan.runs[i].id).string(), int(i))) {
            results.push_back(std::move(*r));
        }
    }
    const StudySummary summary = summariseStudy(spec, plan, results, spec.costMeasure);
    writeStudyCsv((dir / "study.csv").string(), spec, plan, results, summary);
    writeSummaryCsv((dir / "summary.csv").string(), spec, plan, summary);
    if (figures) {
        const std::string error = figures(dir.string(), spec, plan, results, summary);
        if (!error.empty()) {
            throw std::runtime_error("writing the study's figures: " + error);
        }
    }
    if (summary.recommended) {
        const int best = *summary.recommended;
        writeFileAtomically((dir / "recommended.json").string(),
                            recommendedExperiment(spec, plan, best));
        if (!quiet) {
            const SettingSummary& s = summary.settings[std::size_t(best)];
            fmt::print("grainlab study: recommended setting {} ({} of {} runs done): {:.2f}x "
                       "cheaper than the reference in {}; written as {}\n",
                       plan.settings[std::size_t(best)].id, results.size(), plan.runs.size(),
                       s.speedUp.value_or(1.0), spec.costMeasure,
                       (dir / "recommended.json").string());
        }
    } else if (!quiet) {
        fmt::print("grainlab study: no recommendation yet ({} of {} runs done; the reference "
                   "needs results)\n",
                   results.size(), plan.runs.size());
    }
    return results.size();
}

} // namespace

int runStudyCommand(const StudyOptions& options) {
    const StudySpec spec = readStudyFile(options.studyFile);
    const StudyPlan plan = planStudy(spec);
    const fs::path dir = fs::absolute(options.out).lexically_normal();
    prepareFolder(dir, spec, plan);
    const StudyLayout layout{dir.string(), fs::absolute(options.grainlab).string()};
    std::vector<std::string> ids;
    for (const StudyRun& r : plan.runs) {
        ids.push_back(r.id);
    }
    int threads = 1; // the most any run uses: a Slurm task's processors
    for (const StudyRun& r : plan.runs) {
        threads = std::max(threads, threadsOf(r));
    }

    if (options.emit == "slurm" || options.emit == "parallel") {
        const bool slurm = options.emit == "slurm";
        const fs::path file = dir / (slurm ? "study.slurm" : "jobs.txt");
        writeFileAtomically(file.string(), slurm ? slurmScript(layout, spec.name, ids, threads)
                                                 : parallelJobList(layout, ids));
        printEmittedJobs(
            "grainlab study", ids.size(), "runs", file.string(), slurm,
            fmt::format("Then summarise with: {} study collect {}", layout.grainlab, dir.string()));
        return 0;
    }
    if (!options.emit.empty()) {
        throw std::runtime_error(fmt::format("--emit {}: must be slurm or parallel", options.emit));
    }

    // The runs still to do: a run folder with a run file continues, a finished run is skipped.
    std::vector<PoolJob> jobs;
    std::vector<std::string> jobNames;
    std::size_t finishedBefore = 0;
    for (std::size_t i = 0; i < plan.runs.size(); ++i) {
        const std::string folder = layout.runFolder(plan.runs[i].id);
        if (readRunCost(folder).finished) {
            ++finishedBefore;
            continue;
        }
        const bool resume = fs::exists(fs::path(folder) / "run.h5");
        jobs.push_back({runArguments(layout, plan.runs[i].id, resume),
                        layout.logFile(plan.runs[i].id), threadsOf(plan.runs[i])});
        jobNames.push_back(plan.runs[i].id);
    }
    const int slots = poolSlots(options.jobs);
    if (!options.quiet) {
        fmt::print("grainlab study {}: {} settings x {} seeds = {} runs, {} done, at most {} at "
                   "a time; folder {}\n",
                   spec.name, plan.settings.size(), spec.seeds.size(), plan.runs.size(),
                   finishedBefore, slots, dir.string());
    }

    const PoolOutcome outcome =
        runPoolJobs(jobs, jobNames, options.jobs, finishedBefore, plan.runs.size(),
                    fmt::format("study {} ({} runs)", spec.name, plan.runs.size()), options.quiet);
    summarise(dir, spec, plan, options.quiet, options.figures);
    return poolExitStatus(
        outcome, "grainlab study",
        fmt::format("grainlab study: interrupted; the runs wrote checkpoints. Continue with the "
                    "same command: grainlab study {} --out {}",
                    options.studyFile, dir.string()),
        "run(s)");
}

int collectStudyCommand(const std::string& folder, bool quiet, const StudyFigureWriter& figures) {
    const fs::path dir = fs::absolute(folder).lexically_normal();
    const fs::path studyJson = dir / "study.json";
    if (!fs::exists(studyJson)) {
        throw std::runtime_error(
            fmt::format("study collect {}: no study.json: not a study folder", dir.string()));
    }
    const StudySpec spec = readStudyFile(studyJson.string());
    const StudyPlan plan = planStudy(spec);
    const std::size_t done = summarise(dir, spec, plan, quiet, figures);
    if (!quiet) {
        fmt::print("grainlab study collect: {} of {} runs finished; results in {}\n", done,
                   plan.runs.size(), dir.string());
    }
    return done == plan.runs.size() ? 0 : 3;
}

} // namespace grainlab
