// A study's summary against hand computations: means and scatter over seeds, errors against the
// reference (exactly zero for the reference itself), the noise band, tolerances, and the
// recommendation (the cheapest setting within tolerance).
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "grainlab/study_summary.h"
#include "series_builder.h"

namespace grainlab {
namespace {

/// A shear test whose q/p rises linearly to `peak` at 3 % and stays there, to eps1 = 5 %.
SeriesTable test(double peak, const std::string& name = "p015kPa") {
    test::SeriesBuilder b(name);
    for (int k = 0; k <= 50; ++k) {
        auto& r = b.row("shear 15 kPa");
        const double e = 0.001 * k;
        b.at(r, "eps1") = e;
        b.at(r, "q_over_p") = peak * std::min(e / 0.03, 1.0);
        b.at(r, "epsv") = -0.1 * e * peak;
        b.at(r, "sigma22") = 15e3;
    }
    return b.t;
}

StudyPlan threeSettings() {
    StudyPlan plan;
    plan.settings = {{"ref", {}, true}, {"a", {}, false}, {"b", {}, false}};
    for (int s = 0; s < 3; ++s) {
        for (int seed = 1; seed <= 2; ++seed) {
            plan.runs.push_back({plan.settings[std::size_t(s)].id, s, std::uint64_t(seed), ""});
        }
    }
    return plan;
}

/// A study decided by the peak of q/p alone, within `tolerance` (a fraction of the reference
/// mean when `relative`).
StudySpec decidedByPeak(double tolerance, bool relative) {
    StudySpec spec;
    spec.tolerances["peak_q_over_p"] = {tolerance, relative};
    spec.deciding = {"peak_q_over_p"};
    return spec;
}

RunResult result(int run, double peak, double cpu) {
    RunResult r;
    r.run = run;
    r.tests = {test(peak)};
    r.pressures = {15e3};
    r.cost.cpuSeconds = cpu;
    r.cost.wallSeconds = cpu / 2;
    return r;
}

const MetricSummary& metric(const SettingSummary& s, const std::string& name) {
    const auto it = std::find_if(s.metrics.begin(), s.metrics.end(),
                                 [&](const MetricSummary& m) { return m.metric == name; });
    EXPECT_NE(it, s.metrics.end()) << name;
    return *it;
}

TEST(StudySummary, ErrorsNoiseTolerancesAndTheCheapestValidSetting) {
    const StudySpec spec = decidedByPeak(0.05, true); // 5 % of the reference mean
    const StudyPlan plan = threeSettings();
    // ref: 0.50, 0.52; a: 0.51, 0.53 (+0.01, in the noise); b: 0.60, 0.62 (+0.10, out).
    const std::vector<RunResult> results{result(0, 0.50, 10), result(1, 0.52, 12),
                                         result(2, 0.51, 5),  result(3, 0.53, 5),
                                         result(4, 0.60, 1),  result(5, 0.62, 1)};
    const StudySummary s = summariseStudy(spec, plan, results);
    ASSERT_EQ(s.settings.size(), 3u);
    ASSERT_EQ(s.tests, std::vector<std::string>{"p015kPa"});

    const MetricSummary& ref = metric(s.settings[0], "peak_q_over_p");
    EXPECT_DOUBLE_EQ(ref.scatter.mean, 0.51);
    EXPECT_NEAR(ref.scatter.sd, 0.02 / std::sqrt(2.0), 1e-15);
    EXPECT_EQ(*ref.error, 0.0);
    EXPECT_EQ(*metric(s.settings[0], "rms_q_over_p").error, 0.0);
    EXPECT_TRUE(ref.withinNoise);
    EXPECT_NEAR(*ref.noise, 2 * 0.02 / std::sqrt(2.0), 1e-15);

    const MetricSummary& a = metric(s.settings[1], "peak_q_over_p");
    EXPECT_NEAR(*a.error, 0.01, 1e-15);
    EXPECT_TRUE(a.withinNoise);
    EXPECT_TRUE(*a.withinTolerance); // 0.01 <= 0.05 * 0.51
    const MetricSummary& b = metric(s.settings[2], "peak_q_over_p");
    EXPECT_NEAR(*b.error, 0.10, 1e-15);
    EXPECT_FALSE(b.withinNoise);
    EXPECT_FALSE(*b.withinTolerance);

    // The curves: q/p scales with the peak, so the mean curves differ by 0.01 * (min(e/0.03, 1))
    // for a: RMS over 101 points of [0, 0.05] computed by hand.
    double squares = 0;
    for (int k = 0; k <= 100; ++k) {
        const double e = 0.05 * k / 100;
        const double d = 0.01 * std::min(e / 0.03, 1.0);
        squares += d * d;
    }
    EXPECT_NEAR(*metric(s.settings[1], "rms_q_over_p").error, std::sqrt(squares / 101), 1e-12);

    EXPECT_TRUE(s.settings[0].valid);
    EXPECT_TRUE(s.settings[1].valid);
    EXPECT_FALSE(s.settings[2].valid);
    ASSERT_TRUE(s.recommended);
    EXPECT_EQ(*s.recommended, 1); // b is cheaper but not valid
    EXPECT_DOUBLE_EQ(*s.settings[1].speedUp, 11.0 / 5.0);
    EXPECT_DOUBLE_EQ(s.settings[0].cpuSeconds.mean, 11);
    EXPECT_DOUBLE_EQ(s.settings[0].wallSeconds.mean, 5.5);

    // study.csv cells: each run's own metrics; a run's curve error is against the ref mean.
    ASSERT_EQ(s.perRun.size(), 6u);
    EXPECT_DOUBLE_EQ(*s.perRun[4].at("p015kPa.peak_q_over_p"), 0.60);
    EXPECT_GT(*s.perRun[0].at("p015kPa.rms_q_over_p"), 0);
}

TEST(StudySummary, ASettingThatWidensTheSeedScatterBeyondTheToleranceIsNotValid) {
    const StudySpec spec = decidedByPeak(0.05, true); // 0.0255 of the reference mean 0.51
    const StudyPlan plan = threeSettings();
    // ref: 0.50, 0.52 (sd 0.0141); a: 0.47, 0.55 (the same mean, sd 0.0566: one run of a may
    // miss the reference by far more than the tolerance); b: 0.52, 0.54 (+0.02, sd as ref's).
    const std::vector<RunResult> results{result(0, 0.50, 10), result(1, 0.52, 12),
                                         result(2, 0.47, 1),  result(3, 0.55, 1),
                                         result(4, 0.52, 5),  result(5, 0.54, 5)};
    const StudySummary s = summariseStudy(spec, plan, results);
    const MetricSummary& a = metric(s.settings[1], "peak_q_over_p");
    EXPECT_NEAR(*a.error, 0.0, 1e-15);
    // 0 + (0.0566 - 0.0141) = 0.0424 > 0.0255.
    EXPECT_FALSE(*a.withinTolerance);
    EXPECT_FALSE(s.settings[1].valid);
    const MetricSummary& b = metric(s.settings[2], "peak_q_over_p");
    EXPECT_TRUE(*b.withinTolerance);  // 0.02 + 0 <= 0.0255
    EXPECT_TRUE(s.settings[0].valid); // the reference never widens its own scatter
    EXPECT_EQ(*s.recommended, 2);
}

TEST(StudySummary, ASettingWithoutResultsIsNotValidAndTheCostMeasureIsChosen) {
    const StudySpec spec = decidedByPeak(0.5, false);
    const StudyPlan plan = threeSettings();
    const std::vector<RunResult> results{result(0, 0.50, 10), result(1, 0.52, 12),
                                         result(2, 0.51, 5)};
    const StudySummary s = summariseStudy(spec, plan, results, "wall_seconds");
    EXPECT_EQ(s.settings[1].runsDone, 1);
    EXPECT_EQ(s.settings[2].runsDone, 0);
    EXPECT_FALSE(s.settings[2].valid);
    EXPECT_DOUBLE_EQ(s.settings[1].cost.mean, 2.5);
    EXPECT_EQ(*s.recommended, 1);
    EXPECT_THROW(costOf(RunCost{}, "money"), std::invalid_argument);
}

} // namespace
} // namespace grainlab
