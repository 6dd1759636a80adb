// The OpenGL layer draws the same grains as the QPainter renderer: grain colour at every grain
// centre, the cell fill far from every grain. Runs where OpenGL 3.3 exists (e.g. under
// `xvfb-run`); skipped on the offscreen platform, which has none. Its frame time is measured
// by `grainlab bench --gui` (app/bench/window_bench.h), not here.
#include <cmath>

#include <QDir>
#include <QTest>

#include <gtest/gtest.h>

#include "grainlab/ui/gl_scene_layer.h"
#include "grainlab/ui/scene_view.h"
#include "overlay_points.h"
#include "test_scenes.h"

namespace grainlab::ui {
namespace {

bool near(QRgb a, const QColor& b, int tolerance = 3) {
    return std::abs(qRed(a) - b.red()) <= tolerance &&
           std::abs(qGreen(a) - b.green()) <= tolerance &&
           std::abs(qBlue(a) - b.blue()) <= tolerance;
}

/// Under the virtual X server of the test suite OpenGL must be there: a skip would hide a
/// broken GL view (tests/CMakeLists.txt sets GRAINLAB_REQUIRE_OPENGL there).
bool openGLRequired() {
    return qEnvironmentVariableIsSet("GRAINLAB_REQUIRE_OPENGL");
}

TEST(GlSceneLayer, DrawsGrainsWhereTheSnapshotHasThem) {
    ASSERT_TRUE(SceneView::openGLAvailable() || !openGLRequired()) << "no OpenGL under xvfb";
    if (!SceneView::openGLAvailable()) {
        GTEST_SKIP() << "no OpenGL 3.3 on platform "
                     << QGuiApplication::platformName().toStdString();
    }
    const SnapshotPtr s = testing::makeCompactedSnapshot();
    SceneView view;
    view.resize(700, 700);
    ASSERT_TRUE(view.setUseOpenGL(true));
    SceneOptions options = view.renderer().options();
    options.caption = options.scaleBar = false;
    options.periodicImages = true;
    view.setOptions(options);
    view.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&view));
    view.setSnapshot(s);
    const std::uint64_t paints = view.drawingTime().paints;
    const QImage image = view.glLayer()->grabFramebuffer();
    ASSERT_TRUE(view.glLayer()->shadersReady()) << view.glLayer()->failure().toStdString();
    // The layer's frame counts as the view's paint, for the window's picture budget.
    EXPECT_GT(view.drawingTime().paints, paints);
    EXPECT_GT(view.drawingTime().paintMs, 0.0);
    const SceneRenderer& r = view.renderer();
    for (std::size_t g = 0; g < s->x1.size(); ++g) {
        const QPoint p = r.view().toScreen(s->x1[g], s->x2[g]).toPoint();
        EXPECT_TRUE(near(image.pixel(p), r.grainColour(static_cast<int>(g)))) << "grain " << g;
    }
    // Far from every grain and image: the cell fill. Inside a grain, near its outline: grain.
    const CellMatrix& h = s->network.cell;
    const double pixel = 1.0 / r.view().pixelsPerMetre();
    int empty = 0, agree = 0, total = 0;
    const QImage painted = view.renderImage();
    QDir().mkpath(QStringLiteral("test-images"));
    image.save(QStringLiteral("test-images/gl-layer.png"));
    painted.save(QStringLiteral("test-images/gl-layer-qpainter.png"));
    for (int i = 1; i < 60; ++i) {
        for (int j = 1; j < 60; ++j) {
            const double w1 = h[0] * i / 60.0 + h[2] * j / 60.0;
            const double w2 = h[1] * i / 60.0 + h[3] * j / 60.0;
            bool free = true;
            for (std::size_t g = 0; g < s->x1.size() && free; ++g) {
                for (int a = -1; a <= 1 && free; ++a) {
                    for (int b = -1; b <= 1 && free; ++b) {
                        free = std::hypot(w1 - s->x1[g] - h[0] * a - h[2] * b,
                                          w2 - s->x2[g] - h[1] * a - h[3] * b) >
                               s->shapes[s->shape[g]].halfWidth + 2.0 * pixel;
                    }
                }
            }
            const QPoint p = r.view().toScreen(w1, w2).toPoint();
            if (free) {
                ++empty;
                EXPECT_TRUE(near(image.pixel(p), r.options().cellFill)) << p.x() << "," << p.y();
            }
            // Both views agree (within antialiasing) at most sample points.
            ++total;
            agree += near(image.pixel(p), QColor(painted.pixel(p)), 40);
        }
    }
    EXPECT_GT(empty, 10);
    EXPECT_GT(agree, 0.97 * total);
}

TEST(GlSceneLayer, DrawsVoidCellsAndForceChainsWithTheirColours) {
    // The OpenGL layer draws void cells as triangles and force chains as instanced quads: each
    // cell's fill over the grains below it, each strong chain's colour, as the QPainter view.
    ASSERT_TRUE(SceneView::openGLAvailable() || !openGLRequired()) << "no OpenGL under xvfb";
    if (!SceneView::openGLAvailable()) {
        GTEST_SKIP() << "no OpenGL 3.3 on platform "
                     << QGuiApplication::platformName().toStdString();
    }
    const QSize size(700, 700);
    SceneView view;
    view.resize(size);
    ASSERT_TRUE(view.setUseOpenGL(true));
    SceneOptions options = view.renderer().options();
    options.caption = options.scaleBar = false;
    view.setOptions(options);
    view.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&view));
    view.setSnapshot(testing::makeCompactedSnapshot());
    const QImage below = view.glLayer()->grabFramebuffer();
    ASSERT_TRUE(view.glLayer()->shadersReady()) << view.glLayer()->failure().toStdString();
    const SceneRenderer& r = view.renderer();

    options.voidCells = VoidCellShading::Valence;
    view.setOptions(options);
    const QImage shaded = view.glLayer()->grabFramebuffer();
    const auto cells = testing::voidCellCentroids(r, size);
    EXPECT_GT(cells.size(), r.snapshot()->voidCells.size() / 3);
    for (const auto& [cell, pixel] : cells) {
        EXPECT_TRUE(
            near(shaded.pixel(pixel), testing::blended(r.voidCellColour(cell), below.pixel(pixel))))
            << "void cell " << cell << " at " << pixel.x() << "," << pixel.y();
    }

    options.voidCells = VoidCellShading::Off;
    options.forceChains = ForceChains::Strong;
    view.setOptions(options);
    const QImage chains = view.glLayer()->grabFramebuffer();
    const auto midpoints = testing::strongChainMidpoints(r, size);
    EXPECT_GT(midpoints.size(), 20u);
    for (const auto& [force, pixel] : midpoints) {
        EXPECT_TRUE(near(chains.pixel(pixel), r.forceChainColour(force)))
            << "chain of " << force << " N at " << pixel.x() << "," << pixel.y();
    }

    // Everything together, for a look by hand next to the QPainter picture.
    options.voidCells = VoidCellShading::Valence;
    options.periodicImages = true;
    options.selectedVoidCell = 3;
    view.setOptions(options);
    view.fitToCell();
    QDir().mkpath(QStringLiteral("test-images"));
    view.glLayer()->grabFramebuffer().save(QStringLiteral("test-images/gl-overlays.png"));
    view.renderImage().save(QStringLiteral("test-images/gl-overlays-qpainter.png"));
}

} // namespace
} // namespace grainlab::ui
