#pragma once
// What the commands that run many processes from one folder share (`grainlab study`, `grainlab
// stability`): the folder made or checked against its preset file, the jobs written for Slurm or
// GNU parallel, and the local pool run with its progress bar, interruption and failed jobs.

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "common/process_pool.h"

namespace grainlab {

/// How a command names its folder's contents in messages and on disk.
struct PoolFolder {
    std::filesystem::path dir;
    std::string presetFile; ///< the preset kept in the folder ("study.json")
    std::string holdsNo;    ///< what a foreign folder holds none of ("study", "stability map")
    std::string different;  ///< what a folder of another preset holds ("study", "map")
    std::vector<std::string> subfolders; ///< made in the folder ("runs", "logs", ...)
};

/// Creates the folder with its subfolders and preset (`sourceText`, read from `sourcePath`), or
/// checks that an existing one is empty or holds this very preset; throws naming --out when not.
void preparePoolFolder(const PoolFolder& folder, const std::string& sourceText,
                       const std::string& sourcePath);

/// Prints where `--emit` wrote the `count` jobs (`file`, Slurm or GNU parallel) and how to
/// collect them: `command` is "grainlab study", `units` "runs", `then` "Then summarise with: ...".
void printEmittedJobs(const std::string& command, std::size_t count, const std::string& units,
                      const std::string& file, bool slurm, const std::string& then);

/// The processes a pool runs at once for `--jobs` `jobsOption` (0: one a processor).
int poolSlots(int jobsOption);

/// The outcome of a pool run: interrupted (SIGINT or SIGTERM), and the jobs that failed
/// otherwise ("<name> (exit N[, signal S]; log <file>)").
struct PoolOutcome {
    bool interrupted = false;
    std::vector<std::string> failed;
};

/// Runs `jobs` (named `names` in the failures) in a local pool of `--jobs` processes (0: one a
/// processor, threads counted), with a progress bar labelled `label` counting `doneBefore`
/// already done of `total` (not with `quiet`). SIGINT and SIGTERM stop it: the running jobs are
/// told to stop and the call returns once they have ended.
PoolOutcome runPoolJobs(const std::vector<PoolJob>& jobs, const std::vector<std::string>& names,
                        int jobsOption, std::size_t doneBefore, std::size_t total,
                        const std::string& label, bool quiet);

/// The command's exit status for `outcome`: 130 after printing `interrupted` when interrupted, 1
/// after listing the failed jobs ("<command>: N <units> failed:"), else 0.
int poolExitStatus(const PoolOutcome& outcome, const std::string& command,
                   const std::string& interrupted, const std::string& units);

} // namespace grainlab
