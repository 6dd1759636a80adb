#include "grainlab/snapshot.h"

#include "grainlab/measures.h"
#include "grainlab/simulation.h"

namespace grainlab {

void fillSnapshotScene(Snapshot& snap, const Simulation& sim,
                       const std::vector<double>& thetaAtStart, SnapshotMeasures measures) {
    const SimulationState& s = sim.stateRef();
    snap.step = sim.stepCount();
    snap.time = sim.time();
    snap.shapes = s.shapes;
    snap.shape = s.grains.shape;
    snap.network = sim.contactNetwork();
    snap.x1 = snap.network.x1;
    snap.x2 = snap.network.x2;
    snap.theta = s.grains.theta;
    snap.rotation.assign(s.grains.size(), 0.0);
    if (thetaAtStart.size() == s.grains.size()) {
        for (std::size_t i = 0; i < s.grains.size(); ++i) {
            snap.rotation[i] = s.grains.theta[i] - thetaAtStart[i];
        }
    }
    snap.measured = false;
    snap.loadBearing.clear();
    snap.voidCells.clear();
    if (measures == SnapshotMeasures::Now) {
        addSnapshotMeasures(snap);
    }
}

void addSnapshotMeasures(Snapshot& snap) {
    if (snap.measured) {
        return;
    }
    if (snap.network.x1.empty()) {
        snap.measured = true; // no grains, nothing to measure
        return;
    }
    const MeasureSet measures = computeMeasures(snap.network);
    snap.loadBearing = measures.loadBearing.grainInGraph;
    snap.voidCells.clear();
    snap.voidCells.reserve(measures.voidCells.cells.size());
    for (const VoidCell& c : measures.voidCells.cells) {
        VoidCellView v;
        v.grains = c.grains;
        v.area = c.area;
        v.elongation = c.elongation;
        v.direction = c.direction;
        v.centroid1 = c.centroid1;
        v.centroid2 = c.centroid2;
        v.valence = c.valence;
        v.x1.resize(c.vertices1.size());
        v.x2.resize(c.vertices2.size());
        for (std::size_t k = 0; k < c.vertices1.size(); ++k) {
            v.x1[k] = c.centroid1 + c.vertices1[k];
            v.x2[k] = c.centroid2 + c.vertices2[k];
        }
        snap.voidCells.push_back(std::move(v));
    }
    snap.measured = true;
}

} // namespace grainlab
