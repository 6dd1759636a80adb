#pragma once
// The life of a worker thread that waits on a condition variable for work or for the order to
// quit (the simulation controller's engine thread, the snapshot finisher's thread): started
// with a name, ended by setting the quit flag under the lock, waking it and joining it.

#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>

#include <QString>
#include <QThread>

namespace grainlab::ui {

/// A thread named `name` (as debuggers and profilers show it) running `loop`, started.
std::unique_ptr<QThread> startWorkerThread(const QString& name, std::function<void()> loop);

/// Sets `quit` under `mutex` (and does `alsoUnderLock` there, e.g. drops the queued work), wakes
/// the thread waiting on `wake` and waits for it to end.
void quitWorkerThread(QThread& thread, std::mutex& mutex, std::condition_variable& wake, bool& quit,
                      const std::function<void()>& alsoUnderLock = {});

} // namespace grainlab::ui
