// See snapshot_history.h.
#include "gui/snapshot_history.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace grainlab::ui {
namespace {

template <class T>
std::size_t heapOf(const std::vector<T>& v) {
    return v.capacity() * sizeof(T);
}

/// What malloc adds to each block (header and rounding), roughly.
constexpr std::size_t kBlockOverhead = 16;

} // namespace

std::size_t snapshotBytes(const Snapshot& s) {
    std::size_t bytes = sizeof(Snapshot) + heapOf(s.shapes) + heapOf(s.shape) + heapOf(s.x1) +
                        heapOf(s.x2) + heapOf(s.theta) + heapOf(s.rotation) +
                        heapOf(s.loadBearing) + heapOf(s.voidCells);
    const ContactNetwork& n = s.network;
    bytes += heapOf(n.x1) + heapOf(n.x2) + heapOf(n.grainArea) + heapOf(n.grainMass) +
             heapOf(n.netForce1) + heapOf(n.netForce2) + heapOf(n.contacts);
    for (const VoidCellView& v : s.voidCells) {
        bytes += heapOf(v.grains) + heapOf(v.x1) + heapOf(v.x2) + 3 * kBlockOverhead;
    }
    for (const SeriesTable& t : s.series) {
        bytes += sizeof(SeriesTable) + heapOf(t.columns) + heapOf(t.rows) + heapOf(t.stages);
        for (const auto& row : t.rows) {
            bytes += heapOf(row) + kBlockOverhead;
        }
        for (const auto& stage : t.stages) {
            bytes += stage.capacity() + kBlockOverhead;
        }
    }
    return bytes;
}

SnapshotHistory::SnapshotHistory(std::size_t budgetBytes, std::size_t maxCount)
    : budgetBytes_(budgetBytes), maxCount_(std::max<std::size_t>(2, maxCount)) {}

bool SnapshotHistory::wants(std::int64_t record) const {
    std::lock_guard lock(mutex_);
    return record % stride_ == 0;
}

void SnapshotHistory::setFinisher(SnapshotFinisher* finisher) {
    std::lock_guard lock(mutex_);
    finisher_ = finisher;
}

void SnapshotHistory::add(std::int64_t record, std::shared_ptr<Snapshot> snapshot) {
    if (!snapshot) {
        return;
    }
    std::uint64_t generation = 0;
    SnapshotFinisher* finisher = nullptr;
    {
        std::lock_guard lock(mutex_);
        if (record % stride_ != 0) {
            return;
        }
        generation = generation_;
        finisher = finisher_;
    }
    if (snapshot->measured) {
        keep(record, generation, std::move(snapshot));
    } else if (finisher) {
        finisher->submit(
            std::move(snapshot),
            [this, record, generation, finisher](SnapshotPtr done) {
                {
                    std::lock_guard lock(mutex_);
                    measureSeconds_ += finisher->lastSeconds(); // set before `done` runs
                }
                keep(record, generation, done);
            },
            false);
    } else {
        addSnapshotMeasures(*snapshot);
        keep(record, generation, std::move(snapshot));
    }
}

double SnapshotHistory::measureSeconds() const {
    std::lock_guard lock(mutex_);
    return measureSeconds_;
}

void SnapshotHistory::keep(std::int64_t record, std::uint64_t generation, SnapshotPtr snapshot) {
    std::lock_guard lock(mutex_);
    if (generation != generation_ || record % stride_ != 0 ||
        (!entries_.empty() && record <= entries_.back().record)) {
        return;
    }
    const std::size_t bytes = snapshotBytes(*snapshot);
    entries_.push_back({record, std::move(snapshot), bytes});
    bytes_ += bytes;
    // A single snapshot larger than the whole budget is still kept (one picture is better than
    // none).
    while ((bytes_ > budgetBytes_ || entries_.size() > maxCount_) && entries_.size() > 1) {
        thinLocked();
    }
}

void SnapshotHistory::thin() {
    std::lock_guard lock(mutex_);
    thinLocked();
}

void SnapshotHistory::thinLocked() {
    // Evenly: keep the multiples of twice the stride.
    stride_ *= 2;
    std::vector<Entry> kept;
    kept.reserve(entries_.size() / 2 + 1);
    bytes_ = 0;
    for (Entry& e : entries_) {
        if (e.record % stride_ == 0) {
            bytes_ += e.bytes;
            kept.push_back(std::move(e));
        }
    }
    entries_ = std::move(kept);
}

SnapshotPtr SnapshotHistory::nearest(const std::string& test, double eps1) const {
    std::lock_guard lock(mutex_);
    if (entries_.empty()) {
        return nullptr;
    }
    std::string wanted = test;
    bool found = false;
    for (const Entry& e : entries_) {
        found |= e.snapshot->test == wanted;
    }
    if (!found) {
        wanted = entries_.back().snapshot->test;
    }
    SnapshotPtr best;
    double distance = std::numeric_limits<double>::infinity();
    for (const Entry& e : entries_) {
        const double d = std::fabs(e.snapshot->axialStrain - eps1);
        if (e.snapshot->test == wanted && d < distance) {
            distance = d;
            best = e.snapshot;
        }
    }
    return best;
}

void SnapshotHistory::clear() {
    std::lock_guard lock(mutex_);
    entries_.clear();
    bytes_ = 0;
    stride_ = 1;
    ++generation_;
}

std::size_t SnapshotHistory::size() const {
    std::lock_guard lock(mutex_);
    return entries_.size();
}

std::size_t SnapshotHistory::bytes() const {
    std::lock_guard lock(mutex_);
    return bytes_;
}

std::int64_t SnapshotHistory::stride() const {
    std::lock_guard lock(mutex_);
    return stride_;
}

std::vector<std::int64_t> SnapshotHistory::records() const {
    std::lock_guard lock(mutex_);
    std::vector<std::int64_t> out;
    out.reserve(entries_.size());
    for (const Entry& e : entries_) {
        out.push_back(e.record);
    }
    return out;
}

} // namespace grainlab::ui
