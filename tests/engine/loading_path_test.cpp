// The "test" object reader (defaults, every kind, a table of refusals each naming its key and
// range) and the strain-controlled cyclic schedule.
#include "grainlab/loading_path.h"

#include <gtest/gtest.h>

namespace grainlab {
namespace {

const std::string kFile = "paths.json";

LoadingPath read(const std::string& text) {
    const Json root = parseStrictJson(text, kFile);
    const JsonSection top(kFile, root, "", {"test", "seed"});
    return readLoadingPath(top);
}

TEST(LoadingPathReader, NoTestObjectMeansDrained) {
    const LoadingPath path = read(R"({"seed": 1})");
    EXPECT_EQ(path.kind, LoadingPath::Kind::Drained);
    EXPECT_EQ(read(R"({"test": {}})").kind, LoadingPath::Kind::Drained);
    EXPECT_STREQ(loadingKindName(path.kind), "drained");
}

TEST(LoadingPathReader, EachKindAndItsDefaults) {
    EXPECT_EQ(read(R"({"test": {"kind": "constant_volume"}})").kind,
              LoadingPath::Kind::ConstantVolume);
    EXPECT_EQ(read(R"({"test": {"kind": "constant_p"}})").kind, LoadingPath::Kind::ConstantP);
    const LoadingPath sp = read(R"({"test": {"kind": "stress_path", "slope": -0.5}})");
    EXPECT_EQ(sp.kind, LoadingPath::Kind::StressPath);
    EXPECT_EQ(sp.slope, -0.5);

    const LoadingPath c = read(R"({"test": {"kind": "cyclic", "amplitude": 0.002}})");
    EXPECT_EQ(c.control, LoadingPath::Control::Strain);
    EXPECT_EQ(c.drainage, LoadingPath::Drainage::Drained);
    EXPECT_EQ(c.amplitude, 0.002);
    EXPECT_EQ(c.mean, 0.0);
    EXPECT_EQ(c.cycles, 10);
    EXPECT_FALSE(c.stopStrainAmplitude.has_value()); // strain control: the amplitude is imposed
    EXPECT_FALSE(c.stopPressureFraction.has_value());

    const LoadingPath cs = read(R"({"test": {"kind": "cyclic", "control": "stress",
        "drainage": "constant_volume", "amplitude": 2e4, "mean": 1e4, "cycles": 50,
        "stop_strain_amplitude": 0.05, "stop_pressure_fraction": 0.1}})");
    EXPECT_EQ(cs.control, LoadingPath::Control::Stress);
    EXPECT_EQ(cs.drainage, LoadingPath::Drainage::ConstantVolume);
    EXPECT_EQ(cs.amplitude, 2e4);
    EXPECT_EQ(cs.mean, 1e4);
    EXPECT_EQ(cs.cycles, 50);
    EXPECT_EQ(cs.stopStrainAmplitude, 0.05);
    // Under stress control a bound the sample cannot reach must still end the test.
    EXPECT_EQ(read(R"({"test": {"kind": "cyclic", "control": "stress", "amplitude": 1e4}})")
                  .stopStrainAmplitude,
              0.5);
    EXPECT_EQ(cs.stopPressureFraction, 0.1);

    const LoadingPath p = read(R"({"test": {"kind": "probes"}})");
    EXPECT_EQ(p.probeCount, 16);
    EXPECT_EQ(p.increment, 1e-4);
    EXPECT_EQ(p.plane, LoadingPath::Plane::Strain);
    EXPECT_EQ(p.start, LoadingPath::Start::End);
    const LoadingPath ps = read(R"({"test": {"kind": "probes", "count": 36, "increment": 2e-4,
        "plane": "stress", "start": "strain", "start_strain": 0.02}})");
    EXPECT_EQ(ps.probeCount, 36);
    EXPECT_EQ(ps.plane, LoadingPath::Plane::Stress);
    EXPECT_EQ(ps.start, LoadingPath::Start::Strain);
    EXPECT_EQ(ps.startStrain, 0.02);

    // Compression unless the file says extension, which names the series apart.
    EXPECT_FALSE(read(R"({"test": {"kind": "constant_volume"}})").extension);
    const LoadingPath ext =
        read(R"({"test": {"kind": "constant_volume", "direction": "extension"}})");
    EXPECT_TRUE(ext.extension);
    EXPECT_EQ(testSuffix(ext), "-constant-volume-extension");
    EXPECT_EQ(testSuffix(read(R"({"test": {"direction": "extension"}})")), "-extension");
    EXPECT_EQ(testSuffix(read(R"({"test": {"direction": "compression"}})")), "");
}

struct BadInput {
    std::string test;  // the "test" object
    std::string key;   // the key path the message must name
    std::string range; // text the message must hold (the allowed range or values)
};

TEST(LoadingPathReader, RefusalsNameTheFileTheKeyAndTheRange) {
    const std::vector<BadInput> table = {
        {R"("drained")", "test", "object"},
        {R"({"kind": "shear"})", "test.kind", "constant_volume"},
        {R"({"kind": "stress_path"})", "test.slope", "[-10, 10]"},
        {R"({"kind": "stress_path", "slope": 12})", "test.slope", "[-10, 10]"},
        {R"({"kind": "drained", "slope": 0.5})", "test.slope", "stress_path"},
        {R"({"kind": "cyclic"})", "test.amplitude", "(0, 0.5]"},
        {R"({"kind": "cyclic", "amplitude": 0})", "test.amplitude", "(0, 0.5]"},
        {R"({"kind": "cyclic", "control": "stress", "amplitude": -1})", "test.amplitude", "> 0"},
        {R"({"kind": "cyclic", "control": "load", "amplitude": 0.01})", "test.control", "stress"},
        {R"({"kind": "cyclic", "amplitude": 0.01, "mean": 0.7})", "test.mean", "[-0.5, 0.5]"},
        {R"({"kind": "cyclic", "amplitude": 0.01, "cycles": 0})", "test.cycles", "100000"},
        {R"({"kind": "cyclic", "amplitude": 0.01, "cycles": 2.5})", "test.cycles", "100000"},
        {R"({"kind": "cyclic", "amplitude": 0.01, "drainage": "undrained"})", "test.drainage",
         "constant_volume"},
        {R"({"kind": "cyclic", "amplitude": 0.01, "stop_pressure_fraction": 1})",
         "test.stop_pressure_fraction", "(0, 1)"},
        {R"({"kind": "cyclic", "control": "stress", "amplitude": 1e4,
             "stop_strain_amplitude": 0})",
         "test.stop_strain_amplitude", "(0, 0.5]"},
        {R"({"kind": "cyclic", "amplitude": 0.01, "stop_strain_amplitude": 0.02})",
         "test.stop_strain_amplitude", "control \"stress\" only"},
        {R"({"kind": "cyclic", "amplitude": 0.01, "count": 8})", "test.count", "probes"},
        {R"({"kind": "probes", "count": 2})", "test.count", "[4, 360]"},
        {R"({"kind": "probes", "count": 7})", "test.count", "even"},
        {R"({"kind": "probes", "increment": 0.05})", "test.increment", "(0, 0.01]"},
        {R"({"kind": "probes", "plane": "volume"})", "test.plane", "stress"},
        {R"({"kind": "probes", "start": "middle"})", "test.start", "peak"},
        {R"({"kind": "probes", "start": "strain"})", "test.start_strain", "(0, 0.5]"},
        {R"({"kind": "probes", "start": "peak", "start_strain": 0.1})", "test.start_strain",
         "strain"},
        {R"({"kind": "probes", "cout": 8})", "test.cout", "count"},
        {R"({"kind": "constant_p", "direction": "sideways"})", "test.direction", "extension"},
        {R"({"kind": "cyclic", "amplitude": 0.01, "direction": "extension"})", "test.direction",
         "kinds \"drained\", \"constant_volume\", \"constant_p\", \"stress_path\" only"},
    };
    for (const BadInput& bad : table) {
        try {
            read(R"({"test": )" + bad.test + "}");
            ADD_FAILURE() << "accepted: " << bad.test;
        } catch (const JsonFileError& e) {
            const std::string what = e.what();
            EXPECT_EQ(e.file, kFile) << what;
            EXPECT_EQ(e.keyPath, bad.key) << what;
            EXPECT_NE(what.find(bad.key), std::string::npos) << what;
            EXPECT_NE(what.find(bad.range), std::string::npos) << bad.test << " -> " << what;
        }
    }
}

TEST(CyclicStrainSchedule, WaveformReversalsAndCycles) {
    // From eps0 = 0.001 about mean 0.002 with amplitude 0.003 at 1e-4 per step: 40 steps up to
    // 0.005, then 60 steps per half-cycle between 0.005 and -0.001.
    const CyclicStrainSchedule s(0.001, 0.002, 0.003, 1e-4);
    EXPECT_EQ(s.firstLegSteps(), 40);
    EXPECT_EQ(s.halfCycleSteps(), 60);
    EXPECT_EQ(s.reversalStep(0), 40);
    EXPECT_EQ(s.reversalStep(3), 220);
    EXPECT_EQ(s.stepCount(0), 0);
    EXPECT_EQ(s.stepCount(40), 40);
    EXPECT_EQ(s.stepCount(100), -20);
    EXPECT_EQ(s.stepCount(130), 10);
    EXPECT_NEAR(s.upperPeak(), 0.005, 1e-15);
    EXPECT_NEAR(s.lowerPeak(), -0.001, 1e-15);
    EXPECT_EQ(s.direction(39), 1);
    EXPECT_EQ(s.direction(40), -1);
    EXPECT_EQ(s.direction(99), -1);
    EXPECT_EQ(s.direction(100), 1);
    EXPECT_EQ(s.cyclesCompleted(159), 0);
    EXPECT_EQ(s.cyclesCompleted(160), 1);
    // The waveform is the sum of its directions: s(n + 1) - s(n) = direction(n) everywhere.
    for (std::int64_t n = 0; n < 1000; ++n) {
        ASSERT_EQ(s.stepCount(n + 1) - s.stepCount(n), s.direction(n)) << n;
        ASSERT_LE(s.strainAt(n), s.upperPeak() + 1e-15);
        ASSERT_GE(s.strainAt(n), s.lowerPeak() - 1e-15);
    }
    // Reversals by brute force: n is one where the direction into n and out of n differ.
    std::int64_t turns = 0;
    for (std::int64_t n = 1; n < 1000; ++n) {
        const bool turn = s.direction(n - 1) != s.direction(n);
        ASSERT_EQ(s.isReversal(n), turn) << n;
        turns += turn ? 1 : 0;
        ASSERT_EQ(s.reversalsBy(n), turns) << n;
        ASSERT_GT(s.reversalStep(s.reversalsBy(n)), n) << n; // the next one is after n
    }
    // Starting above the upper peak, the first leg extends.
    const CyclicStrainSchedule down(0.01, 0.0, 0.002, 1e-4);
    EXPECT_EQ(down.firstLegSteps(), 80);
    EXPECT_EQ(down.direction(0), -1);
    EXPECT_NEAR(down.strainAt(80), 0.002, 1e-15);
    EXPECT_THROW(CyclicStrainSchedule(0, 0, 0.001, 0.01), std::invalid_argument);
    EXPECT_THROW(CyclicStrainSchedule(0, 0, 0.0, 1e-4), std::invalid_argument);
}

TEST(CyclicStressControl, ReversesAtTheBounds) {
    EXPECT_EQ(cyclicStressDirection(0.5, 1, -1.0, 1.0), 1);
    EXPECT_EQ(cyclicStressDirection(1.0, 1, -1.0, 1.0), -1);
    EXPECT_EQ(cyclicStressDirection(1.2, -1, -1.0, 1.0), -1);
    EXPECT_EQ(cyclicStressDirection(-1.0, -1, -1.0, 1.0), 1);
    EXPECT_EQ(cyclicStressDirection(-1.5, 1, -1.0, 1.0), 1);
}

} // namespace
} // namespace grainlab
