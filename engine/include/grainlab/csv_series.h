#pragma once
// Time series as CSV (docs/formats.md): a header row of `name [unit]` and one row per record,
// numbers written with round-trip precision, the text column `stage` third (after `step` and
// `time`). Written by the experiment runner's output on the engine thread, or by the GUI's export
// on its thread; one writer per file. Never writes NaN or infinity: such a value is refused with an
// error naming the column, before anything of that call is written.

#include <cstddef>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "grainlab/series.h"

namespace grainlab {

/// `text` as one CSV cell: RFC 4180 quoting, only where needed.
std::string csvCell(const std::string& text);
/// The cells as one CSV line (each quoted where needed), newline included.
std::string csvLine(const std::vector<std::string>& cells);

/// The header cells in file order, e.g. {"step [-]", "time [s]", "stage", "eps1 [-]", ...}.
/// `stage` sits at index 2 when the columns start with step, time; first otherwise.
std::vector<std::string> csvHeader(const SeriesTable& table);

/// Writes the whole table (header and every row) to `path`, replacing the file.
/// Throws std::runtime_error on a non-finite value (naming column and record) or an I/O error.
void writeSeriesCsv(const SeriesTable& table, const std::string& path);

/// Reads a file written by writeSeriesCsv or CsvSeriesAppender (for tests and tools).
SeriesTable readSeriesCsv(const std::string& path);

/// Appends a growing table to a CSV file as a run goes, so that an interrupted run leaves a
/// valid file holding every row written so far. The file mirrors the table after each call.
class CsvSeriesAppender {
public:
    /// Does not touch the file until the first append(), which replaces it.
    explicit CsvSeriesAppender(std::string path);

    /// Writes the rows of `table` not yet in the file and flushes. If the table has no more rows
    /// than the file (a run resumed from an earlier checkpoint) or its columns changed, the file
    /// is rewritten from the table.
    void append(const SeriesTable& table);

    const std::string& path() const { return path_; }
    std::size_t rowsWritten() const { return rowsWritten_; }

private:
    void rewrite(const SeriesTable& table);

    std::string path_;
    std::ofstream out_;
    std::vector<std::string> header_;
    std::size_t rowsWritten_ = 0;
};

} // namespace grainlab
