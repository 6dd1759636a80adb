#pragma once
// A finished (or interrupted) HDF5 run file opened in the window: its checkpoints, to scrub
// through with a slider, and every test's series, to overlay with the live run's in the charts.
// Reading happens on the GUI thread when the user opens a file (its series, and the orientations
// at the first checkpoint of each test, which rotation counts from) or moves the slider (one
// checkpoint at a time; a few milliseconds for the quick experiment).

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "grainlab/series.h"
#include "grainlab/snapshot.h"
#include "grainlab/stage_kind.h"

namespace grainlab::ui {

struct RunFileView {
    std::string path;
    /// In write order, but each test's peak checkpoint (of q/p) among its test's by step.
    std::vector<std::string> checkpoints;
    /// Per checkpoint, from its identity attributes in the file: its step, stage ("shear 15
    /// kPa"), test (with the file name, as the series) and eps1 of its test.
    std::vector<std::int64_t> checkpointStep;
    std::vector<std::string> checkpointStage;
    /// Its stage's kind and pressure [Pa], as data (Done for a checkpoint without identity).
    std::vector<StageKind> checkpointKind;
    std::vector<double> checkpointPressure;
    std::vector<std::string> checkpointTest;
    std::vector<double> checkpointStrain;
    /// Where each checkpoint's rotation counts from: an index into thetaAtTestStart, the grain
    /// orientations [rad] at the start of each test as the file records them (the sample's as
    /// its equilibration starts, where the live run's rotation counts from too; for the
    /// compaction, the generated assembly's).
    std::vector<int> checkpointTestStart;
    /// Shared with the snapshots of the file (never modified).
    std::vector<std::shared_ptr<const std::vector<double>>> thetaAtTestStart;
    /// Every test's series; the test names carry the file name, e.g. "run.h5: p015kPa", so that
    /// they never merge with a live test of the same name.
    std::vector<SeriesTable> series;
    /// The warnings the run gave (the run file's /warnings).
    std::vector<RunWarning> warnings;
};

/// Lists a run file's checkpoints with their identities, reads its series and the orientations
/// at the start of each test. Throws std::runtime_error.
RunFileView openRunFile(const std::string& path);

/// The scene stored at checkpoint `index`: grains, contacts and forces (from the stored state),
/// load-bearing grains and void cells, its stage and eps1 (from its identity) and each grain's
/// rotation since the start of its test.
/// Throws std::runtime_error.
SnapshotPtr runFileSnapshot(const RunFileView& file, std::size_t index);

/// The checkpoint of test `test` (any test when empty) whose eps1 is nearest to `eps1`, or -1.
int nearestCheckpoint(const RunFileView& file, const std::string& test, double eps1);

} // namespace grainlab::ui
