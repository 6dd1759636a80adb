// The report page's comparison with the published values: a bound is judged against the seed
// scatter only when there is one (two runs or more).
#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "report/report_page.h"

namespace grainlab {
namespace {

std::string pageWith(const std::vector<HeadlineValue>& values) {
    static const std::vector<ReportFigure> figures;
    static const PooledFitScatter pooled;
    const std::vector<ReportSource> sources{{"runs/seed1", "reference", 1, 8450, 10, 20, true}};
    std::vector<HeadlineRow> headline(1);
    headline[0].key = "I_uf_mean";
    headline[0].label = "mean I_uf during shear";
    headline[0].unit = "%";
    headline[0].values = values;
    headline[0].published = publishedUnbalancedForce();
    return reportMarkdown(ReportPage{figures, headline, pooled, sources, ""});
}

TEST(ReportPage, ABoundIsJudgedAgainstTheSeedScatterOnlyWhenThereIsOne) {
    // One run above the bound of 0.4 %: nothing to judge its distance by.
    std::string md = pageWith(
        {{"p015kPa", 15e3, Scatter{0.412, 0, 1}}, {"p025kPa", 25e3, Scatter{0.299, 0, 1}}});
    EXPECT_NE(md.find("15 kPa: above the bound (one run: no scatter to judge by)"),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("25 kPa: below the bound"), std::string::npos) << md;
    EXPECT_EQ(md.find("beyond the scatter"), std::string::npos) << md;
    // Three runs: 0.012 above is beyond 2 sd = 0.008, within 2 sd = 0.02.
    md = pageWith({{"p015kPa", 15e3, Scatter{0.412, 0.004, 3}}});
    EXPECT_NE(md.find("15 kPa: above the bound, beyond the scatter"), std::string::npos) << md;
    md = pageWith({{"p015kPa", 15e3, Scatter{0.412, 0.01, 3}}});
    EXPECT_NE(md.find("15 kPa: above the bound, within the scatter"), std::string::npos) << md;
}

TEST(ReportPage, TheCriticalStateSectionSaysWhetherDrainedAndUndrainedMAgree) {
    CriticalStateSummary cs;
    cs.ends.resize(5);
    for (int k = 0; k < 4; ++k) {
        cs.ends[std::size_t(k)].steady.steady = true;
    }
    cs.m = {0.55, 0.02, 4};
    cs.mDrained = {0.56, 0.015, 2};
    cs.mConstantVolume = {0.54, 0.01, 2};
    // Standard error of the difference: sqrt(0.015²/2 + 0.01²/2) = 0.0127; 0.02 is within twice.
    std::string text = criticalStateText(cs);
    EXPECT_NE(text.find("4 of 5 test ends are steady"), std::string::npos) << text;
    EXPECT_NE(text.find("M = q/p at the steady ends: 0.550 ± 0.020 (4 ends)"), std::string::npos)
        << text;
    EXPECT_NE(text.find("differ by 0.020, within twice the standard error of the difference "
                        "(0.025)"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("No critical state line"), std::string::npos) << text;
    cs.mConstantVolume = {0.50, 0.01, 2};
    text = criticalStateText(cs);
    EXPECT_NE(text.find("differ by 0.060, beyond"), std::string::npos) << text;
    cs.line = CriticalStateLine{0.8, 0.05, 0.97, 4};
    EXPECT_NE(criticalStateText(cs).find(cs.line->equation() + " (R² = 0.970, 4 points)"),
              std::string::npos);
    cs.m = {};
    EXPECT_NE(criticalStateText(cs).find("No steady end"), std::string::npos);
    // The CSV: one line per end, its header naming the units.
    const std::string csv = criticalStateCsv(cs);
    EXPECT_EQ(csv.substr(0, 30), "run,test,kind,pressure [Pa],st");
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 6);
}

} // namespace
} // namespace grainlab
