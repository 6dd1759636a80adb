#pragma once
// An immutable picture of a run at one instant, published by the engine's worker thread at most
// every ~16 ms as std::shared_ptr<const Snapshot> and drawn by the GUI thread. Nothing in it
// is modified after publication, so it may be read from any thread without locking.

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "grainlab/contact_network.h"
#include "grainlab/oval_shape.h"
#include "grainlab/run_warning.h"
#include "grainlab/series.h"
#include "grainlab/stage_kind.h"

namespace grainlab {

/// One void cell as drawn and inspected (see void_cells.h for the definitions).
struct VoidCellView {
    std::vector<std::int32_t> grains;    ///< grains around the cell, in order
    std::vector<double> x1, x2;          ///< polygon vertices, absolute, may leave the cell [m]
    double area = 0;                     ///< [m^2]
    double elongation = 1;               ///< principal-axis ratio >= 1 [-]
    double direction = 0;                ///< major-axis angle from x1 [rad]
    double centroid1 = 0, centroid2 = 0; ///< wrapped into the cell [m]
    int valence = 0;                     ///< number of sides (grains)
};

struct Snapshot {
    std::int64_t step = 0;
    double time = 0;   ///< [s]
    std::string stage; ///< for display: "compaction 15 kPa", "shear 100 kPa"
    StageKind stageKind = StageKind::Compaction; ///< the stage's kind, as data
    double stagePressure = 0;                    ///< the stage's confining pressure [Pa]
    std::string test;                            ///< the test the series belongs to
    /// Orientations at the start of the test, which `rotation` counts from [rad]; shared by
    /// the snapshots of one test (never modified). Null or empty: none (compaction).
    std::shared_ptr<const std::vector<double>> thetaAtTestStart;
    double axialStrain = 0;    ///< eps1 [-]
    double progress = 0;       ///< fraction of the whole experiment done [0, 1]
    double stepsPerSecond = 0; ///< measured engine speed
    double etaSeconds = -1;    ///< estimated time left, -1 if unknown

    std::vector<OvalShape> shapes;
    std::vector<std::int32_t> shape;   ///< per grain: index into shapes
    std::vector<double> x1, x2, theta; ///< centres wrapped into the cell [m], orientation [rad]
    std::vector<double> rotation;      ///< rotation since the start of the test [rad]
    ContactNetwork network;            ///< touching contacts (cell, centres, forces)
    /// False while the two members below are still to be computed (SnapshotMeasures::Later).
    bool measured = false;
    std::vector<std::uint8_t> loadBearing; ///< per grain: 1 if in the load-bearing graph
    std::vector<VoidCellView> voidCells;
    std::vector<SeriesTable> series;  ///< every test's series so far (the live one last)
    std::vector<RunWarning> warnings; ///< every warning the run has given so far
};

using SnapshotPtr = std::shared_ptr<const Snapshot>;

class Simulation;

/// Whether filling a snapshot also computes its measures (load-bearing flags, void cells), or
/// leaves them to addSnapshotMeasures() on another thread: the live window does that, so that
/// the engine's thread spends only the copy of the configuration on each picture.
enum class SnapshotMeasures { Now, Later };

/// Fills the scene of `snapshot` from the simulation's current configuration: shapes, grains
/// (centres wrapped into the cell), the contact network and, unless `measures` is Later, the
/// load-bearing flags and the void cells. `thetaAtStart` gives each grain's orientation at the
/// start of the test for `rotation` (empty: rotation 0). Called on the thread that owns
/// `simulation`.
void fillSnapshotScene(Snapshot& snapshot, const Simulation& simulation,
                       const std::vector<double>& thetaAtStart = {},
                       SnapshotMeasures measures = SnapshotMeasures::Now);

/// Computes the load-bearing flags and the void cells of `snapshot` from its contact network
/// (no effect when it is already measured). Needs no simulation: any thread, before publication.
void addSnapshotMeasures(Snapshot& snapshot);

} // namespace grainlab
