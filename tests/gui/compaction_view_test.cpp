// While a compaction stage runs, the window charts it (p, e, Z and I_uf against step, on the
// charts' Compaction page, shown by itself) and shows progress above 0 % with an ETA; once the
// shear starts, the charts return to the shear tests.
#include <atomic>
#include <thread>

#include <QLabel>
#include <QProgressBar>

#include <gtest/gtest.h>

#include "chart_index.h"
#include "grainlab/ui/charts_panel.h"
#include "gui/experiment_run.h"
#include "gui/main_window.h"
#include "window_test_support.h"

namespace grainlab::ui {
namespace {

using namespace window_tests;

/// The experiment run, slowed down while `slow` (a pause before each short advance) so that its
/// compaction lasts long enough to be looked at.
class SlowRun final : public SteppedRun {
public:
    SlowRun(std::unique_ptr<SteppedRun> run, std::shared_ptr<std::atomic<bool>> slow)
        : run_(std::move(run)), slow_(std::move(slow)) {}
    bool advance(std::int64_t maxSteps) override {
        if (!slow_->load()) {
            return run_->advance(maxSteps);
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(4));
        return run_->advance(std::min<std::int64_t>(maxSteps, 50));
    }
    std::shared_ptr<Snapshot> snapshot() const override { return run_->snapshot(); }
    RunProgress progress() const override { return run_->progress(); }
    void keepRecordSnapshots(SnapshotHistory* history) override {
        run_->keepRecordSnapshots(history);
    }

private:
    std::unique_ptr<SteppedRun> run_;
    std::shared_ptr<std::atomic<bool>> slow_;
};

using testing::chartIndex;

TEST(CompactionView, ChartsTheCompactionWithProgressAndAnEta) {
    ExperimentConfig config = smallExperiment();
    config.compaction.pressures = {15e3, 25e3};
    config.record.stepInterval = 200;
    auto slow = std::make_shared<std::atomic<bool>>(true);
    MainWindow w([slow](const ExperimentConfig& c) {
        return std::make_unique<SlowRun>(makeExperimentRun(c), slow);
    });
    showWith(w, config);
    ChartsPanel* charts = w.chartsPanel();
    const int p = chartIndex(*charts, QStringLiteral("compaction_p"));
    const int e = chartIndex(*charts, QStringLiteral("compaction_e"));
    const int z = chartIndex(*charts, QStringLiteral("compaction_Z"));
    const int iuf = chartIndex(*charts, QStringLiteral("compaction_I_uf"));
    ASSERT_GE(p, 0) << "no compaction chart";
    ASSERT_GE(e, 0);
    ASSERT_GE(z, 0);
    ASSERT_GE(iuf, 0);

    click(w, w.startAction());
    // During the first compaction stage: its curves, progress above 0 and an ETA.
    bool seen = false;
    ASSERT_TRUE(waitFor([&] {
        w.refresh();
        const RunStatus status = w.controller().status();
        if (status.state != RunState::Running ||
            status.progress.stage.rfind("compaction", 0) != 0) {
            return status.state == RunState::Finished || status.state == RunState::Failed;
        }
        seen = charts->curvePoints(p, "compaction", "p").size() >= 5 &&
               w.progressBar()->value() > 0 && w.controller().status().etaSeconds > 0;
        return seen;
    })) << w.controller().status().error;
    ASSERT_TRUE(seen) << "the compaction ended before it was charted with progress and an ETA";
    EXPECT_EQ(charts->currentPage(), QStringLiteral("Compaction"));
    EXPECT_TRUE(charts->chartView(p)->isVisible());
    EXPECT_FALSE(charts->chartView(0)->isVisible()); // q/p of the shear tests
    const auto points = charts->curvePoints(p, "compaction", "p");
    EXPECT_GT(points.back().x(), points.front().x()); // against step
    EXPECT_GE(points.back().y(), 0.0);                // kPa
    EXPECT_EQ(charts->curvePoints(e, "compaction", "e").size(), points.size());
    EXPECT_EQ(charts->curvePoints(z, "compaction", "Z").size(), points.size());
    EXPECT_EQ(charts->curvePoints(iuf, "compaction", "I_uf").size(), points.size());

    // The progress bar never goes back, and the shear brings the shear charts back.
    slow->store(false);
    int previous = w.progressBar()->value();
    ASSERT_TRUE(waitFor(
        [&] {
            w.refresh();
            EXPECT_GE(w.progressBar()->value(), previous);
            previous = w.progressBar()->value();
            // What the window showed at this refresh, not a newer status read after it.
            return charts->currentPage() == QStringLiteral("Shear tests") ||
                   w.controller().status().state == RunState::Failed;
        },
        120000));
    EXPECT_EQ(charts->currentPage(), QStringLiteral("Shear tests"));
    click(w, w.stopAction());
}

} // namespace
} // namespace grainlab::ui
