// Output files: the HDF5 run file (state round trip bit for bit, restart continues bit for bit,
// series, checkpoints, refusal of NaN, readable by h5dump) and the CSV series.
#include "grainlab/run_file.h"
#include "scenes.h"

#include <algorithm>
#include <bit>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

#include <H5Cpp.h>
#include <gtest/gtest.h>

#include "grainlab/assembly.h"
#include "grainlab/csv_series.h"
#include "grainlab/simulation.h"

namespace grainlab {
namespace {

namespace fs = std::filesystem;

/// A fresh scratch directory per test, removed afterwards.
class ScratchDir {
public:
    ScratchDir() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() / (std::string("grainlab_") + info->test_suite_name() +
                                            "_" + info->name() + "_" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    ~ScratchDir() { fs::remove_all(dir_); }
    std::string file(const std::string& name) const { return (dir_ / name).string(); }

private:
    fs::path dir_;
};

Simulation squeezedAssembly() {
    return test::squeezedAssembly(64, 11, 800);
}

using test::slurp;

std::uint64_t bits(double x) {
    return std::bit_cast<std::uint64_t>(x);
}

void expectSameBits(const std::vector<double>& a, const std::vector<double>& b,
                    const std::string& what) {
    ASSERT_EQ(a.size(), b.size()) << what;
    for (std::size_t i = 0; i < a.size(); ++i) {
        ASSERT_EQ(bits(a[i]), bits(b[i])) << what << "[" << i << "]: " << a[i] << " vs " << b[i];
    }
}

template <std::size_t N>
void expectSameBits(const std::array<double, N>& a, const std::array<double, N>& b,
                    const std::string& what) {
    expectSameBits(std::vector<double>(a.begin(), a.end()), std::vector<double>(b.begin(), b.end()),
                   what);
}

void expectSameState(const SimulationState& a, const SimulationState& b) {
    ASSERT_EQ(a.shapes.size(), b.shapes.size());
    for (std::size_t i = 0; i < a.shapes.size(); ++i) {
        const OvalShape &s = a.shapes[i], &t = b.shapes[i];
        expectSameBits(std::vector<double>{s.width, s.height, s.halfWidth, s.halfHeight,
                                           s.endRadius, s.sideRadius, s.junctionAngle,
                                           s.cosJunction, s.sinJunction, s.area, s.polarMoment},
                       std::vector<double>{t.width, t.height, t.halfWidth, t.halfHeight,
                                           t.endRadius, t.sideRadius, t.junctionAngle,
                                           t.cosJunction, t.sinJunction, t.area, t.polarMoment},
                       "shape " + std::to_string(i));
        EXPECT_EQ(s.isDisk, t.isDisk);
    }
    expectSameBits(a.grains.x1, b.grains.x1, "x1");
    expectSameBits(a.grains.x2, b.grains.x2, "x2");
    expectSameBits(a.grains.theta, b.grains.theta, "theta");
    expectSameBits(a.grains.v1, b.grains.v1, "v1");
    expectSameBits(a.grains.v2, b.grains.v2, "v2");
    expectSameBits(a.grains.omega, b.grains.omega, "omega");
    EXPECT_EQ(a.grains.shape, b.grains.shape);
    EXPECT_EQ(a.pairs.first, b.pairs.first);
    EXPECT_EQ(a.pairs.second, b.pairs.second);
    EXPECT_EQ(a.pairs.shift1, b.pairs.shift1);
    EXPECT_EQ(a.pairs.shift2, b.pairs.shift2);
    expectSameBits(a.pairs.tangentialForce, b.pairs.tangentialForce, "tangentialForce");
    EXPECT_EQ(a.pairs.sliding, b.pairs.sliding);
    expectSameBits(a.cell, b.cell, "cell");
    expectSameBits(a.velocityGradient, b.velocityGradient, "velocityGradient");
    for (int k = 0; k < 2; ++k) {
        EXPECT_EQ(a.axes[k].mode, b.axes[k].mode);
        EXPECT_EQ(bits(a.axes[k].strainRate), bits(b.axes[k].strainRate));
        EXPECT_EQ(bits(a.axes[k].targetStress), bits(b.axes[k].targetStress));
        EXPECT_EQ(bits(a.axes[k].referenceLength), bits(b.axes[k].referenceLength));
    }
    expectSameBits(a.servoIntegral, b.servoIntegral, "servoIntegral");
    expectSameBits(a.reference1, b.reference1, "reference1");
    expectSameBits(a.reference2, b.reference2, "reference2");
    expectSameBits(a.referenceCell, b.referenceCell, "referenceCell");
    EXPECT_EQ(a.step, b.step);
    EXPECT_EQ(bits(a.time), bits(b.time));
    EXPECT_EQ(bits(a.boundaryWork), bits(b.boundaryWork));
    EXPECT_EQ(bits(a.frictionWork), bits(b.frictionWork));
    EXPECT_EQ(bits(a.dampingWork), bits(b.dampingWork));
    const SimulationParameters &p = a.parameters, &q = b.parameters;
    expectSameBits(
        std::vector<double>{p.timeStep, p.normalStiffness, p.tangentialStiffness, p.friction,
                            p.density, p.damping.coefficient, p.servo.gain, p.servo.integralGain,
                            p.servo.maxStrainRate, p.stability.maxOverlapFraction,
                            p.stability.maxStepFraction, p.neighbourSkin},
        std::vector<double>{q.timeStep, q.normalStiffness, q.tangentialStiffness, q.friction,
                            q.density, q.damping.coefficient, q.servo.gain, q.servo.integralGain,
                            q.servo.maxStrainRate, q.stability.maxOverlapFraction,
                            q.stability.maxStepFraction, q.neighbourSkin},
        "parameters");
    EXPECT_EQ(p.damping.kind, q.damping.kind);
    EXPECT_EQ(p.servo.interval, q.servo.interval);
    EXPECT_EQ(p.stability.designCoordination, q.stability.designCoordination);
    EXPECT_EQ(p.threads, q.threads);
    EXPECT_EQ(p.allArcPairs, q.allArcPairs);
}

SeriesTable sampleSeries(const std::string& test, std::size_t rows) {
    SeriesTable t;
    t.test = test;
    t.columns = {{"step", "-"}, {"time", "s"}, {"eps1", "-"}, {"sigma22", "Pa"}};
    for (std::size_t k = 0; k < rows; ++k) {
        const double x = static_cast<double>(k);
        t.rows.push_back({x * 1000, x * 1e-3, 0.1 / 3.0 * x, 15000.0 + 1.0 / 7.0 * x});
        t.stages.push_back(k < rows / 2 ? "equilibration 15 kPa" : "shear 15 kPa");
    }
    return t;
}

/// `back`, read from a file, is the table `written`: its test, its stages, and every row to the
/// bit.
void expectSameSeries(const SeriesTable& back, const SeriesTable& written) {
    EXPECT_EQ(back.test, written.test);
    EXPECT_EQ(back.stages, written.stages);
    ASSERT_EQ(back.rows.size(), written.rows.size());
    for (std::size_t k = 0; k < written.rows.size(); ++k) {
        expectSameBits(back.rows[k], written.rows[k], "row " + std::to_string(k));
    }
}

TEST(RunFile, StateRoundTripIsBitExact) {
    ScratchDir dir;
    const Simulation sim = squeezedAssembly();
    SimulationState state = sim.state();
    // The fixture must exercise the tangential history and the servo.
    ASSERT_GT(sim.contactCount(), 0u);
    ASSERT_TRUE(std::any_of(state.pairs.tangentialForce.begin(), state.pairs.tangentialForce.end(),
                            [](double f) { return f != 0; }));
    state.parameters.damping = {DampingKind::CundallLocal, 0.7};
    state.parameters.allArcPairs = true;
    state.parameters.servo.interval = 3;
    const std::string path = dir.file("run.h5");
    {
        RunFile file(path, "{\"seed\": 1}");
        file.checkpoint("after squeeze", state, "runner: stage 2");
    }
    expectSameState(state, readState(path, checkpointGroup("after squeeze")));
    EXPECT_EQ(readRunnerState(path, checkpointGroup("after squeeze")), "runner: stage 2");
}

// A checkpoint's large datasets are compressed with HDF5's own filters (shuffle, deflate), with
// Fletcher32 after them on the stored bytes; small ones carry Fletcher32 alone; either reads back
// to the bit.
TEST(RunFile, LargeDatasetsAreCompressedAndReadBackBitExact) {
    ScratchDir dir;
    const Simulation sim = test::squeezedAssembly(600, 5, 300);
    const SimulationState state = sim.state();
    const std::string path = dir.file("run.h5");
    {
        RunFile file(path, "{}");
        file.checkpoint("large", state, "");
    }
    expectSameState(state, readState(path, checkpointGroup("large")));
    const auto filters = [&](const std::string& dataset) {
        H5::H5File file(path, H5F_ACC_RDONLY);
        const H5::DSetCreatPropList p =
            file.openDataSet(checkpointGroup("large") + "/" + dataset).getCreatePlist();
        std::vector<H5Z_filter_t> ids;
        for (int k = 0; k < p.getNfilters(); ++k) {
            unsigned flags = 0, config = 0;
            std::size_t count = 8;
            unsigned values[8] = {};
            char name[64] = {};
            ids.push_back(p.getFilter(k, flags, count, values, sizeof name, name, config));
        }
        return ids;
    };
    EXPECT_EQ(
        filters("grains/omega"),
        (std::vector<H5Z_filter_t>{H5Z_FILTER_SHUFFLE, H5Z_FILTER_DEFLATE, H5Z_FILTER_FLETCHER32}));
    EXPECT_EQ(filters("cell"), std::vector<H5Z_filter_t>{H5Z_FILTER_FLETCHER32});
}

TEST(RunFile, RestartFromCheckpointContinuesBitForBit) {
    ScratchDir dir;
    Simulation original = squeezedAssembly();
    const std::string path = dir.file("run.h5");
    {
        RunFile file(path, "{}");
        file.checkpoint("restart", original.state(), "");
    }
    ASSERT_GT(original.contactCount(), 0u);
    Simulation restarted(readState(path, checkpointGroup("restart")));
    original.advance(300);
    restarted.advance(300);
    expectSameState(original.state(), restarted.state());
}

TEST(RunFile, RootAttributesAndExperimentText) {
    ScratchDir dir;
    const std::string path = dir.file("run.h5");
    const std::string text = "{\n  \"name\": \"r\\u00e9f\u00e9rence\"\n}\n";
    { RunFile file(path, text); }
    EXPECT_EQ(readExperimentText(path), text);
    EXPECT_EQ(readSoftwareVersion(path), GRAINLAB_VERSION);
    EXPECT_TRUE(listTests(path).empty());
    EXPECT_TRUE(listCheckpoints(path).empty());
    EXPECT_TRUE(listSamples(path).empty());
}

TEST(RunFile, SeriesAppendIncrementallyAndRoundTrip) {
    ScratchDir dir;
    const std::string path = dir.file("run.h5");
    const SeriesTable full = sampleSeries("p15kPa", 2500); // spans several chunks
    {
        RunFile file(path, "{}");
        SeriesTable growing = full;
        growing.rows.clear();
        growing.stages.clear();
        for (std::size_t k = 0; k < full.rows.size(); ++k) {
            growing.rows.push_back(full.rows[k]);
            growing.stages.push_back(full.stages[k]);
            if (k % 7 == 0 || k + 1 == full.rows.size()) {
                file.record(growing);
            }
        }
        file.record(sampleSeries("p100kPa", 3));
    }
    EXPECT_EQ(listTests(path), (std::vector<std::string>{"p15kPa", "p100kPa"}));
    const SeriesTable back = readSeries(path, "p15kPa");
    ASSERT_EQ(back.columns.size(), full.columns.size());
    for (std::size_t c = 0; c < full.columns.size(); ++c) {
        EXPECT_EQ(back.columns[c].name, full.columns[c].name);
        EXPECT_EQ(back.columns[c].unit, full.columns[c].unit);
    }
    expectSameSeries(back, full);
}

TEST(RunFile, SeriesRewoundByAResumedRunIsCutBack) {
    ScratchDir dir;
    const std::string path = dir.file("run.h5");
    const std::string text = "{\"name\": \"resume\"}";
    {
        RunFile file(path, text);
        file.record(sampleSeries("p15kPa", 10));
    }
    {
        // A resumed run restored 6 rows from its checkpoint and records a different 7th.
        RunFile file(path, text, RunFile::Mode::Resume);
        SeriesTable t = sampleSeries("p15kPa", 7);
        t.rows[6][2] = 0.5;
        file.record(t);
    }
    const SeriesTable back = readSeries(path, "p15kPa");
    ASSERT_EQ(back.rows.size(), 7u);
    EXPECT_EQ(back.rows[6][2], 0.5);
    EXPECT_EQ(back.rows[5], sampleSeries("p15kPa", 7).rows[5]);
    EXPECT_THROW(RunFile(path, "{\"name\": \"other\"}", RunFile::Mode::Resume), std::runtime_error);
}

TEST(RunFile, CheckpointsInWriteOrderAndReplacedByName) {
    ScratchDir dir;
    const std::string path = dir.file("run.h5");
    const Simulation sim = squeezedAssembly();
    SimulationState later = sim.state();
    later.step += 1;
    {
        RunFile file(path, "{}");
        file.checkpoint("latest", sim.state(), "a");
        file.checkpoint("compaction 15 kPa", sim.state(), "b");
        file.checkpoint("shear/1", sim.state(), "c");
        file.checkpoint("latest", later, "d"); // replaces the first, now written last
        file.sample(15e3, sim.state());
        file.sample(25e3, sim.state());
    }
    EXPECT_EQ(listCheckpoints(path),
              (std::vector<std::string>{"compaction 15 kPa", "shear/1", "latest"}));
    EXPECT_EQ(readRunnerState(path, checkpointGroup("latest")), "d");
    EXPECT_EQ(readState(path, checkpointGroup("latest")).step, later.step);
    EXPECT_EQ(readRunnerState(path, checkpointGroup("shear/1")), "c");
    EXPECT_EQ(listSamples(path), (std::vector<double>{15e3, 25e3}));
    EXPECT_EQ(sampleGroup(15e3), "/samples/15000Pa");
    expectSameState(sim.state(), readState(path, sampleGroup(25e3)));
    EXPECT_EQ(readRunnerState(path, sampleGroup(25e3)), "");
}

TEST(RunFile, NonFiniteValuesAreRefusedAndTheFileStaysValid) {
    ScratchDir dir;
    const std::string path = dir.file("run.h5");
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const Simulation sim = squeezedAssembly();
    {
        RunFile file(path, "{}");
        file.checkpoint("good", sim.state(), "");
        SeriesTable t = sampleSeries("p15kPa", 4);
        file.record(t);
        t.rows.push_back(t.rows.back());
        t.stages.push_back("shear 15 kPa");
        t.rows.back()[3] = nan;
        try {
            file.record(t);
            ADD_FAILURE() << "wrote a NaN";
        } catch (const std::runtime_error& e) {
            EXPECT_NE(std::string(e.what()).find("sigma22"), std::string::npos) << e.what();
        }
        SimulationState bad = sim.state();
        bad.grains.v2[5] = std::numeric_limits<double>::infinity();
        try {
            file.checkpoint("bad", bad, "");
            ADD_FAILURE() << "wrote an infinite velocity";
        } catch (const std::runtime_error& e) {
            EXPECT_NE(std::string(e.what()).find("v2[5]"), std::string::npos) << e.what();
        }
    }
    EXPECT_EQ(listCheckpoints(path), std::vector<std::string>{"good"});
    EXPECT_EQ(readSeries(path, "p15kPa").rows.size(), 4u);
}

TEST(RunFile, KilledWriterLeavesAReadableFile) {
    ScratchDir dir;
    const std::string path = dir.file("run.h5");
    const SimulationState state = squeezedAssembly().state();
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        // The child writes a checkpoint, then records without a flush, and is killed.
        RunFile file(path, "{}");
        file.checkpoint("latest", state, "runner");
        for (int k = 1; k <= 40; ++k) {
            file.record(sampleSeries("p15kPa", k));
        }
        std::raise(SIGKILL);
    }
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFSIGNALED(status));
    EXPECT_EQ(listCheckpoints(path), std::vector<std::string>{"latest"});
    expectSameState(state, readState(path, checkpointGroup("latest")));
    EXPECT_EQ(readRunnerState(path, checkpointGroup("latest")), "runner");
    // Records after the last flush may be lost, but what is there reads back.
    for (const auto& test : listTests(path)) {
        EXPECT_NO_THROW(readSeries(path, test));
    }
}

TEST(RunFile, H5DumpReadsTheFile) {
    if (std::system("command -v h5dump > /dev/null 2>&1") != 0) {
        GTEST_SKIP() << "h5dump not installed";
    }
    ScratchDir dir;
    const std::string path = dir.file("run.h5");
    {
        RunFile file(path, "{\"seed\": 1}");
        file.record(sampleSeries("p15kPa", 5));
        file.checkpoint("latest", squeezedAssembly().state(), "state");
    }
    const std::string out = dir.file("dump.txt");
    ASSERT_EQ(std::system(("h5dump -H '" + path + "' > '" + out + "' 2>&1").c_str()), 0)
        << slurp(out);
    const std::string dump = slurp(out);
    for (const char* fragment :
         {"GROUP \"tests\"", "DATASET \"sigma22\"", "DATASET \"experiment\"",
          "GROUP \"checkpoints\"", "DATASET \"tangential_force\"", "ATTRIBUTE \"unit\""}) {
        EXPECT_NE(dump.find(fragment), std::string::npos) << fragment;
    }
}

// ---- CSV ------------------------------------------------------------------------------------

TEST(CsvSeries, HeaderHasUnitsAndStageThird) {
    const SeriesTable t = sampleSeries("p15kPa", 1);
    EXPECT_EQ(csvHeader(t), (std::vector<std::string>{"step [-]", "time [s]", "stage", "eps1 [-]",
                                                      "sigma22 [Pa]"}));
    SeriesTable other;
    other.columns = {{"eps1", "-"}, {"q", "Pa"}};
    EXPECT_EQ(csvHeader(other), (std::vector<std::string>{"stage", "eps1 [-]", "q [Pa]"}));
}

TEST(CsvSeries, NumbersRoundTripAndStagesAreQuoted) {
    ScratchDir dir;
    SeriesTable t = sampleSeries("p15kPa", 50);
    t.rows[3][2] = 1e-300;
    t.rows[4][3] = -0.0;
    t.stages[5] = "odd, \"quoted\" stage";
    const std::string path = dir.file("p15kPa.csv");
    writeSeriesCsv(t, path);
    const std::string text = slurp(path);
    EXPECT_EQ(text.substr(0, text.find('\n')), "step [-],time [s],stage,eps1 [-],sigma22 [Pa]");
    EXPECT_NE(text.find("\n1000,0.001,equilibration 15 kPa,0.03333333333333333,"
                        "15000.142857142857\n"),
              std::string::npos)
        << text.substr(0, 300);
    EXPECT_NE(text.find("\"odd, \"\"quoted\"\" stage\""), std::string::npos);
    expectSameSeries(readSeriesCsv(path), t);
}

/// A scratch series.csv whose appender has written the sample series' first three rows.
struct AppendedSeries {
    AppendedSeries() { appender.append(t); }
    /// Adds a shear row at step 3000 with eps1 = `eps1` to the table (not yet written).
    void addShearRow(double eps1) {
        t.rows.push_back({3000, 0.003, eps1, 15000});
        t.stages.push_back("shear 15 kPa");
    }

    ScratchDir dir;
    const std::string path = dir.file("series.csv");
    CsvSeriesAppender appender{path};
    SeriesTable t = sampleSeries("p15kPa", 3);
};

TEST(CsvSeries, AppenderWritesOnlyNewRowsAndMirrorsTheTable) {
    AppendedSeries s;
    const std::string first = slurp(s.path);
    s.addShearRow(0.1);
    s.appender.append(s.t);
    const std::string second = slurp(s.path);
    EXPECT_EQ(second.substr(0, first.size()), first); // appended, not rewritten
    EXPECT_EQ(second.substr(first.size()), "3000,0.003,shear 15 kPa,0.1,15000\n");
    EXPECT_EQ(s.appender.rowsWritten(), 4u);
    // A resumed run rewound to two rows: the file follows the table.
    s.appender.append(sampleSeries("p15kPa", 2));
    EXPECT_EQ(readSeriesCsv(s.path).rows.size(), 2u);
}

TEST(CsvSeries, NonFiniteValueIsRefusedNamingTheColumn) {
    AppendedSeries s;
    s.addShearRow(std::numeric_limits<double>::quiet_NaN());
    try {
        s.appender.append(s.t);
        FAIL() << "wrote a NaN";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("eps1"), std::string::npos) << e.what();
    }
    EXPECT_EQ(readSeriesCsv(s.path).rows.size(), 3u);
    EXPECT_THROW(writeSeriesCsv(s.t, s.dir.file("whole.csv")), std::runtime_error);
}

} // namespace
} // namespace grainlab

namespace grainlab {
namespace {

// A restart in a cell so narrow that it limits the Verlet skin: the skin of the stored list is
// the one of the cell at its last rebuild (the reference cell), not of the cell now, or the
// restarted run rebuilds its list at other steps.
TEST(RunFile, RestartInANarrowCellKeepsTheSkinOfItsList) {
    AssemblySpec spec;
    spec.grainCount = 9;
    spec.widths = evenlySpacedWidths(1.0e-3, 2.0e-3, 2);
    spec.aspectRatio = 0.6;
    spec.gap = 0.1;
    spec.seed = 3;
    SimulationParameters p;
    p.friction = 0.5;
    p.threads = 1;
    p.neighbourSkin = 3.0e-3; // more than the cell allows: 0.45 (width - 4 a_max)
    SimulationState s = generateGridAssembly(spec, p);
    // The cell widens (extension), so the skin it allows grows: a restart that took the skin
    // from the cell now would keep its list longer than the run it continues.
    s.axes[0] = {AxisMode::Strain, -500.0, 0.0, 0.0};
    s.axes[1] = {AxisMode::Strain, -500.0, 0.0, 0.0};
    Simulation original(std::move(s));
    original.advance(50);
    int restarts = 0;
    for (int k = 0; k < 40; ++k) {
        Simulation restarted(original.state());
        original.advance(25);
        restarted.advance(25);
        ASSERT_TRUE(identicalDynamics(original.state(), restarted.state()))
            << "restart at step " << original.stepCount() - 25 << " differs after 25 steps";
        ++restarts;
    }
    EXPECT_EQ(restarts, 40);
    EXPECT_GE(original.neighbourRebuilds(), 2); // the first list, and one rebuild at least
}

} // namespace
} // namespace grainlab
