#pragma once
// `grainlab run`: runs an experiment headless with a progress bar, writing the run file and the
// CSV series into an output folder; Ctrl-C writes a checkpoint and leaves valid files;
// `--resume DIR` continues from the last checkpoint. Main thread.
//
// For the crash tests only: with the environment variable GRAINLAB_TEST_STOP_AFTER_STEPS=N the
// run raises a signal on itself once this process has advanced N steps (GRAINLAB_TEST_STOP_SIGNAL
// = KILL, the default, INT or TERM), so that a test can interrupt it at an exact step.

#include <string>

namespace grainlab {

struct RunOptions {
    std::string experiment; ///< experiment file (new run)
    std::string out;        ///< output folder
    std::string resume;     ///< output folder of a run to continue
    int threads = 0;        ///< 0: as the experiment file says
    bool force = false;     ///< replace an existing run in `out`
    bool quiet = false;     ///< no progress bar
};

int runExperimentCommand(const RunOptions& options);

} // namespace grainlab
