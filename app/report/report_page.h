#pragma once
// The report page: report.md and a self-contained report.html (styles inline, every figure's
// PNG embedded), with the figures in the report's order and the table of headline numbers per
// confining pressure, each as mean ± sd over the runs, set beside the published study's values
// with the difference and whether it exceeds the seed scatter. Pure text; main thread.

#include <string>
#include <vector>

#include "grainlab/report_data.h"
#include "report/report_command.h"

namespace grainlab {

struct ReportPage {
    const std::vector<ReportFigure>& figures;
    const std::vector<HeadlineRow>& headline;
    const PooledFitScatter& pooled;
    const std::vector<ReportSource>& sources;
    std::string figureFolder; ///< where the figures' files are (PNG embedded when present)
    const CriticalStateSummary* criticalState = nullptr; ///< its section, when given
};

/// The critical state section's text: steady tests, M with its scatter (drained and constant
/// volume apart, and whether they agree within it), the critical state line.
std::string criticalStateText(const CriticalStateSummary& cs);
/// One line per test end of every run (critical_state.csv).
std::string criticalStateCsv(const CriticalStateSummary& cs);

std::string reportMarkdown(const ReportPage& page);
std::string reportHtml(const ReportPage& page);

/// "Z̄ = 3.45 N_v/N_vi + 2.10 (R² = 0.93)".
std::string fitEquation(const LinearFit& fit);
/// "0.137 ± 0.002" (the sd left out with one run).
std::string withScatter(const Scatter& s, int digits = 3);
/// The void-cell pictures' file stems (figure 5) in the order of the page: for the lowest and
/// highest pressure, at eps1 = 0, at the peak of q/p and at eps1 = 10 %.
std::vector<std::string> voidCellPictureNames(const std::vector<std::string>& tests);

/// Standard base64 of `bytes` (for the embedded images).
std::string base64(const std::string& bytes);

} // namespace grainlab
