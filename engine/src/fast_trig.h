#pragma once
// Engine-internal sin/cos for the grain loop (see sinCos). Pure inline arithmetic; any thread.

#include <cstdint>

namespace grainlab {

/// sin and cos of x, to about one unit in the last place for |x| < 10^6, written without calls
/// or branches so that the integrator's grain loop vectorises (libm's sincos was ~11 % of a
/// step). Every orientation's cos and sin come from here, so a restart sees the same bits.
/// Reduction x = k pi/2 + r, |r| <= pi/4, with pi/2 in three parts (Cody and Waite): the first
/// two have 33 significant bits, so k times them is exact for |k| < 2^20. Then the Taylor
/// series of sin to r^17 and cos to r^18 (truncation below 1e-19 on |r| <= pi/4).
inline void sinCos(double x, double& sine, double& cosine) {
    constexpr double kTwoOverPi = 0.6366197723675814;
    constexpr double kHalfPi1 = 0x1.921fb544p+0, kHalfPi2 = 0x1.0b4611a6p-34,
                     kHalfPi3 = 0x1.3198a2e037073p-69;
    constexpr double kRound = 0x1.8p52; // adding and subtracting it rounds to an integer
    const double k = (x * kTwoOverPi + kRound) - kRound;
    const double r = ((x - k * kHalfPi1) - k * kHalfPi2) - k * kHalfPi3;
    const double r2 = r * r;
    // 1/n! for n = 2..18.
    constexpr double c2 = 1.0 / 2, c3 = 1.0 / 6, c4 = 1.0 / 24, c5 = 1.0 / 120, c6 = 1.0 / 720,
                     c7 = 1.0 / 5040, c8 = 1.0 / 40320, c9 = 1.0 / 362880, c10 = 1.0 / 3628800,
                     c11 = 1.0 / 39916800, c12 = 1.0 / 479001600, c13 = 1.0 / 6227020800,
                     c14 = 1.0 / 87178291200, c15 = 1.0 / 1307674368000, c16 = 1.0 / 20922789888000,
                     c17 = 1.0 / 355687428096000, c18 = 1.0 / 6402373705728000;
    const double sr =
        r + r * r2 *
                (-c3 +
                 r2 * (c5 +
                       r2 * (-c7 + r2 * (c9 + r2 * (-c11 + r2 * (c13 + r2 * (-c15 + r2 * c17)))))));
    const double cr =
        1.0 +
        r2 * (-c2 +
              r2 * (c4 +
                    r2 * (-c6 +
                          r2 * (c8 +
                                r2 * (-c10 + r2 * (c12 + r2 * (-c14 + r2 * (c16 - r2 * c18))))))));
    // Quadrant q = k mod 4: (sin, cos) = (s, c), (c, -s), (-s, -c), (-c, s). An integer, not
    // floor(): GCC vectorises no floor() under -ftrapping-math. Selects, not branches.
    const std::int64_t q = static_cast<std::int64_t>(k) & 3;
    const bool odd = (q & 1) != 0;
    const double s0 = odd ? cr : sr, c0 = odd ? sr : cr;
    sine = q >= 2 ? -s0 : s0;
    cosine = ((q == 1) | (q == 2)) ? -c0 : c0;
}

} // namespace grainlab
