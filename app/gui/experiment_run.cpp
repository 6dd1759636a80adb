// See experiment_run.h: the ExperimentRunner adapter. It is also the runner's RunOutput: it hands
// everything on to the run folder's writer when the run is recorded (RunOutputFolder, the one
// `grainlab run` uses), and at the shear records the history wants, it builds a snapshot of the
// scene and keeps it there.
#include "gui/experiment_run.h"

#include <chrono>
#include <string>
#include <vector>

#include "cli/run_output.h"
#include "gui/snapshot_history.h"

namespace grainlab::ui {
namespace {

/// Copying and measuring the kept snapshots may cost the engine at most about this share of its
/// time: measured over at least kCostSamples kept snapshots, a larger share thins the history
/// (every other record from then on) and the count starts again. The measures are computed on
/// the controller's snapshot thread, but where the engine's threads fill every processor that
/// time is taken from them as much as the copies' (the window's pictures keep to 3 % more:
/// picture_budget.h).
constexpr double kHistoryShare = 0.02;
constexpr int kCostSamples = 8;

double wallSeconds() {
    using namespace std::chrono;
    return duration<double>(steady_clock::now().time_since_epoch()).count();
}

class ExperimentRun final : public SteppedRun, private RunOutput {
public:
    explicit ExperimentRun(const ExperimentConfig& config,
                           std::unique_ptr<RunOutputFolder> folder = nullptr,
                           std::string folderPath = {})
        : folder_(std::move(folder)), folderPath_(std::move(folderPath)), runner_(config, this) {}
    ExperimentRun(const ExperimentConfig& config, ResumePoint resume)
        : runner_(config, std::move(resume), this) {}
    bool advance(std::int64_t maxSteps) override {
        const bool more = runner_.advance(maxSteps);
        if (!more) {
            folder_.reset(); // the run is complete: its files are closed now, as headless
        }
        return more;
    }
    std::shared_ptr<Snapshot> snapshot() const override {
        return runner_.snapshot(SnapshotMeasures::Later);
    }
    RunProgress progress() const override { return runner_.progress(); }
    void keepRecordSnapshots(SnapshotHistory* history) override { history_ = history; }
    std::string runFolder() const override { return folderPath_; }
    std::string lastGoodCheckpoint() const override {
        return folder_ ? folder_->lastCheckpoint() : std::string();
    }
    void interrupt() override {
        if (folder_ && !runner_.finished()) {
            runner_.checkpointNow("interrupted");
        }
    }

private:
    void record(const SeriesTable& series) override {
        if (folder_) {
            folder_->record(series);
        }
        // The record just made is of the stage under way: the history keeps the test's.
        if (!history_ || series.rows.empty() || !isTestStage(runner_.progress().kind)) {
            return;
        }
        const std::int64_t record = shearRecords_++;
        if (!history_->wants(record)) {
            return;
        }
        const double start = wallSeconds();
        history_->add(record, recordSnapshot());
        const double end = wallSeconds();
        // The measures finished since the last record (those of this one come later).
        const double measured = history_->measureSeconds();
        if (costSamples_ == 0) {
            costSince_ = start;
            costSeconds_ = 0.0;
        }
        costSeconds_ += (end - start) + (measured - measuredBefore_);
        measuredBefore_ = measured;
        if (++costSamples_ > kCostSamples && costSeconds_ > kHistoryShare * (end - costSince_)) {
            history_->thin();
            costSamples_ = 0;
        }
    }
    void checkpoint(const CheckpointData& data) override {
        if (folder_) {
            folder_->checkpoint(data); // with its identity, contacts and the running peak
        }
    }
    void sample(double pressure, const SimulationState& state) override {
        if (folder_) {
            folder_->sample(pressure, state);
        }
    }
    void warnings(const std::vector<RunWarning>& all) override {
        if (folder_) {
            folder_->warnings(all);
        }
    }

    /// The scene now (grains, contacts; the history has the measures computed off this thread),
    /// without the series: the charts draw those from the live snapshot, and a copy in every
    /// kept snapshot would dominate the memory.
    std::shared_ptr<Snapshot> recordSnapshot() {
        const RunProgress p = runner_.progress();
        auto s = std::make_shared<Snapshot>();
        s->stage = p.stage;
        s->stageKind = p.kind;
        s->stagePressure = p.pressure;
        s->test = p.test;
        s->axialStrain = p.axialStrain;
        s->progress = p.fraction;
        s->thetaAtTestStart = p.thetaAtTestStart; // shared by every snapshot of the test
        fillSnapshotScene(*s, runner_.simulation(), *p.thetaAtTestStart, SnapshotMeasures::Later);
        return s;
    }

    // Declared before the runner, which writes to it from its constructor on.
    std::unique_ptr<RunOutputFolder> folder_; ///< null when the run is not recorded
    std::string folderPath_;
    ExperimentRunner runner_;
    SnapshotHistory* history_ = nullptr;
    std::int64_t shearRecords_ = 0; ///< shear records seen, the history's record numbers
    // What the kept snapshots cost since costSince_ (wall clock) [s].
    int costSamples_ = 0;
    double costSince_ = 0;
    double costSeconds_ = 0;
    double measuredBefore_ = 0; ///< the history's measureSeconds() at the last record
};

} // namespace

std::unique_ptr<SteppedRun> makeExperimentRun(const ExperimentConfig& config) {
    return std::make_unique<ExperimentRun>(config);
}

std::unique_ptr<SteppedRun> makeRecordedExperimentRun(const ExperimentConfig& config,
                                                      const std::string& folder) {
    auto output = std::make_unique<RunOutputFolder>(folder, config.sourceText, false);
    return std::make_unique<ExperimentRun>(config, std::move(output), folder);
}

std::unique_ptr<SteppedRun> makeResumedExperimentRun(const ExperimentConfig& config,
                                                     ResumePoint resume) {
    return std::make_unique<ExperimentRun>(config, std::move(resume));
}

} // namespace grainlab::ui
