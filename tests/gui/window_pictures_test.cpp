// The main window's pictures of a running run (app/gui/picture_budget.h): with strong force
// chains and void cells shown, new pictures of later steps keep coming; a budget that binds
// spaces them (and the controller publishes no more often), while zooming redraws at once and a
// paused run's picture is shown at once.
#include <cstdint>
#include <vector>

#include <QApplication>
#include <QComboBox>
#include <QElapsedTimer>
#include <QImage>
#include <QTest>
#include <QThread>
#include <QWheelEvent>

#include <gtest/gtest.h>

#include "grainlab/experiment_runner.h"
#include "grainlab/ui/scene_options_bar.h"
#include "grainlab/ui/scene_view.h"
#include "gui/main_window.h"
#include "gui/picture_budget.h"
#include "window_test_support.h"

namespace grainlab::ui {
namespace {

using namespace window_tests;

/// Pixels that differ between two images of the same size.
int differingPixels(const QImage& a, const QImage& b) {
    int n = 0;
    for (int y = 0; y < a.height(); ++y) {
        for (int x = 0; x < a.width(); ++x) {
            n += a.pixel(x, y) != b.pixel(x, y);
        }
    }
    return n;
}

bool stillRunning(MainWindow& w) {
    return w.controller().status().state == RunState::Running;
}

TEST(WindowPictures, GrainlabPictureShareReplacesTheRuleAndNonsenseIsRefused) {
    struct Unset {
        ~Unset() { qunsetenv("GRAINLAB_PICTURE_SHARE"); }
    } unset; // also when an assertion ends the test
    qputenv("GRAINLAB_PICTURE_SHARE", "0.2");
    {
        MainWindow w;
        EXPECT_DOUBLE_EQ(w.pictureBudget().share(), 0.2);
        // It holds for the runs started here, whatever their engine threads.
        w.setExperiment(smallExperiment(0.01));
        click(w, w.startAction());
        ASSERT_TRUE(waitFor([&] { return w.controller().status().state != RunState::Idle; }));
        EXPECT_DOUBLE_EQ(w.pictureBudget().share(), 0.2);
    }
    for (const char* bad : {"0", "1.5", "-0.1", "lots"}) {
        qputenv("GRAINLAB_PICTURE_SHARE", bad);
        MainWindow w;
        w.setExperiment(smallExperiment(0.01));
        click(w, w.startAction());
        ASSERT_TRUE(waitFor([&] { return w.controller().status().state != RunState::Idle; }));
        EXPECT_DOUBLE_EQ(w.pictureBudget().share(),
                         PictureBudget::shareFor(smallExperiment(0.01).parameters.threads,
                                                 QThread::idealThreadCount()))
            << bad;
    }
}

TEST(WindowPictures, NewPicturesKeepComingWhileRunningWithForceChainsAndVoidCells) {
    const ExperimentConfig config = smallExperiment(0.3); // runs for a while
    MainWindow w;
    showWith(w, config);
    w.sceneOptionsBar()->forceChainsBox()->setCurrentIndex(int(ForceChains::Strong));
    w.sceneOptionsBar()->voidCellsBox()->setCurrentIndex(int(VoidCellShading::Valence));
    const std::uint64_t paints = w.sceneView()->drawingTime().paints;
    click(w, w.startAction());
    ASSERT_TRUE(waitFor([&] { return stillRunning(w); }));

    // Five new pictures with void cells to draw (the loose start of the compaction has no
    // contacts, hence none).
    std::vector<SnapshotPtr> pictures;
    std::vector<QImage> images;
    SnapshotPtr last;
    ASSERT_TRUE(waitFor([&] {
        const SnapshotPtr s = w.sceneView()->snapshot();
        if (s && s != last && stillRunning(w)) {
            last = s;
            // Every running picture was measured by the snapshot thread before it was shown.
            EXPECT_TRUE(s->measured) << "step " << s->step;
            if (!s->voidCells.empty()) {
                pictures.push_back(s);
                images.push_back(w.sceneView()->renderImage());
            }
        }
        return pictures.size() >= 5 || !stillRunning(w);
    }));
    ASSERT_EQ(pictures.size(), 5u) << "the run stopped running: " << w.controller().status().error;
    for (std::size_t k = 1; k < pictures.size(); ++k) {
        EXPECT_GT(pictures[k]->step, pictures[k - 1]->step);
    }
    // What is drawn changes from picture to picture.
    EXPECT_GT(differingPixels(images.front(), images.back()), 100);
    // They were painted, and the budget knows what a picture costs.
    EXPECT_GE(w.sceneView()->drawingTime().paints, paints + 4);
    EXPECT_GT(w.sceneView()->pictureMs(), 0.0);
    EXPECT_GT(w.pictureCostMs(), 0.0);
    EXPECT_GE(w.pictureIntervalMs(), 33.0);
    EXPECT_DOUBLE_EQ(w.pictureBudget().share(),
                     PictureBudget::shareFor(engineThreads(config), QThread::idealThreadCount()));
}

TEST(WindowPictures, ABindingBudgetSpacesRunningPicturesButZoomAndPauseShowAtOnce) {
    MainWindow w;
    showWith(w, smallExperiment(0.3)); // outlasts the 3 s below
    // 1.5 % of a core: even this small scene's pictures (copy, measures, preparation and paint:
    // about 3 ms here) are about 200 ms apart.
    w.setPictureShare(0.015);
    click(w, w.startAction());
    ASSERT_TRUE(waitFor([&] { return stillRunning(w) && w.sceneView()->snapshot(); }));
    EXPECT_DOUBLE_EQ(w.pictureBudget().share(), 0.015);

    struct Shown {
        double atMs;       ///< when the window took it, by its own clock
        double intervalMs; ///< the spacing the window applied to this picture
    };
    std::vector<Shown> shown;
    SnapshotPtr last = w.sceneView()->snapshot();
    const std::uint64_t published = w.controller().status().publications;
    bool zoomed = false;
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < 3000 && stillRunning(w)) {
        QTest::qWait(2);
        const SnapshotPtr now = w.sceneView()->snapshot();
        if (now == last) {
            continue;
        }
        last = now;
        shown.push_back({w.runningPictureAtMs(), w.runningPictureIntervalMs()});
        if (!zoomed && w.pictureIntervalMs() >= 100.0) {
            // Just after a picture, the next is far: a zoom is drawn at once all the same.
            zoomed = true;
            const std::uint64_t paints = w.sceneView()->drawingTime().paints;
            const double scale = w.sceneView()->renderer().view().pixelsPerMetre();
            const QPointF centre(w.sceneView()->width() / 2.0, w.sceneView()->height() / 2.0);
            QWheelEvent wheel(centre, w.sceneView()->mapToGlobal(centre), QPoint(), QPoint(0, 120),
                              Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
            QApplication::sendEvent(w.sceneView(), &wheel);
            QTest::qWait(50);
            EXPECT_GT(w.sceneView()->renderer().view().pixelsPerMetre(), scale);
            EXPECT_GT(w.sceneView()->drawingTime().paints, paints);
            EXPECT_EQ(w.sceneView()->snapshot(), now); // the zoom's paint, not a new picture's
        }
    }
    ASSERT_TRUE(stillRunning(w)) << "the run should outlast the 3 s";
    const std::uint64_t publications = w.controller().status().publications - published;
    EXPECT_TRUE(zoomed);
    EXPECT_GE(w.pictureIntervalMs(), 3 * 33.0);
    // The pictures come, spaced by the budget, not every 33 ms: each no sooner than its spacing
    // after the one before (less the window's 3 ms slack for a timer tick), by the window's own
    // clock, so that a loaded machine delaying this loop cannot blur it. A picture this loop
    // missed only makes a gap longer.
    ASSERT_GE(shown.size(), 2u);
    for (std::size_t k = 1; k < shown.size(); ++k) {
        EXPECT_GE(shown[k].atMs - shown[k - 1].atMs, shown[k].intervalMs - 3.0) << "picture " << k;
        EXPECT_GE(shown[k].intervalMs, 33.0);
    }
    // The controller publishes at the pictures' pace, not every 33 ms (about 90 in 3 s).
    EXPECT_LE(publications, 2 * shown.size() + 3);

    // Pause: the paused picture is shown at once, whatever the budget says.
    click(w, w.pauseAction());
    ASSERT_TRUE(waitFor([&] { return w.controller().status().state == RunState::Paused; }));
    w.refresh();
    EXPECT_EQ(w.sceneView()->snapshot(), w.controller().latestSnapshot());
}

TEST(WindowPictures, APicturePublishedBeforeTheBudgetAllowsWaitsForIt) {
    MainWindow w;
    showWith(w, smallExperiment(0.3));
    click(w, w.startAction());
    ASSERT_TRUE(waitFor([&] { return stillRunning(w) && w.sceneView()->snapshot(); }));
    // Just after a new picture at the run's own pace...
    const SnapshotPtr first = w.sceneView()->snapshot();
    ASSERT_TRUE(waitFor([&] { return w.sceneView()->snapshot() != first; }));
    const SnapshotPtr shown = w.sceneView()->snapshot();
    QElapsedTimer clock;
    clock.start();
    // ... the budget shrinks to a twentieth of a percent of a core (its next picture seconds
    // away), while the engine still publishes at once (until the window's next refresh tells it
    // the budget's pace): a newer picture is there, and it waits.
    w.setPictureShare(0.0005);
    w.controller().setPublishInterval(0.001);
    bool newerWaiting = false;
    while (clock.elapsed() < 1000) {
        QTest::qWait(5);
        ASSERT_EQ(w.sceneView()->snapshot(), shown) << "after " << clock.elapsed() << " ms";
        newerWaiting = newerWaiting || w.controller().latestSnapshot() != shown;
    }
    ASSERT_TRUE(stillRunning(w));
    EXPECT_TRUE(newerWaiting);
    EXPECT_GE(w.pictureIntervalMs(), 1000.0);
    // Back to the rule: the pictures come again.
    w.setPictureShare(0);
    EXPECT_TRUE(waitFor([&] { return w.sceneView()->snapshot() != shown; }, 5000));
}

} // namespace
} // namespace grainlab::ui
