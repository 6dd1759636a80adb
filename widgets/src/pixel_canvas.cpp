// See pixel_canvas.h.
#include "grainlab/ui/pixel_canvas.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace grainlab::ui {
namespace {

/// x * a / 255 on each 8-bit channel of x, rounded as Qt's raster engine rounds (BYTE_MUL).
inline std::uint32_t byteMul(std::uint32_t x, std::uint32_t a) {
    std::uint32_t t = (x & 0xff00ffu) * a;
    t = (t + ((t >> 8) & 0xff00ffu) + 0x800080u) >> 8;
    t &= 0xff00ffu;
    x = ((x >> 8) & 0xff00ffu) * a;
    x = (x + ((x >> 8) & 0xff00ffu) + 0x800080u);
    x &= 0xff00ff00u;
    return x | t;
}

/// A pixel index from a coordinate, clamped to [lo, hi] before the conversion (coordinates far
/// outside the image must not overflow an int).
inline int clampedIndex(double v, int lo, int hi) {
    return static_cast<int>(std::clamp(v, double(lo), double(hi)));
}

/// One non-horizontal polygon edge, upwards: it crosses the rows whose centres lie in [y0, y1).
struct Edge {
    double y0, y1, x0, slope; ///< x = x0 + (y - y0) slope
};

} // namespace

PixelCanvas::PixelCanvas(QImage& image, double scale)
    : width_(image.width()), height_(image.height()), scale_(scale) {
    // Source-over on an opaque pixel leaves it opaque: RGB32's alpha byte stays 0xff.
    if (image.format() != QImage::Format_ARGB32_Premultiplied &&
        image.format() != QImage::Format_RGB32) {
        throw std::invalid_argument("PixelCanvas: the image must be ARGB32_Premultiplied or RGB32");
    }
    bits_ = image.bits();
    stride_ = image.bytesPerLine();
}

void PixelCanvas::fillSpan(int y, int x0, int x1, QRgb premultiplied) {
    auto* row = reinterpret_cast<std::uint32_t*>(bits_ + y * stride_);
    if (qAlpha(premultiplied) == 255) {
        std::fill(row + x0, row + x1, std::uint32_t(premultiplied));
        return;
    }
    const std::uint32_t keep = 255u - qAlpha(premultiplied);
    for (int x = x0; x < x1; ++x) {
        row[x] = premultiplied + byteMul(row[x], keep);
    }
}

void PixelCanvas::fillPolygon(const QPointF* points, int n, QRgb colour) {
    if (n < 3 || qAlpha(colour) == 0) {
        return;
    }
    constexpr int kMostEdges = 256;
    Edge edges[kMostEdges];
    double crossings[kMostEdges];
    int count = 0;
    double top = 1e300, bottom = -1e300;
    for (int k = 0; k < n; ++k) {
        const double ax = points[k].x() * scale_, ay = points[k].y() * scale_;
        const QPointF& next = points[k + 1 < n ? k + 1 : 0];
        const double bx = next.x() * scale_, by = next.y() * scale_;
        if (!std::isfinite(ax) || !std::isfinite(ay) || !std::isfinite(bx) || !std::isfinite(by)) {
            return;
        }
        top = std::min(top, ay);
        bottom = std::max(bottom, ay);
        if (ay == by) {
            continue; // a horizontal edge crosses no row's centre line in its interior
        }
        if (count == kMostEdges) {
            return; // longer polygons than the scene draws
        }
        const double slope = (bx - ax) / (by - ay);
        edges[count++] = ay < by ? Edge{ay, by, ax, slope} : Edge{by, ay, bx, slope};
    }
    // Rows whose centres y + 0.5 lie in [top, bottom).
    const int row0 = clampedIndex(std::ceil(top - 0.5), 0, height_);
    const int row1 = clampedIndex(std::ceil(bottom - 0.5), 0, height_);
    const QRgb premultiplied = qPremultiply(colour);
    for (int y = row0; y < row1; ++y) {
        const double centre = y + 0.5;
        int m = 0;
        for (int e = 0; e < count; ++e) {
            if (edges[e].y0 <= centre && centre < edges[e].y1) {
                // Insertion sort as they come: a row crosses few edges (two for convex shapes).
                const double x = edges[e].x0 + (centre - edges[e].y0) * edges[e].slope;
                int k = m++;
                for (; k > 0 && crossings[k - 1] > x; --k) {
                    crossings[k] = crossings[k - 1];
                }
                crossings[k] = x;
            }
        }
        // Pixels whose centres x + 0.5 lie in [crossing 2k, crossing 2k + 1).
        for (int k = 0; k + 1 < m; k += 2) {
            const int x0 = clampedIndex(std::ceil(crossings[k] - 0.5), 0, width_);
            const int x1 = clampedIndex(std::ceil(crossings[k + 1] - 0.5), 0, width_);
            if (x0 < x1) {
                fillSpan(y, x0, x1, premultiplied);
            }
        }
    }
}

void PixelCanvas::fillConvexPolygon(const QPointF* points, int n, QRgb colour) {
    // The two chains of edges from the top vertex to the bottom one, walked down row by row:
    // on a convex polygon each row's centre line crosses one edge of each, which are the two
    // crossings fillPolygon would find among all edges.
    constexpr int kMostPoints = 256;
    if (n < 3 || n > kMostPoints || qAlpha(colour) == 0) {
        return;
    }
    double x[kMostPoints], y[kMostPoints];
    int top = 0, bottom = 0;
    for (int k = 0; k < n; ++k) {
        x[k] = points[k].x() * scale_;
        y[k] = points[k].y() * scale_;
        if (!std::isfinite(x[k]) || !std::isfinite(y[k])) {
            return;
        }
        top = y[k] < y[top] ? k : top;
        bottom = y[k] > y[bottom] ? k : bottom;
    }
    const int row0 = clampedIndex(std::ceil(y[top] - 0.5), 0, height_);
    const int row1 = clampedIndex(std::ceil(y[bottom] - 0.5), 0, height_);
    const QRgb premultiplied = qPremultiply(colour);
    // Chain c steps through the vertices by step[c] (forwards, backwards) from the top; its
    // current edge runs from vertex from[c] to vertex to[c].
    const int step[2] = {1, n - 1};
    int from[2] = {top, top}, to[2] = {(top + 1) % n, (top + n - 1) % n};
    double slope[2] = {0.0, 0.0};
    bool current[2] = {false, false}; ///< slope[c] is that of chain c's current edge
    for (int row = row0; row < row1; ++row) {
        const double centre = row + 0.5;
        double cross[2];
        for (int c = 0; c < 2; ++c) {
            // The edge of this chain that spans the row's centre line (y[from] <= centre <
            // y[to]); the chain ends at the bottom vertex, below every row drawn.
            while (y[to[c]] <= centre && to[c] != bottom) {
                from[c] = to[c];
                to[c] = (to[c] + step[c]) % n;
                current[c] = false;
            }
            if (!current[c]) {
                // As fillPolygon computes it, to the bit.
                slope[c] = (x[to[c]] - x[from[c]]) / (y[to[c]] - y[from[c]]);
                current[c] = true;
            }
            cross[c] = x[from[c]] + (centre - y[from[c]]) * slope[c];
        }
        const double left = std::min(cross[0], cross[1]), right = std::max(cross[0], cross[1]);
        const int x0 = clampedIndex(std::ceil(left - 0.5), 0, width_);
        const int x1 = clampedIndex(std::ceil(right - 0.5), 0, width_);
        if (x0 < x1) {
            fillSpan(row, x0, x1, premultiplied);
        }
    }
}

void PixelCanvas::drawLine(QPointF a, QPointF b, QRgb colour) {
    const double ax = a.x() * scale_, ay = a.y() * scale_, bx = b.x() * scale_, by = b.y() * scale_;
    if (std::isfinite(ax) && std::isfinite(ay) && std::isfinite(bx) && std::isfinite(by) &&
        qAlpha(colour) != 0) {
        line(ax, ay, bx, by, qRgba(qRed(colour), qGreen(colour), qBlue(colour), 255),
             qAlpha(colour));
    }
}

void PixelCanvas::drawPolygonOutline(const QPointF* points, int n, QRgb colour) {
    if (n < 2 || qAlpha(colour) == 0) {
        return;
    }
    const QRgb opaque = qRgba(qRed(colour), qGreen(colour), qBlue(colour), 255);
    const double x0 = points[0].x() * scale_, y0 = points[0].y() * scale_;
    double ax = x0, ay = y0;
    for (int k = 1; k <= n; ++k) {
        const double bx = k < n ? points[k].x() * scale_ : x0;
        const double by = k < n ? points[k].y() * scale_ : y0;
        if (std::isfinite(ax) && std::isfinite(ay) && std::isfinite(bx) && std::isfinite(by)) {
            line(ax, ay, bx, by, opaque, qAlpha(colour));
        }
        ax = bx;
        ay = by;
    }
}

void PixelCanvas::line(double ax, double ay, double bx, double by, QRgb opaque, int alpha) {
    // Steep lines are drawn with the roles of x and y exchanged: i runs along the line, j across.
    const bool steep = std::fabs(by - ay) > std::fabs(bx - ax);
    if (steep) {
        std::swap(ax, ay);
        std::swap(bx, by);
    }
    if (ax == bx) {
        return;
    }
    const int across = steep ? width_ : height_, along = steep ? height_ : width_;
    const double slope = (by - ay) / (bx - ax);
    // The columns whose centres lie between a (included) and b (excluded).
    int i0, i1;
    if (bx > ax) {
        i0 = clampedIndex(std::ceil(ax - 0.5), 0, along);
        i1 = clampedIndex(std::ceil(bx - 0.5), 0, along);
    } else {
        i0 = clampedIndex(std::floor(bx - 0.5) + 1.0, 0, along);
        i1 = clampedIndex(std::floor(ax - 0.5) + 1.0, 0, along);
    }
    // Pixel (i, j) of the line's frame is at bits_ + i * alongStep + j * acrossStep.
    const qsizetype acrossStep = steep ? 4 : stride_, alongStep = steep ? stride_ : 4;
    const std::uint32_t a = std::uint32_t(alpha);
    auto blend = [opaque](uchar* pixel, std::uint32_t coverage) {
        auto* p = reinterpret_cast<std::uint32_t*>(pixel);
        *p = byteMul(opaque, coverage) + byteMul(*p, 255u - coverage);
    };
    double t = ay + (i0 + 0.5 - ax) * slope - 0.5; // the line's centre, in pixel-centre units
    for (int i = i0; i < i1; ++i, t += slope) {
        if (!(t > -1.0 && t < across)) {
            continue;
        }
        // Rows j and j + 1 share the coverage by their distance from the line's centre.
        const int j = static_cast<int>(t + 1.0) - 1; // floor, as t > -1
        const auto share = static_cast<std::uint32_t>((t - j) * 256.0 + 0.5);
        const std::uint32_t lower = (a * share + 128) >> 8, upper = a - lower;
        uchar* column = bits_ + i * alongStep;
        if (j >= 0) {
            blend(column + j * acrossStep, upper);
        }
        if (j + 1 < across) {
            blend(column + (j + 1) * acrossStep, lower);
        }
    }
}

} // namespace grainlab::ui
