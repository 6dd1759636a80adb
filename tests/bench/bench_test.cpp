// `grainlab bench --gui` (app/bench/window_bench.h) runs to the end and prints its figures (what
// it measures is not checked here: speed figures belong in the benchmark's output, not in
// tests). The LAMMPS data reader is tested in lammps_peer_test.cpp.
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace grainlab {
namespace {

/// Runs `command` through the shell; its exit code and standard output.
std::pair<int, std::string> runCapturing(const std::string& command) {
    FILE* pipe = popen(command.c_str(), "r");
    if (pipe == nullptr) {
        return {-1, {}};
    }
    std::string out;
    char buffer[4096];
    std::size_t n = 0;
    while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) {
        out.append(buffer, n);
    }
    const int status = pclose(pipe);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

/// `grainlab bench --gui` on a tiny experiment (120 grains), 400 steps, one round, a scene of
/// 150 ovals, with `prefix` before the command (the platform) and `options` after it.
std::pair<int, std::string> runTinyGuiBench(const std::string& prefix,
                                            const std::string& options = "") {
    std::ifstream quick(std::string(GRAINLAB_SOURCE_DIR) + "/resources/experiments/quick.json");
    std::stringstream text;
    text << quick.rdbuf();
    nlohmann::json j = nlohmann::json::parse(text.str());
    j["name"] = "tiny";
    j["grains"]["count"] = 120;
    const std::string path = testing::TempDir() + "grainlab_gui_bench_tiny.json";
    std::ofstream(path) << j.dump(2);
    return runCapturing(fmt::format("{} {} bench --gui --gui-steps 400 --rounds 1 --grains 150 "
                                    "--experiment {} {} 2>/dev/null",
                                    prefix, GRAINLAB_EXE, path, options));
}

TEST(GuiBench, RunsOffscreenAndPrintsEveryFigure) {
    const auto [code, out] = runTinyGuiBench("QT_QPA_PLATFORM=offscreen");
#ifdef GRAINLAB_WITH_GUI
    ASSERT_EQ(code, 0) << out;
    for (const char* expected : {"platform offscreen",
                                 "(a) engine speed, headless and in the live window",
                                 "\"tiny\"",
                                 "120 grains",
                                 "400 steps per run",
                                 "round 1: headless",
                                 "engine steps/s headless:",
                                 "the window with its default display options",
                                 "live window: scene drawn with QPainter:",
                                 "slowdown",
                                 "kept for chart hover",
                                 "the scene on the GUI thread:",
                                 "picture budget",
                                 "a new picture at most every",
                                 "measured by the snapshot thread in",
                                 "of the engine thread's time",
                                 "(b) scene frame time: 150 ovals",
                                 "QPainter renderer (raster image): whole cell",
                                 "QPainter renderer, the window's default options",
                                 "one overlay over the grains, whole cell: void cells",
                                 "OpenGL view: skipped: the offscreen platform has no OpenGL"}) {
        EXPECT_NE(out.find(expected), std::string::npos) << expected << " in\n" << out;
    }
#else
    EXPECT_EQ(code, 2) << out; // built without the window: refused with a message
#endif
}

#ifdef GRAINLAB_WITH_GUI
TEST(GuiBench, ShowsForceChainsAndVoidCellsInTheWindowWithGuiOverlays) {
    const auto [code, out] = runTinyGuiBench("QT_QPA_PLATFORM=offscreen", "--gui-overlays");
    ASSERT_EQ(code, 0) << out;
    for (const char* expected : {"the window showing strong force chains and void cells by valence",
                                 "(--gui-overlays)", "live window: scene drawn with QPainter:",
                                 "the scene on the GUI thread:", "ms painting", "picture budget"}) {
        EXPECT_NE(out.find(expected), std::string::npos) << expected << " in\n" << out;
    }
    EXPECT_EQ(out.find("the window with its default display options"), std::string::npos) << out;
}

TEST(GuiBench, GuiOverlaysWithoutGuiIsRefused) {
    const auto [code, out] =
        runCapturing(fmt::format("{} bench --gui-overlays 2>&1", GRAINLAB_EXE));
    EXPECT_EQ(code, 2) << out;
    EXPECT_NE(out.find("--gui-overlays belongs to the window bench: add --gui"), std::string::npos)
        << out;
}

TEST(GuiBench, RunsTheOpenGLViewUnderAVirtualXServer) {
    if (std::system("command -v xvfb-run > /dev/null 2>&1") != 0) {
        GTEST_SKIP() << "xvfb-run is not installed";
    }
    // The virtual X server's child must not inherit a caller's QT_QPA_PLATFORM (offscreen).
    const auto [code, out] = runTinyGuiBench("env -u QT_QPA_PLATFORM xvfb-run -a");
    ASSERT_EQ(code, 0) << out;
    EXPECT_NE(out.find("platform xcb"), std::string::npos) << out;
    // Xvfb's OpenGL is Mesa's software rasteriser: the window keeps QPainter, and the bench
    // measures the window with OpenGL forced as well.
    EXPECT_NE(out.find("live window: scene drawn with QPainter:"), std::string::npos) << out;
    EXPECT_NE(out.find("window with software OpenGL: scene drawn with OpenGL:"), std::string::npos)
        << out;
    EXPECT_NE(out.find("OpenGL view ("), std::string::npos) << out;
    EXPECT_NE(out.find("each including the read-back"), std::string::npos) << out;
}
#endif

} // namespace
} // namespace grainlab
