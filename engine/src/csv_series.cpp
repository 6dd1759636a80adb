#include "grainlab/csv_series.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include <fmt/format.h>

namespace grainlab {

std::string csvCell(const std::string& text) {
    if (text.find_first_of(",\"\r\n") == std::string::npos) {
        return text;
    }
    std::string out = "\"";
    for (char c : text) {
        out += c;
        if (c == '"') {
            out += '"';
        }
    }
    return out + "\"";
}

std::string csvLine(const std::vector<std::string>& cells) {
    std::string text;
    for (std::size_t i = 0; i < cells.size(); ++i) {
        if (i > 0) {
            text += ',';
        }
        text += csvCell(cells[i]);
    }
    return text + '\n';
}

namespace {

/// Index of the `stage` cell in a row of the file.
std::size_t stagePosition(const SeriesTable& table) {
    const bool stepTimeFirst = table.columns.size() >= 2 && table.columns[0].name == "step" &&
                               table.columns[1].name == "time";
    return stepTimeFirst ? 2 : 0;
}

std::vector<std::string> splitCsvLine(const std::string& line) {
    std::vector<std::string> cells(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted) {
            if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
                cells.back() += '"';
                ++i;
            } else if (c == '"') {
                quoted = false;
            } else {
                cells.back() += c;
            }
        } else if (c == '"') {
            quoted = true;
        } else if (c == ',') {
            cells.emplace_back();
        } else if (c != '\r') {
            cells.back() += c;
        }
    }
    return cells;
}

/// Refuses a malformed table or a non-finite value in rows [from, end) before anything is
/// written.
void checkRows(const SeriesTable& table, std::size_t from) {
    if (table.stages.size() != table.rows.size()) {
        throw std::invalid_argument(fmt::format("series {}: {} rows but {} stage names", table.test,
                                                table.rows.size(), table.stages.size()));
    }
    for (std::size_t k = from; k < table.rows.size(); ++k) {
        const auto& row = table.rows[k];
        if (row.size() != table.columns.size()) {
            throw std::invalid_argument(fmt::format("series {}: record {} has {} values for {} "
                                                    "columns",
                                                    table.test, k, row.size(),
                                                    table.columns.size()));
        }
        for (std::size_t c = 0; c < row.size(); ++c) {
            if (!std::isfinite(row[c])) {
                throw std::runtime_error(fmt::format(
                    "series {}: column {} of record {} is {}; refusing to write a "
                    "non-finite value to CSV",
                    table.test, table.columns[c].name, k, std::isnan(row[c]) ? "NaN" : "infinite"));
            }
        }
    }
}

std::string formatRows(const SeriesTable& table, std::size_t from) {
    const std::size_t stageAt = stagePosition(table);
    std::string text;
    std::vector<std::string> cells;
    for (std::size_t k = from; k < table.rows.size(); ++k) {
        cells.clear();
        for (double v : table.rows[k]) {
            cells.push_back(fmt::format("{}", v));
        }
        cells.insert(cells.begin() + static_cast<std::ptrdiff_t>(stageAt),
                     csvCell(table.stages[k]));
        for (std::size_t i = 0; i < cells.size(); ++i) {
            if (i > 0) {
                text += ',';
            }
            text += cells[i];
        }
        text += '\n';
    }
    return text;
}

std::string formatHeader(const std::vector<std::string>& header) {
    return csvLine(header);
}

void writeOrThrow(std::ofstream& out, const std::string& text, const std::string& path) {
    out << text;
    out.flush();
    if (!out) {
        throw std::runtime_error(fmt::format("{}: write error", path));
    }
}

} // namespace

std::vector<std::string> csvHeader(const SeriesTable& table) {
    std::vector<std::string> header;
    for (const auto& column : table.columns) {
        header.push_back(
            fmt::format("{} [{}]", column.name, column.unit.empty() ? "-" : column.unit));
    }
    header.insert(header.begin() + static_cast<std::ptrdiff_t>(stagePosition(table)), "stage");
    return header;
}

void writeSeriesCsv(const SeriesTable& table, const std::string& path) {
    checkRows(table, 0);
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) {
        throw std::runtime_error(fmt::format("{}: cannot open for writing", path));
    }
    writeOrThrow(out, formatHeader(csvHeader(table)) + formatRows(table, 0), path);
}

SeriesTable readSeriesCsv(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw std::runtime_error(fmt::format("{}: cannot open for reading", path));
    }
    SeriesTable table;
    const auto slash = path.find_last_of('/');
    table.test = path.substr(slash == std::string::npos ? 0 : slash + 1);
    if (const auto dot = table.test.rfind(".csv"); dot != std::string::npos) {
        table.test.resize(dot);
    }
    std::string line;
    if (!std::getline(in, line)) {
        throw std::runtime_error(fmt::format("{}: empty file, no header", path));
    }
    std::size_t stageAt = std::string::npos;
    const auto header = splitCsvLine(line);
    for (std::size_t i = 0; i < header.size(); ++i) {
        const std::string& cell = header[i];
        if (cell == "stage" || cell == "stage [-]") {
            stageAt = i;
            continue;
        }
        const auto open = cell.rfind(" [");
        if (open == std::string::npos || cell.back() != ']') {
            throw std::runtime_error(
                fmt::format("{}: header cell {} \"{}\" is not `name [unit]`", path, i + 1, cell));
        }
        table.columns.push_back(
            {cell.substr(0, open), cell.substr(open + 2, cell.size() - open - 3)});
    }
    std::size_t lineNumber = 1;
    while (std::getline(in, line)) {
        ++lineNumber;
        if (line.empty()) {
            continue;
        }
        const auto cells = splitCsvLine(line);
        if (cells.size() != header.size()) {
            throw std::runtime_error(fmt::format("{}: line {} has {} cells, the header {}", path,
                                                 lineNumber, cells.size(), header.size()));
        }
        std::vector<double> row;
        for (std::size_t i = 0; i < cells.size(); ++i) {
            if (i == stageAt) {
                table.stages.push_back(cells[i]);
                continue;
            }
            char* end = nullptr;
            errno = 0;
            const double v = std::strtod(cells[i].c_str(), &end);
            if (cells[i].empty() || *end != '\0' || errno == ERANGE) {
                throw std::runtime_error(
                    fmt::format("{}: line {}: \"{}\" is not a number", path, lineNumber, cells[i]));
            }
            row.push_back(v);
        }
        if (stageAt == std::string::npos) {
            table.stages.emplace_back();
        }
        table.rows.push_back(std::move(row));
    }
    return table;
}

CsvSeriesAppender::CsvSeriesAppender(std::string path) : path_(std::move(path)) {}

void CsvSeriesAppender::rewrite(const SeriesTable& table) {
    out_.close();
    out_.clear();
    out_.open(path_, std::ios::binary | std::ios::trunc);
    if (!out_) {
        throw std::runtime_error(fmt::format("{}: cannot open for writing", path_));
    }
    header_ = csvHeader(table);
    rowsWritten_ = 0;
    writeOrThrow(out_, formatHeader(header_) + formatRows(table, 0), path_);
    rowsWritten_ = table.rows.size();
}

void CsvSeriesAppender::append(const SeriesTable& table) {
    const bool sameColumns = out_.is_open() && csvHeader(table) == header_;
    if (!sameColumns || table.rows.size() <= rowsWritten_) {
        checkRows(table, 0);
        rewrite(table);
        return;
    }
    checkRows(table, rowsWritten_);
    writeOrThrow(out_, formatRows(table, rowsWritten_), path_);
    rowsWritten_ = table.rows.size();
}

} // namespace grainlab
