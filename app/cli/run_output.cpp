#include "cli/run_output.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include <fmt/format.h>

namespace grainlab {

namespace fs = std::filesystem;

namespace {

/// The pid the owner of run.lock wrote into it, or 0 when it holds none (an empty file: the run
/// that held it ended and emptied it).
long lockOwner(int fd) {
    char text[32] = {};
    const ssize_t n = ::pread(fd, text, sizeof text - 1, 0);
    if (n <= 0) {
        return 0;
    }
    char* end = nullptr;
    const long pid = std::strtol(text, &end, 10);
    return pid > 0 ? pid : 0;
}

bool processExists(long pid) {
    return ::kill(pid_t(pid), 0) == 0 || errno == EPERM;
}

} // namespace

RunFolderLock::RunFolderLock(const std::string& folder, bool create) {
    const std::string file = path(folder);
    if (create) {
        std::error_code error;
        fs::create_directories(folder, error);
        if (error) {
            throw std::runtime_error(
                fmt::format("cannot create the run folder {}: {}", folder, error.message()));
        }
    }
    fd_ = ::open(file.c_str(), O_RDWR | O_CLOEXEC | (create ? O_CREAT : 0), 0644);
    if (fd_ < 0) {
        throw std::runtime_error(
            fmt::format("cannot open the lock file {}: {}", file, std::strerror(errno)));
    }
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
        const int cause = errno;
        const long owner = lockOwner(fd_);
        ::close(fd_);
        fd_ = -1;
        if (cause == EWOULDBLOCK) {
            if (owner > 0 && !processExists(owner)) {
                // The flock outlives its owner only in a process that inherited the open file.
                throw std::runtime_error(fmt::format(
                    "the run folder {} is in use: its owner, process {}, has ended, but a "
                    "process it started still holds {}; end that process",
                    folder, owner, file));
            }
            throw std::runtime_error(fmt::format(
                "the run folder {} is in use: another run owns it ({}it holds {}); wait for "
                "that run to end or stop it",
                folder, owner > 0 ? fmt::format("process {}, ", owner) : std::string(), file));
        }
        throw std::runtime_error(fmt::format("cannot lock {}: {}", file, std::strerror(cause)));
    }
    // The flock is the lock (the kernel drops it when its holder dies); the pid written into the
    // file names the holder for the refusal above, and a pid still there when the flock is free
    // is that of a run that was killed before it could empty the file.
    const long stale = lockOwner(fd_);
    if (stale > 0 && stale != long(::getpid())) {
        fmt::print(stderr,
                   "grainlab: {}: taking over the stale lock of process {}, which {} (a run "
                   "that was killed leaves its pid there)\n",
                   file, stale, processExists(stale) ? "no longer holds it" : "no longer exists");
    }
    const std::string pid = fmt::format("{}\n", long(::getpid()));
    if (::ftruncate(fd_, 0) != 0 ||
        ::pwrite(fd_, pid.data(), pid.size(), 0) != ssize_t(pid.size())) {
        const int cause = errno;
        ::close(fd_);
        fd_ = -1;
        throw std::runtime_error(
            fmt::format("cannot write the owner into {}: {}", file, std::strerror(cause)));
    }
}

RunFolderLock::~RunFolderLock() {
    if (fd_ >= 0) {
        // An empty file: the run ended, nobody to take over from.
        [[maybe_unused]] const int emptied = ::ftruncate(fd_, 0);
        ::close(fd_); // releases the flock
    }
}

std::string RunFolderLock::path(const std::string& folder) {
    return (fs::path(folder) / "run.lock").string();
}

void removeRunFiles(const std::string& folder) {
    fs::remove(fs::path(folder) / "run.h5");
    fs::remove(fs::path(folder) / "cost.json"); // the old run's cost is not the new one's
    for (const auto& entry : fs::directory_iterator(folder)) {
        if (!entry.is_directory()) {
            continue;
        }
        const fs::path csv = entry.path() / "series.csv";
        if (fs::exists(csv)) {
            fs::remove(csv);
            if (fs::is_empty(entry.path())) {
                fs::remove(entry.path());
            }
        }
    }
}

RunOutputFolder::RunOutputFolder(const std::string& folder, const std::string& experimentText,
                                 bool resume)
    : folder_(folder) {
    fs::create_directories(folder_);
    runFile_ = std::make_unique<RunFile>(runFilePath(), experimentText,
                                         resume ? RunFile::Mode::Resume : RunFile::Mode::Create);
}

void RunOutputFolder::warnings(const std::vector<RunWarning>& all) {
    runFile_->warnings(all);
}

void RunOutputFolder::close() {
    csv_.clear();
    if (runFile_) {
        lastCheckpoint_ = runFile_->lastCheckpoint();
        runFile_->close(); // throws if the last flush fails (the file keeps its last checkpoint)
        runFile_.reset();
    }
}

std::string RunOutputFolder::runFilePath() const {
    return (fs::path(folder_) / "run.h5").string();
}

std::string RunOutputFolder::lastCheckpoint() const {
    return runFile_ ? runFile_->lastCheckpoint() : lastCheckpoint_;
}

std::string RunOutputFolder::seriesPath(const std::string& test) const {
    return (fs::path(folder_) / test / "series.csv").string();
}

void RunOutputFolder::record(const SeriesTable& series) {
    runFile_->record(series);
    auto& appender = csv_[series.test];
    if (!appender) {
        fs::create_directories(fs::path(folder_) / series.test);
        appender = std::make_unique<CsvSeriesAppender>(seriesPath(series.test));
    }
    appender->append(series);
}

void RunOutputFolder::sample(double pressure, const SimulationState& state) {
    runFile_->sample(pressure, state);
}

void RunOutputFolder::checkpoint(const CheckpointData& data) {
    runFile_->checkpoint(data);
}

ResumePoint RunOutputFolder::readResumePoint(const std::string& folder) {
    const std::string path = (fs::path(folder) / "run.h5").string();
    if (!fs::exists(path)) {
        throw std::runtime_error(fmt::format("--resume {}: no run file {} there", folder, path));
    }
    std::string last;
    for (const CheckpointInfo& info : listCheckpointInfo(path)) {
        if (!info.peak) {
            last = info.name;
        }
    }
    if (last.empty()) {
        throw std::runtime_error(
            fmt::format("--resume {}: {} holds no checkpoint yet", folder, path));
    }
    ResumePoint r;
    const std::string group = checkpointGroup(last);
    r.state = readState(path, group);
    r.runnerState = readRunnerState(path, group);
    const std::string peak = ExperimentRunner::runningPeakCheckpoint(r.runnerState);
    if (!peak.empty()) {
        r.runningPeak = readState(path, runningPeakGroup(peak));
    }
    const std::string probeStart = ExperimentRunner::probeStartCheckpoint(r.runnerState);
    if (!probeStart.empty()) {
        r.probeStart = readState(path, probeStartGroup(probeStart));
    }
    for (double pressure : listSamples(path)) {
        r.samples[pressure] = readState(path, sampleGroup(pressure));
    }
    for (const std::string& test : listTests(path)) {
        r.series.push_back(readSeries(path, test));
    }
    return r;
}

} // namespace grainlab
