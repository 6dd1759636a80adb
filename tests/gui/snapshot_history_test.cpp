// The live run's snapshot history: keeps every record until its count or memory budget is
// exceeded, then drops every other kept snapshot and keeps every other record from then on (the
// kept records stay evenly spaced); finds the kept snapshot of a test nearest an eps1.
#include <atomic>
#include <chrono>
#include <thread>

#include <gtest/gtest.h>

#include "gui/snapshot_history.h"
#include "test_scenes.h"

namespace grainlab::ui {
namespace {

std::shared_ptr<Snapshot> recordSnapshot(const std::string& test, double eps1, int grains = 10) {
    auto s = std::make_shared<Snapshot>();
    s->test = test;
    s->axialStrain = eps1;
    s->step = static_cast<std::int64_t>(eps1 * 1e6);
    s->x1.assign(grains, 0.0);
    s->x2.assign(grains, 0.0);
    s->theta.assign(grains, 0.0);
    return s;
}

/// What a run does: asks, builds only what is wanted, adds.
int feed(SnapshotHistory& history, int records, const std::string& test = "p015kPa",
         int grains = 10) {
    int built = 0;
    for (int r = 0; r < records; ++r) {
        if (history.wants(r)) {
            history.add(r, recordSnapshot(test, 1e-4 * r, grains));
            ++built;
        }
    }
    return built;
}

TEST(SnapshotHistory, KeepsEveryRecordWithinItsBounds) {
    SnapshotHistory history(1 << 30, 100);
    feed(history, 60);
    EXPECT_EQ(history.size(), 60u);
    EXPECT_EQ(history.stride(), 1);
    EXPECT_GT(history.bytes(), 60 * 3 * 10 * sizeof(double));
}

TEST(SnapshotHistory, ThinsEvenlyWhenTheCountIsExceeded) {
    SnapshotHistory history(1 << 30, 16);
    const int built = feed(history, 100);
    // 100 records into 16 places: the stride doubled to 8 (13 records kept: 0, 8, ..., 96).
    EXPECT_EQ(history.stride(), 8);
    const std::vector<std::int64_t> kept = history.records();
    ASSERT_EQ(kept.size(), 13u);
    for (std::size_t k = 0; k < kept.size(); ++k) {
        EXPECT_EQ(kept[k], 8 * static_cast<std::int64_t>(k));
    }
    // Snapshots of records that would be dropped at once are not built.
    EXPECT_LT(built, 50);
}

TEST(SnapshotHistory, ThinsWhenTheMemoryBudgetIsExceeded) {
    const std::size_t one = snapshotBytes(*recordSnapshot("p", 0.0, 1000));
    SnapshotHistory history(10 * one + one / 2, 1000);
    feed(history, 40, "p", 1000);
    EXPECT_LE(history.bytes(), 10 * one + one / 2);
    EXPECT_EQ(history.stride(), 4); // 40 records, 10 fit: every 4th
    EXPECT_EQ(history.size(), 10u);
    history.clear();
    EXPECT_EQ(history.size(), 0u);
    EXPECT_EQ(history.stride(), 1);
    EXPECT_EQ(history.nearest("p", 0.0), nullptr);
}

TEST(SnapshotHistory, NearestOfTheTestOrElseOfTheNewestTest) {
    SnapshotHistory history;
    feed(history, 30, "p015kPa");
    for (int r = 30; r < 40; ++r) {
        history.add(r, recordSnapshot("p025kPa", 1e-4 * (r - 30)));
    }
    const SnapshotPtr a = history.nearest("p015kPa", 0.00123);
    ASSERT_NE(a, nullptr);
    EXPECT_EQ(a->test, "p015kPa");
    EXPECT_DOUBLE_EQ(a->axialStrain, 1e-4 * 12);
    const SnapshotPtr b = history.nearest("p050kPa", 0.0004);
    ASSERT_NE(b, nullptr);
    EXPECT_EQ(b->test, "p025kPa");
    EXPECT_DOUBLE_EQ(b->axialStrain, 1e-4 * 4);
}

/// `complete` without its measures, as the live run builds the pictures it keeps, at `step`.
std::shared_ptr<Snapshot> unmeasuredCopy(const Snapshot& complete, std::int64_t step) {
    auto s = testing::unmeasuredCopy(complete);
    s->step = step;
    s->axialStrain = 1e-4 * double(step);
    return s;
}

TEST(SnapshotHistory, KeepsUnmeasuredSnapshotsOnceTheFinisherMeasuredThem) {
    static const SnapshotPtr complete = testing::makeCompactedSnapshot();
    ASSERT_FALSE(complete->voidCells.empty());
    SnapshotFinisher finisher;
    SnapshotHistory history;
    history.setFinisher(&finisher);
    for (int r = 0; r < 5; ++r) {
        history.add(r, unmeasuredCopy(*complete, r));
    }
    finisher.drain();
    ASSERT_EQ(history.size(), 5u);
    const SnapshotPtr kept = history.nearest(complete->test, 3e-4);
    ASSERT_NE(kept, nullptr);
    EXPECT_EQ(kept->step, 3);
    EXPECT_TRUE(kept->measured);
    EXPECT_EQ(kept->loadBearing, complete->loadBearing);
    ASSERT_EQ(kept->voidCells.size(), complete->voidCells.size());
    for (std::size_t v = 0; v < kept->voidCells.size(); ++v) {
        EXPECT_EQ(kept->voidCells[v].grains, complete->voidCells[v].grains);
        EXPECT_DOUBLE_EQ(kept->voidCells[v].area, complete->voidCells[v].area);
    }
    // The finisher's time on them is counted, for the run's cost of the history: at least the
    // last job's.
    EXPECT_GE(history.measureSeconds(), finisher.lastSeconds());
    EXPECT_GT(finisher.lastSeconds(), 0.0);
    // Without a finisher, add() measures on the caller's thread (in the run's own time).
    SnapshotHistory direct;
    direct.add(0, unmeasuredCopy(*complete, 0));
    ASSERT_EQ(direct.size(), 1u);
    EXPECT_EQ(direct.nearest(complete->test, 0.0)->voidCells.size(), complete->voidCells.size());
    EXPECT_EQ(direct.measureSeconds(), 0.0);
}

TEST(SnapshotHistory, ASnapshotMeasuredAfterClearIsDropped) {
    static const SnapshotPtr complete = testing::makeCompactedSnapshot();
    SnapshotFinisher finisher;
    SnapshotHistory history;
    history.setFinisher(&finisher);
    // Hold the finisher on a job of its own until the history has been cleared (a new run).
    std::atomic<bool> release{false};
    finisher.submit(
        std::make_shared<Snapshot>(),
        [&](SnapshotPtr) {
            while (!release) {
                std::this_thread::sleep_for(std::chrono::milliseconds(1));
            }
        },
        false);
    history.add(0, unmeasuredCopy(*complete, 0));
    history.clear();
    release = true;
    finisher.drain();
    EXPECT_EQ(history.size(), 0u);
    // The next run's snapshots are kept again.
    history.add(0, unmeasuredCopy(*complete, 0));
    finisher.drain();
    EXPECT_EQ(history.size(), 1u);
}

} // namespace
} // namespace grainlab::ui
