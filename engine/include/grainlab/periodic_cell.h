#pragma once
// Arithmetic of the periodic cell (docs/physics.md): the cell matrix h has the cell vectors as its
// columns, stored column-major as {h11, h21, h12, h22}. Inline functions of plain numbers, for
// the engine, the measures and the renderers on any thread.

#include <algorithm>
#include <array>
#include <cmath>

namespace grainlab {

using CellMatrix = std::array<double, 4>; ///< column-major 2x2 [m] (or [1/s] for L)

inline double cellDeterminant(const CellMatrix& h) {
    return h[0] * h[3] - h[2] * h[1];
}

inline CellMatrix cellInverse(const CellMatrix& h) {
    const double d = cellDeterminant(h);
    return {h[3] / d, -h[1] / d, -h[2] / d, h[0] / d};
}

/// a * b for column-major 2x2 matrices.
inline CellMatrix cellProduct(const CellMatrix& a, const CellMatrix& b) {
    return {a[0] * b[0] + a[2] * b[1], a[1] * b[0] + a[3] * b[1], a[0] * b[2] + a[2] * b[3],
            a[1] * b[2] + a[3] * b[3]};
}

/// Widths of the cell across each axis: the distance between the two faces spanned by the
/// other cell vector (area / length of the other vector) [m].
inline std::array<double, 2> cellWidths(const CellMatrix& h) {
    const double area = std::fabs(cellDeterminant(h));
    return {area / std::hypot(h[2], h[3]), area / std::hypot(h[0], h[1])};
}

/// Spectral norm |F - I|_2 of a 2x2 matrix's difference from the identity.
inline double spectralNormOfDifferenceFromIdentity(const CellMatrix& F) {
    const double a = F[0] - 1.0, b = F[2], c = F[1], d = F[3] - 1.0;
    // Largest singular value of [[a, b], [c, d]].
    const double s = a * a + b * b + c * c + d * d;
    const double det = a * d - b * c;
    const double disc = std::sqrt(std::max(0.0, s * s - 4.0 * det * det));
    return std::sqrt(0.5 * (s + disc));
}

/// Fractional coordinates s = h^-1 x.
inline std::array<double, 2> toFractional(const CellMatrix& h, double x1, double x2) {
    const double d = cellDeterminant(h);
    return {(h[3] * x1 - h[2] * x2) / d, (-h[1] * x1 + h[0] * x2) / d};
}

} // namespace grainlab
