#pragma once
// What a run warns about while it goes on: a time step close to the stable limit (time_step.h),
// a shear test loaded faster than the measured quasi-static limit (loading_rate.h), and a test
// ended early by one of its stop criteria (a cyclic test whose p' fell below its fraction of p0,
// stage_cyclic.h). The
// experiment runner issues them, keeps them in its checkpoints' runner state (a resumed run keeps
// them and does not issue them twice) and hands the whole list to its RunOutput (the run file's
// /warnings) and to its snapshots (the window's status bar); `grainlab run` prints each once.
// Plain data, any thread.

#include <cstdint>
#include <string>

namespace grainlab {

struct RunWarning {
    std::string kind;       ///< "time_step", "inertial_number" or "test_end"
    std::string test;       ///< the test it concerns ("compaction", "p015kPa")
    std::int64_t step = 0;  ///< simulation step at which it was issued [-]
    double axialStrain = 0; ///< eps1 of that test then [-]
    std::string text;       ///< what it says, in words

    bool operator==(const RunWarning&) const = default;
};

} // namespace grainlab
