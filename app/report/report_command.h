#pragma once
// `grainlab report RUN_DIR... --out DIR`: the reference study's figure set from finished runs of
// one experiment (several seeds: means with ±1σ bands, every number with its scatter). Writes
// into DIR: figures/<name>.csv (the plotted data of every figure), in GUI builds
// figures/<name>.png|svg|pdf, headline.csv (the table of headline numbers per confining
// pressure, beside the published values), report.md and report.html (self-contained: the
// figures embedded). docs/report.md documents every file. Main thread.
//
// `grainlab reproduce [--grains N] [--seeds K] --out DIR`: runs the reference experiment at K
// seeds (at N grains) as a study (the local pool of `grainlab study`, resumable), then reports
// on its runs into DIR/report.

#include <functional>
#include <string>
#include <vector>

#include "grainlab/report_data.h"

namespace grainlab {

/// A run the report is made of: its folder and what `grainlab study` reads of it.
struct ReportSource {
    std::string folder;
    std::string experimentName;
    int seed = 0;
    int grains = 0;
    double wallSeconds = 0, cpuSeconds = 0; ///< from cost.json (0 without one)
    bool finished = false; ///< cost.json says the run finished (else: reported as far as it got)
};

/// Draws the report's figures into `folder` (figures/ of the report), one file per format per
/// figure, and the void-cell pictures from the runs' checkpoints; returns "" or what went wrong.
/// The headless command has one in GUI builds.
using ReportFigureWriter = std::function<std::string(
    const std::string& folder, const std::vector<ReportFigure>&, const std::vector<ReportSource>&)>;

struct ReportCommandOptions {
    std::vector<std::string> runFolders;
    std::string out;
    bool quiet = false;
    ReportFigureWriter figures;
};

int runReportCommand(const ReportCommandOptions& options);

struct ReproduceOptions {
    std::string experiment; ///< the reference experiment file
    int grains = 0;         ///< 0: the experiment's
    int seeds = 1;
    int jobs = 0;
    std::string out;
    bool quiet = false;
    std::string grainlab; ///< this executable, for the runs
    ReportFigureWriter figures;
};

int runReproduceCommand(const ReproduceOptions& options);

/// The CSV of one figure's data: one row per point of each line.
std::string figureCsv(const ReportFigure& figure);
/// headline.csv: one row per (number, test), with the published value and the comparison.
std::string headlineCsv(const std::vector<HeadlineRow>& rows, const PooledFitScatter& pooled);

} // namespace grainlab
