#pragma once
// The HDF5 run file (SPEC §5; layout in docs/formats.md): the experiment text, the software
// version, every test's time series, the compacted samples and complete checkpoints
// (SimulationState + runner state) from which a run continues bit for bit.
//
// RunFile is the writer: it implements RunOutput and is driven by the experiment runner on the
// engine thread (the GUI's worker thread, or the main thread headless). One RunFile per file,
// one thread at a time. The file stays valid if the process is killed between writes: every
// checkpoint and sample ends with a flush, records are flushed at least every couple of seconds,
// and a checkpoint replaces an older one of the same name only once it is complete.
//
// The free functions read a closed (or flushed) run file; they open it read-only per call and
// may run on any thread that is not writing the same file. Non-finite numbers are never
// written: they are refused with an error naming the dataset.

#include <memory>
#include <string>
#include <vector>

#include "grainlab/run_output.h"
#include "grainlab/series.h"
#include "grainlab/simulation_state.h"

namespace grainlab {

/// Format of the layout written by this version (root attribute `format_version`). Version 2:
/// checksummed (Fletcher32) chunked datasets, fixed-length text, stage identity attributes.
/// Files of another version are refused by every reader, naming the version.
inline constexpr int kRunFileFormatVersion = 2;

class RunFile : public RunOutput {
public:
    enum class Mode {
        Create, ///< a new file, replacing any file at `path`
        Resume, ///< an existing run file of the same experiment, to continue writing
    };

    /// Create writes the root attributes (software, software_version, created, format_version)
    /// and /experiment. Resume opens an existing file read-write and refuses one whose
    /// /experiment differs from `experimentText`. Throws std::runtime_error.
    RunFile(const std::string& path, const std::string& experimentText, Mode mode = Mode::Create);
    ~RunFile() override;
    RunFile(const RunFile&) = delete;
    RunFile& operator=(const RunFile&) = delete;

    /// Appends the rows of `series` not yet in /tests/<test>/series. If the table has no more
    /// rows than the file (the runner resumed from an earlier checkpoint) the file's series is
    /// cut back and its tail rewritten; if the columns changed it is rewritten whole. The file
    /// mirrors the table after each call.
    void record(const SeriesTable& series) override;
    /// Writes /checkpoints/<name> (replacing an older one of that name) and flushes.
    void checkpoint(const std::string& name, const SimulationState& state,
                    const std::string& runnerState) override;
    /// ... with the identity of its stage as attributes (stage_kind, test, pressure,
    /// axial_strain) and the dataset theta_at_test_start.
    void checkpoint(const std::string& name, const SimulationState& state,
                    const std::string& runnerState, const StageIdentity& identity) override;
    /// Writes /samples/<pressure>Pa (e.g. /samples/15000Pa) and flushes.
    void sample(double pressure, const SimulationState& state) override;
    /// Writes /checkpoints/<name>/void_cells: one row per void cell (valence, area, elongation,
    /// direction, centroid, its grains as CSR) and the valence histogram.
    void voidCells(const std::string& name, const VoidCellSet& cells) override;
    /// Flushes everything written so far to disk.
    void flush();

    const std::string& path() const;

private:
    void recordNow(const SeriesTable& series);
    void checkpointNow(const std::string& name, const SimulationState& state,
                       const std::string& runnerState, const StageIdentity* identity);
    void sampleNow(double pressure, const SimulationState& state);
    void voidCellsNow(const std::string& name, const VoidCellSet& cells);

    struct Impl;
    std::unique_ptr<Impl> impl_;
};

/// Group of the checkpoint `name`: "/checkpoints/<name>" with '/' replaced by '_'.
std::string checkpointGroup(const std::string& name);
/// Group of the sample at `pressure` [Pa]: "/samples/<pressure>Pa", e.g. "/samples/15000Pa".
std::string sampleGroup(double pressure);

/// The state stored in `groupPath` (a checkpoint or a sample), bit for bit as written.
SimulationState readState(const std::string& path, const std::string& groupPath);
/// The runner state stored with a checkpoint ("" for a sample).
std::string readRunnerState(const std::string& path, const std::string& groupPath);
/// Checkpoint names in write order (complete checkpoints only).
std::vector<std::string> listCheckpoints(const std::string& path);
/// A checkpoint's name and the identity of its stage (StageIdentity without the orientations).
struct CheckpointInfo {
    std::string name;
    std::string stageKind; ///< "compaction", "equilibration", "shear" ("" if not recorded)
    std::string test;      ///< "compaction", "p100kPa" ("" if not recorded)
    double pressure = 0;   ///< [Pa]
    std::int64_t step = 0;
    double axialStrain = 0; ///< eps1 of its test [-]
};
/// Every complete checkpoint with its identity, in write order.
std::vector<CheckpointInfo> listCheckpointInfo(const std::string& path);
/// The orientations at the start of the checkpoint's test [rad] (empty if not recorded).
std::vector<double> readThetaAtTestStart(const std::string& path, const std::string& name);
/// Sample pressures [Pa] in write order.
std::vector<double> listSamples(const std::string& path);
/// Test names in the order their first record was written.
std::vector<std::string> listTests(const std::string& path);
/// The series of test `test` as written.
SeriesTable readSeries(const std::string& path, const std::string& test);
/// The experiment file text stored in /experiment.
std::string readExperimentText(const std::string& path);
/// The root attribute software_version of the program that created the file.
std::string readSoftwareVersion(const std::string& path);

} // namespace grainlab
