#pragma once
// The grainlab command line: `grainlab` (the window, or the quick experiment headless when
// there is no display), `grainlab run`, `grainlab bench`, `grainlab export vtk`, ... Runs on the
// main thread.

namespace grainlab {

int runCommandLine(int argc, char** argv);

} // namespace grainlab
