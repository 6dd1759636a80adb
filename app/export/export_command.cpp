// See export_command.h.
#include "export/export_command.h"

#include <cstdio>
#include <exception>
#include <optional>

#include <fmt/format.h>

#include "common/progress_bar.h"

namespace grainlab {

int runExportVtkCommand(const VtkExportOptions& options, bool quiet) {
    std::optional<ProgressBar> bar;
    if (!quiet) {
        bar.emplace("export vtk");
    }
    // An error goes on a line of its own, not after the bar drawn in place.
    const auto error = [&](const std::string& line) {
        if (bar) {
            bar->note(line);
        } else {
            fmt::print(stderr, "{}\n", line);
        }
    };
    try {
        std::function<void(double, const std::string&)> progress;
        if (bar) {
            progress = [&](double fraction, const std::string& status) {
                bar->update(fraction, status);
            };
        }
        const VtkExportSummary summary = exportVtk(options, progress);
        if (bar) {
            bar->finish();
            fmt::print("{}: {} tests, {} frames, {} files, {:.1f} MB (open the .pvd files in "
                       "ParaView)\n",
                       summary.out, summary.tests, summary.frames, summary.files,
                       double(summary.bytes) / 1e6);
        }
        return 0;
    } catch (const VtkExportRefused& e) {
        error(fmt::format("grainlab export vtk: {}", e.what()));
        return 2;
    } catch (const std::exception& e) {
        error(fmt::format("grainlab export vtk: error: {} (nothing was written to {})", e.what(),
                          options.out));
        return 1;
    }
}

} // namespace grainlab
