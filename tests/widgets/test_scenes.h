#pragma once
// Small real scenes for the widget tests: the shared compacted scene (engine/scenes), turned
// into a Snapshot (grains, contacts, void cells, a synthetic series). Built
// once per test binary on the test's thread.

#include <cmath>
#include <cstdint>
#include <memory>

#include "grainlab/assembly.h"
#include "grainlab/scenes/compacted_scene.h"
#include "grainlab/simulation.h"
#include "grainlab/snapshot.h"
#include "grainlab/void_cells.h"

namespace grainlab::testing {

/// A snapshot of `grains` ovals compacted isotropically to 100 kPa by the shared compacted scene
/// (the experiment runner's equilibrium rule), at most `steps` steps.
inline SnapshotPtr makeCompactedSnapshot(int grains = 150, std::int64_t steps = 200000) {
    scenes::CompactedSceneSpec spec;
    spec.grains = grains;
    spec.widths = evenlySpacedWidths(1e-3, 2e-3, 5);
    spec.aspectRatio = 0.6;
    spec.seed = 7;
    spec.friction = 0.3;
    spec.pressure = 1e5;
    spec.criterion.maxSteps = steps;
    const scenes::CompactedScene scene = scenes::compactScene(spec);

    auto s = std::make_shared<Snapshot>();
    fillSnapshotScene(*s, scene.simulation, scene.initialTheta);
    s->stage = "compaction 100 kPa";
    s->test = "compaction";
    return s;
}

/// A copy of `complete` without its measures (void cells, load-bearing flags), as the live run
/// builds its pictures for the controller's snapshot thread to complete.
inline std::shared_ptr<Snapshot> unmeasuredCopy(const Snapshot& complete) {
    auto s = std::make_shared<Snapshot>(complete);
    s->measured = false;
    s->loadBearing.clear();
    s->voidCells.clear();
    return s;
}

/// A synthetic shear series (columns of docs/measures.md that the charts use) for test `name`.
inline SeriesTable makeSeries(const std::string& name, int rows, double peak) {
    SeriesTable t;
    t.test = name;
    for (const char* column : {"eps1", "epsv", "q_over_p", "Hdev", "Hsdev", "Hwdev", "Z", "Z_eff",
                               "S", "Nv_over_Nvi", "p", "q", "e"}) {
        t.columns.push_back({column, "-"});
    }
    for (int k = 0; k < rows; ++k) {
        const double e = 0.15 * k / std::max(1, rows - 1);
        const double q = peak * (1.0 - std::exp(-e / 0.01));
        const double p = 20e3 * (1.0 + e);
        t.rows.push_back({e, 0.002 - 0.1 * e, q, 0.4 * q, 0.6 * q, 0.1 * q, 3.9 - 2 * e,
                          4.1 - 3 * e, 0.2 * q, 1.0 - 2 * e, p, q * p, 0.2 - 0.1 * e});
        t.stages.push_back("shear " + name);
        t.stageKinds.push_back("shear");
    }
    return t;
}

/// A compaction series as the runner records it: step, p, e, Z, I_uf (and eps1, 0 throughout),
/// two stages.
inline SeriesTable makeCompactionSeries(int rows) {
    SeriesTable t;
    t.test = "compaction";
    for (const char* column : {"step", "eps1", "p", "e", "Z", "I_uf"}) {
        t.columns.push_back({column, "-"});
    }
    for (int k = 0; k < rows; ++k) {
        const double s = 1000.0 * (k + 1);
        t.rows.push_back({s, 0.0, 15e3 * (1.0 - std::exp(-k / 10.0)) + (k > rows / 2 ? 10e3 : 0.0),
                          0.4 - 0.1 * std::exp(-k / 10.0), 3.5 * (1.0 - std::exp(-k / 5.0)),
                          50.0 * std::exp(-k / 8.0)});
        t.stages.push_back(k > rows / 2 ? "compaction 25 kPa" : "compaction 15 kPa");
        t.stageKinds.push_back("compaction");
    }
    return t;
}

} // namespace grainlab::testing
