// The pixel canvas follows its rules exactly: a fill covers the pixels whose centres lie inside
// the polygon (brute force over every pixel), polygons that tile the plane cover each pixel once,
// the convex walk equals the general fill, blending is Qt's to the bit, and a line's coverage in
// each column adds up to its alpha.
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <QImage>
#include <QPainter>

#include <gtest/gtest.h>

#include "grainlab/ui/pixel_canvas.h"

namespace grainlab::ui {
namespace {

/// Is the centre of pixel (x, y) inside the polygon by the odd-even rule, with the canvas's
/// half-open edges (a crossing at or left of the centre counts)?
bool centreInside(const std::vector<QPointF>& polygon, int x, int y) {
    const double cx = x + 0.5, cy = y + 0.5;
    bool inside = false;
    for (std::size_t k = 0; k < polygon.size(); ++k) {
        const QPointF a = polygon[k], b = polygon[(k + 1) % polygon.size()];
        if ((a.y() <= cy) != (b.y() <= cy)) {
            const QPointF lo = a.y() < b.y() ? a : b, hi = a.y() < b.y() ? b : a;
            const double crossing =
                lo.x() + (cy - lo.y()) * ((hi.x() - lo.x()) / (hi.y() - lo.y()));
            if (crossing <= cx) {
                inside = !inside;
            }
        }
    }
    return inside;
}

/// `n` random angles in [0, 2 pi), in increasing order: vertex directions going round once.
std::vector<double> sortedAngles(std::mt19937& rng, int n) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<double> angles(n);
    for (double& a : angles) {
        a = 2.0 * M_PI * unit(rng);
    }
    std::sort(angles.begin(), angles.end());
    return angles;
}

/// A random star-shaped polygon (simple, often concave) about `centre`.
std::vector<QPointF> randomPolygon(std::mt19937& rng, QPointF centre, double size, int n) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const std::vector<double> angles = sortedAngles(rng, n);
    std::vector<QPointF> polygon;
    for (double a : angles) {
        const double r = size * (0.3 + 0.7 * unit(rng));
        polygon.emplace_back(centre.x() + r * std::cos(a), centre.y() + r * std::sin(a));
    }
    return polygon;
}

/// A convex polygon: points on an ellipse at random angles.
std::vector<QPointF> randomConvexPolygon(std::mt19937& rng, QPointF centre, double size, int n) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const std::vector<double> angles = sortedAngles(rng, n);
    const double aspect = 0.4 + 0.6 * unit(rng), turn = 2.0 * M_PI * unit(rng);
    std::vector<QPointF> polygon;
    for (double a : angles) {
        const double u = size * std::cos(a), v = aspect * size * std::sin(a);
        polygon.emplace_back(centre.x() + u * std::cos(turn) - v * std::sin(turn),
                             centre.y() + u * std::sin(turn) + v * std::cos(turn));
    }
    return polygon;
}

QImage blank(int w, int h, QRgb fill = 0xffffffff) {
    QImage image(w, h, QImage::Format_ARGB32_Premultiplied);
    image.fill(fill);
    return image;
}

TEST(PixelCanvas, FillCoversExactlyThePixelsWhoseCentresAreInside) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> where(-10.0, 70.0), size(1.0, 30.0);
    int covered = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const auto polygon =
            randomPolygon(rng, QPointF(where(rng), where(rng)), size(rng), 3 + trial % 12);
        QImage image = blank(64, 48);
        PixelCanvas canvas(image);
        canvas.fillPolygon(polygon.data(), int(polygon.size()), qRgb(200, 10, 10));
        for (int y = 0; y < image.height(); ++y) {
            for (int x = 0; x < image.width(); ++x) {
                const bool filled = image.pixel(x, y) == qRgb(200, 10, 10);
                ASSERT_EQ(filled, centreInside(polygon, x, y))
                    << "trial " << trial << ", pixel " << x << ", " << y;
                covered += filled;
            }
        }
    }
    EXPECT_GT(covered, 20000); // the polygons did reach the image
}

TEST(PixelCanvas, ConvexWalkEqualsTheGeneralFill) {
    std::mt19937 rng(12);
    std::uniform_real_distribution<double> where(-5.0, 45.0), size(0.5, 25.0);
    for (int trial = 0; trial < 500; ++trial) {
        const auto polygon =
            randomConvexPolygon(rng, QPointF(where(rng), where(rng)), size(rng), 3 + trial % 30);
        QImage general = blank(40, 40), convex = blank(40, 40);
        PixelCanvas(general).fillPolygon(polygon.data(), int(polygon.size()), qRgb(0, 90, 0));
        PixelCanvas(convex).fillConvexPolygon(polygon.data(), int(polygon.size()), qRgb(0, 90, 0));
        ASSERT_EQ(general, convex) << "trial " << trial;
    }
}

TEST(PixelCanvas, PolygonsThatTileThePlaneCoverEachPixelOnce) {
    // A jittered grid of quadrilaterals sharing their corners, each filled translucent: a pixel
    // covered twice or missed would show another shade than one layer over white.
    std::mt19937 rng(13);
    std::uniform_real_distribution<double> jitter(-3.7, 3.7);
    constexpr int kCells = 10;
    constexpr double kSide = 9.3;
    std::vector<std::vector<QPointF>> corner(kCells + 1, std::vector<QPointF>(kCells + 1));
    for (int i = 0; i <= kCells; ++i) {
        for (int j = 0; j <= kCells; ++j) {
            const bool border = i == 0 || j == 0 || i == kCells || j == kCells;
            corner[i][j] = QPointF(2.0 + i * kSide + (border ? 0.0 : jitter(rng)),
                                   2.0 + j * kSide + (border ? 0.0 : jitter(rng)));
        }
    }
    QImage image = blank(100, 100);
    PixelCanvas canvas(image);
    for (int i = 0; i < kCells; ++i) {
        for (int j = 0; j < kCells; ++j) {
            const QPointF quad[] = {corner[i][j], corner[i + 1][j], corner[i + 1][j + 1],
                                    corner[i][j + 1]};
            canvas.fillPolygon(quad, 4, qRgba(0, 0, 255, 100));
        }
    }
    QImage once = blank(1, 1);
    PixelCanvas(once).fillPolygon(std::vector<QPointF>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}.data(), 4,
                                  qRgba(0, 0, 255, 100));
    const double end = 2.0 + kCells * kSide;
    int inside = 0;
    for (int y = 0; y < 100; ++y) {
        for (int x = 0; x < 100; ++x) {
            const bool within = x + 0.5 >= 2.0 && x + 0.5 < end && y + 0.5 >= 2.0 && y + 0.5 < end;
            ASSERT_EQ(image.pixel(x, y), within ? once.pixel(0, 0) : 0xffffffff) << x << ", " << y;
            inside += within;
        }
    }
    EXPECT_EQ(inside, 93 * 93);
}

TEST(PixelCanvas, BlendingIsQtsSourceOverToTheBit) {
    // Over a background of every shade, a translucent fill here and QPainter's aliased fill of
    // the same rectangle give the same bytes.
    QImage ours(256, 64, QImage::Format_ARGB32_Premultiplied);
    for (int y = 0; y < 64; ++y) {
        for (int x = 0; x < 256; ++x) {
            ours.setPixel(x, y, qPremultiply(qRgba(x, 255 - x, (x * 7 + y * 3) % 256, 255 - y)));
        }
    }
    QImage qt = ours.copy();
    for (const QRgb colour : {qRgba(30, 30, 90, 176), qRgba(250, 200, 0, 120), qRgba(9, 9, 9, 1),
                              qRgba(255, 255, 255, 254)}) {
        const QPointF rect[] = {{0, 0}, {256, 0}, {256, 64}, {0, 64}};
        PixelCanvas(ours).fillPolygon(rect, 4, colour);
        QPainter p(&qt);
        p.fillRect(QRect(0, 0, 256, 64), QColor::fromRgba(colour));
        p.end();
        ASSERT_EQ(ours, qt) << "colour " << std::hex << colour;
    }
}

/// Coverage at each pixel: how much darker than white a black line left it (0 to 255).
int darkness(const QImage& image, int x, int y) {
    return 255 - qRed(image.pixel(x, y));
}

TEST(PixelCanvas, ALinesCoverageInEachColumnAddsUpToItsAlpha) {
    std::mt19937 rng(14);
    std::uniform_real_distribution<double> where(4.0, 60.0);
    for (int trial = 0; trial < 200; ++trial) {
        const QPointF a(where(rng), where(rng)), b(where(rng), where(rng));
        const int alpha = trial % 2 ? 255 : 176;
        QImage image = blank(64, 64);
        PixelCanvas(image).drawLine(a, b, qRgba(0, 0, 0, alpha));
        const bool steep = std::fabs(b.y() - a.y()) > std::fabs(b.x() - a.x());
        // Columns (rows, if steep) whose centres lie from a's included to b's excluded.
        const double from = steep ? a.y() : a.x(), to = steep ? b.y() : b.x();
        for (int i = 0; i < 64; ++i) {
            const double centre = i + 0.5;
            const bool drawn =
                from < to ? centre >= from && centre < to : centre <= from && centre > to;
            int sum = 0;
            for (int j = 0; j < 64; ++j) {
                sum += steep ? darkness(image, j, i) : darkness(image, i, j);
            }
            if (drawn) {
                EXPECT_NEAR(sum, alpha, 2) << "trial " << trial << ", column " << i;
            } else {
                EXPECT_EQ(sum, 0) << "trial " << trial << ", column " << i;
            }
        }
    }
}

TEST(PixelCanvas, AClosedOutlineDrawsEachColumnOfEachEdgeOnce) {
    // A square's outline: its corners are not drawn twice, so each side's pixels carry one
    // line's coverage, and the inside stays untouched.
    const QPointF square[] = {{10.5, 10.5}, {30.5, 10.5}, {30.5, 30.5}, {10.5, 30.5}};
    QImage image = blank(40, 40);
    PixelCanvas(image).drawPolygonOutline(square, 4, qRgb(0, 0, 0));
    int dark = 0;
    for (int y = 0; y < 40; ++y) {
        for (int x = 0; x < 40; ++x) {
            const bool onSide = ((y == 10 || y == 30) && x >= 10 && x <= 30) ||
                                ((x == 10 || x == 30) && y >= 10 && y <= 30);
            EXPECT_EQ(darkness(image, x, y), onSide ? 255 : 0) << x << ", " << y;
            dark += onSide;
        }
    }
    EXPECT_EQ(dark, 80);
}

TEST(PixelCanvas, ShapesOutsideTheImageAndNonFinitePointsDrawNothing) {
    QImage image = blank(20, 20);
    const QImage before = image.copy();
    PixelCanvas canvas(image);
    const QPointF far[] = {{1e12, 1e12}, {2e12, 1e12}, {1e12, 3e12}};
    canvas.fillPolygon(far, 3, qRgb(0, 0, 0));
    canvas.fillConvexPolygon(far, 3, qRgb(0, 0, 0));
    const QPointF bad[] = {{1, 1}, {std::nan(""), 5}, {10, 10}};
    canvas.fillPolygon(bad, 3, qRgb(0, 0, 0));
    canvas.fillConvexPolygon(bad, 3, qRgb(0, 0, 0));
    canvas.drawLine({-50, -50}, {-10, -40}, qRgb(0, 0, 0));
    canvas.drawLine({1, 1}, {HUGE_VAL, 4}, qRgb(0, 0, 0));
    EXPECT_EQ(image, before);
    // A huge polygon covering the image fills all of it.
    const QPointF huge[] = {{-1e9, -1e9}, {1e9, -1e9}, {0, 1e9}};
    canvas.fillPolygon(huge, 3, qRgb(0, 0, 0));
    EXPECT_EQ(image.pixel(0, 0), qRgb(0, 0, 0));
    EXPECT_EQ(image.pixel(19, 19), qRgb(0, 0, 0));
}

TEST(PixelCanvas, RefusesImageFormatsItCannotBlendInto) {
    QImage indexed(4, 4, QImage::Format_Indexed8);
    EXPECT_THROW(PixelCanvas{indexed}, std::invalid_argument);
    QImage opaque(4, 4, QImage::Format_RGB32);
    EXPECT_NO_THROW(PixelCanvas{opaque});
}

} // namespace
} // namespace grainlab::ui
