#include "cli/run_session.h"

#include <filesystem>

#include <fmt/format.h>

#include "grainlab/experiment_file.h"
#include "grainlab/run_file.h"

namespace grainlab {

namespace fs = std::filesystem;

std::unique_ptr<RunSession> RunSession::create(ExperimentConfig config, const std::string& folder,
                                               bool force, int threads) {
    std::unique_ptr<RunSession> s(new RunSession);
    s->config_ = std::move(config);
    s->folder_ = folder;
    // The folder is locked before anything in it is read or written; a refusal touches nothing.
    const fs::path runFile = fs::path(folder) / "run.h5";
    try {
        if (fs::exists(RunFolderLock::path(folder))) {
            s->lock_ = std::make_unique<RunFolderLock>(folder, false);
        }
        if (fs::exists(runFile) && !force) {
            throw RunFolderRefused(fmt::format(
                "--out {}: that folder already holds a run ({}); continue it with `grainlab run "
                "--resume {}`, or give --force to replace it",
                folder, runFile.string(), folder));
        }
        if (!s->lock_) {
            s->lock_ = std::make_unique<RunFolderLock>(folder, true);
        }
    } catch (const RunFolderRefused&) {
        throw;
    } catch (const std::runtime_error& e) {
        throw RunFolderRefused(e.what());
    }
    if (force) {
        removeRunFiles(folder); // the old run's files, CSVs too, do not linger
    }
    if (threads > 0) {
        s->config_.parameters.threads = threads;
    }
    s->openOutput();
    return s;
}

std::unique_ptr<RunSession> RunSession::resume(const std::string& folder, int threads) {
    std::unique_ptr<RunSession> s(new RunSession);
    s->folder_ = folder;
    s->resumed_ = true;
    const fs::path runFile = fs::path(folder) / "run.h5";
    if (!fs::exists(runFile)) {
        throw RunFolderRefused(
            fmt::format("--resume {}: no run file {}", folder, runFile.string()));
    }
    try {
        s->lock_ = std::make_unique<RunFolderLock>(folder, true);
    } catch (const std::runtime_error& e) {
        throw RunFolderRefused(e.what());
    }
    const std::string path = runFile.string();
    s->config_ = parseExperimentText(readExperimentText(path), path + ":/experiment");
    s->point_ = RunOutputFolder::readResumePoint(folder);
    if (ExperimentRunner::finishedAt(s->point_.runnerState)) {
        s->finishedBefore_ = true;
        return s; // the files stay exactly as they are
    }
    if (threads > 0) {
        s->config_.parameters.threads = threads;
    }
    s->openOutput();
    return s;
}

RunSession::~RunSession() = default;

void RunSession::openOutput() {
    output_ = std::make_unique<RunOutputFolder>(folder_, config_.sourceText, resumed_);
    // What the run costs, beside its run file (cost.json), for the study commands.
    cost_ = std::make_unique<RunCostMeter>(folder_, resumed_);
}

void RunSession::completeCostRecord() {
    // The process was killed between the run's last checkpoint and its cost record's end.
    RunCostRecord cost = readRunCost(folder_);
    if (!cost.finished) {
        cost.finished = true;
        writeRunCost(folder_, cost);
    }
}

void RunSession::start() {
    runner_ = resumed_
                  ? std::make_unique<ExperimentRunner>(config_, std::move(point_), output_.get())
                  : std::make_unique<ExperimentRunner>(config_, output_.get());
}

bool RunSession::advance(std::int64_t steps) {
    const bool more = runner_->advance(steps);
    if (more) {
        cost_->saveEvery(5.0, work());
    }
    return more;
}

RunCostMeter::Work RunSession::work() const {
    return {runner_->stepsTaken(), config_.assembly.grainCount,
            runner_->simulation().stateRef().parameters.threads, runner_->times()};
}

void RunSession::saveCost(bool finished) {
    if (runner_) {
        cost_->save(work(), finished);
    }
}

void RunSession::interrupt() {
    runner_->checkpointNow("interrupted");
    saveCost(false);
}

void RunSession::finish() {
    // The run file is complete on disk before the cost record says the run is finished (a
    // study takes a finished record as a finished, readable run).
    output_->close();
    saveCost(true);
}

void RunSession::saveCostAfterFailure() noexcept {
    try {
        saveCost(false);
    } catch (const std::exception&) {
        // The failure being reported matters; a cost record that cannot be written does not.
    }
}

} // namespace grainlab
