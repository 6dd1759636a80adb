#pragma once
// `grainlab bench --gui` (GUI builds only): what the live window costs, in one run.
//
// (a) Engine speed headless against the same steps in the shown main window (worker thread
//     publishing snapshots, keeping the chart-hover history, GUI thread drawing scene and
//     charts): the first shear test of an experiment (--experiment, default the quick one) from
//     a checkpoint taken in memory at the start of its shear, --gui-steps steps per run (default
//     100 000), --rounds interleaved rounds (headless, window, headless, ...), medians printed.
//     The window shows its default view, or with --gui-overlays strong force chains and void
//     cells by valence over the whole cell (the scene being drawn is what the slowdown depends
//     on); its scene's time per picture on the GUI thread and its picture budget are printed.
// (b) The scene's frame time on a compacted assembly of --grains ovals (default 8450) with
//     strong force chains and void cells by valence, at 1000 x 1000 pixels: the QPainter
//     renderer, and the OpenGL view where the platform has OpenGL (not on `offscreen`).
//
// Creates its own QApplication (the offscreen platform when there is no display) and runs on
// the main thread. Results go to stdout, progress to stderr.

namespace grainlab {

struct BenchOptions;

int runGuiBench(const BenchOptions& options);

} // namespace grainlab
