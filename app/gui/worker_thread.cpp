// See worker_thread.h.
#include "gui/worker_thread.h"

namespace grainlab::ui {

std::unique_ptr<QThread> startWorkerThread(const QString& name, std::function<void()> loop) {
    std::unique_ptr<QThread> thread(QThread::create(std::move(loop)));
    thread->setObjectName(name);
    thread->start();
    return thread;
}

void quitWorkerThread(QThread& thread, std::mutex& mutex, std::condition_variable& wake, bool& quit,
                      const std::function<void()>& alsoUnderLock) {
    {
        std::lock_guard lock(mutex);
        quit = true;
        if (alsoUnderLock) {
            alsoUnderLock();
        }
    }
    wake.notify_all();
    thread.wait();
}

} // namespace grainlab::ui
