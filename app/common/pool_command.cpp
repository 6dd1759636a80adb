#include "common/pool_command.h"

#include <atomic>
#include <csignal>
#include <stdexcept>

#include <fmt/format.h>

#include "common/atomic_file.h"
#include "common/progress_bar.h"

namespace grainlab {

namespace fs = std::filesystem;

namespace {

std::atomic<bool> stopRequested{false};

extern "C" void onPoolInterrupt(int) {
    stopRequested.store(true);
}

} // namespace

void preparePoolFolder(const PoolFolder& folder, const std::string& sourceText,
                       const std::string& sourcePath) {
    const fs::path& dir = folder.dir;
    const fs::path preset = dir / folder.presetFile;
    if (fs::exists(dir)) {
        if (!fs::is_directory(dir)) {
            throw std::runtime_error(
                fmt::format("--out {}: exists and is not a folder", dir.string()));
        }
        if (!fs::exists(preset)) {
            if (!fs::is_empty(dir)) {
                throw std::runtime_error(
                    fmt::format("--out {}: the folder is not empty and holds no {} (no {}); give "
                                "a new or empty folder",
                                dir.string(), folder.holdsNo, folder.presetFile));
            }
        } else if (readWholeFile(preset.string()) != sourceText) {
            throw std::runtime_error(fmt::format(
                "--out {}: the folder holds a different {} (its {} differs from {}); give another "
                "folder, or continue that {} with its own {}",
                dir.string(), folder.different, folder.presetFile, sourcePath, folder.different,
                folder.presetFile));
        }
    }
    for (const std::string& sub : folder.subfolders) {
        fs::create_directories(dir / sub);
    }
    if (!fs::exists(preset)) {
        writeFileAtomically(preset.string(), sourceText);
    }
}

void printEmittedJobs(const std::string& command, std::size_t count, const std::string& units,
                      const std::string& file, bool slurm, const std::string& then) {
    fmt::print("{}: {} {} written as {}\n", command, count, units, file);
    if (slurm) {
        fmt::print("Submit with: sbatch {}\n", file);
    } else {
        fmt::print("Run with: parallel --jobs N < {}\n", file);
    }
    fmt::print("{}\n", then);
}

int poolSlots(int jobsOption) {
    return jobsOption > 0 ? jobsOption : processorCount();
}

PoolOutcome runPoolJobs(const std::vector<PoolJob>& jobs, const std::vector<std::string>& names,
                        int jobsOption, std::size_t doneBefore, std::size_t total,
                        const std::string& label, bool quiet) {
    stopRequested.store(false);
    auto previous = std::signal(SIGINT, onPoolInterrupt);
    auto previousTerm = std::signal(SIGTERM, onPoolInterrupt);
    ProgressBar bar(label);
    PoolOutcome outcome;
    ProcessPool pool(poolSlots(jobsOption), jobsOption > 0 ? 1 << 20 : processorCount());
    pool.run(
        jobs,
        [&](std::size_t job, const PoolResult& r) {
            if (!r.succeeded() && !stopRequested.load()) {
                outcome.failed.push_back(fmt::format(
                    "{} (exit {}{}; log {})", names[job], r.exitStatus,
                    r.signal ? fmt::format(", signal {}", r.signal) : "", jobs[job].logPath));
            }
        },
        [&](std::size_t ended, std::size_t running) {
            if (!quiet) {
                bar.update(double(doneBefore + ended) / double(total),
                           fmt::format("{} done, {} running", doneBefore + ended, running));
            }
        },
        &stopRequested);
    if (!quiet) {
        bar.finish();
    }
    std::signal(SIGINT, previous);
    std::signal(SIGTERM, previousTerm);
    outcome.interrupted = stopRequested.load();
    return outcome;
}

int poolExitStatus(const PoolOutcome& outcome, const std::string& command,
                   const std::string& interrupted, const std::string& units) {
    if (outcome.interrupted) {
        fmt::print(stderr, "{}\n", interrupted);
        return 130;
    }
    if (!outcome.failed.empty()) {
        fmt::print(stderr, "{}: {} {} failed:\n", command, outcome.failed.size(), units);
        for (const std::string& f : outcome.failed) {
            fmt::print(stderr, "  {}\n", f);
        }
        return 1;
    }
    return 0;
}

} // namespace grainlab
