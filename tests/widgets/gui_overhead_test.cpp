// What the live window costs the engine (issue 5: at most 10 % of its headless speed): the quick
// experiment's first 60 000 steps headless, then the same steps in the shown main window (worker
// thread publishing snapshots, GUI thread drawing scene and charts). Prints both speeds and
// checks the target; docs/user-guide.md quotes the measured figure. Opt-in
// (GRAINLAB_MEASURE_GUI_OVERHEAD=1): it takes about 40 s and needs an otherwise idle machine to
// mean anything.
#include <chrono>
#include <cstdio>

#include <QTest>

#include <gtest/gtest.h>

#include "grainlab/experiment_file.h"
#include "grainlab/ui/scene_view.h"
#include "gui_main_window.h"

namespace grainlab::ui {
namespace {

constexpr std::int64_t kSteps = 60000;

ExperimentConfig quick() {
    ExperimentConfig c =
        readExperimentFile(GRAINLAB_SOURCE_DIR "/resources/experiments/quick.json");
    c.parameters.threads = 1; // leave a core for the GUI thread
    return c;
}

double seconds(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

TEST(GuiOverhead, LiveWindowCostsTheEngineLittle) {
    if (qEnvironmentVariable("GRAINLAB_MEASURE_GUI_OVERHEAD") != QLatin1String("1")) {
        GTEST_SKIP() << "a 40 s timing run: set GRAINLAB_MEASURE_GUI_OVERHEAD=1 to measure";
    }
    const ExperimentConfig config = quick();
    double headless = 0;
    {
        ExperimentRunner runner(config);
        const auto t0 = std::chrono::steady_clock::now();
        for (std::int64_t done = 0; done < kSteps; done += 1000) {
            runner.advance(1000);
        }
        headless = seconds(t0);
    }
    MainWindow window;
    window.setExperiment(config);
    window.resize(1400, 900);
    window.show();
    QTest::qWait(50);
    int frames = 0;
    const auto t0 = std::chrono::steady_clock::now();
    window.startRun();
    std::uint64_t shown = 0;
    while (window.controller().status().stepsDone < kSteps && seconds(t0) < 300) {
        QTest::qWait(1);
        const auto s = window.sceneView()->snapshot();
        if (s && reinterpret_cast<std::uintptr_t>(s.get()) != shown) {
            shown = reinterpret_cast<std::uintptr_t>(s.get());
            ++frames;
        }
    }
    const double live = seconds(t0);
    const std::int64_t steps = window.controller().status().stepsDone;
    std::printf("[ gui overhead ] %llu snapshots published, the last built in %.2f ms\n",
                static_cast<unsigned long long>(window.controller().status().publications),
                1e3 * window.controller().status().snapshotSeconds);
    window.stopRun();
    const double headlessRate = double(kSteps) / headless;
    const double liveRate = double(steps) / live;
    const double slowdown = 1.0 - liveRate / headlessRate;
    std::printf(
        "[ gui overhead ] headless %.0f steps/s, live window %.0f steps/s (%.1f %% slower), "
        "%d new scenes drawn (%.1f per second)\n",
        headlessRate, liveRate, 100.0 * slowdown, frames, frames / live);
    ::testing::Test::RecordProperty("headless_steps_per_s", std::to_string(headlessRate));
    ::testing::Test::RecordProperty("live_steps_per_s", std::to_string(liveRate));
    EXPECT_LT(slowdown, 0.10);
    EXPECT_GT(frames / live, 5.0);
}

} // namespace
} // namespace grainlab::ui
