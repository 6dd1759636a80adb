// The report page's comparison with the published values: a bound is judged against the seed
// scatter only when there is one (two runs or more).
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
    std::string md = pageWith({{"p015kPa", 15e3, Scatter{0.412, 0, 1}},
                               {"p025kPa", 25e3, Scatter{0.299, 0, 1}}});
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

} // namespace
} // namespace grainlab
