#pragma once
// The files of a study folder, read and written by `grainlab study` and `grainlab study collect`
// (and read by the Study window):
//   study.json             the study file as given (its base experiment resolved into base.json)
//   base.json              the base experiment's text
//   experiments/<run>.json the experiment file of each run
//   runs/<run>/            an ordinary run folder, exactly as `grainlab run` writes it
//   logs/<run>.log         what each run printed
//   study.csv, summary.csv the results (docs/study.md), recommended.json the recommendation
// Main thread (or the Study window's worker thread).

#include <optional>
#include <string>
#include <vector>

#include "grainlab/study_plan.h"
#include "grainlab/study_summary.h"

namespace grainlab {

/// Reads what a study needs of a finished run folder: the shear tests' series (from run.h5),
/// their confining pressures (from the experiment it holds) and its cost (cost.json). Nothing
/// when the run is not finished (no cost.json saying so). Throws std::runtime_error naming the
/// file when a finished run's files cannot be read.
std::optional<RunResult> readRunResult(const std::string& runFolder, int runIndex);
/// The shear tests' series and pressures of a run folder's run.h5, finished or not (no cost).
/// Throws std::runtime_error naming the file when it cannot be read.
RunResult readRunSeries(const std::string& runFolder, int runIndex);

/// Writes study.csv: one row per run with results (knob levels, every metric, cost).
void writeStudyCsv(const std::string& path, const StudySpec& spec, const StudyPlan& plan,
                   const std::vector<RunResult>& results, const StudySummary& summary);

/// Writes summary.csv: one row per (setting, test, metric), and the cost rows of each setting.
void writeSummaryCsv(const std::string& path, const StudySpec& spec, const StudyPlan& plan,
                     const StudySummary& summary);

/// The recommended setting as an experiment file (the base experiment's own seed).
std::string recommendedExperiment(const StudySpec& spec, const StudyPlan& plan, int setting);

} // namespace grainlab
