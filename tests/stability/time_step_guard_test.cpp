// The time-step guard sits on the measured stability map (issue 16): for every cell of the full
// map as measured (resources/stability/measured/full/limits.csv, written by `grainlab stability
// --preset full` and `collect`), the step the engine accepts at most is below the measured limit
// (it never accepts a step the map found unstable), and for dense and sheared packings it is
// not more than 3 times below it. The estimate is recomputed here from the engine, so a change
// of the estimate or of the margin is checked against the measurement.
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "grainlab/assembly.h"
#include "grainlab/stability_map.h"
#include "grainlab/time_step.h"

namespace grainlab {
namespace {

const std::string kMeasured =
    std::string(GRAINLAB_SOURCE_DIR) + "/resources/stability/measured/full";

/// limits.csv as rows of named cells (no cell of this file holds a comma or a quote).
std::vector<std::map<std::string, std::string>> readLimits(const std::string& path) {
    std::ifstream in(path);
    std::vector<std::map<std::string, std::string>> rows;
    std::string line;
    std::vector<std::string> header;
    const auto split = [](const std::string& text) {
        std::vector<std::string> out;
        std::stringstream s(text);
        std::string cell;
        while (std::getline(s, cell, ',')) {
            out.push_back(cell);
        }
        return out;
    };
    while (std::getline(in, line)) {
        const std::vector<std::string> cells = split(line);
        if (header.empty()) {
            header = cells;
            continue;
        }
        std::map<std::string, std::string> row;
        for (std::size_t k = 0; k < cells.size() && k < header.size(); ++k) {
            row[header[k]] = cells[k];
        }
        rows.push_back(row);
    }
    return rows;
}

TEST(TimeStepGuard, SitsBelowEveryMeasuredLimitAndWithinThreeTimesOfTheDenseOnes) {
    const StabilityMapSpec spec = readStabilityPreset(kMeasured + "/stability.json");
    const auto rows = readLimits(kMeasured + "/limits.csv");
    ASSERT_EQ(rows.size(), stabilityCells(spec).size()) << "the measured map is not complete";
    std::map<std::string, StabilityCell> cells;
    for (const StabilityCell& c : stabilityCells(spec)) {
        cells[c.id] = c;
    }
    int dense = 0;
    double smallest = 1e300, largest = 0;
    for (const auto& row : rows) {
        const StabilityCell& cell = cells.at(row.at("cell"));
        // The cell's grains and material, as the map's scene has them.
        std::vector<OvalShape> shapes;
        for (double w :
             evenlySpacedWidths(spec.smallestWidth, spec.largestWidth, spec.sizeClasses)) {
            shapes.push_back(makeOval(w, cell.aspectRatio));
        }
        SimulationParameters p;
        p.tangentialStiffness = cell.stiffnessRatio * p.normalStiffness;
        p.damping = cell.damping;
        const TimeStepLimit guard = criticalTimeStep(shapes, p);
        const double unit = std::stod(row.at("time_unit [s]"));
        const double measured = std::stod(row.at("limit [s]"));
        if (row.at("bracketed") != "yes") {
            // Stable up to the bracket's top: the guard must only stay below it.
            EXPECT_LT(guard.limit, std::stod(row.at("limit_high [sqrt(m_min/k_n)]")) * unit)
                << row.at("cell");
            continue;
        }
        // Never accepts a step the map found unstable: the lowest unstable step found is
        // limit_high; the largest stable one, the limit.
        EXPECT_LT(guard.limit, measured) << row.at("cell");
        if (cell.packing.kind != PackingKind::Gas) {
            ++dense;
            EXPECT_GT(guard.limit, measured / 3.0) << row.at("cell");
            smallest = std::min(smallest, measured / guard.estimate);
            largest = std::max(largest, measured / guard.estimate);
        }
    }
    EXPECT_GT(dense, 0);
    // The measured range the refusal message quotes is the map's, to its two digits.
    EXPECT_NEAR(smallest, kSmallestMeasuredLimit, 0.005);
    EXPECT_NEAR(largest, kLargestMeasuredLimit, 0.05);
    EXPECT_LT(kTimeStepMargin, smallest);
}

} // namespace
} // namespace grainlab
