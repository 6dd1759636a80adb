#pragma once
// A recorded time series: named columns with units, one row per record, plus the text column
// `stage`. Filled by the experiment runner on the engine thread; copied into snapshots for the
// GUI and written to CSV and to the run file. Plain data.

#include <cstdint>
#include <string>
#include <vector>

namespace grainlab {

struct SeriesColumn {
    std::string name;  ///< e.g. "sigma22"
    std::string unit;  ///< e.g. "Pa"; "-" for dimensionless; the CSV header is "name [unit]"
    bool text = false; ///< true for `stage` only: not part of a numeric row
};

struct SeriesTable {
    std::string test;                      ///< e.g. "p100kPa"
    std::vector<SeriesColumn> columns;     ///< numeric columns, in order
    std::vector<std::vector<double>> rows; ///< rows[k][c] is column c of record k
    std::vector<std::string> stages;       ///< stage name of record k
    /// The identity of record k's stage as data (run file: stage_kind, pressure); empty for a
    /// table that does not come from the runner (e.g. read from a CSV file).
    std::vector<std::string> stageKinds; ///< "compaction", "equilibration", "shear"
    std::vector<double> stagePressures;  ///< the stage's confining pressure [Pa]

    /// Index of the column `name`, or -1.
    int column(const std::string& name) const {
        for (std::size_t c = 0; c < columns.size(); ++c) {
            if (columns[c].name == name) {
                return static_cast<int>(c);
            }
        }
        return -1;
    }
    /// All values of column `name` (empty if absent).
    std::vector<double> values(const std::string& name) const {
        const int c = column(name);
        std::vector<double> out;
        if (c < 0) {
            return out;
        }
        out.reserve(rows.size());
        for (const auto& r : rows) {
            out.push_back(r[c]);
        }
        return out;
    }
};

} // namespace grainlab
