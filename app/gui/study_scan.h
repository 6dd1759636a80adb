#pragma once
// What a study folder holds so far, for the Study window: which runs have finished, their
// results (read once each) and the summary over them. scanStudyFolder() is a plain function
// over the folder's files (no Qt); the Study window calls it on its worker thread and hands the
// immutable result to the GUI thread, so reading run files never blocks the window.

#include <memory>
#include <string>
#include <vector>

#include "grainlab/study_plan.h"
#include "grainlab/study_summary.h"

namespace grainlab::ui {

/// A study folder as last read. Immutable once made; shared between the worker and GUI threads.
struct StudyProgress {
    std::vector<bool> finished;      ///< per run of the plan: cost.json says finished
    std::vector<RunResult> results;  ///< the finished runs' results, in plan order
    StudySummary summary;            ///< over `results`
    std::vector<std::string> errors; ///< runs marked finished whose files could not be read
    int finishedCount() const;
};

/// Reads the runs of `plan` in `studyFolder` (runs/<run>/) that have finished since `previous`
/// (all of them when it is null), keeps the results `previous` already holds, and summarises
/// them when anything new came in.
std::shared_ptr<const StudyProgress>
scanStudyFolder(const std::string& studyFolder, const StudySpec& spec, const StudyPlan& plan,
                const std::shared_ptr<const StudyProgress>& previous);

} // namespace grainlab::ui
