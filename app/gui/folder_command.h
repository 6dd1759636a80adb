#pragma once
// What the Study window and the Stability view share around a grainlab subcommand that works in
// a folder (`grainlab study`, `grainlab stability`): the row that starts and stops it and shows
// its progress with the ETA (CommandRow), and the scans of its folder on a worker thread, one at a
// time, a stale one dropped (FolderScanner). GUI thread only, but for the scans themselves.

#include <cstdint>
#include <functional>
#include <memory>

#include <QElapsedTimer>
#include <QMetaObject>
#include <QObject>
#include <QString>
#include <QThread>

class QHBoxLayout;
class QLabel;
class QProgressBar;
class QPushButton;

namespace grainlab::ui {

/// Start, Stop, the progress bar of finished items ("runs", "cells") and the progress text.
class CommandRow {
public:
    /// Makes the row's widgets (parented once `layout` is added to a window's layout).
    CommandRow(const QString& startTip, const QString& stopTip, const QString& unit);

    QHBoxLayout* layout;
    QPushButton* start;
    QPushButton* stop;
    QProgressBar* bar;
    QLabel* text;

    /// The command started with `finishedNow` items finished: the ETA counts from here.
    void started(int finishedNow);
    /// `done` of `total` finished; while `running`, the time since the start, the ETA from the
    /// items finished since, and `extra` (the command's own progress) after them.
    void show(int done, int total, bool running, const QString& extra = {});

private:
    QString unit_;
    QElapsedTimer sinceStart_;
    int finishedAtStart_ = 0;
};

/// What the status line says once the command ended with `exitStatus`: `finished` (0), `stopped`
/// (130, the command stopped its own work; or any status after Stop, which may come before it
/// started any), `current` when it already says the command could not start, else `failed`
/// (which may hold %1 for the status).
QString commandEndedText(int exitStatus, bool stopping, const QString& current,
                         const QString& finished, const QString& stopped, const QString& failed);

/// For a start() that cannot start: `message` into `error` (when given); false.
bool refuseStart(QString* error, const QString& message);

/// Scans of a folder on a worker thread of its own.
class FolderScanner {
public:
    FolderScanner();
    /// Waits for a scan under way; its result is dropped.
    ~FolderScanner();
    FolderScanner(const FolderScanner&) = delete;
    FolderScanner& operator=(const FolderScanner&) = delete;

    /// The folder or what is read from it changed: the scans posted so far are dropped.
    void forget() { ++generation_; }

    /// Runs `scan` on the worker thread (it must copy in all it reads), then `done(result,
    /// error)` on `receiver`'s thread, unless forget() came in between; `result` is null when
    /// `scan` threw, `error` its message. One scan at a time: a request during a scan calls
    /// `again` once that scan is done (which asks anew with the state of then).
    template <class Result>
    void request(QObject* receiver, std::function<std::shared_ptr<const Result>()> scan,
                 std::function<void(std::shared_ptr<const Result>, const QString&)> done,
                 std::function<void()> again) {
        if (scanning_) {
            again_ = std::move(again);
            return;
        }
        scanning_ = true;
        QMetaObject::invokeMethod(
            context_,
            [this, receiver, generation = generation_, scan = std::move(scan),
             done = std::move(done)] {
                std::shared_ptr<const Result> next;
                QString error;
                try {
                    next = scan();
                } catch (const std::exception& e) {
                    error = QString::fromStdString(e.what());
                }
                QMetaObject::invokeMethod(
                    receiver,
                    [this, generation, next, error, done] {
                        scanning_ = false;
                        if (generation == generation_) {
                            done(next, error);
                        }
                        if (again_) {
                            const std::function<void()> again = std::move(again_);
                            again_ = nullptr;
                            again();
                        }
                    },
                    Qt::QueuedConnection);
            },
            Qt::QueuedConnection);
    }

private:
    QThread worker_;
    QObject* context_; ///< lives on worker_: the context of the scans posted there
    std::uint64_t generation_ = 0;
    bool scanning_ = false;
    std::function<void()> again_; ///< asked for during a scan
};

} // namespace grainlab::ui
