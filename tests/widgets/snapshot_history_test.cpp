// The live run's snapshot history: keeps every record until its count or memory budget is
// exceeded, then drops every other kept snapshot and keeps every other record from then on (the
// kept records stay evenly spaced); finds the kept snapshot of a test nearest an eps1.
#include <gtest/gtest.h>

#include "gui_snapshot_history.h"

namespace grainlab::ui {
namespace {

SnapshotPtr recordSnapshot(const std::string& test, double eps1, int grains = 10) {
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

} // namespace
} // namespace grainlab::ui
