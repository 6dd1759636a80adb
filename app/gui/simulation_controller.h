#pragma once
// The simulation controller: owns the run in a worker QThread and is the only bridge between the
// engine and the GUI. The GUI thread calls start / pause / step / stop; the commands are queued
// and applied by the worker between advance() calls. While running, the worker copies the
// configuration into a new snapshot at most every publish interval (default ~16 ms; the main
// window uses 33 ms) and never more often than 1/50 of the time the copy takes, so that pictures
// cost the engine about 2 % of its time at most; the snapshot finisher (its own thread,
// snapshot_finisher.h) computes the picture's measures and publishes it by swapping a
// mutex-guarded shared pointer. When the run pauses, steps or ends, the worker publishes a
// complete snapshot itself, so that the paused picture is there when the state says so. The GUI
// picks the newest snapshot on its own timer and never waits for the worker. The controller also
// keeps the run's history (a snapshot at each shear record, within a memory budget:
// snapshot_history.h), cleared when a new run starts, for the GUI to show a past moment.
//
// Threads: every public function is called from the GUI thread; latestSnapshot() and status()
// may be called from any thread. stateChanged is emitted from the worker thread (queued to
// receivers living in the GUI thread).

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <string>

#include <QObject>
#include <QThread>

#include "gui/experiment_run.h"
#include "gui/snapshot_finisher.h"
#include "gui/snapshot_history.h"

namespace grainlab::ui {

enum class RunState { Idle, Running, Paused, Finished, Failed };

/// What the GUI shows about the run besides the snapshot. Copied out under the lock.
struct RunStatus {
    RunState state = RunState::Idle;
    RunProgress progress;
    std::int64_t stepsDone = 0;   ///< steps advanced by this controller since start
    double stepsPerSecond = 0;    ///< measured over the last publications
    double strainPerSecond = 0;   ///< d eps1 / dt (wall clock) [1/s]
    double etaSeconds = -1;       ///< from the rate of progress, -1 when unknown
    double snapshotSeconds = 0;   ///< engine thread's wall time to copy the last snapshot [s]
    double publishingSeconds = 0; ///< the engine thread's total on running pictures [s]
    std::uint64_t runningPublications = 0; ///< the running pictures behind publishingSeconds
    double measureSeconds = 0;      ///< the finisher's time for the last snapshot's measures [s]
    std::uint64_t publications = 0; ///< snapshots published so far
    std::string error;              ///< why the run failed
    std::string runFolder;          ///< the folder the current (or last) run writes, or ""
};

class SimulationController : public QObject {
    Q_OBJECT
public:
    using RunFactory = std::function<std::unique_ptr<SteppedRun>()>;

    explicit SimulationController(QObject* parent = nullptr);
    /// Stops the worker and waits for it (at most one advance() chunk, a few ms).
    ~SimulationController() override;

    /// What start() or step() creates when no run exists (Idle). Takes effect at the next run.
    void setRunFactory(RunFactory factory);
    void start();
    void pause();
    /// Advances `steps` steps then stays paused (creates the run if needed).
    void step(std::int64_t steps = 1);
    /// Ends the run; the next start() begins a new one. The last snapshot stays published. A
    /// recorded run that had not finished writes an "interrupted" checkpoint first (on the
    /// worker thread), as it does when the controller is destroyed.
    void stop();

    SnapshotPtr latestSnapshot() const;
    RunStatus status() const;
    /// The snapshots kept at the shear records of the current (or last) run. Thread-safe.
    const SnapshotHistory& history() const { return history_; }
    /// Minimum time between publications [s] (default 1/60 s).
    void setPublishInterval(double seconds);

signals:
    /// The run state changed (Running, Paused, Finished, Failed, Idle).
    void stateChanged(grainlab::ui::RunState state);

private:
    enum class CommandKind { Start, Pause, Step, Stop };
    struct Command {
        CommandKind kind;
        std::int64_t steps = 0;
    };
    void post(Command command);
    void workerLoop();
    bool ensureRun();
    /// Ends run_ on the worker thread: the interrupted checkpoint of a recorded run, then reset.
    void endRun();
    void publish(RunState state);
    void setState(RunState state, const std::string& error = {});

    // Guarded by mutex_.
    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::deque<Command> commands_;
    bool quit_ = false;
    RunFactory factory_;
    SnapshotPtr latest_;
    std::uint64_t latestSequence_ = 0;    ///< publication number of latest_
    std::uint64_t publishedSequence_ = 0; ///< publications numbered so far
    RunStatus status_;
    double publishInterval_ = 1.0 / 60.0;

    // Filled by the run on the worker thread, read by the GUI; locks itself.
    SnapshotHistory history_;
    // Completes the running pictures and the history's; declared after what its jobs touch, so
    // that it is joined before they go.
    SnapshotFinisher finisher_;

    // Worker thread only.
    std::unique_ptr<SteppedRun> run_;
    bool running_ = false;
    double lastRateTime_ = 0; ///< wall clock of the previous publication [s]
    std::int64_t lastRateSteps_ = 0;
    double lastRateStrain_ = 0;
    double lastRateFraction_ = 0;

    std::unique_ptr<QThread> worker_;
};

} // namespace grainlab::ui

Q_DECLARE_METATYPE(grainlab::ui::RunState)
