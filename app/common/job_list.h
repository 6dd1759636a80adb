#pragma once
// The runs of a study as plain `grainlab run` commands, for the local pool and for real
// schedulers: a Slurm job-array script (one array task per run) and a GNU parallel job list
// (one line per run). Every command works for a run not yet started and for one to continue:
// it resumes the run folder when it holds a run file, and starts the run otherwise. Pure text,
// no I/O; main thread.

#include <string>
#include <vector>

namespace grainlab {

/// Where a study keeps its runs, relative to its folder.
struct StudyLayout {
    std::string folder;   ///< the study folder (absolute in emitted scripts)
    std::string grainlab; ///< the grainlab executable (absolute)

    std::string experimentFile(const std::string& run) const; ///< experiments/<run>.json
    std::string runFolder(const std::string& run) const;      ///< runs/<run>
    std::string logFile(const std::string& run) const;        ///< logs/<run>.log
};

/// argv of the command that starts run `run`, or continues it when `resume` is set.
std::vector<std::string> runArguments(const StudyLayout& layout, const std::string& run,
                                      bool resume);

/// One shell command line that starts or continues run `run` (a GNU parallel job).
std::string runShellLine(const StudyLayout& layout, const std::string& run);

/// A Slurm batch script with a job array of one task per run, `threads` processors each.
std::string slurmScript(const StudyLayout& layout, const std::string& studyName,
                        const std::vector<std::string>& runs, int threads);

/// A GNU parallel job list: one runShellLine per run.
std::string parallelJobList(const StudyLayout& layout, const std::vector<std::string>& runs);

/// `s` quoted for a POSIX shell.
std::string shellQuote(const std::string& s);

/// One shell command line running `argv` (every argument quoted).
std::string shellLine(const std::vector<std::string>& argv);

/// A Slurm batch script with a job array of one task per command (any argv, e.g. the cells of a
/// stability map), `threads` processors each; `comment` (lines without '#') heads the script
/// and each task's output goes to `logFolder`/slurm-<job>_<task>.log.
std::string slurmArrayScript(const std::string& jobName, const std::string& comment,
                             const std::string& logFolder,
                             const std::vector<std::vector<std::string>>& commands, int threads);

/// A GNU parallel job list: one shellLine per command.
std::string commandJobList(const std::vector<std::vector<std::string>>& commands);

} // namespace grainlab
