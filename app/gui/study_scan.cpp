// See study_scan.h.
#include "gui/study_scan.h"

#include <algorithm>
#include <filesystem>

#include "study/study_files.h"

namespace grainlab::ui {

int StudyProgress::finishedCount() const {
    return int(std::count(finished.begin(), finished.end(), true));
}

std::shared_ptr<const StudyProgress>
scanStudyFolder(const std::string& studyFolder, const StudySpec& spec, const StudyPlan& plan,
                const std::shared_ptr<const StudyProgress>& previous) {
    const bool samePlan = previous && previous->finished.size() == plan.runs.size();
    auto next = std::make_shared<StudyProgress>();
    next->finished.assign(plan.runs.size(), false);
    bool changed = !samePlan;
    std::vector<RunResult> fresh;
    for (std::size_t i = 0; i < plan.runs.size(); ++i) {
        if (samePlan && previous->finished[i]) {
            next->finished[i] = true;
            continue;
        }
        const std::string folder =
            (std::filesystem::path(studyFolder) / "runs" / plan.runs[i].id).string();
        try {
            if (auto r = readRunResult(folder, int(i))) {
                fresh.push_back(std::move(*r));
                next->finished[i] = true;
                changed = true;
            }
        } catch (const std::exception& e) {
            next->errors.emplace_back(e.what());
        }
    }
    if (!changed && next->errors == previous->errors) {
        return previous;
    }
    if (!changed) {
        // Nothing new: the same results and summary (errors as found now).
        auto same = std::make_shared<StudyProgress>(*previous);
        same->errors = std::move(next->errors);
        return same;
    }
    if (samePlan) {
        next->results = previous->results;
    }
    for (RunResult& r : fresh) {
        next->results.push_back(std::move(r));
    }
    std::sort(next->results.begin(), next->results.end(),
              [](const RunResult& a, const RunResult& b) { return a.run < b.run; });
    next->summary = summariseStudy(spec, plan, next->results, spec.costMeasure);
    return next;
}

} // namespace grainlab::ui
