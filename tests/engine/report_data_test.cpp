// The numbers behind the report's figures and table, against hand computations on series whose
// curves are known in closed form.
#include <cmath>

#include <gtest/gtest.h>

#include "grainlab/report_data.h"
#include "series_builder.h"

namespace grainlab {
namespace {

/// A test sheared from eps1 = 0 to 0.12 in `records` records, with the columns given as
/// functions of eps1 (all others zero); row 0 is its re-equilibration, with void ratio e0.
template <class F>
SeriesTable shearTest(const std::string& name, double e0, int records, F columns) {
    test::SeriesBuilder b(name);
    auto& first = b.row("equilibration");
    b.at(first, "e") = e0;
    b.t.stageKinds.push_back("equilibration");
    for (int k = 0; k <= records; ++k) {
        const double eps1 = 0.12 * k / records;
        auto& r = b.row("shear");
        b.t.stageKinds.push_back("shear");
        b.at(r, "eps1") = eps1;
        columns(b, r, eps1);
    }
    return b.t;
}

const ReportFigure& figure(const std::vector<ReportFigure>& figures, const std::string& name) {
    for (const ReportFigure& f : figures) {
        if (f.name == name) {
            return f;
        }
    }
    throw std::runtime_error("no figure " + name);
}

const HeadlineRow& row(const std::vector<HeadlineRow>& rows, const std::string& key) {
    for (const HeadlineRow& r : rows) {
        if (r.key == key) {
            return r;
        }
    }
    throw std::runtime_error("no row " + key);
}

/// Two runs of two tests: q/p = a eps1 (a = 4 and 6 at 15 kPa, 2 and 3 at 100 kPa), eps_v =
/// -0.2 eps1, Z_eff = 3 N_v/N_vi + 2 with N_v/N_vi = 1 + eps1, Z = Z_eff - 0.5.
std::vector<ReportRun> twoRuns() {
    std::vector<ReportRun> runs;
    for (int seed = 0; seed < 2; ++seed) {
        ReportRun run;
        run.name = "seed" + std::to_string(seed + 1);
        for (int t = 0; t < 2; ++t) {
            const double slope = (t == 0 ? 4.0 : 2.0) * (seed == 0 ? 1.0 : 1.5);
            run.tests.push_back(shearTest(
                t == 0 ? "p015kPa" : "p100kPa", 0.12 + 0.01 * seed, 60,
                [&](test::SeriesBuilder& b, std::vector<double>& r, double eps1) {
                    b.at(r, "q_over_p") = slope * eps1;
                    b.at(r, "phi_deg") = 10.0 * slope * eps1;
                    b.at(r, "epsv") = -0.2 * eps1;
                    b.at(r, "Nv_over_Nvi") = 1.0 + eps1;
                    b.at(r, "Z_eff") = 3.0 * (1.0 + eps1) + 2.0;
                    b.at(r, "Z") = 3.0 * (1.0 + eps1) + 1.5;
                    b.at(r, "I_uf") = 0.1 + 0.1 * seed;
                }));
            run.pressures.push_back(t == 0 ? 15e3 : 100e3);
        }
        runs.push_back(std::move(run));
    }
    return runs;
}

TEST(FitLine, RecoversAnExactLineAndMatchesTheNormalEquations) {
    const auto exact = fitLine({1, 2, 3, 4}, {3.45 * 1 + 2.1, 3.45 * 2 + 2.1, 3.45 * 3 + 2.1,
                                              3.45 * 4 + 2.1});
    ASSERT_TRUE(exact);
    EXPECT_NEAR(exact->slope, 3.45, 1e-12);
    EXPECT_NEAR(exact->intercept, 2.1, 1e-12);
    EXPECT_NEAR(exact->r2, 1.0, 1e-12);
    // (0,0), (1,1), (2,4): slope 2, intercept -1/3, SS_res 2/3 of SS_tot 26/3.
    const auto fit = fitLine({0, 1, 2}, {0, 1, 4});
    ASSERT_TRUE(fit);
    EXPECT_NEAR(fit->slope, 2.0, 1e-12);
    EXPECT_NEAR(fit->intercept, -1.0 / 3.0, 1e-12);
    EXPECT_NEAR(fit->r2, 1.0 - (2.0 / 3.0) / (26.0 / 3.0), 1e-12);
    EXPECT_FALSE(fitLine({1, 1}, {2, 3})); // no spread in x
    EXPECT_FALSE(fitLine({1}, {2}));
}

TEST(ReportFigures, CurvesAreTheMeanOverRunsWithTheirStandardDeviation) {
    const auto figures = reportFigures(twoRuns());
    const ReportFigure& qp = figure(figures, "01_q_over_p");
    ASSERT_EQ(qp.lines.size(), 2u);
    EXPECT_EQ(qp.lines[0].test, "p015kPa");
    EXPECT_EQ(qp.lines[1].test, "p100kPa");
    const ReportLine& low = qp.lines[0];
    ASSERT_FALSE(low.x.empty());
    for (std::size_t k = 0; k < low.x.size(); ++k) {
        const double a = 4.0 * low.x[k], b = 6.0 * low.x[k];
        EXPECT_NEAR(low.y[k], (a + b) / 2, 1e-12);
        EXPECT_NEAR(low.sd[k], std::abs(a - b) / std::sqrt(2.0), 1e-12); // two samples
        EXPECT_EQ(low.runs[k], 2);
    }
    EXPECT_DOUBLE_EQ(low.x.back(), 0.12);
}

TEST(ReportFigures, AxesAreLabelledAsAPaperWouldWithTheDataInStoredUnits) {
    const auto figures = reportFigures(twoRuns());
    const ReportFigure& qp = figure(figures, "01_q_over_p");
    EXPECT_EQ(qp.xLabel, "ε1 [%]");
    EXPECT_EQ(qp.xScale, 100.0);
    EXPECT_EQ(qp.yLabel, "q/p");
    EXPECT_EQ(qp.yScale, 1.0);
    EXPECT_DOUBLE_EQ(qp.lines[0].x.back(), 0.12); // the lines keep the stored strain
    EXPECT_EQ(figure(figures, "03_epsv").yLabel, "εv [%]");
    EXPECT_EQ(figure(figures, "03_epsv").yScale, 100.0);
    EXPECT_EQ(figure(figures, "01_q").yLabel, "q [kPa]");
    EXPECT_EQ(figure(figures, "01_q").yScale, 1e-3);
    for (const ReportFigure& f : figures) {
        EXPECT_EQ(f.xLabel.find("[-]"), std::string::npos) << f.name << ": " << f.xLabel;
        EXPECT_EQ(f.yLabel.find("[-]"), std::string::npos) << f.name << ": " << f.yLabel;
        EXPECT_EQ(f.xLabel.find("_over_"), std::string::npos) << f.name << ": " << f.xLabel;
        EXPECT_EQ(f.yLabel.find("_over_"), std::string::npos) << f.name << ": " << f.yLabel;
    }
}

TEST(ReportFigures, SmoothedDilatancyOfALinearVolumeChangeIsItsSlope) {
    ReportOptions options;
    options.dilatancyWindow = 0.01;
    const auto figures = reportFigures(twoRuns(), options);
    const ReportFigure& di = figure(figures, "03_DI");
    ASSERT_EQ(di.lines.size(), 2u);
    const ReportLine& line = di.lines[0];
    ASSERT_FALSE(line.x.empty());
    // The window must lie inside the curve: the first and last half-windows have no value.
    EXPECT_GE(line.x.front(), 0.005 - 1e-12);
    EXPECT_LE(line.x.back(), 0.115 + 1e-12);
    for (double y : line.y) {
        EXPECT_NEAR(y, 0.2, 1e-9);
    }
    ASSERT_EQ(line.extra.size(), 2u);
    EXPECT_EQ(line.extra[0].second.size(), line.x.size());
}

TEST(ReportFigures, PeakFrictionAngleAgainstPressureAndThePooledFit) {
    const auto figures = reportFigures(twoRuns());
    const ReportFigure& phi = figure(figures, "02_phi_peak");
    ASSERT_EQ(phi.lines.size(), 1u);
    const ReportLine& points = phi.lines[0];
    ASSERT_EQ(points.x.size(), 2u);
    EXPECT_DOUBLE_EQ(points.x[0], 15.0);
    EXPECT_DOUBLE_EQ(points.x[1], 100.0);
    // The peak is at eps1 = 0.12: phi = 10 a 0.12 with a = 4, 6 at 15 kPa.
    EXPECT_NEAR(points.y[0], 10 * 0.12 * 5.0, 1e-12);
    EXPECT_NEAR(points.sd[0], 10 * 0.12 * 2.0 / std::sqrt(2.0), 1e-12);

    const ReportFigure& fit = figure(figures, "06_Z_eff_vs_Nv_over_Nvi");
    ASSERT_TRUE(fit.fit);
    EXPECT_NEAR(fit.fit->slope, 3.0, 1e-9);
    EXPECT_NEAR(fit.fit->intercept, 2.0, 1e-9);
    EXPECT_EQ(fit.fit->count, 2u * 2u * 61u);
    // One series against another: both means taken at the same eps1.
    ASSERT_EQ(fit.lines.size(), 2u);
    ASSERT_FALSE(fit.lines[0].x.empty());
    for (std::size_t k = 0; k < fit.lines[0].x.size(); ++k) {
        EXPECT_NEAR(fit.lines[0].y[k], 3.0 * fit.lines[0].x[k] + 2.0, 1e-9);
        EXPECT_NEAR(fit.lines[0].xSd[k], 0.0, 1e-12);
    }
    const PooledFitScatter pooled = pooledFitOverRuns(twoRuns());
    EXPECT_EQ(pooled.slope.count, 2);
    EXPECT_NEAR(pooled.slope.mean, 3.0, 1e-9);
    EXPECT_NEAR(pooled.intercept.mean, 2.0, 1e-9);
}

TEST(HeadlineTable, NumbersCarryTheirScatterAndFaceThePublishedValues) {
    const auto rows = headlineTable(twoRuns());
    const HeadlineRow& e = row(rows, "e_compacted");
    ASSERT_EQ(e.values.size(), 2u);
    EXPECT_NEAR(e.values[0].value.mean, 0.125, 1e-12); // 0.12 and 0.13
    EXPECT_NEAR(e.values[0].value.sd, 0.01 / std::sqrt(2.0), 1e-12);
    ASSERT_TRUE(e.published);
    const Comparison ce = compare(e.values[0].value, *e.published);
    EXPECT_NEAR(ce.difference, -0.001, 1e-12);
    EXPECT_TRUE(ce.agrees); // within 2 sd
    EXPECT_FALSE(ce.beyondScatter);

    const HeadlineRow& dz = row(rows, "Z_eff_minus_Z");
    EXPECT_NEAR(dz.values[1].value.mean, 0.5, 1e-12);
    EXPECT_NEAR(dz.values[1].value.sd, 0.0, 1e-12);
    EXPECT_NEAR(row(rows, "fit_slope").values[0].value.mean, 3.0, 1e-9);
    EXPECT_NEAR(row(rows, "fit_intercept").values[0].value.mean, 2.0, 1e-9);

    const HeadlineRow& iuf = row(rows, "I_uf_mean");
    EXPECT_NEAR(iuf.values[0].value.mean, 0.15, 1e-12);
    ASSERT_TRUE(iuf.published && iuf.published->upperBound);
    EXPECT_TRUE(compare(iuf.values[0].value, *iuf.published).agrees);
    EXPECT_FALSE(compare(Scatter{0.5, 0.01, 2}, *iuf.published).agrees);
    EXPECT_TRUE(compare(Scatter{0.5, 0.01, 2}, *iuf.published).beyondScatter);
    EXPECT_FALSE(compare(Scatter{0.41, 0.01, 2}, *iuf.published).beyondScatter);
    // One run has no scatter: any difference lies beyond it.
    EXPECT_TRUE(compare(Scatter{0.127, 0.0, 1}, *e.published).beyondScatter);
}

} // namespace
} // namespace grainlab
