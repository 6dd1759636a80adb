// See export_command.h.
#include "export/export_command.h"

#include <cstdio>
#include <exception>

#include <fmt/format.h>

#include "common/progress_bar.h"

namespace grainlab {

int runExportVtkCommand(const VtkExportOptions& options, bool quiet) {
    try {
        VtkExportSummary summary;
        if (quiet) {
            summary = exportVtk(options);
        } else {
            ProgressBar bar("export vtk");
            summary = exportVtk(options, [&](double fraction, const std::string& status) {
                bar.update(fraction, status);
            });
            bar.finish();
        }
        if (!quiet) {
            fmt::print("{}: {} tests, {} frames, {} files, {:.1f} MB (open the .pvd files in "
                       "ParaView)\n",
                       summary.out, summary.tests, summary.frames, summary.files,
                       double(summary.bytes) / 1e6);
        }
        return 0;
    } catch (const VtkExportRefused& e) {
        fmt::print(stderr, "grainlab export vtk: {}\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        fmt::print(stderr, "grainlab export vtk: error: {} (nothing was written to {})\n", e.what(),
                   options.out);
        return 1;
    }
}

} // namespace grainlab
