#pragma once
// Draws straight into the pixels of a 32-bit premultiplied image: aliased polygon fills and
// one-pixel antialiased lines, the two things the scene's overview needs (SceneRenderer, at
// zooms where a grain is a few pixels wide). Qt's raster engine pays a fixed cost for every
// shape it draws (~0.4 us a call before any pixel, more for antialiasing, and hand-overs to its
// thread pool); thousands of shapes a few pixels wide cost it tens of milliseconds, almost all of
// it overhead. Here a small polygon costs a few rows of a scanline loop.
//
// The rules are Qt's, so that a picture drawn here matches one drawn by QPainter:
// - a fill covers the pixels whose centres lie inside the polygon (odd-even rule), a centre on
//   an edge belonging to one side only (edges are half-open in y and x), so that polygons that
//   tile the plane cover each pixel exactly once;
// - a line is one pixel wide: in each column (each row, for a steep line) its coverage is split
//   between the two pixels nearest to it, in proportion to their distance (Wu's line), scaled
//   by the colour's alpha; consecutive segments of a polyline meet without drawing the shared
//   point twice;
// - blending is source-over on premultiplied 8-bit channels with Qt's rounding (BYTE_MUL).
//
// Plain code on a QImage: usable on any thread that owns the image.

#include <QImage>
#include <QPointF>
#include <QRgb>

namespace grainlab::ui {

class PixelCanvas {
public:
    /// Draws into `image`, which must be Format_ARGB32_Premultiplied, or Format_RGB32 when it is
    /// opaque (throws otherwise). Points are given in units that `scale` turns into image pixels
    /// (the device pixel ratio).
    explicit PixelCanvas(QImage& image, double scale = 1.0);

    /// Fills the polygon of `n` points, aliased, with `colour` (not premultiplied; its alpha
    /// blends).
    void fillPolygon(const QPointF* points, int n, QRgb colour);
    /// The same for a convex polygon, faster (a walk down its two sides).
    void fillConvexPolygon(const QPointF* points, int n, QRgb colour);
    /// A one-pixel antialiased line from a to b, without its end point b.
    void drawLine(QPointF a, QPointF b, QRgb colour);
    /// The closed outline of a polygon: its edges as drawLine draws them.
    void drawPolygonOutline(const QPointF* points, int n, QRgb colour);

private:
    /// drawLine in image pixels, with an opaque colour at coverage `alpha` (1-255).
    void line(double ax, double ay, double bx, double by, QRgb opaque, int alpha);
    void fillSpan(int y, int x0, int x1, QRgb premultiplied);

    uchar* bits_;      ///< the image's, which must outlive the canvas
    qsizetype stride_; ///< bytes per row
    int width_, height_;
    double scale_;
};

} // namespace grainlab::ui
