// Experiment file: the shipped presets parse as docs/experiment-file.md says, and every kind of bad
// input is refused with an error naming the file, the key path, the value and what is allowed.
#include "experiment_fixtures.h"
#include "grainlab/experiment_file.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace grainlab {
namespace {

using Json = nlohmann::json;

using test::minimalExperiment;

/// Parses `j` as "bad.json" and checks the error's key path and that its message holds each of
/// `fragments` (and the file name).
void expectRefused(const Json& j, const std::string& keyPath,
                   std::initializer_list<std::string> fragments) {
    try {
        parseExperimentText(j.dump(2), "bad.json");
        ADD_FAILURE() << "accepted, expected an error at " << keyPath;
    } catch (const ExperimentFileError& e) {
        const std::string what = e.what();
        EXPECT_EQ(e.keyPath, keyPath) << what;
        EXPECT_EQ(e.file, "bad.json");
        EXPECT_NE(what.find("bad.json"), std::string::npos) << what;
        for (const auto& f : fragments) {
            EXPECT_NE(what.find(f), std::string::npos) << "missing \"" << f << "\" in: " << what;
        }
    }
}

std::string sourceFile(const std::string& relative) {
    return std::string(GRAINLAB_SOURCE_DIR) + "/" + relative;
}

TEST(ExperimentFile, MinimalFileGetsDocumentedDefaults) {
    const ExperimentConfig c = parseExperimentText(minimalExperiment().dump(), "dir/minimal.json");
    EXPECT_EQ(c.name, "minimal");
    EXPECT_EQ(c.sourcePath, "dir/minimal.json");
    EXPECT_EQ(c.assembly.seed, 7u);
    EXPECT_EQ(c.assembly.grainCount, 50);
    ASSERT_EQ(c.assembly.widths.size(), 3u);
    EXPECT_EQ(c.assembly.widths[0], 1.0e-3);
    EXPECT_EQ(c.assembly.widths[1], 1.5e-3);
    EXPECT_EQ(c.assembly.widths[2], 2.0e-3);
    EXPECT_EQ(c.assembly.closure, OvalClosure::EqualArea);
    EXPECT_EQ(c.assembly.gap, 0.1);
    EXPECT_EQ(c.assembly.cellAspectRatio, 1.0);
    EXPECT_EQ(c.parameters.threads, 1);
    EXPECT_EQ(c.parameters.damping.kind, DampingKind::GlobalViscous);
    EXPECT_EQ(c.parameters.damping.coefficient, 0.05);
    EXPECT_EQ(c.parameters.servo.gain, 0.3);
    EXPECT_EQ(c.parameters.servo.integralGain, 0.05);
    EXPECT_EQ(c.parameters.servo.interval, 1);
    EXPECT_EQ(c.parameters.stability.designCoordination, 6);
    EXPECT_EQ(c.parameters.neighbourSkin, 0.0);
    EXPECT_EQ(c.parameters.friction, 0.0); // compaction friction: the first stage
    EXPECT_EQ(c.parameters.servo.maxStrainRate, 20.0);
    EXPECT_EQ(c.compaction.friction, 0.0);
    EXPECT_EQ(c.compaction.maxStrainRate, 20.0);
    EXPECT_EQ(c.compaction.criterion.calmChecks, 20);
    EXPECT_EQ(c.compaction.criterion.maxSteps, 2000000);
    EXPECT_EQ(c.shear.friction, 0.5);
    EXPECT_EQ(c.shear.pressures, c.compaction.pressures);
    EXPECT_EQ(c.shear.axialStrainPerStep, 2e-7);
    EXPECT_EQ(c.shear.targetAxialStrain, 0.1);
    EXPECT_EQ(c.shear.maxStrainRate, 1.0);
    EXPECT_EQ(c.record.strainInterval, 1e-4);
    EXPECT_EQ(c.record.stepInterval, 1000);
    EXPECT_EQ(c.record.snapshotStrainInterval, 0.01);
    EXPECT_EQ(c.record.snapshotStepInterval, 50000);
}

TEST(ExperimentFile, ReferencePresetIsSpecSection1) {
    const ExperimentConfig c =
        readExperimentFile(sourceFile("resources/experiments/reference.json"));
    EXPECT_EQ(c.assembly.grainCount, 8450);
    ASSERT_EQ(c.assembly.widths.size(), 11u);
    EXPECT_EQ(c.assembly.widths.front(), 1.0e-3);
    EXPECT_EQ(c.assembly.widths.back(), 2.0e-3);
    EXPECT_EQ(c.assembly.aspectRatio, 0.6);
    EXPECT_EQ(c.parameters.normalStiffness, 1e8);
    EXPECT_EQ(c.parameters.tangentialStiffness, 1e8);
    EXPECT_EQ(c.parameters.density, 2650.0);
    EXPECT_EQ(c.parameters.timeStep, 1e-6);
    EXPECT_EQ(c.parameters.damping.kind, DampingKind::GlobalViscous);
    EXPECT_EQ(c.parameters.damping.coefficient, 0.05);
    EXPECT_EQ(c.compaction.friction, 0.0);
    EXPECT_EQ(c.compaction.pressures, (std::vector<double>{15e3, 25e3, 50e3, 100e3}));
    EXPECT_EQ(c.shear.pressures, c.compaction.pressures);
    EXPECT_EQ(c.shear.friction, 0.5);
    EXPECT_EQ(c.shear.axialStrainPerStep, 2e-7);
    EXPECT_EQ(c.shear.targetAxialStrain, 0.15);
    EXPECT_EQ(c.compaction.criterion.calmChecks, 20);
    EXPECT_EQ(c.compaction.criterion.checkInterval, 100);
    EXPECT_FALSE(c.sourceText.empty());
    EXPECT_EQ(c.name, "reference");
}

TEST(ExperimentFile, QuickPresetParses) {
    const ExperimentConfig c = readExperimentFile(sourceFile("resources/experiments/quick.json"));
    EXPECT_EQ(c.name, "quick");
    EXPECT_LT(c.assembly.grainCount, 1000);
    EXPECT_EQ(c.compaction.pressures, (std::vector<double>{15e3, 25e3, 50e3, 100e3}));
    EXPECT_GT(c.shear.targetAxialStrain, 0.0);
}

TEST(ExperimentFile, EveryShippedPresetParsesAndIsNamedAfterItsFile) {
    int presets = 0;
    for (const auto& entry :
         std::filesystem::directory_iterator(sourceFile("resources/experiments"))) {
        if (entry.path().extension() != ".json") {
            continue;
        }
        SCOPED_TRACE(entry.path().filename().string());
        ExperimentConfig c;
        ASSERT_NO_THROW(c = readExperimentFile(entry.path().string()));
        EXPECT_FALSE(c.tests.empty());
        EXPECT_EQ(c.name, entry.path().stem().string());
        ++presets;
    }
    EXPECT_GE(presets, 20);
    // The extension preset: drained in compression, then in extension, at two pressures.
    const ExperimentConfig ext =
        readExperimentFile(sourceFile("resources/experiments/quick-extension.json"));
    ASSERT_EQ(ext.tests.size(), 2u);
    EXPECT_FALSE(ext.tests[0].extension);
    EXPECT_TRUE(ext.tests[1].extension);
    EXPECT_EQ(ext.tests[1].kind, LoadingPath::Kind::Drained);
}

TEST(ExperimentFile, SourceTextIsVerbatim) {
    const auto path = std::filesystem::temp_directory_path() / "grainlab_verbatim_test.json";
    const std::string text = "  " + minimalExperiment().dump(4) + "\n\n";
    std::ofstream(path) << text;
    const ExperimentConfig c = readExperimentFile(path.string());
    EXPECT_EQ(c.sourceText, text);
    EXPECT_EQ(c.sourcePath, path.string());
    std::filesystem::remove(path);
}

TEST(ExperimentFile, UnreadableFileNamesThePath) {
    try {
        readExperimentFile("/nonexistent/dir/missing.json");
        FAIL() << "accepted a missing file";
    } catch (const ExperimentFileError& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/missing.json"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("cannot open"), std::string::npos);
    }
}

TEST(ExperimentFile, SyntaxErrorGivesLineAndColumn) {
    const std::string text = "{\n  \"seed\": 1,\n  \"grains\" {}\n}\n";
    try {
        parseExperimentText(text, "broken.json");
        FAIL() << "accepted broken JSON";
    } catch (const ExperimentFileError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("broken.json"), std::string::npos) << what;
        EXPECT_NE(what.find("line 3"), std::string::npos) << what;
        EXPECT_NE(what.find("column"), std::string::npos) << what;
    }
}

TEST(ExperimentFile, RootMustBeAnObject) {
    EXPECT_THROW(parseExperimentText("[1, 2]", "array.json"), ExperimentFileError);
}

TEST(ExperimentFile, UnknownKeysAreRefusedWithASuggestion) {
    Json j = minimalExperiment();
    j["sead"] = 3;
    expectRefused(j, "sead", {"unknown key sead", "did you mean seed?"});

    j = minimalExperiment();
    j["grains"]["aspect_ration"] = 0.6;
    expectRefused(j, "grains.aspect_ration",
                  {"unknown key grains.aspect_ration", "did you mean grains.aspect_ratio?"});

    j = minimalExperiment();
    j["compaction"]["criterion"] = {{"calm_check", 3}};
    expectRefused(j, "compaction.criterion.calm_check",
                  {"compaction.criterion.calm_check", "compaction.criterion.calm_checks"});

    j = minimalExperiment();
    j["colour"] = "blue";
    expectRefused(j, "colour", {"unknown key colour", "seed"}); // lists the allowed keys
}

TEST(ExperimentFile, TheTestKeyHoldsOneTestOrAList) {
    Json j = minimalExperiment();
    EXPECT_EQ(parseExperimentText(j.dump(), "a.json").tests.size(), 1u); // drained
    EXPECT_EQ(parseExperimentText(j.dump(), "a.json").tests[0].kind, LoadingPath::Kind::Drained);
    j["test"] = Json::parse(R"({"kind": "constant_volume"})");
    const ExperimentConfig one = parseExperimentText(j.dump(), "a.json");
    ASSERT_EQ(one.tests.size(), 1u);
    EXPECT_EQ(one.tests[0].kind, LoadingPath::Kind::ConstantVolume);
    j["test"] = Json::parse(R"([{"kind": "drained"}, {"kind": "stress_path", "slope": -0.5},
                                {"kind": "stress_path", "slope": 0.5}])");
    const ExperimentConfig three = parseExperimentText(j.dump(), "a.json");
    ASSERT_EQ(three.tests.size(), 3u);
    EXPECT_EQ(testSuffix(three.tests[1]), "-path-0.5");
    EXPECT_EQ(testSuffix(three.tests[2]), "-path+0.5");

    j["test"] = Json::array();
    expectRefused(j, "test", {"test = []", "an object or a non-empty array of objects"});
    j["test"] = Json::parse(R"([{"kind": "constant_p"}, {"kind": "constant_p"}])");
    expectRefused(j, "test[1].kind", {"a second test of the same kind"});
    j["test"] = Json::parse(R"([{"kind": "drained"}, {"kind": "stress_path"}])");
    expectRefused(j, "test[1].slope", {"missing required key test[1].slope", "[-10, 10]"});
    j["test"] = Json::parse(R"([{"kind": "drained"}, 3])");
    expectRefused(j, "test[1]", {"test[1] = 3: must be an object"});
    // Probes from a strain or the peak need a monotonic test just before them, and a strain it
    // reaches.
    j["test"] = Json::parse(R"({"kind": "probes", "start": "peak"})");
    expectRefused(j, "test.start", {"test.start = \"peak\"", "must follow that test", "\"end\""});
    j["test"] = Json::parse(
        R"([{"kind": "cyclic", "amplitude": 0.001}, {"kind": "probes", "start": "strain", "start_strain": 0.001}])");
    expectRefused(j, "test[1].start", {"test[1].start = \"strain\"", "constant_volume"});
    j["test"] = Json::parse(
        R"([{"kind": "drained"}, {"kind": "probes", "start": "strain", "start_strain": 0.5}])");
    expectRefused(j, "test[1].start_strain",
                  {"test[1].start_strain = 0.5", "shear.target_axial_strain"});
    j["test"] =
        Json::parse(R"([{"kind": "constant_volume"}, {"kind": "probes", "start": "peak"}])");
    EXPECT_EQ(parseExperimentText(j.dump(), "probes-from-peak.json").tests[1].start,
              LoadingPath::Start::Peak);
    // Kinds the runner does not play yet are refused, not run as something else.
    j["test"] = Json::parse(R"([{"kind": "drained"}, {"kind": "probes", "plane": "stress"}])");
    expectRefused(j, "test[1].plane", {"\"stress\": not available", "\"strain\""});
    // A strain cycle shorter than one step of strain has no waveform.
    j["shear"]["axial_strain_per_step"] = 1e-5;
    j["shear"]["max_strain_rate"] = 100;
    j["test"] = Json::parse(R"({"kind": "cyclic", "amplitude": 5e-6})");
    expectRefused(j, "test.amplitude", {"test.amplitude = 5e-06", "shear.axial_strain_per_step"});
}

TEST(ExperimentFile, DuplicateKeysAreRefused) {
    const std::string text = R"({"seed": 1, "grains": {"count": 10, "count": 20}})";
    try {
        parseExperimentText(text, "dup.json");
        FAIL() << "accepted a duplicate key";
    } catch (const ExperimentFileError& e) {
        EXPECT_EQ(e.keyPath, "grains.count");
        EXPECT_NE(std::string(e.what()).find("duplicate key grains.count"), std::string::npos);
    }
}

TEST(ExperimentFile, MissingRequiredKeysAreNamed) {
    for (const auto& [section, key] :
         std::vector<std::pair<std::string, std::string>>{{"grains", "count"},
                                                          {"grains", "aspect_ratio"},
                                                          {"grains", "width_min"},
                                                          {"grains", "size_classes"},
                                                          {"material", "density"},
                                                          {"material", "normal_stiffness"},
                                                          {"compaction", "pressures"},
                                                          {"shear", "target_axial_strain"}}) {
        Json j = minimalExperiment();
        j[section].erase(key);
        expectRefused(j, section + "." + key, {"missing required key " + section + "." + key});
    }
    for (const std::string key : {"seed", "time_step", "grains", "material", "shear"}) {
        Json j = minimalExperiment();
        j.erase(key);
        expectRefused(j, key, {"missing required key " + key});
    }
}

TEST(ExperimentFile, WrongTypesAreNamed) {
    Json j = minimalExperiment();
    j["grains"]["count"] = "50";
    expectRefused(j, "grains.count", {"grains.count = \"50\"", "an integer >= 1", "a string"});

    j = minimalExperiment();
    j["grains"]["count"] = 10.5;
    expectRefused(j, "grains.count", {"grains.count = 10.5", "an integer >= 1"});

    j = minimalExperiment();
    j["time_step"] = true;
    expectRefused(j, "time_step", {"time_step = true", "a number > 0", "a boolean"});

    j = minimalExperiment();
    j["material"] = 5;
    expectRefused(j, "material", {"material = 5", "an object"});

    j = minimalExperiment();
    j["compaction"]["pressures"] = 15000;
    expectRefused(j, "compaction.pressures", {"compaction.pressures = 15000", "array"});

    j = minimalExperiment();
    j["compaction"]["pressures"] = {15000, "25000"};
    expectRefused(j, "compaction.pressures[1]", {"compaction.pressures[1] = \"25000\""});

    j = minimalExperiment();
    j["damping"] = {{"kind", "viscous"}};
    expectRefused(j, "damping.kind",
                  {"damping.kind = \"viscous\"", "\"global_viscous\"", "\"cundall_local\""});
}

TEST(ExperimentFile, IntegralRealsAreAcceptedAsIntegers) {
    Json j = minimalExperiment();
    j["compaction"]["criterion"] = {{"max_steps", 2e6}};
    const ExperimentConfig c = parseExperimentText(j.dump(), "ok.json");
    EXPECT_EQ(c.compaction.criterion.maxSteps, 2000000);
}

TEST(ExperimentFile, OutOfRangeValuesNameTheRange) {
    struct Case {
        std::vector<std::string> key;
        Json value;
        std::string path, shown, range;
    };
    const std::vector<Case> cases = {
        {{"grains", "aspect_ratio"}, 1.5, "grains.aspect_ratio", "1.5", "(0, 1]"},
        {{"grains", "aspect_ratio"}, 0, "grains.aspect_ratio", "0", "(0, 1]"},
        {{"grains", "count"}, 0, "grains.count", "0", ">= 1"},
        {{"grains", "width_min"}, -1e-3, "grains.width_min", "-0.001", "[1e-09, 1000]"},
        {{"grains", "width_max"}, 0.5e-3, "grains.width_max", "0.0005", "[0.001, 1000]"},
        {{"grains", "grid_gap"}, -0.1, "grains.grid_gap", "-0.1", "[0, 100]"},
        {{"material", "normal_stiffness"}, 0, "material.normal_stiffness", "0", "> 0"},
        {{"material", "tangential_stiffness"}, -1, "material.tangential_stiffness", "-1", "> 0"},
        {{"material", "density"}, 0, "material.density", "0", "> 0"},
        {{"time_step"}, 0, "time_step", "0", "> 0"},
        {{"compaction", "friction"}, -0.1, "compaction.friction", "-0.1", ">= 0"},
        {{"shear", "friction"}, -0.5, "shear.friction", "-0.5", ">= 0"},
        {{"shear", "target_axial_strain"}, 1.2, "shear.target_axial_strain", "1.2", "(0, 1)"},
        {{"shear", "axial_strain_per_step"}, 0.2, "shear.axial_strain_per_step", "0.2", "(0, 0.1)"},
        {{"servo", "gain"}, 1.5, "servo.gain", "1.5", "(0, 1]"},
        {{"servo", "interval"}, 0, "servo.interval", "0", ">= 1"},
        {{"threads"}, 0, "threads", "0", "[1, 1024]"},
        {{"seed"}, -1, "seed", "-1", ">= 0"},
        {{"damping", "coefficient"}, 1.5, "damping.coefficient", "1.5", "[0, 1]"},
        {{"neighbour_skin"}, -1e-4, "neighbour_skin", "-0.0001", ">= 0"},
        {{"record", "strain_interval"}, 0, "record.strain_interval", "0", "> 0"},
        {{"compaction", "max_strain_rate"}, 0, "compaction.max_strain_rate", "0", "> 0"},
    };
    for (const auto& c : cases) {
        Json j = minimalExperiment();
        if (c.key.size() == 1) {
            j[c.key[0]] = c.value;
        } else {
            j[c.key[0]][c.key[1]] = c.value;
        }
        expectRefused(j, c.path, {c.path + " = " + c.shown, c.range});
    }
}

TEST(ExperimentFile, PressuresMustAscendAndShearPressuresBeCompacted) {
    Json j = minimalExperiment();
    j["compaction"]["pressures"] = {25e3, 15e3};
    expectRefused(j, "compaction.pressures[1]",
                  {"compaction.pressures[1] = 15000.0", "ascending", "25000"});

    j = minimalExperiment();
    j["compaction"]["pressures"] = {15e3, -25e3};
    expectRefused(j, "compaction.pressures[1]", {"compaction.pressures[1]", "> 0"});

    j = minimalExperiment();
    j["compaction"]["pressures"] = Json::array();
    expectRefused(j, "compaction.pressures", {"non-empty array"});

    j = minimalExperiment();
    j["shear"]["pressures"] = {25e3, 30e3};
    expectRefused(
        j, "shear.pressures[1]",
        {"shear.pressures[1] = 30000.0", "one of the compaction pressures (15000, 25000)"});

    j = minimalExperiment();
    j["shear"]["pressures"] = {25e3, 25e3};
    expectRefused(j, "shear.pressures[1]", {"twice"});

    j = minimalExperiment();
    j["shear"]["pressures"] = {25e3};
    EXPECT_EQ(parseExperimentText(j.dump(), "ok.json").shear.pressures, std::vector<double>{25e3});
}

TEST(ExperimentFile, ClosureAndDampingCombinations) {
    Json j = minimalExperiment();
    j["grains"]["closure"] = "end_radius_ratio";
    expectRefused(j, "grains.end_radius_ratio", {"missing required key grains.end_radius_ratio"});
    j["grains"]["end_radius_ratio"] = 0.4;
    expectRefused(j, "grains.end_radius_ratio", {"grains.end_radius_ratio = 0.4", "(0, 0.3)"});
    j["grains"]["end_radius_ratio"] = 0.2;
    const ExperimentConfig c = parseExperimentText(j.dump(), "ok.json");
    EXPECT_EQ(c.assembly.closure, OvalClosure::EndRadiusRatio);
    EXPECT_EQ(c.assembly.endRadiusRatio, 0.2);

    j = minimalExperiment();
    j["grains"]["end_radius_ratio"] = 0.2;
    expectRefused(j, "grains.end_radius_ratio", {"only used with"});

    j = minimalExperiment();
    j["damping"] = {{"kind", "none"}, {"coefficient", 0.05}};
    expectRefused(j, "damping.coefficient", {"not used"});
    j["damping"].erase("coefficient");
    EXPECT_EQ(parseExperimentText(j.dump(), "ok.json").parameters.damping.kind, DampingKind::None);

    j = minimalExperiment();
    j["grains"]["widths"] = {1e-3, 2e-3};
    expectRefused(j, "grains.width_min", {"exclude each other"});
    for (const char* k : {"width_min", "width_max", "size_classes"}) {
        j["grains"].erase(k);
    }
    EXPECT_EQ(parseExperimentText(j.dump(), "ok.json").assembly.widths,
              (std::vector<double>{1e-3, 2e-3}));

    j = minimalExperiment();
    j["grains"]["size_classes"] = 1;
    expectRefused(j, "grains.width_max", {"size_classes is 1"});
}

TEST(ExperimentFile, UnstableTimeStepIsRefusedNamingTheLimit) {
    Json j = minimalExperiment();
    j["time_step"] = 1e-4;
    expectRefused(j, "time_step", {"time_step = 0.0001", "stable limit"});
}

} // namespace
} // namespace grainlab
