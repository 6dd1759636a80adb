#pragma once
// The HDF5 run file (layout in docs/formats.md): the experiment text, the software
// version, every test's time series, the compacted samples and complete checkpoints
// (SimulationState + runner state) from which a run continues bit for bit, each with its
// contacts (forces, normals, contact points) and void cells (polygons, second moments), and per
// shear test a checkpoint at the peak of q/p.
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
/// Version 3 adds to each checkpoint its contacts, the void cells' polygons and second moments,
/// the shapes' outlines, the attribute `peak`, and the peak checkpoint of each shear test (whose
/// running maximum a resumed run continues from the runner state). Readers read versions 2 and
/// 3 (what a version-2 file lacks is absent); only a version-3 file is continued (Mode::Resume).
inline constexpr int kRunFileFormatVersion = 3;
inline constexpr int kRunFileOldestReadableVersion = 2;
/// Points of each shape's outline in a checkpoint (shape_outline1/2) [-].
inline constexpr int kShapeOutlinePoints = 48;

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
    /// Writes /checkpoints/<name> (replacing an older one of that name), the state and the
    /// runner state only, and flushes.
    void checkpoint(const std::string& name, const SimulationState& state,
                    const std::string& runnerState);
    /// Writes /samples/<pressure>Pa (e.g. /samples/15000Pa) and flushes.
    void sample(double pressure, const SimulationState& state) override;
    /// Writes /checkpoints/<name> whole before it appears under its name: the state, the
    /// runner state (not for a peak checkpoint), the identity of its stage (attributes
    /// stage_kind, test, pressure, axial_strain; the dataset theta_at_test_start), the contacts
    /// with the shapes' outlines, the void cells and the running peak; for a peak checkpoint also
    /// the attribute peak_checkpoint of its test. Flushes.
    void checkpoint(const CheckpointData& data) override;
    /// Writes /warnings (replacing the older list whole, so that a resumed run's list is what
    /// its checkpoint held plus what it gave since): one entry per warning, datasets kind, test,
    /// step, axial_strain and text. Flushes.
    void warnings(const std::vector<RunWarning>& all) override;
    /// Flushes everything written so far to disk.
    void flush();
    /// Flushes and closes the file (the destructor does too, but cannot report a failure).
    /// Throws std::runtime_error if the last flush fails; the file then keeps its last
    /// complete checkpoint. Nothing may be written after it.
    void close();

    const std::string& path() const;
    /// The last complete checkpoint on disk that a resumed run continues from (not a peak
    /// checkpoint); "" before the first. After a failed write: the one the file keeps.
    const std::string& lastCheckpoint() const;

private:
    void open(const std::string& experimentText, Mode mode);
    void closeHandles();
    void recordNow(const SeriesTable& series);
    void checkpointNow(const std::string& name, const SimulationState& state,
                       const std::string& runnerState);
    void sampleNow(double pressure, const SimulationState& state);
    void checkpointNow(const CheckpointData& data);

    struct Impl;
    std::unique_ptr<Impl> impl_;
};

/// Group of the checkpoint `name`: "/checkpoints/<name>" with '/' replaced by '_'.
std::string checkpointGroup(const std::string& name);
/// Group of the sample at `pressure` [Pa]: "/samples/<pressure>Pa", e.g. "/samples/15000Pa".
std::string sampleGroup(double pressure);
/// Group of the running peak kept in checkpoint `name`: "<checkpointGroup(name)>/running_peak".
std::string runningPeakGroup(const std::string& name);
/// Group of the probes' start state kept in checkpoint `name`:
/// "<checkpointGroup(name)>/probe_start".
std::string probeStartGroup(const std::string& name);

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
    double axialStrain = 0;     ///< eps1 of its test [-]
    bool peak = false;          ///< the checkpoint at the peak of q/p of its test
    double peakStressRatio = 0; ///< q/p there [-] (peak checkpoints only)
};
/// Every complete checkpoint with its identity, in write order.
std::vector<CheckpointInfo> listCheckpointInfo(const std::string& path);
/// The orientations at the start of the checkpoint's test [rad] (empty if not recorded).
std::vector<double> readThetaAtTestStart(const std::string& path, const std::string& name);
/// The contacts stored with a checkpoint (dataset names in docs/formats.md), one entry per
/// touching contact in the engine's order. Empty vectors for a checkpoint without contacts (a
/// version-2 file).
struct StoredContacts {
    std::vector<std::int32_t> first, second, shift1, shift2;
    std::vector<double> normal1, normal2; ///< unit normal from first to second [-]
    std::vector<double> point1, point2;   ///< contact point, world coordinates [m]
    std::vector<double> branch1, branch2; ///< x_second + h k - x_first [m]
    std::vector<double> overlap;          ///< [m]
    std::vector<double> normalForce;      ///< [N]
    std::vector<double> tangentialForce;  ///< [N]
    std::vector<std::uint8_t> sliding, strong, loadBearing;
    std::vector<double> centre1, centre2; ///< grain centres wrapped into the cell [m]
    double strongThreshold = 0;           ///< [N]
};
StoredContacts readContacts(const std::string& path, const std::string& name);
/// The void cells stored with a checkpoint, one entry per cell (vertex lists as CSR).
struct StoredVoidCells {
    std::vector<std::int32_t> valence;
    std::vector<double> area, centroid1, centroid2;                     ///< [m^2], [m]
    std::vector<double> secondMoment11, secondMoment22, secondMoment12; ///< [m^4]
    std::vector<double> elongation, direction;                          ///< [-], [rad]
    std::vector<std::int32_t> grains;
    std::vector<std::int64_t> grainOffsets;
    std::vector<double> vertices1, vertices2; ///< world coordinates [m] (empty in version 2)
    std::vector<std::int64_t> vertexOffsets;
    std::vector<std::int32_t> valenceHistogram;
};
StoredVoidCells readVoidCells(const std::string& path, const std::string& name);
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
/// The warnings the run gave (/warnings), in order; none for a file without the group.
std::vector<RunWarning> readWarnings(const std::string& path);

} // namespace grainlab
