// Hostile experiment files: each is refused up front, before any allocation or step, with the
// file, the key and a range that the engine can honour (no crash, no hang, no out-of-memory).
#include <cfenv>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "experiment_fixtures.h"
#include "grainlab/experiment_file.h"
#include "grainlab/experiment_limits.h"

namespace grainlab {
namespace {

using Json = nlohmann::json;

using test::minimalExperiment;

/// The engine tests trap floating-point exceptions (tests/engine/main.cpp); the reader finds a
/// non-finite derived quantity by computing it, so the traps are off while it reads.
class TrapsOff {
public:
    TrapsOff() : traps_(fegetexcept()) { fedisableexcept(FE_ALL_EXCEPT); }
    ~TrapsOff() {
        feclearexcept(FE_ALL_EXCEPT);
        feenableexcept(traps_);
    }

private:
    int traps_;
};

void expectRefusedText(const std::string& text, const std::string& keyPath,
                       std::initializer_list<std::string> fragments) {
    const TrapsOff quiet;
    try {
        parseExperimentText(text, "bad.json");
        ADD_FAILURE() << "accepted, expected an error at " << keyPath;
    } catch (const ExperimentFileError& e) {
        const std::string what = e.what();
        EXPECT_EQ(e.keyPath, keyPath) << what;
        EXPECT_EQ(e.file, "bad.json");
        EXPECT_EQ(what.rfind("bad.json: ", 0), 0u) << what;
        for (const auto& f : fragments) {
            EXPECT_NE(what.find(f), std::string::npos) << "missing \"" << f << "\" in: " << what;
        }
    }
}

void expectRefused(const Json& j, const std::string& keyPath,
                   std::initializer_list<std::string> fragments) {
    expectRefusedText(j.dump(2), keyPath, fragments);
}

/// The minimal experiment with its grains' size classes given as `widths` (instead of
/// width_min, width_max and size_classes).
Json withWidths(const std::vector<double>& widths) {
    Json j = minimalExperiment();
    j["grains"].erase("width_min");
    j["grains"].erase("width_max");
    j["grains"].erase("size_classes");
    j["grains"]["widths"] = widths;
    return j;
}

TEST(HostileExperiment, ALateralServoSlowerThanTheAxialLoadingIsRefused) {
    // 1e-6 per step at dt = 1e-6 s is 1 /s axially: a dilating sample needs a lateral cap of
    // at least 2 /s.
    Json j = minimalExperiment();
    j["time_step"] = 1e-6;
    j["shear"]["axial_strain_per_step"] = 1e-6;
    j["shear"]["max_strain_rate"] = 1.9;
    expectRefused(j, "shear.max_strain_rate", {"shear.max_strain_rate", "1.9", "at least 2 /s"});
    j["shear"]["max_strain_rate"] = 2.0; // the limit itself is fine
    EXPECT_NO_THROW(parseExperimentText(j.dump(), "ok.json"));
    j["shear"].erase("max_strain_rate");
    j["shear"]["axial_strain_per_step"] = 5e-7; // 0.5 /s: the default cap of 1 /s is enough
    EXPECT_NO_THROW(parseExperimentText(j.dump(), "ok.json"));
    j["shear"]["axial_strain_per_step"] = 6e-7; // 0.6 /s against the default cap
    expectRefused(j, "shear.max_strain_rate", {"shear.max_strain_rate", "default 1", "set it"});
}

TEST(HostileExperiment, StrainRateBeyondWhatTheNeighbourListFollowsIsRefused) {
    // 1e8 / s at dt = 1e-6 s is a cell strain of 100 per step: it crashed the neighbour rebuild.
    for (const double rate : {1e8, 1e9, 2e3}) {
        Json j = minimalExperiment();
        j["compaction"]["max_strain_rate"] = rate;
        expectRefused(j, "compaction.max_strain_rate", {"compaction.max_strain_rate", "1000"});
        j = minimalExperiment();
        j["shear"]["max_strain_rate"] = rate;
        expectRefused(j, "shear.max_strain_rate", {"shear.max_strain_rate"});
    }
    Json j = minimalExperiment();
    j["compaction"]["max_strain_rate"] = 1e3; // 1e-3 per step: the limit itself is fine
    EXPECT_NO_THROW(parseExperimentText(j.dump(), "ok.json"));
    j = minimalExperiment();
    j["shear"]["axial_strain_per_step"] = 0.05;
    expectRefused(j, "shear.axial_strain_per_step", {"shear.axial_strain_per_step", "0.001"});
}

TEST(HostileExperiment, GrainCountBeyondMemoryIsRefused) {
    // 1e9 grains allocated until the machine ran out of memory.
    Json j = minimalExperiment();
    j["grains"]["count"] = 1e9;
    expectRefused(j, "grains.count", {"grains.count = 1000000000", "memory"});
    EXPECT_LT(maxGrainCount(), 1000000000);
    EXPECT_GE(maxGrainCount(), 100000); // any machine that runs the suite holds 100k grains
}

TEST(HostileExperiment, SizeClassesAreBounded) {
    // 1e8 size classes built 1e8 oval shapes: the reader hung (found by experiment_fuzz).
    Json j = minimalExperiment();
    j["grains"]["size_classes"] = 100000000;
    expectRefused(j, "grains.size_classes", {"grains.size_classes", "[1, 50]"});
    expectRefused(withWidths(std::vector<double>(51, 1e-3)), "grains.widths",
                  {"grains.widths", "at most 50"});
}

TEST(HostileExperiment, DerivedQuantitiesMustBeFinite) {
    // aspect_ratio 1e-308 gave a non-finite time-step limit that passed the check.
    Json j = minimalExperiment();
    j["grains"]["aspect_ratio"] = 1e-308;
    expectRefused(j, "grains.aspect_ratio", {"grains.aspect_ratio", "finite"});
    // width_max 1e308 was blamed on aspect_ratio.
    j = minimalExperiment();
    j["grains"]["width_max"] = 1e308;
    expectRefused(j, "grains.width_max", {"grains.width_max = 1e+308", "1000"});
    expectRefused(withWidths({1e-3, 1e-300}), "grains.widths[1]", {"grains.widths[1]", "1e-09"});
}

TEST(HostileExperiment, BytesAfterANulAreRefusedWithItsPosition) {
    // "{...}\0garbage" was read up to the NUL and accepted.
    std::string text = minimalExperiment().dump();
    text += std::string(1, '\0') + "garbage";
    expectRefusedText(text, "", {"NUL", "line 1, column " + std::to_string(text.find('\0') + 1)});
    // Inside the object, on a later line, too.
    text = minimalExperiment().dump(2);
    const std::size_t at = text.find("\n") + 1;
    text.insert(at, std::string(1, '\0'));
    expectRefusedText(text, "", {"NUL", "line 2, column 1", fmt::format("byte {}", at + 1)});
}

TEST(HostileExperiment, AnEmptyKeyOrANonObjectFileIsNamedInWords) {
    // "bad.json:  = [1,2]: must be an object" and "unknown key ;" named nothing.
    expectRefusedText("[1, 2]", "",
                      {"bad.json: the file must hold one object", "top level", "got an array"});
    Json j = minimalExperiment();
    j[""] = 1;
    expectRefused(j, "", {"unknown key \"\" (an empty key name) at the top level"});
    j = minimalExperiment();
    j["grains"][""] = 1;
    expectRefused(j, "grains.", {"unknown key \"\" (an empty key name) in grains"});
}

TEST(HostileExperiment, ATinyDensityIsBlamedOnTheDensity) {
    // density 5e-324 gives no finite mass to a grain whose width is in range: it was blamed on
    // grains.width_min.
    Json j = minimalExperiment();
    j["material"]["density"] = 5e-324;
    expectRefused(j, "material.density", {"material.density", "mass"});
}

TEST(HostileExperiment, ARoundRateAtItsDerivedBoundIsAccepted) {
    // 2 x 5e-4 / 1e-6 s is 1000.0000000000001 in doubles: 1000 /s was refused as "must be at
    // least 1000 /s".
    Json j = minimalExperiment();
    j["time_step"] = 1e-6;
    j["shear"]["axial_strain_per_step"] = 5e-4;
    j["shear"]["max_strain_rate"] = 1000;
    ASSERT_GT(2.0 * 5e-4 / 1e-6, 1000.0); // the rounding the tolerance absorbs
    const TrapsOff quiet;
    EXPECT_NO_THROW(parseExperimentText(j.dump(), "ok.json"));
    // Below the bound by more than a rounding is still refused.
    j["shear"]["max_strain_rate"] = 999.999;
    expectRefused(j, "shear.max_strain_rate", {"at least 1000 /s"});
}

TEST(HostileExperiment, GridGapAndCellShapeAreBounded) {
    // grid_gap 1e308 passed the reader and blew up at step 1 (found by experiment_fuzz).
    Json j = minimalExperiment();
    j["grains"]["grid_gap"] = 1e308;
    expectRefused(j, "grains.grid_gap", {"grains.grid_gap", "[0, 100]"});
    j = minimalExperiment();
    j["grains"]["cell_aspect_ratio"] = 1e308;
    expectRefused(j, "grains.cell_aspect_ratio", {"grains.cell_aspect_ratio", "[0.001, 1000]"});
    j = minimalExperiment();
    j["grains"]["cell_aspect_ratio"] = 1e-300;
    expectRefused(j, "grains.cell_aspect_ratio", {"grains.cell_aspect_ratio"});
}

TEST(HostileExperiment, TimeStepCheckRefusesANonFiniteLimit) {
    Json j = minimalExperiment();
    j["material"]["normal_stiffness"] = 1e308; // k z overflows: the limit is 0
    j["material"]["tangential_stiffness"] = 1e308;
    expectRefused(j, "time_step", {"time_step"});
}

TEST(HostileExperiment, DeepNestingIsRefusedWithoutParsingIt) {
    // 100k levels cost memory growing with the square of the depth.
    std::string deep = R"({"name": "deep", "description": )";
    const int depth = 100000;
    deep += std::string(depth, '[') + std::string(depth, ']') + "}";
    expectRefusedText(deep, "description", {"nesting", "32"});
    const std::string deepObject = R"({"grains": {"count": {"a": {"b": )" + std::string(40, '[') +
                                   std::string(40, ']') + "}}}}";
    expectRefusedText(deepObject, "grains.count.a.b", {"nesting"});
}

TEST(HostileExperiment, NumberBeyondADoubleNamesItsKey) {
    std::string text = minimalExperiment().dump();
    const std::string from = "\"time_step\":1e-06";
    ASSERT_NE(text.find(from), std::string::npos) << text;
    text.replace(text.find(from), from.size(), "\"time_step\":1e309");
    expectRefusedText(text, "time_step", {"time_step", "1e309", "beyond"});
    std::string list = minimalExperiment().dump();
    const std::string pressures = "[15000.0,25000.0]";
    ASSERT_NE(list.find(pressures), std::string::npos) << list;
    list.replace(list.find(pressures), pressures.size(), "[15000.0,-1e400]");
    expectRefusedText(list, "compaction.pressures[1]", {"compaction.pressures[1]"});
}

TEST(HostileExperiment, AFolderIsCalledAFolder) {
    const std::string folder = std::filesystem::temp_directory_path().string();
    try {
        readExperimentFile(folder);
        ADD_FAILURE() << "a folder was accepted";
    } catch (const ExperimentFileError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("is a folder"), std::string::npos) << what;
        EXPECT_EQ(what.find("syntax"), std::string::npos) << what;
    }
}

} // namespace
} // namespace grainlab
