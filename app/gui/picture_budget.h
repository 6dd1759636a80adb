#pragma once
// How often the main window takes a new picture of a running run. Each new picture costs the
// processor work besides the steps: the engine thread copies the configuration, the snapshot
// thread computes its void cells and load-bearing flags, the GUI thread prepares and paints the
// scene. Where the engine's threads fill every core, that time is taken from the engine (at 8450
// grains with force chains and void cells the painting alone is tens of ms). The budget holds
// that work to a share of one core: after a picture that cost c [ms], the next one comes no
// sooner than c / share later, and never sooner than the window's frame period (33 ms). It has
// no memory: the last picture's cost decides, because the cost follows the view and the display
// options, which change at once (zooming in, switching the void cells off).
//
// Only running pictures are spaced: a paused, stepped or finished run's picture, and the
// redraws of zooming, panning or changed options, are shown at once by the window.
//
// A plain computation with no Qt; the main window owns one (GUI thread).

namespace grainlab::ui {

class PictureBudget {
public:
    /// The engine's loss the budget is made for: 3 % of its headless speed, so that with the
    /// chart history's copies and measures (held to 2 %, experiment_run.cpp) the window costs the
    /// engine at most 5 % (the target for the window).
    static constexpr double kEngineLoss = 0.03;
    /// The share of a core the pictures may take when the engine leaves a core free.
    static constexpr double kFreeCoreShare = 0.5;

    /// `share`: of one core, in (0, 1] (out of range: clamped); `floorMs`: the shortest spacing.
    explicit PictureBudget(double share = kFreeCoreShare, double floorMs = 33.0);

    /// The share of one core for a run whose engine uses `engineThreads` threads on a machine of
    /// `processors` processors (QThread::idealThreadCount()).
    ///  - The engine fills every core (engineThreads >= processors): its threads wait for one
    ///    another at every step's barriers, so a millisecond of the pictures' work on any core
    ///    holds up all of them for about that millisecond (measured with `grainlab bench --gui`
    ///    on 2 processors: other work of 14 % of a core cost the engine 17 %). A loss of
    ///    kEngineLoss is then kEngineLoss of one core, whatever the processor count.
    ///  - A core is free (engineThreads < processors): the pictures' work runs there and takes
    ///    from the engine only what the cores share (caches, memory). The GUI thread keeps half
    ///    of that core (kFreeCoreShare) for the snapshot thread, the display server and the
    ///    user's input, which waits while a picture is painted.
    static double shareFor(int engineThreads, int processors);

    double share() const { return share_; }
    double floorMs() const { return floorMs_; }
    /// The spacing after a picture that cost `pictureCostMs` (negative or not finite: 0).
    double intervalMs(double pictureCostMs) const;
    /// The earliest time of the next picture after one taken at `lastPictureAtMs` (any clock in
    /// ms) that cost `pictureCostMs`.
    double nextPictureAtMs(double lastPictureAtMs, double pictureCostMs) const {
        return lastPictureAtMs + intervalMs(pictureCostMs);
    }

private:
    double share_;
    double floorMs_;
};

} // namespace grainlab::ui
