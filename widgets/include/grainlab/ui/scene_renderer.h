#pragma once
// Draws a Snapshot with QPainter: the periodic cell, every grain as its true four-arc outline,
// optional periodic images, force chains, void cells, a contact-normal rose and a scale bar. The
// same code paints the live QPainter view, PNG images and vector exports (SVG, PDF), so what is
// exported is what is seen. Also answers hit tests (which grain or void cell is under a pixel).
//
// Used on the GUI thread by SceneView, and by exporters and tests on whatever thread owns the
// paint device. The snapshot is immutable; the renderer keeps derived data (coordination, force
// statistics) computed once per snapshot, and grain outlines and void-cell edges built on first
// use (also in const functions), so it is not itself thread-safe.
//
// Speed: the window redraws the scene up to 30 times a second beside the running engine, on the
// default view (800 grains about 40 pixels wide) as on the whole reference assembly (8450 grains,
// ~6000 void cells, ~5000 strong chains). What costs in Qt's raster engine (measured, see
// scene_renderer_grains.cpp and scene_renderer_overlays.cpp): antialiased fills (a high cost per
// shape), and translucent fills or lines that reach ~100 spans in one call, which Qt 6 hands to
// its GUI thread pool and waits for (tens of microseconds each, and on two cores the pool's
// threads compete with the engine thread). So on raster devices fills are aliased and shapes wide
// enough get an antialiased one-pixel outline that hides the staircase (vector exports get one
// smooth shape per grain); outlines have the fewest vertices that keep them within an eighth of
// a pixel of the true outline; pens and brushes change once per colour (items sorted by colour,
// force chains in 64 bins); translucent void cells are filled in bands of at most 64 pixel rows
// and outlined once per shared edge in pieces of at most 32 pixels. What a frame reads in drawing
// order (fills by colour, force chains by force) is gathered once per snapshot into arrays read
// in sequence.
//
// The overview: where no grain is wider than a few pixels (SceneOptions::overviewHalfWidth, 12
// pixels in half width: the whole reference assembly in a window), thousands of shapes a few
// pixels wide cost Qt mostly its fixed cost per call. There the grains and the void-cell shading
// are drawn straight into the pixels of an image (PixelCanvas, the same rules: aliased fills,
// one-pixel antialiased outlines and edges) in bands down the screen, and the image goes onto
// the device in one copy; force chains and annotations follow through QPainter. Its picture
// equals the full drawing's within a stated tolerance at the sizes where it switches
// (tests/widgets/scene_overview_test.cpp).
//
// The implementation is split by what is drawn: scene_renderer.cpp (derived data, colours, hit
// tests, the order of the layers), scene_renderer_grains.cpp, scene_renderer_overlays.cpp (void
// cells, force chains) and scene_renderer_decorations.cpp (cell, rose, scale bar, caption).

#include <array>
#include <cstdint>
#include <vector>

#include <QColor>
#include <QImage>
#include <QPointF>
#include <QPolygonF>
#include <QRgb>
#include <QSize>

#include "grainlab/snapshot.h"
#include "grainlab/ui/view_transform.h"

class QPainter;

namespace grainlab::ui {

class PixelCanvas;

enum class GrainColouring {
    Size,         ///< equivalent diameter, smallest dark to largest light
    Rotation,     ///< rotation since the start of the test: positive (x1 towards x2, clockwise
                  ///< on screen, where x1 points up) red, negative blue
    Coordination, ///< number of contacts, 0 to 8+
    LoadBearing,  ///< load-bearing graph vs rattlers
    Uniform,      ///< one colour
};

enum class ForceChains { Off, Strong, All };
enum class VoidCellShading { Off, Valence, Area };

/// One grain (or periodic image of a grain) as the OpenGL layer draws it.
struct GrainInstance {
    double x1, x2;      ///< centre [m]
    double theta;       ///< orientation [rad]
    std::int32_t shape; ///< index into the snapshot's shapes
    QRgb colour;        ///< fill, images already lightened
};

/// One force-chain segment as the OpenGL layer draws it: the same bins as the QPainter view.
struct ChainSegment {
    double a1, a2, b1, b2; ///< end points [m]
    double width;          ///< [pixel]
    QRgb colour;           ///< not premultiplied
};

/// What renderOverlays() paints.
enum class Overlays {
    All,        ///< void cells, force chains, rose, scale bar, caption
    Annotations ///< for the OpenGL layer, which draws void-cell shading and force chains
                ///< itself: the selected grain's outline and void cell, rose, bar, caption
};

/// What to draw. Plain data, changed freely between frames.
struct SceneOptions {
    GrainColouring colouring = GrainColouring::Size;
    bool periodicImages = false; ///< draw images of the grains near the cell border
    double imageBorder = 3.0;    ///< width of the image border, in largest grain widths
    ForceChains forceChains = ForceChains::Off;
    VoidCellShading voidCells = VoidCellShading::Off;
    bool contactRose = false; ///< polar histogram of contact normals in a corner
    bool scaleBar = true;
    bool caption = true; ///< step, stage and eps1 at the top left
    /// The key of the void-cell colours (valence, or area over the mean area) at the bottom
    /// right, when void cells are shaded.
    bool colourKey = true;
    double rotationRange = 0.5;       ///< |rotation| mapped to the end of the colour scale [rad]
    QColor background{250, 250, 250}; ///< outside the cell
    QColor cellFill{255, 255, 255};   ///< inside the cell
    QColor uniformGrain{150, 150, 160};
    int selectedGrain = -1;
    int selectedVoidCell = -1;
    /// [pixel] The overview's level of detail: on raster devices (the window's QPainter view,
    /// PNG images), when no grain is wider than this in half width at the current zoom, the
    /// grains and the void-cell shading are drawn straight into the pixels (PixelCanvas) instead
    /// of shape by shape through QPainter, with the same rules. 0: never.
    double overviewHalfWidth = 12.0;
};

class SceneRenderer {
public:
    SceneRenderer();

    /// Sets the snapshot to draw and recomputes what depends on it (one pass over grains and
    /// contacts). A null pointer clears the scene.
    void setSnapshot(SnapshotPtr snapshot);
    const SnapshotPtr& snapshot() const { return snapshot_; }

    SceneOptions& options() { return options_; }
    const SceneOptions& options() const { return options_; }
    ViewTransform& view() { return view_; }
    const ViewTransform& view() const { return view_; }
    /// Fits the whole cell into a viewport.
    void fitToCell(QSize viewport);

    /// Paints the scene into a viewport of `viewport` pixels (device or logical units of the
    /// painter). Only what is visible is drawn, with outline detail matched to the zoom.
    void render(QPainter& painter, QSize viewport) const;
    /// Does render() draw the grains and void-cell shading on `painter` as an overview, straight
    /// into the pixels (a raster device, no transformation, no grain wider than
    /// SceneOptions::overviewHalfWidth)?
    bool drawsOverview(const QPainter& painter) const;
    /// The parts of render() below and above the grains, for a view that draws the grains
    /// itself (the OpenGL layer): background and cell; then the overlays (see Overlays).
    void renderBackground(QPainter& painter, QSize viewport) const;
    void renderOverlays(QPainter& painter, QSize viewport, Overlays overlays) const;
    /// Every grain and drawn periodic image with its fill colour (in the current options).
    std::vector<GrainInstance> grainInstances() const;
    /// The force-chain segments visible in a viewport, in drawing order (weakest first), with
    /// their widths and colours at the current zoom; empty when force chains are off.
    std::vector<ChainSegment> forceChainSegments(QSize viewport) const;

    /// The fill colour of grain `grain` in the current colour mode (before image lightening).
    /// Rotations are shown in 256 steps of colour across the range.
    QColor grainColour(int grain) const;
    /// The fill of void cell `index` in the current shading (by area: 128 steps of colour
    /// across the two decades), with its alpha; the selected cell's is more opaque.
    QColor voidCellColour(int index) const;
    /// Colour and width [pixel, at the current zoom] of a force-chain line for a contact force
    /// of magnitude `force` [N], exactly (the views draw each bin's mean force).
    QColor forceChainColour(double force) const;
    double forceChainWidth(double force) const;
    /// Grain under a screen point (images included when drawn), or -1.
    int grainAt(QPointF screenPoint) const;
    /// Void cell under a screen point (cells near the border tested at their images), or -1.
    int voidCellAt(QPointF screenPoint) const;
    /// Void cell `index`'s polygon in world coordinates, shifted so that its vertex mean lies
    /// inside the cell (the way it is drawn).
    const QPolygonF& voidCellPolygon(int index) const { return voidPolygons_[index]; }
    /// Number of contacts of each grain (from the snapshot's network).
    const std::vector<int>& coordination() const { return coordination_; }
    /// Strong-contact threshold f_a = sqrt(sum |f|^2 / N_c): the engine's strongForceThreshold
    /// (RmsForce) [N].
    double strongForceThreshold() const { return strongThreshold_; }
    /// Is world point (x1, x2) inside grain `grain` placed at centre (c1, c2)?
    bool grainContains(int grain, double c1, double c2, double x1, double x2) const;

private:
    static constexpr int kOutlineLevels = 9;   ///< detail levels of the grain outlines
    static constexpr int kVoidCellAlpha = 120; ///< of void-cell fills; the selected one's is 200

    /// Image shifts (i, j) at which grain `g` is drawn: (0, 0) first.
    int grainImages(int g, std::array<std::array<int, 2>, 9>& shifts) const;
    /// Outline of shape `shape` in its body frame at detail `level` (built on first use).
    const QPolygonF& outline(int shape, int level) const;
    /// Writes grain `g` at image shift `shift` as screen points at detail `level` into `screen`
    /// (room for outline(shape, level).size() points); returns the point count.
    int grainScreenOutline(int g, std::array<int, 2> shift, int level, QPointF* screen) const;
    void drawCell(QPainter& p) const;
    void drawSelectedGrainOutline(QPainter& p, const WorldBox& box) const;
    /// The visible grains and images in drawing order, with their screen outlines.
    struct GrainItems;
    GrainItems visibleGrains(const WorldBox& box) const;
    void drawGrains(QPainter& p, const WorldBox& box) const;
    void drawGrains(PixelCanvas& canvas, const WorldBox& box) const;
    /// Background, cell, grains and void-cell shading drawn into layer_ with PixelCanvas, then
    /// onto `p`.
    void drawOverview(QPainter& p, QSize viewport, const WorldBox& box) const;
    /// Calls f(i, j) for each periodic image (i, j) of void cell `v` that reaches into `box`.
    template <class F>
    void forEachVisibleVoidImage(int v, const WorldBox& box, F&& f) const;
    /// Calls f(a, b) with the screen end points of each void-cell edge (each shared edge once,
    /// at each drawn periodic image) that reaches into `box`.
    template <class F>
    void forEachVisibleVoidEdge(const WorldBox& box, F&& f) const;
    void drawVoidCells(QPainter& p, const WorldBox& box, bool shading) const;
    void drawVoidCellShading(PixelCanvas& canvas, const WorldBox& box) const;
    /// The overlays above the grains; `voidShading`: the void cells' fills and outlines.
    void drawOverlays(QPainter& p, QSize viewport, bool voidShading, bool chains,
                      bool selectedGrain) const;
    void drawForceChains(QPainter& p, const WorldBox& box) const;
    /// Calls visit(bin, a1, a2, b1, b2) for every visible force-chain segment, bin by bin.
    template <class Visit>
    void forEachVisibleChain(const WorldBox& box, Visit&& visit) const;
    void drawRose(QPainter& p, QSize viewport) const;
    void drawScaleBar(QPainter& p, QSize viewport) const;
    void drawCaption(QPainter& p) const;
    void drawColourKey(QPainter& p, QSize viewport) const;
    /// Where a void cell's valence, or area over the mean area, sits on the colour scale [0, 1]
    /// of the current shading (one rule for the fills and their key).
    double voidCellScalePosition(double valence, double areaOverMean) const;

    SnapshotPtr snapshot_;
    SceneOptions options_;
    ViewTransform view_;
    // Derived from the snapshot.
    std::vector<int> coordination_;
    std::vector<std::uint8_t> loadBearing_; ///< the snapshot's, or the engine's loadBearingGraph
    std::vector<double> forceMagnitude_;    ///< per contact [N]
    std::vector<std::int32_t> forceOrder_;  ///< contacts by increasing force
    /// Runs of forceOrder_ drawn with one pen: equal force bins, split at the strong threshold.
    struct ChainBin {
        std::int32_t begin, end; ///< range in forceOrder_
        double force;            ///< mean force of the bin, which sets its pen [N]
        bool strong;             ///< every contact of the bin is above the threshold
    };
    std::vector<ChainBin> chainBins_;
    /// One contact as a force-chain line, in the order of forceOrder_.
    struct ChainLine {
        double a1, a2;           ///< centre of grain A [m]
        double branch1, branch2; ///< from A to B's image [m]
        double length;           ///< |branch| [m]
        double b1, b2;           ///< centre of grain B [m]
        bool crossesBorder;      ///< B's image is not B: also drawn from B's side
    };
    /// The force-chain lines gathered from the contacts in drawing order, so that a frame reads
    /// them in sequence instead of jumping through the contacts and grains: valid from position
    /// `from` of forceOrder_ on (built on first use).
    const std::vector<ChainLine>& chainLines(std::int32_t from) const;
    mutable std::vector<ChainLine> chainLines_;
    mutable std::int32_t chainLinesFrom_ = 0; ///< chainLines_ is valid from here on
    double maxForce_ = 0, strongThreshold_ = 0;
    double minDiameter_ = 0, maxDiameter_ = 0, maxHalfWidth_ = 0;
    /// Per shape, body frame, by detail level; empty until first used (see outline()).
    mutable std::vector<std::array<QPolygonF, kOutlineLevels>> outlines_;
    std::vector<QPolygonF> voidPolygons_;          ///< world coordinates
    std::vector<std::array<double, 4>> voidBoxes_; ///< min1, max1, min2, max2
    std::vector<std::int32_t> voidOrder_;          ///< the cells by increasing min1
    /// The void cells' outline edges, each once [m] (built on first use).
    const std::vector<std::array<double, 4>>& voidEdges() const;
    mutable std::vector<std::array<double, 4>> voidEdges_;
    mutable bool voidEdgesReady_ = false;
    /// One void cell's fill: its colour (alpha kVoidCellAlpha) and its polygon, a range of
    /// voidFillPoints_.
    struct VoidFill {
        QRgb colour;
        std::int32_t cell;
        std::int32_t begin, end;
    };
    /// The void-cell fills of the current shading sorted by colour (then cell), their polygons
    /// copied into one array in that order, so that a frame neither computes colours nor sorts
    /// (built on first use and when the shading changes).
    const std::vector<VoidFill>& voidFills() const;
    /// The fill colour of void cell `v` in the current shading, with alpha `alpha`.
    QColor voidCellShade(int v, int alpha) const;
    mutable std::vector<VoidFill> voidFills_;
    mutable std::vector<QPointF> voidFillPoints_;
    mutable VoidCellShading voidFillsShading_ = VoidCellShading::Off; ///< Off: not built
    double meanVoidArea_ = 0;
    std::array<double, 18> roseCounts_{}; ///< contact normals in 10 degree bins
    /// The overview's picture before it goes onto the painter's device (drawOverview()).
    mutable QImage layer_;
};

} // namespace grainlab::ui
