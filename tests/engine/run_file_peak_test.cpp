// The run file a Python user can read (issue 14): each shear test's checkpoint at the peak of
// q/p, each checkpoint's contacts and void cells, and a resumed run that writes the same peak.
// Checked on a real run of a small experiment against the engine's own measures.
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <H5Cpp.h>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli/run_output.h"
#include "grainlab/experiment_file.h"
#include "grainlab/experiment_runner.h"
#include "grainlab/measures.h"
#include "grainlab/run_file.h"
#include "grainlab/simulation.h"
#include "grainlab/void_cells.h"

namespace grainlab {
namespace {

namespace fs = std::filesystem;

/// 150 ovals compacted to 50 kPa and sheared there to 3 %, a checkpoint every 0.4 %: the peak
/// of q/p comes well before the end, with checkpoints after it.
ExperimentConfig peakExperiment() {
    std::ifstream in(std::string(GRAINLAB_SOURCE_DIR) + "/resources/experiments/tiny.json");
    std::stringstream text;
    text << in.rdbuf();
    nlohmann::json j = nlohmann::json::parse(text.str());
    j["name"] = "peak";
    j["compaction"]["pressures"] = {50e3};
    j["shear"]["pressures"] = {50e3};
    j["shear"]["target_axial_strain"] = 0.03;
    j["record"]["strain_interval"] = 4e-4;
    j["record"]["snapshot_strain_interval"] = 4e-3;
    return parseExperimentText(j.dump(), "peak.json");
}

fs::path scratch() {
    static const fs::path dir =
        fs::temp_directory_path() / fmt::format("grainlab_run_file_peak_{}", getpid());
    fs::create_directories(dir);
    return dir;
}

/// The peak checkpoint of `test` (asserts there is exactly one).
CheckpointInfo peakOf(const std::string& path, const std::string& test) {
    std::vector<CheckpointInfo> peaks;
    for (const CheckpointInfo& info : listCheckpointInfo(path)) {
        if (info.peak && info.test == test) {
            peaks.push_back(info);
        }
    }
    EXPECT_EQ(peaks.size(), 1u) << test;
    return peaks.empty() ? CheckpointInfo{} : peaks.front();
}

template <class T>
bool sameBits(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() &&
           (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

/// The unbroken run, made once for the tests of this file.
class RunFilePeak : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        path_ = (scratch() / "whole.h5").string();
        const ExperimentConfig config = peakExperiment();
        RunFile file(path_, config.sourceText);
        ExperimentRunner runner(config, &file);
        while (runner.advance(2000)) {
        }
    }
    static void TearDownTestSuite() { fs::remove_all(scratch()); }
    static std::string path_;
};
std::string RunFilePeak::path_;

TEST_F(RunFilePeak, PeakCheckpointHoldsTheSeriesMaximumOfQOverP) {
    const SeriesTable t = readSeries(path_, "p050kPa");
    const int q = t.column("q_over_p"), eps1 = t.column("eps1"), step = t.column("step");
    double best = -std::numeric_limits<double>::infinity();
    std::size_t at = 0, shearRows = 0;
    for (std::size_t r = 0; r < t.rows.size(); ++r) {
        if (t.stageKinds[r] == "shear") {
            ++shearRows;
            if (t.rows[r][q] > best) {
                best = t.rows[r][q];
                at = r;
            }
        }
    }
    ASSERT_GT(shearRows, 50u);
    const CheckpointInfo peak = peakOf(path_, "p050kPa");
    // The peak is inside the test (the test of resuming after it needs checkpoints after it).
    ASSERT_LT(t.rows[at][eps1], 0.02) << "the peak is too late in the test for these tests";
    EXPECT_EQ(peak.stageKind, "shear");
    EXPECT_EQ(peak.pressure, 50e3);
    EXPECT_EQ(std::bit_cast<std::uint64_t>(peak.peakStressRatio),
              std::bit_cast<std::uint64_t>(best));
    EXPECT_EQ(peak.step, static_cast<std::int64_t>(t.rows[at][step]));
    EXPECT_EQ(peak.axialStrain, t.rows[at][eps1]);

    // q/p recomputed from the stored state with the engine's measures: the series maximum.
    const SimulationState state = readState(path_, checkpointGroup(peak.name));
    EXPECT_EQ(state.step, peak.step);
    const Simulation sim(state);
    EXPECT_EQ(std::bit_cast<std::uint64_t>(stressMeasures(sim.stress()).qOverP),
              std::bit_cast<std::uint64_t>(best));
    // Marked for readers: the test's attribute, and no runner state (not for continuing).
    EXPECT_EQ(readRunnerState(path_, checkpointGroup(peak.name)), "");
    const H5::H5File file(path_, H5F_ACC_RDONLY);
    const H5::Attribute a = file.openGroup("/tests/p050kPa").openAttribute("peak_checkpoint");
    std::string name;
    a.read(a.getDataType(), name);
    EXPECT_EQ(name.c_str(), peak.name);
    // The only peak: the other checkpoints say peak = 0.
    int peaks = 0;
    for (const CheckpointInfo& info : listCheckpointInfo(path_)) {
        peaks += info.peak ? 1 : 0;
    }
    EXPECT_EQ(peaks, 1);
}

TEST_F(RunFilePeak, CheckpointContactsAreTheEnginesNetwork) {
    const CheckpointInfo peak = peakOf(path_, "p050kPa");
    // The compacted sample's (the first checkpoint, the generated grid, has no contacts), the
    // peak's and the end's.
    std::string compacted;
    for (const CheckpointInfo& info : listCheckpointInfo(path_)) {
        if (info.stageKind == "compaction") {
            compacted = info.name;
        }
    }
    EXPECT_TRUE(readContacts(path_, listCheckpoints(path_).front()).first.empty());
    const std::vector<std::string> names = {compacted, peak.name, listCheckpoints(path_).back()};
    for (const std::string& name : names) {
        SCOPED_TRACE(name);
        const Simulation sim(readState(path_, checkpointGroup(name)));
        const ContactNetwork net = sim.contactNetwork();
        const StoredContacts c = readContacts(path_, name);
        ASSERT_EQ(c.first.size(), net.contacts.size());
        ASSERT_GT(c.first.size(), 0u);
        const MeasureSet m = computeMeasures(net);
        int strong = 0, loadBearing = 0, sliding = 0;
        for (std::size_t k = 0; k < net.contacts.size(); ++k) {
            const ContactRecord& r = net.contacts[k];
            ASSERT_EQ(c.first[k], r.first);
            ASSERT_EQ(c.second[k], r.second);
            ASSERT_EQ(c.shift1[k], r.shift1);
            ASSERT_EQ(c.shift2[k], r.shift2);
            ASSERT_EQ(c.normalForce[k], r.normalForce);
            ASSERT_EQ(c.tangentialForce[k], r.tangentialForce);
            ASSERT_EQ(c.normal1[k], r.normal1);
            ASSERT_EQ(c.normal2[k], r.normal2);
            ASSERT_EQ(c.branch1[k], r.branch1);
            ASSERT_EQ(c.overlap[k], r.overlap);
            // World coordinates: the wrapped centre of the first grain plus the offset.
            ASSERT_EQ(c.point1[k], c.centre1[r.first] + r.point1);
            ASSERT_EQ(c.point2[k], c.centre2[r.first] + r.point2);
            strong += c.strong[k];
            loadBearing += c.loadBearing[k];
            sliding += c.sliding[k];
        }
        EXPECT_TRUE(sameBits(c.centre1, net.x1));
        EXPECT_TRUE(sameBits(c.centre2, net.x2));
        // The flags are the measures' own split and graph.
        EXPECT_EQ(strong, m.strongWeak.strong.contacts);
        EXPECT_EQ(c.strongThreshold, m.strongWeak.threshold);
        EXPECT_EQ(loadBearing, m.loadBearing.contacts);
        EXPECT_EQ(sliding, m.slidingContacts);
    }
}

/// Shoelace area of vertices [begin, end).
double polygonArea(const std::vector<double>& x, const std::vector<double>& y, std::int64_t begin,
                   std::int64_t end) {
    double twice = 0;
    for (std::int64_t i = begin; i < end; ++i) {
        const std::int64_t j = i + 1 < end ? i + 1 : begin;
        twice += x[i] * y[j] - x[j] * y[i];
    }
    return 0.5 * twice;
}

TEST_F(RunFilePeak, VoidCellsHoldPolygonsAndSecondMoments) {
    const CheckpointInfo peak = peakOf(path_, "p050kPa");
    const SimulationState state = readState(path_, checkpointGroup(peak.name));
    const VoidCellSet cells = computeVoidCells(Simulation(state).contactNetwork());
    const StoredVoidCells v = readVoidCells(path_, peak.name);
    ASSERT_EQ(v.valence.size(), cells.cells.size());
    ASSERT_GT(v.valence.size(), 20u);
    double total = 0;
    for (std::size_t k = 0; k < cells.cells.size(); ++k) {
        const VoidCell& c = cells.cells[k];
        ASSERT_EQ(v.valence[k], c.valence);
        ASSERT_EQ(v.area[k], c.area);
        ASSERT_EQ(v.centroid1[k], c.centroid1);
        ASSERT_EQ(v.secondMoment11[k], c.secondMoment[0]);
        ASSERT_EQ(v.secondMoment22[k], c.secondMoment[1]);
        ASSERT_EQ(v.secondMoment12[k], c.secondMoment[2]);
        ASSERT_EQ(v.vertexOffsets[k + 1] - v.vertexOffsets[k], 2 * c.valence);
        // The polygon as written: its area and centroid are the cell's.
        const double area =
            polygonArea(v.vertices1, v.vertices2, v.vertexOffsets[k], v.vertexOffsets[k + 1]);
        ASSERT_NEAR(area, c.area, 1e-9 * c.area);
        total += area;
    }
    // The cells tile the periodic cell.
    if (cells.cellular) {
        const auto& h = state.cell;
        EXPECT_NEAR(total, h[0] * h[3] - h[1] * h[2], 1e-9 * total);
    }
}

TEST_F(RunFilePeak, ShapeOutlinesEncloseTheShapeArea) {
    const CheckpointInfo peak = peakOf(path_, "p050kPa");
    const SimulationState state = readState(path_, checkpointGroup(peak.name));
    const H5::H5File file(path_, H5F_ACC_RDONLY);
    const H5::Group g = file.openGroup(checkpointGroup(peak.name));
    std::vector<double> x(state.shapes.size() * kShapeOutlinePoints), y(x.size());
    g.openDataSet("shape_outline1").read(x.data(), H5::PredType::NATIVE_DOUBLE);
    g.openDataSet("shape_outline2").read(y.data(), H5::PredType::NATIVE_DOUBLE);
    for (std::size_t s = 0; s < state.shapes.size(); ++s) {
        const double area =
            polygonArea(x, y, s * kShapeOutlinePoints, (s + 1) * kShapeOutlinePoints);
        // An inscribed polygon of 48 points: within 1 % of the oval's area, below it.
        EXPECT_LT(area, state.shapes[s].area) << s;
        EXPECT_GT(area, 0.99 * state.shapes[s].area) << s;
    }
}

TEST_F(RunFilePeak, ResumedRunsWriteTheSamePeakCheckpoint) {
    const ExperimentConfig config = peakExperiment();
    const CheckpointInfo reference = peakOf(path_, "p050kPa");
    const SimulationState referenceState = readState(path_, checkpointGroup(reference.name));
    const StoredContacts referenceContacts = readContacts(path_, reference.name);
    // The shear checkpoints after the peak, from the unbroken run.
    std::vector<std::int64_t> after;
    std::int64_t before = -1;
    for (const CheckpointInfo& info : listCheckpointInfo(path_)) {
        if (info.stageKind == "shear" && !info.peak) {
            if (info.step > reference.step) {
                after.push_back(info.step);
            } else {
                before = info.step;
            }
        }
    }
    ASSERT_GE(after.size(), 3u);
    ASSERT_GE(before, 0);

    // One run, copied where it is stopped (a flushed file is what a killed run leaves), and
    // finally interrupted (the checkpoint of Ctrl-C).
    struct Stop {
        std::string what;
        std::int64_t step;
        int expectKept; ///< the resume point needs the running peak of a checkpoint (1), not (0)
    };
    const std::vector<Stop> stops = {
        {"between the peak and the next checkpoint", reference.step + 1, -1},
        {"just after the first checkpoint after the peak", after[0] + 1, 1},
        {"after the second checkpoint after the peak", after[1] + 1, 1},
        {"interrupted after the peak", (after[1] + after[2]) / 2, 1},
    };
    {
        RunFile file((scratch() / "broken.h5").string(), config.sourceText);
        ExperimentRunner runner(config, &file);
        for (std::size_t k = 0; k < stops.size(); ++k) {
            while (runner.simulation().stepCount() < stops[k].step) {
                runner.advance(
                    std::min<std::int64_t>(997, stops[k].step - runner.simulation().stepCount()));
            }
            if (k + 1 == stops.size()) {
                runner.checkpointNow("interrupted");
            }
            file.flush();
            const fs::path folder = scratch() / fmt::format("case{}", k);
            fs::create_directories(folder);
            fs::copy_file(scratch() / "broken.h5", folder / "run.h5",
                          fs::copy_options::overwrite_existing);
        }
    }
    for (std::size_t k = 0; k < stops.size(); ++k) {
        SCOPED_TRACE(stops[k].what);
        // What `grainlab run --resume` reads from the stopped run's folder.
        const fs::path folder = scratch() / fmt::format("case{}", k);
        const std::string path = (folder / "run.h5").string();
        ResumePoint point = RunOutputFolder::readResumePoint(folder.string());
        if (stops[k].expectKept >= 0) {
            EXPECT_EQ(point.runningPeak.has_value(), stops[k].expectKept == 1);
        }
        {
            RunFile file(path, config.sourceText, RunFile::Mode::Resume);
            ExperimentRunner runner(config, std::move(point), &file);
            while (runner.advance(2000)) {
            }
        }
        const CheckpointInfo peak = peakOf(path, "p050kPa");
        EXPECT_EQ(peak.step, reference.step);
        EXPECT_EQ(peak.peakStressRatio, reference.peakStressRatio);
        EXPECT_EQ(peak.axialStrain, reference.axialStrain);
        EXPECT_TRUE(identicalDynamics(readState(path, checkpointGroup(peak.name)), referenceState));
        const StoredContacts contacts = readContacts(path, peak.name);
        EXPECT_TRUE(sameBits(contacts.normalForce, referenceContacts.normalForce));
        EXPECT_TRUE(sameBits(contacts.point1, referenceContacts.point1));
        const SeriesTable a = readSeries(path_, "p050kPa"), b = readSeries(path, "p050kPa");
        EXPECT_EQ(a.rows, b.rows);
    }
}

} // namespace
} // namespace grainlab
