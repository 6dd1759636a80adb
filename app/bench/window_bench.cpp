// See window_bench.h.
#include "bench/window_bench.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <optional>
#include <stdexcept>
#include <thread>
#include <vector>

#include <QApplication>
#include <QComboBox>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QImage>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QPainter>
#include <QThread>
#include <QTimer>
#include <QWindow>

#include <fmt/format.h>
#include <time.h>

#include "bench/bench.h"
#include "common/progress_bar.h"
#include "grainlab/assembly.h"
#include "grainlab/experiment_file.h"
#include "grainlab/experiment_runner.h"
#include "grainlab/scenes/compacted_scene.h"
#include "grainlab/simulation.h"
#include "grainlab/ui/gl_scene_layer.h"
#include "grainlab/ui/scene_options_bar.h"
#include "grainlab/ui/scene_renderer.h"
#include "grainlab/ui/scene_view.h"
#include "gui/main_window.h"
#include "gui/snapshot_history.h"

namespace grainlab {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// The 1-minute load average (Linux), or -1: other jobs on the machine take processor time
/// from the engine and the window alike.
double loadAverage() {
    double load = -1.0;
    if (FILE* f = std::fopen("/proc/loadavg", "r")) {
        if (std::fscanf(f, "%lf", &load) != 1) {
            load = -1.0;
        }
        std::fclose(f);
    }
    return load;
}

/// CPU time of the calling thread [s].
double threadCpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n == 0 ? 0.0 : n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

/// Lets Qt process events until `widget`'s window is exposed (at most `timeoutMs`).
void waitUntilExposed(QWidget& widget, int timeoutMs = 5000) {
    QElapsedTimer timer;
    timer.start();
    while (!(widget.windowHandle() && widget.windowHandle()->isExposed()) &&
           timer.elapsed() < timeoutMs) {
        QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    QCoreApplication::processEvents();
}

// ---------------------------------------------------------------------------------------------
// (a) The live window's cost to the engine

/// The experiment reduced to its first test: one compaction and the shear of that sample.
ExperimentConfig firstTestOf(const std::string& path, int threads) {
    ExperimentConfig c = readExperimentFile(path);
    c.compaction.pressures.resize(1);
    c.shear.pressures = {c.compaction.pressures.front()};
    c.parameters.threads = threads;
    return c;
}

/// Keeps, in memory, what a run needs to continue from the checkpoint the runner writes as the
/// shear starts.
class ShearStartCapture final : public RunOutput {
public:
    void record(const SeriesTable&) override {}
    void checkpoint(const CheckpointData& data) override {
        if (!found && data.name.find("-shear-") != std::string::npos) {
            resume.state = *data.state;
            resume.runnerState = data.runnerState;
            found = true;
        }
    }
    void sample(double pressure, const SimulationState& state) override {
        resume.samples[pressure] = state;
    }

    ResumePoint resume;
    bool found = false;
};

ResumePoint shearStart(const ExperimentConfig& config) {
    ShearStartCapture capture;
    ExperimentRunner runner(config, &capture);
    ProgressBar bar(
        fmt::format("compacting and equilibrating {} grains", runner.simulation().grainCount()));
    while (!capture.found && runner.advance(1000)) {
        bar.update(runner.progress().fraction, runner.progress().stage);
    }
    bar.finish();
    if (!capture.found) {
        throw std::runtime_error("bench --gui: the experiment finished before its first shear");
    }
    capture.resume.series = runner.series(); // cut back to the checkpoint's rows on resume
    return std::move(capture.resume);
}

struct HeadlessResult {
    double stepsPerSecond = 0;
    double cpuShare = 0; ///< CPU time of the engine thread / wall time
};

/// f() on a thread of its own, joined. libgomp keeps a pool of worker threads for each thread
/// that has run a parallel region, until that thread ends, and once the pools' threads outnumber
/// the processors it makes every OpenMP thread sleep at each barrier instead of spinning (its
/// "throttled" wait). Had the compaction and the headless runs used the GUI thread, its idle pool
/// would have throttled the window's engine, which no user's window does: measured, the window
/// then ran 35 to 50 % slower on 2 processors.
template <class F>
auto onOwnThread(F&& f) {
    std::optional<decltype(f())> result;
    std::exception_ptr failure;
    std::thread([&] {
        try {
            result.emplace(f());
        } catch (...) {
            failure = std::current_exception();
        }
    }).join();
    if (failure) {
        std::rethrow_exception(failure);
    }
    return std::move(*result);
}

/// Steps per second of the runner alone from `resume`.
HeadlessResult headlessStepsPerSecond(const ExperimentConfig& config, const ResumePoint& resume,
                                      std::int64_t steps) {
    ExperimentRunner runner(config, resume);
    const auto t0 = Clock::now();
    const double cpu0 = threadCpuSeconds();
    std::int64_t done = 0;
    while (done < steps) {
        const std::int64_t n = std::min<std::int64_t>(1000, steps - done);
        const bool more = runner.advance(n);
        done += n;
        if (!more) {
            break;
        }
    }
    const double wall = secondsSince(t0);
    return {double(done) / wall, (threadCpuSeconds() - cpu0) / wall};
}

/// Timed on the worker thread: the wall and CPU time from the first advance() to the last step.
struct RunTiming {
    std::atomic<double> seconds{0.0};
    std::atomic<double> cpuSeconds{0.0};
    std::atomic<std::int64_t> steps{0};
};

/// The experiment run as the window drives it, stopped after `steps` steps, timed.
class TimedRun final : public ui::SteppedRun {
public:
    TimedRun(std::unique_ptr<ui::SteppedRun> run, std::int64_t steps,
             std::shared_ptr<RunTiming> timing)
        : run_(std::move(run)), steps_(steps), timing_(std::move(timing)) {}
    bool advance(std::int64_t maxSteps) override {
        if (done_ == 0) {
            start_ = Clock::now();
            cpuStart_ = threadCpuSeconds();
        }
        const std::int64_t n = std::min(maxSteps, steps_ - done_);
        const bool more = n > 0 && run_->advance(n);
        done_ += std::max<std::int64_t>(0, n);
        if (!more || done_ >= steps_) {
            timing_->seconds = secondsSince(start_);
            timing_->cpuSeconds = threadCpuSeconds() - cpuStart_;
            timing_->steps = done_;
            return false;
        }
        return true;
    }
    std::shared_ptr<Snapshot> snapshot() const override { return run_->snapshot(); }
    RunProgress progress() const override { return run_->progress(); }
    void keepRecordSnapshots(ui::SnapshotHistory* history) override {
        run_->keepRecordSnapshots(history);
    }

private:
    std::unique_ptr<ui::SteppedRun> run_;
    std::int64_t steps_;
    std::int64_t done_ = 0;
    Clock::time_point start_;
    double cpuStart_ = 0;
    std::shared_ptr<RunTiming> timing_;
};

struct WindowResult {
    double stepsPerSecond = 0;
    double picturesPerSecond = 0; ///< new snapshots shown in the scene
    double engineCpuShare = 0;    ///< CPU time of the engine thread / wall time
    double guiCpuShare = 0;       ///< CPU time of the GUI thread / wall time
    double snapshotMs = 0;        ///< the engine thread's mean time on a running picture
    double publishingShare = 0;   ///< the engine thread's time on snapshots / wall time
    double measureMs = 0;         ///< the finisher's time on the last snapshot's measures
    std::uint64_t publications = 0;
    std::size_t kept = 0, keptBytes = 0; ///< the chart-hover history at the end
    bool openGL = false;
    double prepareMs = 0; ///< the GUI thread's mean time preparing a new snapshot
    double paintMs = 0;   ///< the GUI thread's mean time painting the whole scene
    std::uint64_t paints = 0;
    double budgetShare = 0;   ///< the window's picture budget: share of a core
    double intervalMs = 0;    ///< the budget's spacing of running pictures at the end
    double pictureCostMs = 0; ///< the last running picture's cost the spacing follows
};

/// The same steps in the shown main window, as a user runs them (Start); with `overlays`, the
/// user has chosen strong force chains and void cells by valence in the scene's options bar.
WindowResult windowStepsPerSecond(const ExperimentConfig& config, const ResumePoint& resume,
                                  std::int64_t steps, bool overlays) {
    auto timing = std::make_shared<RunTiming>();
    ui::MainWindow window([&config, &resume, steps, timing](const ExperimentConfig&) {
        return std::make_unique<TimedRun>(ui::makeResumedExperimentRun(config, resume), steps,
                                          timing);
    });
    window.setExperiment(config);
    window.resize(1500, 950);
    window.show();
    waitUntilExposed(window);
    if (overlays) {
        window.sceneOptionsBar()->forceChainsBox()->setCurrentIndex(int(ui::ForceChains::Strong));
        window.sceneOptionsBar()->voidCellsBox()->setCurrentIndex(
            int(ui::VoidCellShading::Valence));
        QCoreApplication::processEvents();
    }
    const ui::SceneView::DrawingTime drawn0 = window.sceneView()->drawingTime();

    // The end of the run comes as the controller's state change, and the pictures are counted
    // by the scene: no timer of the bench's own wakes the GUI thread (each wake-up can take a
    // processor from one of the engine's threads, which the other then waits for).
    QEventLoop loop;
    QObject::connect(&window.controller(), &ui::SimulationController::stateChanged, &loop,
                     [&loop](ui::RunState state) {
                         if (state == ui::RunState::Finished || state == ui::RunState::Failed) {
                             loop.quit();
                         }
                     });
    const double guiCpu0 = threadCpuSeconds();
    window.startRun();
    const ui::RunState started = window.controller().status().state;
    if (started != ui::RunState::Finished && started != ui::RunState::Failed) {
        loop.exec();
    }
    const auto pictures = double(window.sceneView()->drawingTime().snapshots - drawn0.snapshots);
    const double guiCpu = threadCpuSeconds() - guiCpu0;
    const ui::RunStatus status = window.controller().status();
    if (status.state == ui::RunState::Failed) {
        throw std::runtime_error("bench --gui: the run failed: " + status.error);
    }
    WindowResult r;
    r.stepsPerSecond = double(timing->steps) / timing->seconds;
    r.picturesPerSecond = pictures / timing->seconds;
    r.engineCpuShare = timing->cpuSeconds / timing->seconds;
    r.guiCpuShare = guiCpu / timing->seconds;
    r.snapshotMs = status.runningPublications > 0
                       ? 1e3 * status.publishingSeconds / double(status.runningPublications)
                       : 0.0;
    r.publishingShare = status.publishingSeconds / timing->seconds;
    r.measureMs = 1e3 * status.measureSeconds;
    r.publications = status.publications;
    r.kept = window.controller().history().size();
    r.keptBytes = window.controller().history().bytes();
    r.openGL = window.sceneView()->usesOpenGL();
    const ui::SceneView::DrawingTime& drawn = window.sceneView()->drawingTime();
    const std::uint64_t prepared = drawn.snapshots - drawn0.snapshots;
    r.paints = drawn.paints - drawn0.paints;
    r.prepareMs = prepared > 0
                      ? 1e3 * (drawn.prepareSeconds - drawn0.prepareSeconds) / double(prepared)
                      : 0.0;
    r.paintMs =
        r.paints > 0 ? 1e3 * (drawn.paintSeconds - drawn0.paintSeconds) / double(r.paints) : 0.0;
    r.budgetShare = window.pictureBudget().share();
    r.intervalMs = window.pictureIntervalMs();
    r.pictureCostMs = window.pictureCostMs();
    return r;
}

/// One way of showing the window, measured in every round.
struct WindowVariant {
    std::string name;
    bool forceOpenGL = false;
    std::vector<double> stepsPerSecond, slowdown, pictures, engineCpu, guiCpu;
    WindowResult last;
};

void benchWindow(const BenchOptions& o, int threads) {
    const ExperimentConfig config = firstTestOf(o.experiment, threads);
    const ResumePoint resume = onOwnThread([&] { return shearStart(config); });
    const double pressure = config.shear.pressures.front();
    fmt::print("(a) engine speed, headless and in the live window\n");
    const char* shown =
        o.guiOverlays ? "the window showing strong force chains and void cells by valence over "
                        "the grains\n    coloured by size, the whole cell in view (--gui-overlays)"
                      : "the window with its default display options (colour by size,\n    no "
                        "force chains, no void cells)";
    fmt::print("    experiment \"{}\" ({}), {} grains, its first test (p = {:g} kPa) from the "
               "start of its shear,\n    {} steps per run, engine threads: at most {} ({} used), "
               "{} interleaved round(s); {}\n",
               config.name, o.experiment, config.assembly.grainCount, pressure / 1e3, o.guiSteps,
               threads, engineThreads(config), o.rounds, shown);
    // The window keeps QPainter where OpenGL is software (gui/main_window.cpp): measure the
    // OpenGL window too, to show why.
    std::vector<WindowVariant> variants(1);
    variants[0].name = "live window";
    if (ui::SceneView::openGLIsSoftware()) {
        fmt::print("    OpenGL here is drawn by the processor ({}): the window uses QPainter; "
                   "measured with OpenGL forced (GRAINLAB_OPENGL=1) too\n",
                   ui::SceneView::openGLRenderer().toStdString());
        variants.push_back({"window with software OpenGL", true, {}, {}, {}, {}, {}, {}});
    }
    std::fflush(stdout);
    std::vector<double> headless, headlessCpu;
    for (int round = 0; round < o.rounds; ++round) {
        fmt::print(stderr, "round {}/{}: headless\n", round + 1, o.rounds);
        const HeadlessResult alone =
            onOwnThread([&] { return headlessStepsPerSecond(config, resume, o.guiSteps); });
        headless.push_back(alone.stepsPerSecond);
        headlessCpu.push_back(alone.cpuShare);
        std::string line =
            fmt::format("    round {}: headless {:.0f} steps/s", round + 1, headless.back());
        for (WindowVariant& v : variants) {
            fmt::print(stderr, "round {}/{}: {}\n", round + 1, o.rounds, v.name);
            if (v.forceOpenGL) {
                qputenv("GRAINLAB_OPENGL", "1");
            }
            v.last = windowStepsPerSecond(config, resume, o.guiSteps, o.guiOverlays);
            qunsetenv("GRAINLAB_OPENGL");
            v.stepsPerSecond.push_back(v.last.stepsPerSecond);
            v.slowdown.push_back(1.0 - v.last.stepsPerSecond / headless.back());
            v.pictures.push_back(v.last.picturesPerSecond);
            v.engineCpu.push_back(v.last.engineCpuShare);
            v.guiCpu.push_back(v.last.guiCpuShare);
            line +=
                fmt::format(", {} {:.0f} steps/s ({:.1f} % slower, {:.1f} new pictures/s)", v.name,
                            v.stepsPerSecond.back(), 100.0 * v.slowdown.back(), v.pictures.back());
        }
        fmt::print("{}\n", line);
        std::fflush(stdout);
    }
    fmt::print("    engine steps/s headless: {:.0f} (median; engine thread on the processor {:.0f} "
               "% of the time)\n",
               median(headless), 100.0 * median(headlessCpu));
    for (const WindowVariant& v : variants) {
        fmt::print("    {}: scene drawn with {}: {:.0f} steps/s, slowdown {:.1f} % (medians of the "
                   "rounds; target <= 5 %)\n",
                   v.name, v.last.openGL ? "OpenGL" : "QPainter", median(v.stepsPerSecond),
                   100.0 * median(v.slowdown));
        fmt::print(
            "      {:.1f} new pictures/s, {} snapshots published (copied by the engine thread "
            "in {:.2f} ms on average, the last measured by the snapshot thread in {:.2f} ms; "
            "copies took {:.1f} % of the engine thread's time),\n      {} kept for chart "
            "hover ({:.1f} MB); on the processor: engine thread {:.0f} %, GUI thread "
            "{:.0f} % of the time\n",
            median(v.pictures), v.last.publications, v.last.snapshotMs, v.last.measureMs,
            100.0 * v.last.publishingShare, v.last.kept, double(v.last.keptBytes) / (1 << 20),
            100.0 * median(v.engineCpu), 100.0 * median(v.guiCpu));
        fmt::print(
            "      the scene on the GUI thread: {:.1f} ms a new picture ({:.1f} ms preparing "
            "the snapshot, {:.1f} ms painting, {} paints); picture budget {:.0f} % of a "
            "core ({} processors):\n      a new picture at most every {:.0f} ms at the "
            "last one's cost of {:.1f} ms (copy, measures, preparation and paint)\n",
            v.last.prepareMs + v.last.paintMs, v.last.prepareMs, v.last.paintMs, v.last.paints,
            100.0 * v.last.budgetShare, QThread::idealThreadCount(), v.last.intervalMs,
            v.last.pictureCostMs);
    }
    std::fflush(stdout);
}

// ---------------------------------------------------------------------------------------------
// (b) The scene's frame time

/// `grains` ovals (the reference study's widths) compacted at 100 kPa by the runner's
/// equilibrium rule (the shared scene), as a snapshot with contacts and void cells.
SnapshotPtr compactedOvals(int grains, std::uint64_t seed, int threads) {
    scenes::CompactedSceneSpec spec;
    spec.grains = grains;
    spec.aspectRatio = 0.6;
    spec.seed = seed;
    spec.friction = 0.3;
    spec.threads = threads;
    ProgressBar bar(fmt::format("compacting {} ovals for the scene", grains));
    scenes::CompactedScene scene =
        scenes::compactScene(spec, [&](const scenes::CompactionProgress& p) {
            bar.update(double(p.step) / p.maxSteps,
                       fmt::format("p error {:.1f} % I_uf {:.2f} %", 100 * p.check.stressError,
                                   p.check.unbalancedForce));
        });
    bar.finish();
    auto s = std::make_shared<Snapshot>();
    fillSnapshotScene(*s, scene.simulation, scene.initialTheta);
    s->stage = "compaction 100 kPa";
    s->test = "compaction";
    return s;
}

struct FrameTimes {
    double wholeMs = 0;  ///< the whole cell in view
    double zoomedMs = 0; ///< zoomed x8 about the centre
};

constexpr int kFrames = 10;
const QSize kViewport(1000, 1000);

FrameTimes painterFrameTimes(const SnapshotPtr& s, const ui::SceneOptions& options,
                             double* prepareMs) {
    ui::SceneRenderer r;
    auto t0 = Clock::now();
    r.setSnapshot(s);
    *prepareMs = 1e3 * secondsSince(t0);
    r.options() = options;
    r.fitToCell(kViewport);
    QImage image(kViewport, QImage::Format_ARGB32_Premultiplied);
    auto frameMs = [&] {
        QPainter painter(&image);
        r.render(painter, kViewport); // warm-up
        const auto start = Clock::now();
        for (int k = 0; k < kFrames; ++k) {
            r.render(painter, kViewport);
        }
        return 1e3 * secondsSince(start) / kFrames;
    };
    FrameTimes t;
    t.wholeMs = frameMs();
    r.view().zoomAt(QPointF(kViewport.width() / 2.0, kViewport.height() / 2.0), 8.0);
    t.zoomedMs = frameMs();
    return t;
}

struct GlFrameTimes {
    FrameTimes times;
    QString renderer; ///< GL_RENDERER and GL_VERSION
    QString failure;  ///< why there are no times
};

GlFrameTimes openGLFrameTimes(const SnapshotPtr& s, const ui::SceneOptions& options) {
    GlFrameTimes out;
    if (!ui::SceneView::openGLAvailable()) {
        out.failure = QStringLiteral("the %1 platform has no OpenGL 3.3")
                          .arg(QGuiApplication::platformName());
        return out;
    }
    ui::SceneView view;
    view.resize(kViewport);
    if (!view.setUseOpenGL(true)) {
        out.failure = QStringLiteral("the OpenGL view could not be created");
        return out;
    }
    view.setOptions(options);
    view.show();
    waitUntilExposed(view);
    view.setSnapshot(s);
    ui::GlSceneLayer* gl = view.glLayer();
    gl->grabFramebuffer(); // builds the shaders
    if (!gl->shadersReady()) {
        out.failure = QStringLiteral("the shaders failed: %1").arg(gl->failure());
        return out;
    }
    gl->makeCurrent();
    QOpenGLFunctions* f = QOpenGLContext::currentContext()->functions();
    out.renderer = QStringLiteral("%1; OpenGL %2")
                       .arg(reinterpret_cast<const char*>(f->glGetString(GL_RENDERER)),
                            reinterpret_cast<const char*>(f->glGetString(GL_VERSION)));
    gl->doneCurrent();
    auto frameMs = [&] {
        gl->grabFramebuffer(); // warm-up
        const auto start = Clock::now();
        for (int k = 0; k < kFrames; ++k) {
            gl->grabFramebuffer();
        }
        return 1e3 * secondsSince(start) / kFrames;
    };
    out.times.wholeMs = frameMs();
    view.renderer().view().zoomAt(QPointF(kViewport.width() / 2.0, kViewport.height() / 2.0), 8.0);
    out.times.zoomedMs = frameMs();
    return out;
}

void benchScene(const BenchOptions& o, int threads) {
    const SnapshotPtr s = compactedOvals(o.grains, o.seed, threads);
    ui::SceneOptions options;
    options.forceChains = ui::ForceChains::Strong;
    options.voidCells = ui::VoidCellShading::Valence;
    fmt::print("\n(b) scene frame time: {} ovals compacted at 100 kPa (Z = {:.2f}, {} contacts, "
               "{} void cells),\n    strong force chains and void cells by valence, {} x {} "
               "pixels, mean of {} frames\n",
               s->x1.size(), 2.0 * double(s->network.contacts.size()) / double(s->x1.size()),
               s->network.contacts.size(), s->voidCells.size(), kViewport.width(),
               kViewport.height(), kFrames);
    std::fflush(stdout);
    double prepareMs = 0;
    const FrameTimes painter = painterFrameTimes(s, options, &prepareMs);
    fmt::print("    new snapshot: {:.1f} ms to prepare for drawing (once per new picture)\n",
               prepareMs);
    fmt::print("    QPainter renderer (raster image): whole cell {:.1f} ms ({:.1f} frames/s), "
               "zoomed x8 {:.1f} ms ({:.1f} frames/s)\n",
               painter.wholeMs, 1e3 / painter.wholeMs, painter.zoomedMs, 1e3 / painter.zoomedMs);
    // The same picture without the overview (SceneOptions::overviewHalfWidth), every grain and
    // void cell drawn through QPainter: what the overview saves, measured in the same run.
    ui::SceneOptions fullDetail = options;
    fullDetail.overviewHalfWidth = 0.0;
    const FrameTimes full = painterFrameTimes(s, fullDetail, &prepareMs);
    fmt::print(
        "    QPainter renderer without the overview (every shape through QPainter): whole cell "
        "{:.1f} ms ({:.1f} frames/s); the overview draws it {:.2f}x faster\n",
        full.wholeMs, 1e3 / full.wholeMs, full.wholeMs / painter.wholeMs);
    const FrameTimes grainsOnly = painterFrameTimes(s, ui::SceneOptions{}, &prepareMs);
    fmt::print("    QPainter renderer, the window's default options (grains coloured by size, no "
               "overlays): whole cell {:.1f} ms ({:.1f} frames/s), zoomed x8 {:.1f} ms ({:.1f} "
               "frames/s)\n",
               grainsOnly.wholeMs, 1e3 / grainsOnly.wholeMs, grainsOnly.zoomedMs,
               1e3 / grainsOnly.zoomedMs);
    ui::SceneOptions voidsOnly, chainsOnly;
    voidsOnly.voidCells = options.voidCells;
    chainsOnly.forceChains = options.forceChains;
    const FrameTimes withVoids = painterFrameTimes(s, voidsOnly, &prepareMs);
    const FrameTimes withChains = painterFrameTimes(s, chainsOnly, &prepareMs);
    fmt::print("    QPainter renderer, one overlay over the grains, whole cell: void cells {:.1f} "
               "ms, strong force chains {:.1f} ms\n",
               withVoids.wholeMs, withChains.wholeMs);
    std::fflush(stdout);
    const GlFrameTimes gl = openGLFrameTimes(s, options);
    if (!gl.failure.isEmpty()) {
        fmt::print("    OpenGL view: skipped: {}\n", gl.failure.toStdString());
    } else {
        fmt::print("    OpenGL view ({}): whole cell {:.1f} ms ({:.1f} frames/s), zoomed x8 "
                   "{:.1f} ms ({:.1f} frames/s), each including the read-back of the frame\n",
                   gl.renderer.toStdString(), gl.times.wholeMs, 1e3 / gl.times.wholeMs,
                   gl.times.zoomedMs, 1e3 / gl.times.zoomedMs);
    }
    std::fflush(stdout);
}

} // namespace

int runGuiBench(const BenchOptions& o) {
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM") && qEnvironmentVariableIsEmpty("DISPLAY") &&
        qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY")) {
        qputenv("QT_QPA_PLATFORM", "offscreen");
        fmt::print(stderr, "bench --gui: no display, using Qt's offscreen platform (no OpenGL; "
                           "run it under xvfb-run -a for the OpenGL view)\n");
    }
    int argc = 1;
    char name[] = "grainlab";
    char* argv[] = {name, nullptr};
    QApplication app(argc, argv);
    const int threads = std::max(1, std::atoi(o.threads.c_str()));
    fmt::print("grainlab bench --gui: Qt {}, platform {}, {} processors, load average {:.2f} "
               "before the start\n\n",
               qVersion(), QGuiApplication::platformName().toStdString(),
               std::thread::hardware_concurrency(), loadAverage());
    std::fflush(stdout);
    benchWindow(o, threads);
    benchScene(o, threads);
    return 0;
}

} // namespace grainlab
