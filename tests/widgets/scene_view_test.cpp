// The scene view driven with QTest: a click at a void cell's centroid selects it and the
// inspector shows its valence and area; a click at a grain centre selects the grain; the wheel
// zooms about the cursor and keys pan; the widget paints what the renderer paints.
#include <QGuiApplication>
#include <QSignalSpy>
#include <QTest>

#include <gtest/gtest.h>

#include "grainlab/ui/inspector_panel.h"
#include "grainlab/ui/scene_view.h"
#include "test_scenes.h"

namespace grainlab::ui {
namespace {

const SnapshotPtr& scene() {
    static const SnapshotPtr s = testing::makeCompactedSnapshot();
    return s;
}

struct Window {
    SceneView view;
    InspectorPanel inspector;
    Window() {
        view.resize(600, 600);
        QObject::connect(&view, &SceneView::voidCellClicked, &inspector,
                         [this](int v) { inspector.showVoidCell(view.snapshot(), v); });
        QObject::connect(&view, &SceneView::grainClicked, &inspector,
                         [this](int g) { inspector.showGrain(view.snapshot(), g); });
        view.show();
        view.setSnapshot(scene());
    }
};

TEST(SceneView, ClickAtVoidCellCentroidShowsItInTheInspector) {
    Window w;
    SceneOptions options = w.view.renderer().options();
    options.voidCells = VoidCellShading::Valence;
    w.view.setOptions(options);
    const Snapshot& s = *scene();
    // The largest cell: its centroid lies well inside its polygon.
    int chosen = 0;
    for (std::size_t v = 0; v < s.voidCells.size(); ++v) {
        if (s.voidCells[v].area > s.voidCells[chosen].area) {
            chosen = static_cast<int>(v);
        }
    }
    const VoidCellView& cell = s.voidCells[chosen];
    QSignalSpy spy(&w.view, &SceneView::voidCellClicked);
    QTest::mouseClick(&w.view, Qt::LeftButton, Qt::NoModifier,
                      w.view.toWidget(cell.centroid1, cell.centroid2));
    ASSERT_EQ(spy.count(), 1);
    EXPECT_EQ(spy.front().front().toInt(), chosen);
    EXPECT_EQ(w.inspector.title(), QStringLiteral("Void cell %1").arg(chosen));
    EXPECT_EQ(w.inspector.value(QStringLiteral("valence")), QString::number(cell.valence));
    EXPECT_EQ(w.inspector.value(QStringLiteral("area [mm²]")),
              QString::number(cell.area * 1e6, 'g', 4));
    EXPECT_FALSE(w.inspector.value(QStringLiteral("elongation [-]")).isEmpty());
    EXPECT_EQ(w.view.renderer().options().selectedVoidCell, chosen);

    // The highlight is drawn: the pixel at the centroid changed colour.
    const QImage selected = w.view.renderImage();
    w.view.selectVoidCell(-1);
    const QImage unselected = w.view.renderImage();
    const QPoint c = w.view.toWidget(cell.centroid1, cell.centroid2);
    EXPECT_NE(selected.pixel(c), unselected.pixel(c));
}

TEST(SceneView, ClickOnGrainShowsItsContacts) {
    Window w;
    const Snapshot& s = *scene();
    const int grain = 17;
    QTest::mouseClick(&w.view, Qt::LeftButton, Qt::NoModifier,
                      w.view.toWidget(s.x1[grain], s.x2[grain]));
    EXPECT_EQ(w.inspector.title(), QStringLiteral("Grain %1").arg(grain));
    int contacts = 0;
    for (const auto& c : s.network.contacts) {
        contacts += (c.first == grain) + (c.second == grain);
    }
    EXPECT_EQ(w.inspector.value(QStringLiteral("contacts")), QString::number(contacts));
    EXPECT_FALSE(w.inspector.value(QStringLiteral("sliding contacts")).isEmpty());
}

TEST(SceneView, WheelZoomsAboutTheCursorAndKeysPan) {
    Window w;
    const QPoint cursor(200, 250);
    const auto before = w.view.renderer().view().toWorld(cursor);
    const double scale = w.view.renderer().view().pixelsPerMetre();
    QWheelEvent wheel(QPointF(cursor), w.view.mapToGlobal(QPointF(cursor)), QPoint(),
                      QPoint(0, 120), Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(&w.view, &wheel);
    EXPECT_NEAR(w.view.renderer().view().pixelsPerMetre(), 1.25 * scale, 1e-9 * scale);
    const auto after = w.view.renderer().view().toWorld(cursor);
    EXPECT_NEAR(after[0], before[0], 1e-12);
    EXPECT_NEAR(after[1], before[1], 1e-12);
    const QPointF origin = w.view.renderer().view().toScreen(0, 0);
    QTest::keyClick(&w.view, Qt::Key_Left);
    EXPECT_GT(w.view.renderer().view().toScreen(0, 0).x(), origin.x());
    QTest::keyClick(&w.view, Qt::Key_Minus);
    EXPECT_LT(w.view.renderer().view().pixelsPerMetre(), 1.25 * scale);
    // A new snapshot keeps the user's view.
    const double zoomed = w.view.renderer().view().pixelsPerMetre();
    w.view.setSnapshot(scene());
    EXPECT_EQ(w.view.renderer().view().pixelsPerMetre(), zoomed);
    QTest::keyClick(&w.view, Qt::Key_0);
    EXPECT_NEAR(w.view.renderer().view().pixelsPerMetre(), scale, 1e-9 * scale);
}

TEST(SceneView, WidgetPaintsTheScene) {
    Window w;
    const QImage grabbed = w.view.grab().toImage();
    const QImage rendered = w.view.renderImage();
    const Snapshot& s = *scene();
    const QPoint p = w.view.toWidget(s.x1[0], s.x2[0]);
    EXPECT_EQ(QColor(grabbed.pixel(p)).rgb(), QColor(rendered.pixel(p)).rgb());
    EXPECT_EQ(QColor(grabbed.pixel(p)).rgb(), w.view.renderer().grainColour(0).rgb());
}

TEST(SceneView, TimesEachNewSnapshotAndEachPaintOfTheWholeView) {
    Window w;
    const SceneView::DrawingTime before = w.view.drawingTime();
    EXPECT_EQ(before.snapshots, 1u); // the fixture's snapshot
    EXPECT_GT(before.prepareMs, 0.0);
    w.view.setSnapshot(testing::unmeasuredCopy(*scene()));
    EXPECT_EQ(w.view.drawingTime().snapshots, 2u);
    EXPECT_GT(w.view.drawingTime().prepareSeconds, before.prepareSeconds);
    w.view.setSnapshot(nullptr); // clearing the scene prepares nothing
    EXPECT_EQ(w.view.drawingTime().snapshots, 2u);
    w.view.setSnapshot(scene());

    const std::uint64_t paints = w.view.drawingTime().paints;
    const QImage grabbed = w.view.grab().toImage(); // a paint of the whole view
    const SceneView::DrawingTime whole = w.view.drawingTime();
    EXPECT_EQ(whole.paints, paints + 1);
    EXPECT_GT(whole.paintMs, 0.0);
    EXPECT_FALSE(grabbed.isNull());
    EXPECT_DOUBLE_EQ(w.view.pictureMs(), whole.prepareMs + whole.paintMs);
    // A clipped paint of a corner says nothing about the next picture: not counted.
    QImage corner(20, 20, QImage::Format_ARGB32_Premultiplied);
    w.view.render(&corner, QPoint(), QRegion(0, 0, 20, 20));
    EXPECT_EQ(w.view.drawingTime().paints, paints + 1);
    EXPECT_EQ(w.view.drawingTime().paintMs, whole.paintMs);
}

TEST(SceneView, TellsASoftwareOpenGLRendererFromAGraphicsCard) {
    if (!SceneView::openGLAvailable()) {
        EXPECT_TRUE(SceneView::openGLRenderer().isEmpty());
        EXPECT_FALSE(SceneView::openGLIsSoftware());
        GTEST_SKIP() << "no OpenGL on platform " << QGuiApplication::platformName().toStdString();
    }
    const QString renderer = SceneView::openGLRenderer();
    EXPECT_FALSE(renderer.isEmpty());
    // The suite's virtual X server (tests/CMakeLists.txt) has Mesa's software rasteriser.
    if (qEnvironmentVariableIsSet("GRAINLAB_REQUIRE_OPENGL")) {
        EXPECT_TRUE(SceneView::openGLIsSoftware()) << renderer.toStdString();
    }
}

} // namespace
} // namespace grainlab::ui
