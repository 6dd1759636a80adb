#pragma once
// Completes snapshots on a thread of its own: the live window's engine thread copies only the
// configuration and the contact network into each picture (SnapshotMeasures::Later) and hands it
// here, where the load-bearing flags and the void cells are computed (addSnapshotMeasures)
// before the picture is published. The measures cost several times the copy (at 8450 grains
// about 4 ms against 1 ms), and on the engine's thread they were taken from the run.
//
// Jobs run in order. A replaceable job (the newest live picture) that has not started yet is
// replaced by the next replaceable one: a picture superseded before it could be shown is never
// measured. Other jobs (the pictures kept for chart hover) all run.
//
// Threads: submit() and drain() from any thread; each job's `done` runs on the finisher's thread
// with the completed snapshot, which nobody else has seen yet.

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>

#include <QThread>

#include "grainlab/snapshot.h"

namespace grainlab::ui {

class SnapshotFinisher {
public:
    using Done = std::function<void(SnapshotPtr)>;

    SnapshotFinisher();
    /// Finishes the job under way, drops the queued ones, joins the thread.
    ~SnapshotFinisher();
    SnapshotFinisher(const SnapshotFinisher&) = delete;
    SnapshotFinisher& operator=(const SnapshotFinisher&) = delete;

    void submit(std::shared_ptr<Snapshot> snapshot, Done done, bool replaceable);
    /// Returns once every job submitted before the call has run.
    void drain();
    /// Wall time of the last job's measures [s] (set before its `done` runs).
    double lastSeconds() const;

private:
    struct Job {
        std::shared_ptr<Snapshot> snapshot;
        Done done;
        bool replaceable;
    };
    void loop();

    mutable std::mutex mutex_;
    std::condition_variable wake_, idle_;
    std::deque<Job> jobs_;
    bool busy_ = false;
    bool quit_ = false;
    double lastSeconds_ = 0;
    std::unique_ptr<QThread> thread_;
};

} // namespace grainlab::ui
