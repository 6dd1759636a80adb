#pragma once
// Draws a Snapshot with QPainter: the periodic cell, every grain as its true four-arc outline,
// optional periodic images, force chains, void cells, a contact-normal rose and a scale bar. The
// same code paints the live QPainter view, PNG images and vector exports (SVG, PDF), so what is
// exported is what is seen. Also answers hit tests (which grain or void cell is under a pixel).
//
// Used on the GUI thread by SceneView, and by exporters and tests on whatever thread owns the
// paint device. The snapshot is immutable; the renderer keeps derived data (coordination, force
// statistics, outlines) computed once per snapshot, so it is not itself thread-safe.

#include <array>
#include <cstdint>
#include <vector>

#include <QColor>
#include <QPointF>
#include <QPolygonF>
#include <QRgb>
#include <QSize>

#include "grainlab/snapshot.h"
#include "grainlab/ui/view_transform.h"

class QPainter;

namespace grainlab::ui {

enum class GrainColouring {
    Size,         ///< equivalent diameter, smallest dark to largest light
    Rotation,     ///< rotation since the start of the test, clockwise blue, anticlockwise red
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

/// What to draw. Plain data, changed freely between frames.
struct SceneOptions {
    GrainColouring colouring = GrainColouring::Size;
    bool periodicImages = false; ///< draw images of the grains near the cell border
    double imageBorder = 3.0;    ///< width of the image border, in largest grain widths
    ForceChains forceChains = ForceChains::Off;
    VoidCellShading voidCells = VoidCellShading::Off;
    bool contactRose = false; ///< polar histogram of contact normals in a corner
    bool scaleBar = true;
    bool caption = true;              ///< step, stage and eps1 at the top left
    double rotationRange = 0.5;       ///< |rotation| mapped to the end of the colour scale [rad]
    QColor background{250, 250, 250}; ///< outside the cell
    QColor cellFill{255, 255, 255};   ///< inside the cell
    QColor uniformGrain{150, 150, 160};
    int selectedGrain = -1;
    int selectedVoidCell = -1;
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
    /// The parts of render() below and above the grains, for a view that draws the grains
    /// itself (the OpenGL layer): background and cell; then void cells, force chains, the
    /// selected grain's outline (when `outlineSelectedGrain`), rose, scale bar and caption.
    void renderBackground(QPainter& painter, QSize viewport) const;
    void renderOverlays(QPainter& painter, QSize viewport, bool outlineSelectedGrain) const;
    /// Every grain and drawn periodic image with its fill colour (in the current options).
    std::vector<GrainInstance> grainInstances() const;

    /// The fill colour of grain `grain` in the current colour mode (before image lightening).
    QColor grainColour(int grain) const;
    /// Grain under a screen point (images included when drawn), or -1.
    int grainAt(QPointF screenPoint) const;
    /// Void cell under a screen point (cells near the border tested at their images), or -1.
    int voidCellAt(QPointF screenPoint) const;
    /// Void cell `index`'s polygon in world coordinates, shifted so that its vertex mean lies
    /// inside the cell (the way it is drawn).
    const QPolygonF& voidCellPolygon(int index) const { return voidPolygons_[index]; }
    /// Number of contacts of each grain (from the snapshot's network).
    const std::vector<int>& coordination() const { return coordination_; }
    /// Strong-contact threshold f_a = sqrt(sum |f|^2 / N_c) (SPEC §4) [N].
    double strongForceThreshold() const { return strongThreshold_; }
    /// Is world point (x1, x2) inside grain `grain` placed at centre (c1, c2)?
    bool grainContains(int grain, double c1, double c2, double x1, double x2) const;

private:
    /// Image shifts (i, j) at which grain `g` is drawn: (0, 0) first.
    int grainImages(int g, std::array<std::array<int, 2>, 9>& shifts) const;
    void drawCell(QPainter& p) const;
    void drawSelectedGrainOutline(QPainter& p) const;
    void drawGrains(QPainter& p, const WorldBox& box) const;
    void drawVoidCells(QPainter& p, const WorldBox& box) const;
    void drawForceChains(QPainter& p, const WorldBox& box) const;
    void drawRose(QPainter& p, QSize viewport) const;
    void drawScaleBar(QPainter& p, QSize viewport) const;
    void drawCaption(QPainter& p) const;

    SnapshotPtr snapshot_;
    SceneOptions options_;
    ViewTransform view_;
    // Derived from the snapshot.
    std::vector<int> coordination_;
    std::vector<std::uint8_t> loadBearing_; ///< the snapshot's, or computed when it has none
    std::vector<double> forceMagnitude_;    ///< per contact [N]
    std::vector<std::int32_t> forceOrder_;  ///< contacts by increasing force
    double maxForce_ = 0, strongThreshold_ = 0;
    double minDiameter_ = 0, maxDiameter_ = 0, maxHalfWidth_ = 0;
    std::vector<std::array<QPolygonF, 3>> outlines_; ///< per shape, body frame, 3 detail levels
    std::vector<QPolygonF> voidPolygons_;            ///< world coordinates
    std::vector<std::array<double, 4>> voidBoxes_;   ///< min1, max1, min2, max2
    double meanVoidArea_ = 0;
    std::array<double, 18> roseCounts_{}; ///< contact normals in 10 degree bins
};

} // namespace grainlab::ui
