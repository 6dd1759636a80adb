// The experiment reader's guards on the servo, placed on the servo map's measured lines
// (docs/stability.md): a gain past the measured stable limit and an interval past the measured
// 1 % line are refused, naming the file, the key, the allowed range and the measured limit; a
// setting inside both is accepted.
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "experiment_fixtures.h"
#include "grainlab/experiment_file.h"
#include "grainlab/experiment_limits.h"

namespace grainlab {
namespace {

using Json = nlohmann::json;

std::string refusal(const Json& j, std::string* keyPath = nullptr) {
    try {
        parseExperimentText(j.dump(2), "servo.json");
    } catch (const ExperimentFileError& e) {
        if (keyPath) {
            *keyPath = e.keyPath;
        }
        return e.what();
    }
    return "";
}

/// `j` is refused at `key` with a message naming the file (servo.json) and each of `words`;
/// when it is accepted, a fatal failure says `ifAccepted`. Call it within
/// ASSERT_NO_FATAL_FAILURE.
void expectRefusedAt(const Json& j, const std::string& key, const std::vector<std::string>& words,
                     const std::string& ifAccepted) {
    std::string keyPath;
    const std::string what = refusal(j, &keyPath);
    ASSERT_FALSE(what.empty()) << ifAccepted;
    EXPECT_EQ(keyPath, key);
    EXPECT_NE(what.find("servo.json"), std::string::npos) << what;
    for (const std::string& word : words) {
        EXPECT_NE(what.find(word), std::string::npos) << what;
    }
}

TEST(ServoGuard, TheGainBoundKeepsAMarginBelowTheMeasuredLimit) {
    EXPECT_LT(kMaxServoGain, kMeasuredServoGainLimit);
    // The affine estimate over-predicts the packing's modulus (r = E / E_hat <= 1), so up to
    // g = 1 a servo update never overshoots: the bound is no tighter than that.
    EXPECT_GE(kMaxServoGain, 1.0);
}

TEST(ServoGuard, AGainPastTheMeasuredLimitIsRefusedWithTheLimitNamed) {
    Json j = test::minimalExperiment();
    j["servo"] = {{"gain", kMeasuredServoGainLimit * 1.1}};
    ASSERT_NO_FATAL_FAILURE(
        expectRefusedAt(j, "servo.gain",
                        {fmt::format("(0, {}]", kMaxServoGain),
                         fmt::format("g = {}", kMeasuredServoGainLimit), "docs/stability.md"},
                        "a gain past the measured limit was accepted"));

    // Just past the bound is refused too; the bound itself and the default are accepted.
    j["servo"] = {{"gain", std::nextafter(kMaxServoGain, 2 * kMaxServoGain)}};
    EXPECT_FALSE(refusal(j).empty());
    j["servo"] = {{"gain", kMaxServoGain}};
    EXPECT_EQ(refusal(j), "");
    EXPECT_EQ(parseExperimentText(j.dump(), "ok.json").parameters.servo.gain, kMaxServoGain);
}

TEST(ServoGuard, AnIntervalPastTheMeasuredLagLineIsRefusedWithItsRange) {
    EXPECT_LT(kMaxServoLagPerGain, kMeasuredServoLagPerGain);
    // The minimal file: k_n = 1e8 N/m, shear at 2e-7 per step, lowest shear pressure 15 kPa,
    // default gain 0.3: one step is a lag number of 2e-7 * 1e8 / 15e3, and the largest interval
    // is floor(kMaxServoLagPerGain * 0.3 / that).
    Json j = test::minimalExperiment();
    const double lagOfOne = 2e-7 * 1e8 / 15e3;
    const int largest = int(std::floor(kMaxServoLagPerGain * 0.3 / lagOfOne));
    ASSERT_GE(largest, 2);
    j["servo"] = {{"interval", largest}};
    EXPECT_EQ(refusal(j), "");
    j["servo"] = {{"interval", largest + 1}};
    ASSERT_NO_FATAL_FAILURE(expectRefusedAt(j, "servo.interval",
                                            {fmt::format("[1, {}]", largest), "1 % band",
                                             fmt::format("from {} on", kMeasuredServoLagPerGain)},
                                            "an interval past the measured line was accepted"));
    // The line scales with the loading and the gain: a gain three times larger, or a loading
    // three times slower, allows three times the interval.
    j["servo"] = {{"interval", 3 * largest}, {"gain", 0.9}};
    EXPECT_EQ(refusal(j), "");
    j["servo"] = {{"interval", 3 * largest}};
    EXPECT_FALSE(refusal(j).empty());
    j["shear"]["axial_strain_per_step"] = 2e-7 / 3;
    EXPECT_EQ(refusal(j), "");
    // Interval 1 is always accepted, however fast the loading or small the gain.
    j["servo"] = {{"interval", 1}, {"gain", 0.01}};
    j["shear"]["axial_strain_per_step"] = 1e-4;
    j["shear"]["max_strain_rate"] = 500;
    EXPECT_EQ(refusal(j), "");
}

} // namespace
} // namespace grainlab
