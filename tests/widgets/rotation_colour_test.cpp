// The rotation colouring, checked the way a user reads it: one grain spun by the engine with a
// positive angular velocity (from x1 towards x2), drawn before and after. On screen x1 points up
// and x2 to the right, so that rotation turns the grain clockwise as seen on screen; the user
// guide says clockwise grains are red. The test measures the turn from the grain's pixels.
#include <cmath>

#include <QImage>
#include <QPainter>

#include <gtest/gtest.h>

#include "grainlab/assembly.h"
#include "grainlab/simulation.h"
#include "grainlab/snapshot.h"
#include "grainlab/ui/scene_renderer.h"

namespace grainlab::ui {
namespace {

struct Blob {
    double angle = 0; ///< major axis on screen, from screen-right towards screen-up [rad]
    int pixels = 0;
};

/// The principal axis of the pixels within `radius` of `centre` that are neither background nor
/// cell fill (the cell's outline is farther away).
Blob grainBlob(const QImage& image, const SceneOptions& options, QPointF centre, double radius) {
    double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
    int n = 0;
    for (int row = 0; row < image.height(); ++row) {
        for (int col = 0; col < image.width(); ++col) {
            if (std::hypot(col - centre.x(), row - centre.y()) > radius) {
                continue;
            }
            const QRgb p = image.pixel(col, row);
            if (p == options.background.rgb() || p == options.cellFill.rgb()) {
                continue;
            }
            const double x = col, y = -row; // y up, as the user sees it
            sx += x;
            sy += y;
            sxx += x * x;
            syy += y * y;
            sxy += x * y;
            ++n;
        }
    }
    Blob b;
    b.pixels = n;
    if (n == 0) {
        return b;
    }
    const double mx = sx / n, my = sy / n;
    const double cxx = sxx / n - mx * mx, cyy = syy / n - my * my, cxy = sxy / n - mx * my;
    b.angle = 0.5 * std::atan2(2 * cxy, cxx - cyy);
    return b;
}

QImage draw(const SnapshotPtr& s, QSize size, SceneOptions& usedOptions, QPointF& centre,
            double& pixelsPerMetre) {
    SceneRenderer r;
    r.setSnapshot(s);
    r.options().caption = false;
    r.options().scaleBar = false;
    r.options().colouring = GrainColouring::Rotation;
    r.fitToCell(size);
    usedOptions = r.options();
    centre = r.view().toScreen(s->x1[0], s->x2[0]);
    pixelsPerMetre = r.view().pixelsPerMetre();
    QImage image(size, QImage::Format_ARGB32);
    QPainter painter(&image);
    r.render(painter, size);
    return image;
}

TEST(RotationColour, AGrainTurningClockwiseOnScreenIsRed) {
    AssemblySpec spec;
    spec.grainCount = 1;
    spec.widths = {2e-3};
    spec.aspectRatio = 0.5;
    spec.gap = 1.2; // a cell wider than two grains
    spec.seed = 3;
    SimulationParameters parameters;
    parameters.damping.kind = DampingKind::None;
    SimulationState initial = generateGridAssembly(spec, parameters);
    initial.grains.theta[0] = 0.3;   // major axis tilted off the screen axes
    initial.grains.omega[0] = 400.0; // positive: from x1 towards x2 [rad/s]
    Simulation sim(initial);
    sim.advance(1000); // 0.4 rad

    auto before = std::make_shared<Snapshot>();
    fillSnapshotScene(*before, Simulation(initial), initial.grains.theta);
    auto after = std::make_shared<Snapshot>();
    fillSnapshotScene(*after, sim, initial.grains.theta);
    ASSERT_NEAR(after->rotation[0], 0.4, 1e-9);

    const QSize size(300, 300);
    SceneOptions options;
    QPointF c0, c1;
    double scale0 = 0, scale1 = 0;
    const QImage still = draw(before, size, options, c0, scale0);
    const QImage turned = draw(after, size, options, c1, scale1);
    const double radius = 0.6 * spec.widths[0] * scale0 + 3; // half a width and a margin
    const Blob b0 = grainBlob(still, options, c0, radius);
    const Blob b1 = grainBlob(turned, options, c1, radius);
    ASSERT_GT(b0.pixels, 300);
    ASSERT_GT(b1.pixels, 300);
    // Clockwise on screen: the axis angle (anticlockwise positive, y up) decreases by 0.4 rad.
    const double turn = std::remainder(b1.angle - b0.angle, M_PI); // an axis, not a vector
    EXPECT_NEAR(turn, -0.4, 0.05);

    // ... and the grain is drawn red (full colour at +0.5 rad: 0.4 rad is well towards red).
    const QColor c = turned.pixelColor(c1.toPoint());
    EXPECT_GT(c.red(), c.blue() + 60) << c.name().toStdString();
}

} // namespace
} // namespace grainlab::ui
