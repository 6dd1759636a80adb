#pragma once
// The study's figures for the headless `grainlab study` (GUI builds only): paints them with the
// window's figure code into the study folder's figures/, under Qt's offscreen platform when no
// Qt application runs yet. Main thread.

#include <string>
#include <vector>

#include "grainlab/study_plan.h"
#include "grainlab/study_summary.h"

namespace grainlab {

/// Writes figures/ into `studyFolder`; returns "" or what went wrong.
std::string writeStudyFiguresHeadless(const std::string& studyFolder, const StudySpec& spec,
                                      const StudyPlan& plan, const std::vector<RunResult>& results,
                                      const StudySummary& summary);

} // namespace grainlab
