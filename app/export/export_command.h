#pragma once
// `grainlab export vtk RUN --out DIR [--every N | --strains a,b,...] [--unfinished] [--quiet]`:
// the run's checkpoints as ParaView files (vtk_export.h, docs/paraview.md), with a progress bar
// on stderr. Main thread.

#include "export/vtk_export.h"

namespace grainlab {

/// Runs the export; returns the exit status: 0 written, 2 refused (bad input: the message names
/// the file and what is allowed), 1 failed while writing. Nothing is left in --out unless 0.
int runExportVtkCommand(const VtkExportOptions& options, bool quiet);

} // namespace grainlab
