// The overview's level of detail: where no grain is wider than SceneOptions::overviewHalfWidth,
// the renderer draws the grains and the void-cell shading straight into the pixels. At the
// sizes where it switches it shows the same picture as the full drawing through QPainter,
// within the tolerance stated here, with every overlay; it is used only where it applies.
#include <algorithm>
#include <cmath>

#include <QImage>
#include <QPainter>
#include <QPicture>

#include <gtest/gtest.h>

#include "grainlab/ui/scene_renderer.h"
#include "test_scenes.h"

namespace grainlab::ui {
namespace {

const SnapshotPtr& scene() {
    static const SnapshotPtr s = testing::makeCompactedSnapshot();
    return s;
}

double largestHalfWidth(const Snapshot& s) {
    double h = 0.0;
    for (const OvalShape& shape : s.shapes) {
        h = std::max(h, shape.halfWidth);
    }
    return h;
}

const QSize kSize(420, 420);

/// A renderer of the scene zoomed about the view's centre so that the widest grain is
/// `halfWidthPixels` wide in half width.
SceneRenderer zoomedTo(double halfWidthPixels, const SceneOptions& options) {
    SceneRenderer r;
    r.setSnapshot(scene());
    r.options() = options;
    r.fitToCell(kSize);
    const double now = largestHalfWidth(*scene()) * r.view().pixelsPerMetre();
    r.view().zoomAt(QPointF(kSize.width() / 2.0, kSize.height() / 2.0), halfWidthPixels / now);
    return r;
}

struct Drawn {
    QImage image;
    bool overview = false;
};

Drawn draw(const SceneRenderer& r) {
    Drawn d{QImage(kSize, QImage::Format_ARGB32_Premultiplied), false};
    QPainter p(&d.image);
    d.overview = r.drawsOverview(p);
    r.render(p, kSize);
    return d;
}

/// How two pictures differ: the mean over pixels and channels of |difference| (0-255), and the
/// share of pixels where some channel differs by more than a quarter of the range.
struct Difference {
    double mean = 0, farShare = 0;
};

Difference compare(const QImage& a, const QImage& b) {
    double sum = 0;
    int far = 0;
    for (int y = 0; y < a.height(); ++y) {
        for (int x = 0; x < a.width(); ++x) {
            const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
            const int dr = std::abs(qRed(p) - qRed(q)), dg = std::abs(qGreen(p) - qGreen(q)),
                      db = std::abs(qBlue(p) - qBlue(q));
            sum += dr + dg + db;
            far += std::max({dr, dg, db}) > 64;
        }
    }
    const double pixels = double(a.width()) * a.height();
    return {sum / (3.0 * pixels), far / pixels};
}

TEST(SceneOverview, UsedOnlyOnRasterDevicesAtSmallZooms) {
    SceneOptions options;
    const double limit = options.overviewHalfWidth;
    EXPECT_TRUE(draw(zoomedTo(limit, options)).overview);
    EXPECT_TRUE(draw(zoomedTo(0.3 * limit, options)).overview);
    EXPECT_FALSE(draw(zoomedTo(1.01 * limit, options)).overview);
    SceneOptions never = options;
    never.overviewHalfWidth = 0.0;
    EXPECT_FALSE(draw(zoomedTo(0.3 * limit, never)).overview);
    // Vector devices and transformed painters get the full drawing.
    const SceneRenderer small = zoomedTo(0.5 * limit, options);
    QPicture picture;
    QPainter recorder(&picture);
    EXPECT_FALSE(small.drawsOverview(recorder));
    recorder.end();
    QImage image(kSize, QImage::Format_ARGB32_Premultiplied);
    QPainter scaled(&image);
    scaled.scale(0.5, 0.5);
    EXPECT_FALSE(small.drawsOverview(scaled));
}

TEST(SceneOverview, ShowsTheFullDrawingsPixelsWhereItSwitches) {
    // Tolerance: on average within 5 levels of 255 per channel, and at most 1 % of the pixels
    // differ by more than a quarter of the range. The two rasterisers share partial pixels
    // along lines differently: Qt covers both ends of each line, so where void-cell edges meet
    // it blends twice; the worst case, void cells with their periodic images, differs by 3.1
    // levels on average and in 0.15 % of the pixels by more than a quarter. An overview without
    // its void-cell shading or grains would differ by tens of levels on average.
    SceneOptions plain;
    SceneOptions voids = plain;
    voids.voidCells = VoidCellShading::Valence;
    SceneOptions everything = voids;
    everything.forceChains = ForceChains::Strong;
    everything.periodicImages = true;
    everything.selectedGrain = 5;
    SceneOptions area = plain;
    area.voidCells = VoidCellShading::Area;
    area.colouring = GrainColouring::Rotation;
    const double limit = plain.overviewHalfWidth;
    int compared = 0;
    for (const SceneOptions& options : {plain, voids, everything, area}) {
        // At the switch, where grains get their outlines, and a few pixels wide.
        for (const double halfWidth : {limit, 6.5, 5.5, 3.0}) {
            SceneOptions full = options;
            full.overviewHalfWidth = 0.0;
            const Drawn overview = draw(zoomedTo(halfWidth, options));
            const Drawn reference = draw(zoomedTo(halfWidth, full));
            ASSERT_TRUE(overview.overview);
            ASSERT_FALSE(reference.overview);
            const Difference d = compare(overview.image, reference.image);
            EXPECT_LT(d.mean, 5.0) << "half width " << halfWidth;
            EXPECT_LT(d.farShare, 0.01) << "half width " << halfWidth;
            ++compared;
        }
    }
    EXPECT_EQ(compared, 16);
}

TEST(SceneOverview, DrawsSomethingDifferentFromAnEmptyCell) {
    // The comparison above cannot pass with both pictures empty: the overview shows the grains.
    SceneOptions options;
    const Drawn overview = draw(zoomedTo(options.overviewHalfWidth, options));
    SceneRenderer empty = zoomedTo(options.overviewHalfWidth, options);
    empty.setSnapshot(nullptr);
    QImage blank(kSize, QImage::Format_ARGB32_Premultiplied);
    QPainter p(&blank);
    empty.render(p, kSize);
    p.end();
    EXPECT_GT(compare(overview.image, blank).mean, 20.0);
}

} // namespace
} // namespace grainlab::ui
