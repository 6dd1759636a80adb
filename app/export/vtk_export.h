#pragma once
// `grainlab export vtk RUN --out DIR` and the window's Export > ParaView files…: a run file's
// checkpoints as VTK XML files for ParaView (docs/paraview.md). For each test of the run, the
// chosen checkpoints become four .vtp files each (the grains' outlines, the contacts, the void
// cells and the periodic cell) and the test gets one .pvd time index (time = eps1 of the test).
//
// Everything is read from the run file as the engine stored it (run_file.h): the states, the
// contacts with their forces and strong/sliding flags, the void cells' polygons. Nothing of the
// physics is computed again; the only geometry here is the sampling of the oval outlines
// (OvalShape::boundaryPoint) and the drawing of contacts through the periodic boundary.
//
// The export is written into a hidden folder beside DIR, renamed to DIR when complete: an
// export that fails leaves nothing, and an existing DIR is never written into. Runs on the
// caller's thread (the CLI's main thread, or the `grainlab export` process the window starts).

#include <array>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "export/vtk_files.h"
#include "grainlab/oval_shape.h"
#include "grainlab/run_file.h"
#include "grainlab/simulation_state.h"

namespace grainlab {

/// Bad input: not a run folder, an unfinished run without `unfinished`, a damaged run file, an
/// existing --out. The message names the file and what is allowed.
struct VtkExportRefused : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct VtkExportOptions {
    std::string run;             ///< the run folder (or its run.h5)
    std::string out;             ///< the export folder, which must not exist (or be empty)
    int every = 1;               ///< every N-th checkpoint of each test (its last one always)
    std::vector<double> strains; ///< else: per test the checkpoint nearest each eps1 [-]
    bool unfinished = false;     ///< export an unfinished run's checkpoints too
};

/// The outline polygon of a grain drawn as cells: its vertices lie on the outline, and the
/// outline lies within this fraction of the grain's width of the polygon [-].
inline constexpr double kOutlineTolerance = 0.01;

/// The polygon of an oval's outline in its body frame, counter-clockwise from the right end:
/// each of the four arcs is cut into equal chords whose sagitta r (1 - cos(dphi / 2)) is at
/// most `tolerance` [m]. The points are OvalShape::boundaryPoint's.
std::vector<std::array<double, 2>> outlinePolygon(const OvalShape& shape, double tolerance);

/// One frame of a test: a checkpoint and its time in the .pvd.
struct VtkFrame {
    std::string checkpoint;
    std::int64_t step = 0;
    double axialStrain = 0; ///< eps1 of its test [-]
    double time = 0;        ///< its time in the .pvd: eps1, or the step (see VtkTestFrames)
};
/// A test's frames, in increasing time, and the first checkpoint of the test in the file (the
/// reference of the grains' displacement, whether exported or not).
struct VtkTestFrames {
    std::string test;
    std::string firstCheckpoint;
    /// The time is the step when eps1 of the test's checkpoints, taken by step, ever decreases
    /// (a compaction that rebounds, a cyclic test); else eps1.
    bool timeIsStep = false;
    std::vector<VtkFrame> frames;
};
/// Chooses the frames of each test (tests in the order their first checkpoint was written).
/// A test's checkpoints are taken by step (one per step: the later written); when their eps1
/// never decreases, one whose eps1 equals the one before it replaces it (the equilibration and
/// the start of the test both sit at eps1 = 0), so that the time eps1 increases strictly. Then
/// every `every`-th one from the first (and the last), or the one nearest each of `strains` by
/// eps1 (once each). Checkpoints without a test are left out.
std::vector<VtkTestFrames> chooseFrames(const std::vector<CheckpointInfo>& checkpoints, int every,
                                        const std::vector<double>& strains);

/// The four data sets of a checkpoint. `start` is the state at the test's first checkpoint.
VtkPolyData grainCells(const SimulationState& state, const StoredContacts& contacts,
                       const SimulationState& start);
VtkPolyData contactCells(const StoredContacts& contacts, const std::array<double, 4>& cell);
VtkPolyData voidCellPolygons(const StoredVoidCells& cells);
VtkPolyData periodicCellQuad(const std::array<double, 4>& cell);

/// The run file of a run folder (RUN/run.h5, or RUN itself when it is a file). Throws
/// VtkExportRefused when there is none.
std::string runFileOf(const std::string& run);

struct VtkExportSummary {
    std::string out;
    int tests = 0;
    int frames = 0;
    int files = 0;
    std::uintmax_t bytes = 0;
};
/// Writes the export (layout in docs/paraview.md). `progress` (may be empty) is called after
/// each frame with the fraction done and the frame's test and eps1. Throws VtkExportRefused for
/// bad input and std::runtime_error when writing fails; either way nothing is left in `out`.
VtkExportSummary exportVtk(const VtkExportOptions& options,
                           const std::function<void(double, const std::string&)>& progress = {});

} // namespace grainlab
