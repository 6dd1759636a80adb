// The scene renderer draws what the snapshot says: grain colour at every grain centre, the cell
// fill wherever no grain (or image) can reach, background outside the cell; hit tests find the
// grain and void cell under a pixel; overlays change the picture.
#include <cmath>

#include <QDir>
#include <QImage>
#include <QPainter>

#include <gtest/gtest.h>

#include "grainlab/measures.h"
#include "grainlab/ui/colour_maps.h"
#include "grainlab/ui/scene_renderer.h"
#include "overlay_points.h"
#include "test_scenes.h"

namespace grainlab::ui {
namespace {

const SnapshotPtr& scene() {
    static const SnapshotPtr s = testing::makeCompactedSnapshot();
    return s;
}

bool sameColour(QRgb a, const QColor& b, int tolerance = 2) {
    return std::abs(qRed(a) - b.red()) <= tolerance &&
           std::abs(qGreen(a) - b.green()) <= tolerance &&
           std::abs(qBlue(a) - b.blue()) <= tolerance;
}

QImage render(const SceneRenderer& r, QSize size) {
    QImage image(size, QImage::Format_ARGB32);
    QPainter painter(&image);
    r.render(painter, size);
    return image;
}

SceneRenderer plainRenderer(QSize size) {
    SceneRenderer r;
    r.setSnapshot(scene());
    r.options().caption = false;
    r.options().scaleBar = false;
    r.options().colourKey = false;
    r.fitToCell(size);
    return r;
}

/// Pixels of `colour` (within 2 per channel) in the bottom-right quarter of `image`.
int countInBottomRight(const QImage& image, const QColor& colour) {
    int n = 0;
    for (int y = image.height() / 2; y < image.height(); ++y) {
        for (int x = image.width() / 2; x < image.width(); ++x) {
            n += sameColour(image.pixel(x, y), colour);
        }
    }
    return n;
}

TEST(SceneRenderer, RendersEveryOverlayTogether) {
    // Written into the build folder for a human look (test-images/scene_all_overlays.png).
    const QSize size(800, 800);
    SceneRenderer r;
    r.setSnapshot(scene());
    r.options().forceChains = ForceChains::All;
    r.options().voidCells = VoidCellShading::Valence;
    r.options().contactRose = true;
    r.options().periodicImages = true;
    r.options().selectedVoidCell = 3;
    r.fitToCell(size);
    const QImage image = render(r, size);
    QDir().mkpath(QStringLiteral("test-images"));
    EXPECT_TRUE(image.save(QStringLiteral("test-images/scene_all_overlays.png")));
}

TEST(SceneRenderer, FixtureHasContactsAndVoidCells) {
    EXPECT_GT(scene()->network.contacts.size(), scene()->x1.size());
    EXPECT_GT(scene()->voidCells.size(), 10u);
}

TEST(SceneRenderer, LoadBearingGrainsAndStrongThresholdAreTheEngines) {
    // A snapshot without its measures: the renderer finds the load-bearing graph itself, by
    // the engine's rule, and splits strong from weak contacts at the engine's f_a.
    auto bare = std::make_shared<Snapshot>(*scene());
    bare->loadBearing.clear();
    SceneRenderer r;
    r.setSnapshot(bare);
    r.options().colouring = GrainColouring::LoadBearing;
    const LoadBearingGraph graph = loadBearingGraph(bare->network);
    ASSERT_EQ(graph.grainInGraph.size(), bare->x1.size());
    int outside = 0;
    for (std::size_t g = 0; g < bare->x1.size(); ++g) {
        const bool drawnIn = r.grainColour(static_cast<int>(g)) == QColor(70, 110, 170);
        EXPECT_EQ(drawnIn, graph.grainInGraph[g] != 0) << "grain " << g;
        outside += graph.grainInGraph[g] ? 0 : 1;
    }
    EXPECT_GT(outside, 0);
    EXPECT_LT(outside, static_cast<int>(bare->x1.size()));
    EXPECT_EQ(r.strongForceThreshold(),
              grainlab::strongForceThreshold(bare->network, StrongForceThreshold::RmsForce));
}

TEST(SceneRenderer, GrainColourAtEveryCentreAndCellFillFarFromGrains) {
    const QSize size(700, 700);
    for (GrainColouring mode : {GrainColouring::Size, GrainColouring::Rotation,
                                GrainColouring::Coordination, GrainColouring::LoadBearing}) {
        SceneRenderer r = plainRenderer(size);
        r.options().colouring = mode;
        const QImage image = render(r, size);
        const Snapshot& s = *scene();
        for (std::size_t g = 0; g < s.x1.size(); ++g) {
            const QPoint p = r.view().toScreen(s.x1[g], s.x2[g]).toPoint();
            ASSERT_TRUE(image.rect().contains(p));
            const QColor expected = r.grainColour(static_cast<int>(g));
            EXPECT_FALSE(sameColour(r.options().cellFill.rgb(), expected, 3)) << "grain " << g;
            EXPECT_TRUE(sameColour(image.pixel(p), expected))
                << "mode " << int(mode) << " grain " << g << " at " << p.x() << "," << p.y();
        }
    }

    // Points of the cell farther than a bounding radius (plus two pixels) from every grain and
    // every periodic image of a grain show the cell fill.
    SceneRenderer r = plainRenderer(size);
    const QImage image = render(r, size);
    const Snapshot& s = *scene();
    const CellMatrix& h = s.network.cell;
    const double pixel = 1.0 / r.view().pixelsPerMetre();
    int empty = 0;
    for (int i = 1; i < 60; ++i) {
        for (int j = 1; j < 60; ++j) {
            const double f0 = i / 60.0, f1 = j / 60.0;
            const double w1 = h[0] * f0 + h[2] * f1, w2 = h[1] * f0 + h[3] * f1;
            bool free = true;
            for (std::size_t g = 0; g < s.x1.size() && free; ++g) {
                const double reach = s.shapes[s.shape[g]].halfWidth + 2.0 * pixel;
                for (int a = -1; a <= 1 && free; ++a) {
                    for (int b = -1; b <= 1 && free; ++b) {
                        const double c1 = s.x1[g] + h[0] * a + h[2] * b;
                        const double c2 = s.x2[g] + h[1] * a + h[3] * b;
                        free = std::hypot(w1 - c1, w2 - c2) > reach;
                    }
                }
            }
            if (free) {
                ++empty;
                const QPoint p = r.view().toScreen(w1, w2).toPoint();
                EXPECT_TRUE(sameColour(image.pixel(p), r.options().cellFill))
                    << "empty point " << p.x() << "," << p.y();
            }
        }
    }
    EXPECT_GT(empty, 20);
    // The corners of the image lie outside the cell's bounding box margin: background.
    EXPECT_TRUE(sameColour(image.pixel(1, 1), r.options().background));
    EXPECT_TRUE(
        sameColour(image.pixel(size.width() - 2, size.height() - 2), r.options().background));
}

TEST(SceneRenderer, VoidCellsAndForceChainsShowTheirColours) {
    // Void cells and force chains are painted in batches (one path per colour or force bin):
    // each cell still shows its own fill over what lies below it, each strong chain its colour.
    const QSize size(700, 700);
    for (VoidCellShading shading : {VoidCellShading::Valence, VoidCellShading::Area}) {
        SceneRenderer r = plainRenderer(size);
        const QImage below = render(r, size);
        r.options().voidCells = shading;
        const QImage shaded = render(r, size);
        const auto points = testing::voidCellCentroids(r, size);
        EXPECT_GT(points.size(), scene()->voidCells.size() / 3);
        int distinct = 0;
        for (const auto& [cell, pixel] : points) {
            const QColor fill = r.voidCellColour(cell);
            EXPECT_EQ(fill.alpha(), 120);
            distinct += fill != r.voidCellColour(points.front().cell);
            EXPECT_TRUE(
                sameColour(shaded.pixel(pixel), testing::blended(fill, below.pixel(pixel)), 3))
                << "shading " << int(shading) << " void cell " << cell << " at " << pixel.x() << ","
                << pixel.y();
        }
        EXPECT_GT(distinct, 0) << "every cell has the same colour";
    }

    SceneRenderer r = plainRenderer(size);
    r.options().forceChains = ForceChains::Strong;
    const QImage chains = render(r, size);
    const auto points = testing::strongChainMidpoints(r, size);
    EXPECT_GT(points.size(), 20u);
    for (const auto& [force, pixel] : points) {
        const QColor colour = r.forceChainColour(force);
        EXPECT_EQ(colour.alpha(), 255); // strong chains are opaque
        EXPECT_TRUE(sameColour(chains.pixel(pixel), colour, 3))
            << "chain of " << force << " N at " << pixel.x() << "," << pixel.y();
    }
}

TEST(SceneRenderer, ShadedVoidCellsCarryAColourKey) {
    // Valence 3 and 10+, and a tenth and ten times the mean area: the ends of the two scales,
    // each a swatch of the fills' colour as seen over the white cell, at the bottom right.
    const QSize size(700, 700);
    const auto seen = [](double t) {
        const QColor c = sequentialColour(t);
        const double a = 120 / 255.0; // the fills' alpha (VoidCellsAndForceChainsShowTheirColours)
        return QColor::fromRgbF(float(a * c.redF() + 1 - a), float(a * c.greenF() + 1 - a),
                                float(a * c.blueF() + 1 - a));
    };
    for (VoidCellShading shading : {VoidCellShading::Valence, VoidCellShading::Area}) {
        SceneRenderer r = plainRenderer(size);
        r.options().voidCells = shading;
        const QImage without = render(r, size);
        r.options().colourKey = true;
        const QImage with = render(r, size);
        for (double t : {0.0, 1.0}) {
            const int added =
                countInBottomRight(with, seen(t)) - countInBottomRight(without, seen(t));
            EXPECT_GT(added, 200) << "shading " << int(shading) << ": no swatch of the key at " << t
                                  << " of the scale";
        }
    }
    // Without shading there is no key.
    SceneRenderer r = plainRenderer(size);
    const QImage without = render(r, size);
    r.options().colourKey = true;
    EXPECT_EQ(render(r, size), without);
}

TEST(SceneRenderer, VoidCellFillsFollowTheOptionsFromFrameToFrame) {
    // The fills' colours and drawing order are kept from frame to frame (built once per shading):
    // on one renderer, switching the shading or the selected cell repaints every cell in its new
    // colour, and the selected cell is not filled twice.
    const QSize size(700, 700);
    SceneRenderer r = plainRenderer(size);
    const QImage below = render(r, size);
    const auto points = testing::voidCellCentroids(r, size);
    ASSERT_FALSE(points.empty());
    const int selected = points.front().cell;
    std::vector<QRgb> valenceColours;
    for (VoidCellShading shading :
         {VoidCellShading::Valence, VoidCellShading::Area, VoidCellShading::Valence}) {
        r.options().voidCells = shading;
        r.options().selectedVoidCell = shading == VoidCellShading::Area ? selected : -1;
        const QImage shaded = render(r, size);
        int changed = 0;
        for (std::size_t k = 0; k < points.size(); ++k) {
            const auto& [cell, pixel] = points[k];
            const QColor fill = r.voidCellColour(cell);
            if (valenceColours.size() < points.size()) {
                valenceColours.push_back(fill.rgba());
            }
            changed += fill.rgba() != valenceColours[k];
            if (cell == selected && shading == VoidCellShading::Area) {
                EXPECT_EQ(fill.alpha(), 200);
            }
            EXPECT_TRUE(
                sameColour(shaded.pixel(pixel), testing::blended(fill, below.pixel(pixel)), 3))
                << "shading " << int(shading) << " void cell " << cell << " at " << pixel.x() << ","
                << pixel.y();
        }
        if (shading == VoidCellShading::Area) {
            EXPECT_GT(changed, int(points.size()) / 4) << "the shadings give the same colours";
        } else {
            EXPECT_EQ(changed, 0);
        }
    }
}

TEST(SceneRenderer, WideGrainsKeepTheirOutlineAndADarkerEdge) {
    // Fills are aliased and outlines have as few vertices as stay within a quarter of a pixel of
    // the true outline: 3 pixels inside the true outline, every grain still shows its own fill;
    // near its edge, a pixel darker than the fill (the antialiased outline, of the fill's colour
    // 1.6 times darker, which hides the aliased fill's staircase).
    const QSize size(700, 700);
    SceneRenderer r = plainRenderer(size);
    const QImage image = render(r, size);
    const Snapshot& s = *scene();
    const double pixel = 1.0 / r.view().pixelsPerMetre();
    auto brightness = [](QRgb c) { return qRed(c) + qGreen(c) + qBlue(c); };
    int edges = 0, darker = 0;
    for (std::size_t g = 0; g < s.x1.size(); ++g) {
        const OvalShape& shape = s.shapes[s.shape[g]];
        ASSERT_GT(shape.halfWidth / pixel, 8.0);
        const QColor fill = r.grainColour(static_cast<int>(g));
        const double c = std::cos(s.theta[g]), sn = std::sin(s.theta[g]);
        for (int k = 0; k < 24; ++k) {
            const double alpha = 2.0 * std::acos(-1.0) * (k + 0.5) / 24.0;
            const auto b = shape.boundaryPoint(alpha);
            // World point at `depth` pixels along the outward normal from the boundary point.
            auto at = [&](double depth) {
                const double bx = b[0] + depth * pixel * std::cos(alpha);
                const double by = b[1] + depth * pixel * std::sin(alpha);
                const QPointF p =
                    r.view().toScreen(s.x1[g] + c * bx - sn * by, s.x2[g] + sn * bx + c * by);
                return QPoint(int(std::floor(p.x())), int(std::floor(p.y())));
            };
            const QPoint inside = at(-3.0);
            if (!image.rect().contains(inside)) {
                continue; // grains may stick out of the cell, and out of the view
            }
            EXPECT_TRUE(sameColour(image.pixel(inside), fill))
                << "grain " << g << " direction " << k << " at " << inside.x() << "," << inside.y();
            const QPoint edge = at(0.0);
            if (!image.rect().adjusted(2, 2, -2, -2).contains(edge)) {
                continue;
            }
            int darkest = brightness(fill.rgb());
            for (int dy = -2; dy <= 2; ++dy) {
                for (int dx = -2; dx <= 2; ++dx) {
                    if (image.rect().contains(edge + QPoint(dx, dy))) {
                        darkest = std::min(darkest, brightness(image.pixel(edge + QPoint(dx, dy))));
                    }
                }
            }
            ++edges;
            darker += darkest < brightness(fill.rgb()) - 12;
        }
    }
    // Against the white cell a dark fill's outline can fall mostly on the outer pixels, which
    // are then lighter than the fill: most, not all, edges show a darker pixel.
    EXPECT_GT(edges, 1000);
    EXPECT_GT(darker, 0.95 * edges);
}

TEST(SceneRenderer, ZoomedVoidCellsShowTheirFillOnEveryRow) {
    // Zoomed in, tall void cells are filled in bands of rows (so that Qt does not hand a tall
    // translucent fill to its thread pool): no row is missed or blended twice.
    const QSize size(700, 700);
    SceneRenderer r = plainRenderer(size);
    r.view().zoomAt(QPointF(350, 350), 3.0);
    const QImage below = render(r, size);
    r.options().voidCells = VoidCellShading::Valence;
    const QImage shaded = render(r, size);
    int tall = 0, checked = 0;
    for (const auto& [cell, centroid] : testing::voidCellCentroids(r, size)) {
        QPolygonF screen;
        for (const QPointF& w : r.voidCellPolygon(cell)) {
            screen << r.view().toScreen(w.x(), w.y());
        }
        tall += screen.boundingRect().height() > 70.0;
        const QColor fill = r.voidCellColour(cell);
        for (int y = 0; y < size.height(); ++y) {
            const QPointF centre(centroid.x() + 0.5, y + 0.5);
            double nearest = 1e300;
            for (qsizetype k = 0; k < screen.size(); ++k) {
                nearest =
                    std::min(nearest, testing::segmentDistance(centre, screen[k],
                                                               screen[(k + 1) % screen.size()]));
            }
            if (nearest < 3.0 || !screen.containsPoint(centre, Qt::OddEvenFill)) {
                continue;
            }
            ++checked;
            const QPoint p(centroid.x(), y);
            EXPECT_TRUE(sameColour(shaded.pixel(p), testing::blended(fill, below.pixel(p)), 3))
                << "void cell " << cell << " at " << p.x() << "," << p.y();
        }
    }
    EXPECT_GT(tall, 3) << "no void cell is taller than a band";
    EXPECT_GT(checked, 1000);
}

TEST(SceneRenderer, HitTestsFindGrainsAndVoidCells) {
    const QSize size(700, 700);
    SceneRenderer r = plainRenderer(size);
    const Snapshot& s = *scene();
    for (std::size_t g = 0; g < s.x1.size(); ++g) {
        EXPECT_EQ(r.grainAt(r.view().toScreen(s.x1[g], s.x2[g])), static_cast<int>(g));
    }
    int found = 0;
    for (std::size_t v = 0; v < s.voidCells.size(); ++v) {
        const auto& c = s.voidCells[v];
        found += r.voidCellAt(r.view().toScreen(c.centroid1, c.centroid2)) == static_cast<int>(v);
    }
    EXPECT_GE(found, static_cast<int>(0.9 * s.voidCells.size()));
    // Far outside the cell there is nothing.
    EXPECT_EQ(r.grainAt(QPointF(-500, -500)), -1);
    EXPECT_EQ(r.voidCellAt(QPointF(-5000, -5000)), -1);
}

TEST(SceneRenderer, ScreenAndWorldRoundTripUnderZoomAndPan) {
    SceneRenderer r = plainRenderer(QSize(400, 300));
    const auto before = r.view().toWorld(QPointF(120, 80));
    r.view().zoomAt(QPointF(120, 80), 3.0);
    const auto after = r.view().toWorld(QPointF(120, 80));
    EXPECT_NEAR(before[0], after[0], 1e-12);
    EXPECT_NEAR(before[1], after[1], 1e-12);
    r.view().panBy(QPointF(10, -20));
    const QPointF p = r.view().toScreen(after[0], after[1]);
    EXPECT_NEAR(p.x(), 130.0, 1e-9);
    EXPECT_NEAR(p.y(), 60.0, 1e-9);
    // x1 is up on screen.
    EXPECT_LT(r.view().toScreen(1e-3, 0).y(), r.view().toScreen(0, 0).y());
}

TEST(SceneRenderer, OverlaysAndImagesChangeThePicture) {
    const QSize size(600, 600);
    SceneRenderer r = plainRenderer(size);
    const QImage plain = render(r, size);
    auto differingPixels = [&](const QImage& other) {
        int n = 0;
        for (int y = 0; y < size.height(); y += 2) {
            for (int x = 0; x < size.width(); x += 2) {
                n += plain.pixel(x, y) != other.pixel(x, y);
            }
        }
        return n;
    };
    r.options().forceChains = ForceChains::All;
    const int all = differingPixels(render(r, size));
    r.options().forceChains = ForceChains::Strong;
    const int strong = differingPixels(render(r, size));
    EXPECT_GT(all, 500);
    EXPECT_GT(strong, 100);
    EXPECT_LT(strong, all);
    r.options().forceChains = ForceChains::Off;
    r.options().voidCells = VoidCellShading::Valence;
    EXPECT_GT(differingPixels(render(r, size)), 2000);
    r.options().voidCells = VoidCellShading::Off;
    r.options().periodicImages = true;
    r.fitToCell(size);
    EXPECT_GT(differingPixels(render(r, size)), 500);
    r.options().periodicImages = false;
    r.options().contactRose = true;
    r.options().scaleBar = true;
    EXPECT_GT(differingPixels(render(r, size)), 300);
}

} // namespace
} // namespace grainlab::ui
