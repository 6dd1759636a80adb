#pragma once
// Small real scenes for the widget tests: a grid assembly compacted for a few thousand steps by
// the engine, turned into a Snapshot (grains, contacts, void cells, a synthetic series). Built
// once per test binary on the test's thread.

#include <cmath>
#include <cstdint>

#include "grainlab/assembly.h"
#include "grainlab/simulation.h"
#include "grainlab/snapshot.h"
#include "grainlab/void_cells.h"

namespace grainlab::testing {

/// A snapshot of `grains` ovals compacted isotropically for `steps` steps.
/// Compaction stops early once the mean coordination exceeds 3.4 (a dense, connected network).
inline SnapshotPtr makeCompactedSnapshot(int grains = 150, std::int64_t steps = 200000) {
    AssemblySpec spec;
    spec.grainCount = grains;
    spec.widths = evenlySpacedWidths(1e-3, 2e-3, 5);
    spec.aspectRatio = 0.6;
    spec.seed = 7;
    SimulationParameters parameters;
    parameters.friction = 0.3;
    parameters.servo.maxStrainRate = 20.0;
    const SimulationState initial = generateGridAssembly(spec, parameters);
    Simulation sim(initial);
    const AxisControl servo{AxisMode::Stress, 0.0, 1e5};
    sim.setAxisControl(0, servo);
    sim.setAxisControl(1, servo);
    for (std::int64_t done = 0; done < steps; done += 1000) {
        sim.advance(1000);
        if (2.0 * double(sim.contactCount()) > 3.4 * grains && sim.stress().s11 > 5e4) {
            break;
        }
    }

    auto s = std::make_shared<Snapshot>();
    s->step = sim.stepCount();
    s->time = sim.time();
    s->stage = "compaction 100 kPa";
    s->test = "compaction";
    const SimulationState& state = sim.stateRef();
    s->shapes = state.shapes;
    s->shape = state.grains.shape;
    s->network = sim.contactNetwork();
    s->x1 = s->network.x1;
    s->x2 = s->network.x2;
    s->theta = state.grains.theta;
    for (std::size_t g = 0; g < s->theta.size(); ++g) {
        s->rotation.push_back(state.grains.theta[g] - initial.grains.theta[g]);
    }
    const VoidCellSet cells = computeVoidCells(s->network);
    for (const VoidCell& c : cells.cells) {
        VoidCellView v;
        v.grains = c.grains;
        for (std::size_t k = 0; k < c.vertices1.size(); ++k) {
            v.x1.push_back(c.centroid1 + c.vertices1[k]);
            v.x2.push_back(c.centroid2 + c.vertices2[k]);
        }
        v.area = c.area;
        v.elongation = c.elongation;
        v.direction = c.direction;
        v.centroid1 = c.centroid1;
        v.centroid2 = c.centroid2;
        v.valence = c.valence;
        s->voidCells.push_back(std::move(v));
    }
    return s;
}

/// A synthetic shear series (columns of SPEC §4 that the charts use) for test `name`.
inline SeriesTable makeSeries(const std::string& name, int rows, double peak) {
    SeriesTable t;
    t.test = name;
    for (const char* column :
         {"eps1", "epsv", "q_over_p", "Hdev", "Hsdev", "Hwdev", "Z", "Z_eff", "S", "Nv_over_Nvi"}) {
        t.columns.push_back({column, "-"});
    }
    for (int k = 0; k < rows; ++k) {
        const double e = 0.15 * k / std::max(1, rows - 1);
        const double q = peak * (1.0 - std::exp(-e / 0.01));
        t.rows.push_back({e, 0.002 - 0.1 * e, q, 0.4 * q, 0.6 * q, 0.1 * q, 3.9 - 2 * e,
                          4.1 - 3 * e, 0.2 * q, 1.0 - 2 * e});
        t.stages.push_back("shear " + name);
    }
    return t;
}

} // namespace grainlab::testing
