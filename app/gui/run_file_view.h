#pragma once
// A finished (or interrupted) HDF5 run file opened in the window: its checkpoints, to scrub
// through with a slider, and every test's series, to overlay with the live run's in the charts.
// Reading happens on the GUI thread when the user opens a file (its series, and the orientations
// at the first checkpoint of each test, which rotation counts from) or moves the slider (one
// checkpoint at a time; a few milliseconds for the quick experiment).

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "grainlab/series.h"
#include "grainlab/snapshot.h"

namespace grainlab::ui {

struct RunFileView {
    std::string path;
    std::vector<std::string> checkpoints; ///< in write order
    /// Per checkpoint: its step and stage (from its name), and the test and eps1 of the series
    /// row recorded at that step ("" and NaN when no row matches).
    std::vector<std::int64_t> checkpointStep;
    std::vector<std::string> checkpointStage;
    std::vector<std::string> checkpointTest;
    std::vector<double> checkpointStrain;
    /// Where each checkpoint's rotation counts from: an index into thetaAtTestStart, the grain
    /// orientations [rad] at the first checkpoint of each test (its equilibration start, where
    /// the live run's rotation counts from too; for compaction, the run's first checkpoint).
    std::vector<int> checkpointTestStart;
    std::vector<std::vector<double>> thetaAtTestStart;
    /// Every test's series; the test names carry the file name, e.g. "run.h5: p015kPa", so that
    /// they never merge with a live test of the same name.
    std::vector<SeriesTable> series;
};

/// Lists a run file's checkpoints, reads its series and the orientations at the first checkpoint
/// of each test. Throws std::runtime_error.
RunFileView openRunFile(const std::string& path);

/// The scene stored at checkpoint `index`: grains, contacts and forces (from the stored state),
/// load-bearing grains and void cells, the stage (from the checkpoint's name), eps1 (from the
/// series row of that step) and each grain's rotation since the first checkpoint of its test.
/// Throws std::runtime_error.
SnapshotPtr runFileSnapshot(const RunFileView& file, std::size_t index);

/// The checkpoint of test `test` (any test when empty) whose eps1 is nearest to `eps1`, or -1.
int nearestCheckpoint(const RunFileView& file, const std::string& test, double eps1);

} // namespace grainlab::ui
