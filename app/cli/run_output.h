#pragma once
// The output folder of a run: the HDF5 run file (run.h5) and one series.csv per test
// (<test>/series.csv), both kept up to date record by record. Implements RunOutput for the
// experiment runner, on the thread that drives the runner.

#include <map>
#include <memory>
#include <string>

#include "grainlab/csv_series.h"
#include "grainlab/experiment_runner.h"
#include "grainlab/run_file.h"

namespace grainlab {

/// The lock of a run folder: an exclusive flock() on its file run.lock, held while a run owns
/// the folder (released when the process ends, killed or not). The lock file stays.
class RunFolderLock {
public:
    /// Takes the lock, creating run.lock (and the folder) if `create`. Throws
    /// std::runtime_error naming the folder when another run holds it, or when run.lock
    /// cannot be opened (with the cause).
    RunFolderLock(const std::string& folder, bool create);
    ~RunFolderLock();
    RunFolderLock(const RunFolderLock&) = delete;
    RunFolderLock& operator=(const RunFolderLock&) = delete;

    /// The lock file of `folder`.
    static std::string path(const std::string& folder);

private:
    int fd_ = -1;
};

/// Removes what a run wrote into `folder` (run.h5, cost.json and every <test>/series.csv, with
/// the test folders left empty), for `grainlab run --force`. Other files stay.
void removeRunFiles(const std::string& folder);

class RunOutputFolder : public RunOutput {
public:
    /// Creates `folder` (a new run) or opens it to continue (`resume`).
    RunOutputFolder(const std::string& folder, const std::string& experimentText, bool resume);

    void record(const SeriesTable& series) override;
    void checkpoint(const CheckpointData& data) override;
    void sample(double pressure, const SimulationState& state) override;
    void warnings(const std::vector<RunWarning>& all) override;

    std::string runFilePath() const;
    /// The run file's last complete checkpoint ("" before the first: nothing to resume).
    std::string lastCheckpoint() const;
    std::string seriesPath(const std::string& test) const;
    /// Closes the run file and the CSV files (a closed run file is complete on disk). Nothing
    /// may be written after it.
    void close();

    /// Everything a resumed run needs, read from the run file of `folder`: its last checkpoint
    /// that is not a peak checkpoint (those are for reading), with the running peak it names.
    static ResumePoint readResumePoint(const std::string& folder);

private:
    std::string folder_;
    std::unique_ptr<RunFile> runFile_;
    std::string lastCheckpoint_; ///< of the run file once closed
    std::map<std::string, std::unique_ptr<CsvSeriesAppender>> csv_;
};

} // namespace grainlab
