#pragma once
// `grainlab study FILE --out DIR`: runs a study's runs (every setting at every seed) as
// independent `grainlab run` processes through a local pool, with one progress bar and ETA for
// the whole study, then summarises them (study.csv, summary.csv, recommended.json; docs/study.md).
// A killed study resumes with the same command: finished runs are not redone, an interrupted one
// continues from its checkpoint. `--emit slurm|parallel` writes the runs as a Slurm job array or
// a GNU parallel job list instead; `grainlab study collect DIR` summarises once they are done.
// Main thread.

#include <functional>
#include <string>
#include <vector>

#include "grainlab/study_plan.h"
#include "grainlab/study_summary.h"

namespace grainlab {

/// Writes a study's figures into its folder; returns "" or what went wrong. The headless
/// command has one in GUI builds (the figures are painted by the window's code).
using StudyFigureWriter =
    std::function<std::string(const std::string& folder, const StudySpec&, const StudyPlan&,
                              const std::vector<RunResult>&, const StudySummary&)>;

struct StudyOptions {
    std::string studyFile;     ///< the study file (.json)
    std::string out;           ///< the study folder
    int jobs = 0;              ///< runs at once; 0: as many as the processors allow
    std::string emit;          ///< "", "slurm" or "parallel"
    bool quiet = false;        ///< no progress bar
    std::string grainlab;      ///< this executable (argv[0] resolved), for the runs' commands
    StudyFigureWriter figures; ///< writes figures/ when set
};

int runStudyCommand(const StudyOptions& options);

/// `grainlab study collect DIR`: summarises the finished runs of a study folder.
int collectStudyCommand(const std::string& folder, bool quiet = false,
                        const StudyFigureWriter& figures = {});

} // namespace grainlab
