#pragma once
// The live run's past, kept so that hovering a chart can show that moment in the scene: the
// snapshot of the run at its shear records (the points the charts draw). Bounded by a memory
// budget (default 256 MB) and a count (default 2000 snapshots): when either is exceeded, every
// other kept snapshot is dropped and from then on only every other record is kept (the stride
// doubles), so the kept moments stay evenly spread over the whole run however long it is. The
// run thins the same way when copying the kept snapshots costs the engine more than ~2 % of its
// time (experiment_run.cpp).
//
// Threads: the run adds snapshots on the controller's worker thread (SteppedRun::
// keepRecordSnapshots); the GUI thread looks them up. Every member function locks the history's
// own mutex; the snapshots are immutable and shared. A snapshot added without its measures is
// completed first, by the finisher when one is set (then it becomes visible a few ms later), or
// else on the caller's thread.

#include <cstddef>
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

#include "grainlab/snapshot.h"
#include "gui/snapshot_finisher.h"

namespace grainlab::ui {

class SnapshotHistory {
public:
    static constexpr std::size_t kDefaultBudgetBytes = std::size_t(256) << 20;
    static constexpr std::size_t kDefaultMaxCount = 2000;

    explicit SnapshotHistory(std::size_t budgetBytes = kDefaultBudgetBytes,
                             std::size_t maxCount = kDefaultMaxCount);

    /// Whether record `record` (the run's shear records counted from 0) would be kept: the run
    /// asks before it builds the snapshot.
    bool wants(std::int64_t record) const;
    /// Keeps `snapshot` (not yet shared with anyone) as record `record` (ignored when not
    /// wanted), then thins while over the budget or the count.
    void add(std::int64_t record, std::shared_ptr<Snapshot> snapshot);
    /// The finisher's time on the measures of the snapshots added so far [s, wall]: the run
    /// counts it with its copies when it holds the history's cost to the engine (it is taken
    /// from the engine's processors as much as the copies are).
    double measureSeconds() const;
    /// Completes unmeasured snapshots on `finisher` (which must outlive the history's use).
    void setFinisher(SnapshotFinisher* finisher);
    /// The kept snapshot of test `test` whose eps1 is nearest `eps1`; when `test` has none, of
    /// the test of the newest kept snapshot. Null when nothing is kept.
    SnapshotPtr nearest(const std::string& test, double eps1) const;
    /// Drops every other kept snapshot and keeps every other record from now on.
    void thin();
    /// Forgets everything (a new run) and keeps every record again.
    void clear();

    std::size_t size() const;
    std::size_t bytes() const;
    /// Records kept are the multiples of the stride: 1, then 2, 4, ... after each thinning.
    std::int64_t stride() const;
    /// The record numbers kept, in order.
    std::vector<std::int64_t> records() const;

private:
    void thinLocked();
    void keep(std::int64_t record, std::uint64_t generation, SnapshotPtr snapshot);

    struct Entry {
        std::int64_t record;
        SnapshotPtr snapshot;
        std::size_t bytes;
    };

    mutable std::mutex mutex_;
    std::size_t budgetBytes_;
    std::size_t maxCount_;
    std::int64_t stride_ = 1;
    double measureSeconds_ = 0; ///< see measureSeconds()
    std::size_t bytes_ = 0;
    std::vector<Entry> entries_;   ///< by increasing record
    std::uint64_t generation_ = 0; ///< counts clear(): a snapshot finished after one is dropped
    SnapshotFinisher* finisher_ = nullptr;
};

/// Heap bytes held by a snapshot, estimated from its vectors' capacities.
std::size_t snapshotBytes(const Snapshot& snapshot);

} // namespace grainlab::ui
