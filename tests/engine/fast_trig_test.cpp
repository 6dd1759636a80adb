// The engine's inline sin/cos (engine/src/fast_trig.h) against the C library.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "fast_trig.h"
#include "grainlab/random.h"

namespace grainlab {
namespace {

TEST(FastTrig, AgreesWithTheCLibraryToAFewUlps) {
    Random random(99);
    double worst = 0;
    for (int k = 0; k < 2000000; ++k) {
        // Orientations met in runs: mostly a few turns, some far out.
        const double scale = k % 10 == 0 ? 1e5 : 20.0;
        const double x = random.uniform(-scale, scale);
        double s, c;
        sinCos(x, s, c);
        worst = std::max({worst, std::fabs(s - std::sin(x)), std::fabs(c - std::cos(x))});
        ASSERT_LE(s * s + c * c, 1.0 + 1e-15);
    }
    EXPECT_LT(worst, 4e-16);
    // Exact quadrant boundaries and signs.
    const double pi = std::numbers::pi;
    for (int q = -8; q <= 8; ++q) {
        double s, c;
        sinCos(q * 0.5 * pi, s, c);
        EXPECT_NEAR(s, std::sin(q * 0.5 * pi), 1e-15) << q;
        EXPECT_NEAR(c, std::cos(q * 0.5 * pi), 1e-15) << q;
    }
}

} // namespace
} // namespace grainlab
