// The simulation controller: commands are applied between advance() calls on the worker thread,
// a single step advances exactly the requested count, snapshots are published at most every
// ~16 ms while running, a failure is reported with its message, and the GUI never blocks.
#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>

#include <QTest>

#include <gtest/gtest.h>

#include "gui/simulation_controller.h"
#include "test_scenes.h"
#include "window_test_support.h"

namespace grainlab::ui {
namespace {

/// A run that counts steps; each advance() takes about 1 microsecond per step.
class CountingRun final : public SteppedRun {
public:
    /// With a `scene`, each snapshot is a copy of it without its measures (as the experiment
    /// run's are).
    explicit CountingRun(std::int64_t total, std::int64_t failAt = -1, SnapshotPtr scene = {})
        : total_(total), failAt_(failAt), scene_(std::move(scene)) {}
    bool advance(std::int64_t maxSteps) override {
        const std::int64_t n = std::min(maxSteps, total_ - steps_);
        if (failAt_ >= 0 && steps_ + n >= failAt_) {
            throw std::runtime_error("grain 3 overlap too large at step 1234");
        }
        std::this_thread::sleep_for(std::chrono::microseconds(n));
        steps_ += n;
        return steps_ < total_;
    }
    std::shared_ptr<Snapshot> snapshot() const override {
        auto s = scene_ ? testing::unmeasuredCopy(*scene_) : std::make_shared<Snapshot>();
        s->step = steps_;
        s->axialStrain = 1e-6 * double(steps_);
        return s;
    }
    RunProgress progress() const override {
        RunProgress p;
        p.stage = "shear 15 kPa";
        p.step = steps_;
        p.axialStrain = 1e-6 * double(steps_);
        p.fraction = double(steps_) / double(total_);
        p.finished = steps_ >= total_;
        return p;
    }

private:
    std::int64_t steps_ = 0, total_, failAt_;
    SnapshotPtr scene_;
};

using window_tests::waitFor;

TEST(SimulationController, StepAdvancesExactlyThenPauses) {
    SimulationController c;
    c.setRunFactory([] { return std::make_unique<CountingRun>(1000000); });
    c.step(250);
    ASSERT_TRUE(waitFor([&] { return c.latestSnapshot() != nullptr; }));
    EXPECT_EQ(c.latestSnapshot()->step, 250);
    EXPECT_EQ(c.status().state, RunState::Paused);
    c.step(1);
    ASSERT_TRUE(waitFor([&] { return c.latestSnapshot()->step == 251; }));
    EXPECT_EQ(c.status().stepsDone, 251);
}

TEST(SimulationController, RunsPublishesAtMostEvery16msAndPauses) {
    SimulationController c;
    c.setRunFactory([] { return std::make_unique<CountingRun>(100000000); });
    const auto t0 = std::chrono::steady_clock::now();
    c.start();
    ASSERT_TRUE(waitFor([&] { return c.status().state == RunState::Running; }));
    QTest::qWait(500);
    const RunStatus running = c.status();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_GE(running.publications, 5u);
    EXPECT_LE(double(running.publications), seconds * 60.0 + 2.0);
    EXPECT_GT(running.stepsPerSecond, 1000.0);
    EXPECT_GT(running.etaSeconds, 0.0);
    c.pause();
    ASSERT_TRUE(waitFor([&] { return c.status().state == RunState::Paused; }));
    const std::int64_t paused = c.latestSnapshot()->step;
    QTest::qWait(100);
    EXPECT_EQ(c.latestSnapshot()->step, paused);
    EXPECT_EQ(c.status().stepsDone, paused); // the published snapshot is the paused state
    c.start();
    ASSERT_TRUE(waitFor([&] { return c.latestSnapshot()->step > paused; }));
    c.stop();
    ASSERT_TRUE(waitFor([&] { return c.status().state == RunState::Idle; }));
    EXPECT_NE(c.latestSnapshot(), nullptr); // the last picture stays
}

TEST(SimulationController, RunningPicturesAreMeasuredOffTheEngineThreadPausedOnesAtOnce) {
    static const SnapshotPtr scene = testing::makeCompactedSnapshot();
    ASSERT_FALSE(scene->voidCells.empty());
    SimulationController c;
    c.setRunFactory([] { return std::make_unique<CountingRun>(100000000, -1, scene); });
    c.start();
    ASSERT_TRUE(waitFor([&] {
        const SnapshotPtr s = c.latestSnapshot();
        return s && s->step > 0 && c.status().state == RunState::Running;
    }));
    const SnapshotPtr running = c.latestSnapshot();
    EXPECT_TRUE(running->measured);
    EXPECT_EQ(running->voidCells.size(), scene->voidCells.size());
    EXPECT_EQ(running->loadBearing, scene->loadBearing);
    EXPECT_GT(c.status().measureSeconds, 0.0); // measured by the finisher
    c.pause();
    ASSERT_TRUE(waitFor([&] { return c.status().state == RunState::Paused; }));
    // The paused picture is published with the state, complete, and stays: no running picture
    // still being measured replaces it.
    const SnapshotPtr paused = c.latestSnapshot();
    EXPECT_EQ(paused->step, c.status().stepsDone);
    EXPECT_TRUE(paused->measured);
    EXPECT_EQ(paused->voidCells.size(), scene->voidCells.size());
    QTest::qWait(100);
    EXPECT_EQ(c.latestSnapshot(), paused);
}

TEST(SimulationController, FinishesAndReportsFailures) {
    SimulationController c;
    c.setRunFactory([] { return std::make_unique<CountingRun>(20000); });
    c.start();
    ASSERT_TRUE(waitFor([&] { return c.status().state == RunState::Finished; }));
    EXPECT_EQ(c.latestSnapshot()->step, 20000);
    c.stop();
    c.setRunFactory([] { return std::make_unique<CountingRun>(1000000, 5000); });
    c.start();
    ASSERT_TRUE(waitFor([&] { return c.status().state == RunState::Failed; }));
    EXPECT_NE(c.status().error.find("overlap too large"), std::string::npos);
}

TEST(SimulationController, GuiCallsNeverWaitForALongAdvance) {
    // Each advance() may take long; start / pause / status must return at once anyway.
    class SlowRun final : public SteppedRun {
    public:
        bool advance(std::int64_t) override {
            std::this_thread::sleep_for(std::chrono::milliseconds(200));
            return true;
        }
        std::shared_ptr<Snapshot> snapshot() const override { return std::make_shared<Snapshot>(); }
        RunProgress progress() const override { return {}; }
    };
    SimulationController c;
    c.setRunFactory([] { return std::make_unique<SlowRun>(); });
    c.start();
    QTest::qWait(50);
    const auto t0 = std::chrono::steady_clock::now();
    for (int k = 0; k < 100; ++k) {
        c.pause();
        (void)c.status();
        (void)c.latestSnapshot();
        c.start();
    }
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 0.05);
}

} // namespace
} // namespace grainlab::ui
