// The servo and geometry presets: the shipped full presets are the issue's maps, the preset's
// kind picks the reader, and a bad preset is refused naming the file, the key and the range.
#include <string>

#include <gtest/gtest.h>

#include "grainlab/geometry_map.h"
#include "grainlab/servo_map.h"
#include "grainlab/stability_map.h"
#include "grainlab/strict_json.h"

namespace grainlab {
namespace {

std::string preset(const std::string& name) {
    return std::string(GRAINLAB_SOURCE_DIR) + "/resources/stability/" + name + ".json";
}

/// The refusal's key path and message, or "" when accepted.
std::pair<std::string, std::string> refusal(const std::string& text, bool servo) {
    try {
        servo ? (void)parseServoPreset(text, "p.json") : (void)parseGeometryPreset(text, "p.json");
    } catch (const JsonFileError& e) {
        return {e.keyPath, e.what()};
    }
    return {"", ""};
}

TEST(ServoGeometryPreset, TheFullPresetsAreTheIssuesMaps) {
    const ServoMapSpec servo = readServoPreset(preset("servo-full"));
    EXPECT_EQ(servo.pressures, (std::vector<double>{15e3, 100e3}));
    EXPECT_EQ(servo.aspectRatios, (std::vector<double>{1.0, 0.6}));
    EXPECT_GT(servo.gains.back(), 2.0) << "the grid must reach past the stability limit";
    EXPECT_EQ(servoCells(servo).size(), 2u * 2u * servo.intervals.size());
    const GeometryMapSpec geometry = readGeometryPreset(preset("geometry-full"));
    EXPECT_EQ(geometry.aspectRatios, (std::vector<double>{0.8, 0.6, 0.4}));
    EXPECT_EQ(geometry.sizeRatios, (std::vector<double>{1.0, 2.0}));
    EXPECT_EQ(geometry.tolerance, 1e-9);
    for (const char* name : {"tiny", "full"}) {
        EXPECT_EQ(stabilityPresetKind(readInputFile(preset(name), "p"), name), "time_step");
    }
    EXPECT_EQ(stabilityPresetKind(readInputFile(preset("servo-tiny"), "p"), "s"), "servo");
    EXPECT_EQ(stabilityPresetKind(readInputFile(preset("geometry-tiny"), "p"), "g"), "geometry");
}

TEST(ServoGeometryPreset, RefusesWithFileKeyAndRange) {
    const std::string axes = R"("axes": {"pressure": [15000], "aspect_ratio": [1],
                                         "interval": [1], "gain": [0.3, 3]})";
    EXPECT_EQ(refusal(R"({"kind": "servo", )" + axes + "}", true).first, "");
    auto r = refusal(R"({"kind": "servo", "axes": {"pressure": [15000], "aspect_ratio": [1],
                         "interval": [1.5], "gain": [0.3]}})",
                     true);
    EXPECT_EQ(r.first, "axes.interval");
    EXPECT_NE(r.second.find("integers in [1, 100000]"), std::string::npos) << r.second;
    r = refusal(R"({"kind": "servo", "axes": {"pressure": [15000], "aspect_ratio": [1],
                    "interval": [1], "gain": [3, 0.3]}})",
                true);
    EXPECT_EQ(r.first, "axes.gain");
    EXPECT_NE(r.second.find("ascending"), std::string::npos) << r.second;
    r = refusal(R"({"kind": "servo", "judge": {"band": 2}, )" + axes + "}", true);
    EXPECT_EQ(r.first, "judge.band");
    EXPECT_NE(r.second.find("p.json"), std::string::npos) << r.second;
    r = refusal(R"({"kind": "geometry", "axes": {"aspect_ratio": [0.6], "size_ratio": [0.5],
                    "overlap": [0.1]}})",
                false);
    EXPECT_EQ(r.first, "axes.size_ratio[0]");
    EXPECT_NE(r.second.find("[1, 10]"), std::string::npos) << r.second;
    r = refusal(R"({"kind": "geometry", "axes": {"aspect_ratio": [0.6], "size_ratio": [1],
                    "overlap": [0.2, 0.1]}})",
                false);
    EXPECT_EQ(r.first, "axes.overlap");
    // A kind that is no map, and the time-step reader given another kind.
    try {
        stabilityPresetKind(R"({"kind": "servos"})", "p.json");
        ADD_FAILURE() << "an unknown kind was accepted";
    } catch (const JsonFileError& e) {
        EXPECT_EQ(e.keyPath, "kind");
        EXPECT_NE(std::string(e.what()).find("\"geometry\""), std::string::npos) << e.what();
    }
    EXPECT_THROW(parseStabilityPreset(R"({"kind": "servo", )" + axes + "}", "p.json"),
                 JsonFileError);
}

} // namespace
} // namespace grainlab
