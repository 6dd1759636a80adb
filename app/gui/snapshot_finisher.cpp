// See snapshot_finisher.h.
#include "gui/snapshot_finisher.h"

#include <chrono>
#include <exception>

#include <QtGlobal>

#include "gui/worker_thread.h"

namespace grainlab::ui {

SnapshotFinisher::SnapshotFinisher()
    : thread_(startWorkerThread(QStringLiteral("grainlab snapshots"), [this] { loop(); })) {}

SnapshotFinisher::~SnapshotFinisher() {
    quitWorkerThread(*thread_, mutex_, wake_, quit_, [this] { jobs_.clear(); });
}

void SnapshotFinisher::submit(std::shared_ptr<Snapshot> snapshot, Done done, bool replaceable) {
    {
        std::lock_guard lock(mutex_);
        if (replaceable) {
            for (Job& job : jobs_) {
                if (job.replaceable) {
                    job = {std::move(snapshot), std::move(done), true};
                    return;
                }
            }
        }
        jobs_.push_back({std::move(snapshot), std::move(done), replaceable});
    }
    wake_.notify_all();
}

void SnapshotFinisher::drain() {
    std::unique_lock lock(mutex_);
    idle_.wait(lock, [this] { return quit_ || (jobs_.empty() && !busy_); });
}

double SnapshotFinisher::lastSeconds() const {
    std::lock_guard lock(mutex_);
    return lastSeconds_;
}

void SnapshotFinisher::loop() {
    for (;;) {
        Job job;
        {
            std::unique_lock lock(mutex_);
            busy_ = false;
            idle_.notify_all();
            wake_.wait(lock, [this] { return quit_ || !jobs_.empty(); });
            if (quit_) {
                return;
            }
            job = std::move(jobs_.front());
            jobs_.pop_front();
            busy_ = true;
        }
        const auto start = std::chrono::steady_clock::now();
        try {
            addSnapshotMeasures(*job.snapshot);
        } catch (const std::exception& e) {
            // The picture is still shown, without its void cells and load-bearing flags.
            qWarning("grainlab: the measures of the snapshot at step %lld failed: %s",
                     static_cast<long long>(job.snapshot->step), e.what());
        }
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        {
            std::lock_guard lock(mutex_);
            lastSeconds_ = seconds;
        }
        job.done(std::move(job.snapshot));
    }
}

} // namespace grainlab::ui
