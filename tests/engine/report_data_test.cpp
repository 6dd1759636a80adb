// The numbers behind the report's figures and table, against hand computations on series whose
// curves are known in closed form.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "grainlab/path_measures.h"
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
            run.tests.push_back(
                shearTest(t == 0 ? "p015kPa" : "p100kPa", 0.12 + 0.01 * seed, 60,
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
    const auto exact =
        fitLine({1, 2, 3, 4}, {3.45 * 1 + 2.1, 3.45 * 2 + 2.1, 3.45 * 3 + 2.1, 3.45 * 4 + 2.1});
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

TEST(ReportFigures, ATestInExtensionIsDrawnAgainstItsNegativeStrain) {
    // Two runs of a test in extension: eps1 from 0 down to -0.12, q/p = a eps1 (a = 4 and 6).
    std::vector<ReportRun> runs;
    for (double a : {4.0, 6.0}) {
        ReportRun run;
        run.name = "a" + std::to_string(int(a));
        SeriesTable t = shearTest("p015kPa-extension", 0.12, 60,
                                  [&](test::SeriesBuilder& b, std::vector<double>& r, double e) {
                                      b.at(r, "eps1") = -e;
                                      b.at(r, "q_over_p") = -a * e;
                                  });
        run.tests.push_back(std::move(t));
        run.pressures.push_back(15e3);
        runs.push_back(std::move(run));
    }
    const std::vector<ReportFigure> figures = reportFigures(runs);
    const ReportFigure& qp = figure(figures, "01_q_over_p");
    ASSERT_EQ(qp.lines.size(), 1u);
    const ReportLine& line = qp.lines[0];
    ASSERT_GE(line.x.size(), 10u) << "the extension test is missing from the strain figure";
    EXPECT_DOUBLE_EQ(line.x.front(), -0.12);
    EXPECT_DOUBLE_EQ(line.x.back(), 0.0);
    for (std::size_t k = 0; k < line.x.size(); ++k) {
        EXPECT_NEAR(line.y[k], 5.0 * line.x[k], 1e-12); // the mean of 4 eps1 and 6 eps1
        EXPECT_EQ(line.runs[k], 2);
    }
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

/// A test of kind `kind` ("shear", "constant_volume") from eps1 = 0 to 0.12 in 60 records: p, q,
/// e and eps_v ramp to (pEnd, qEnd, eEnd, -0.02) by eps1 = 0.04 and stay there, or, with
/// `hardening`, q keeps growing by 5 p per unit eps1.
SeriesTable endingTest(const std::string& name, const std::string& kind, double pEnd, double qEnd,
                       double eEnd, bool hardening = false) {
    test::SeriesBuilder b(name);
    for (int k = 0; k <= 60; ++k) {
        const double eps1 = 0.12 * k / 60;
        const double ramp = std::min(1.0, eps1 / 0.04);
        auto& r = b.row(kind + " 15 kPa");
        b.t.stageKinds.push_back(kind);
        b.at(r, "eps1") = eps1;
        b.at(r, "p") = pEnd;
        b.at(r, "q") = hardening ? qEnd + 5.0 * pEnd * (eps1 - 0.12) : ramp * qEnd;
        b.at(r, "e") = eEnd;
        b.at(r, "epsv") = kind == "constant_volume" ? 0.0 : -0.02 * ramp;
        b.at(r, "q_over_p") = b.at(r, "q") / pEnd;
    }
    return b.t;
}

TEST(CriticalStateOfRuns, MAndTheLineComeFromTheSteadyEndsOnly) {
    // Two runs; per run a steady drained and a steady constant-volume test at 15 kPa, a drained
    // test at 100 kPa still hardening, a steady constant-volume test at 100 kPa.
    std::vector<ReportRun> runs;
    std::vector<double> ratios, drainedRatios, cvRatios, lnP, e;
    for (int s = 0; s < 2; ++s) {
        ReportRun run;
        run.name = "seed" + std::to_string(s + 1);
        const auto add = [&](const std::string& name, const std::string& kind, double pressure,
                             double p, double ratio, double voids, bool hardening) {
            run.tests.push_back(endingTest(name, kind, p, ratio * p, voids, hardening));
            run.pressures.push_back(pressure);
            if (!hardening) {
                ratios.push_back(ratio);
                (kind == "constant_volume" ? cvRatios : drainedRatios).push_back(ratio);
                lnP.push_back(std::log(p));
                e.push_back(voids);
            }
        };
        add("p015kPa", "shear", 15e3, 15e3, 0.55 + 0.01 * s, 0.20 + 0.002 * s, false);
        add("p015kPa-constant-volume", "constant_volume", 15e3, 40e3 + 1e3 * s, 0.53 + 0.02 * s,
            0.18, false);
        add("p100kPa", "shear", 100e3, 100e3, 0.3, 0.17, true);
        add("p100kPa-constant-volume", "constant_volume", 100e3, 250e3 + 5e3 * s, 0.56 - 0.01 * s,
            0.15 - 0.001 * s, false);
        runs.push_back(std::move(run));
    }
    const CriticalStateSummary cs = criticalStateOf(runs);
    ASSERT_EQ(cs.ends.size(), 8u);
    EXPECT_EQ(cs.steadyCount(), 6);
    for (const TestEndState& end : cs.ends) {
        EXPECT_EQ(end.steady.steady, end.test != "p100kPa") << end.run << " " << end.test;
        if (end.test == "p100kPa") {
            EXPECT_NE(end.steady.reason.find("dq/deps1"), std::string::npos) << end.steady.reason;
        }
        EXPECT_EQ(end.kind,
                  end.test.find("constant") == std::string::npos ? "shear" : "constant_volume");
    }
    // M by hand: mean and sample standard deviation of the steady ends' q/p.
    const auto meanSd = [](const std::vector<double>& v) {
        double m = 0, ss = 0;
        for (double x : v) {
            m += x;
        }
        m /= double(v.size());
        for (double x : v) {
            ss += (x - m) * (x - m);
        }
        return std::pair{m, std::sqrt(ss / double(v.size() - 1))};
    };
    EXPECT_NEAR(cs.m.mean, meanSd(ratios).first, 1e-12);
    EXPECT_NEAR(cs.m.sd, meanSd(ratios).second, 1e-12);
    EXPECT_EQ(cs.m.count, 6);
    EXPECT_NEAR(cs.mDrained.mean, meanSd(drainedRatios).first, 1e-12);
    EXPECT_EQ(cs.mDrained.count, 2);
    EXPECT_NEAR(cs.mConstantVolume.mean, meanSd(cvRatios).first, 1e-12);
    EXPECT_EQ(cs.mConstantVolume.count, 4);
    // The line by hand: least squares of e on ln p over the six steady ends.
    double mx = 0, my = 0;
    for (std::size_t k = 0; k < lnP.size(); ++k) {
        mx += lnP[k] / double(lnP.size());
        my += e[k] / double(e.size());
    }
    double sxy = 0, sxx = 0;
    for (std::size_t k = 0; k < lnP.size(); ++k) {
        sxy += (lnP[k] - mx) * (e[k] - my);
        sxx += (lnP[k] - mx) * (lnP[k] - mx);
    }
    ASSERT_TRUE(cs.line.has_value());
    EXPECT_NEAR(cs.line->lambda, -sxy / sxx, 1e-12);
    EXPECT_NEAR(cs.line->eGamma, my - sxy / sxx * mx, 1e-10);
    EXPECT_EQ(cs.line->points, 6u);

    // The report's figures 9: the paths with q = M p', the steady ends with the line.
    const auto figures = reportFigures(runs);
    const ReportFigure& paths = figure(figures, "09_q_vs_p");
    EXPECT_EQ(paths.lines.size(), 4u);
    ASSERT_TRUE(paths.fit.has_value());
    EXPECT_NEAR(paths.fit->slope, cs.m.mean, 1e-12);
    EXPECT_EQ(paths.fit->intercept, 0.0);
    EXPECT_EQ(paths.xLabel, "p′ [kPa]");
    EXPECT_EQ(paths.yLabel, "q [kPa]");
    EXPECT_FALSE(paths.bands); // x moves too: a band of q alone would misstate the scatter
    const ReportFigure& ends = figure(figures, "09_e_vs_ln_p");
    EXPECT_EQ(ends.lines.size(), 3u); // the steady tests
    ASSERT_TRUE(ends.fit.has_value());
    EXPECT_NEAR(ends.fit->slope, -cs.line->lambda, 1e-12);
    EXPECT_NE(ends.fitLabel.find(cs.line->equation()), std::string::npos);
    for (const ReportLine& l : ends.lines) {
        ASSERT_EQ(l.x.size(), 1u);
        EXPECT_EQ(l.runs[0], 2);
    }
    EXPECT_EQ(ends.lines[1].label, "15 kPa constant volume");

    // With no steady end there is no M, no line and no e - ln p' figure.
    std::vector<ReportRun> hardening(1);
    hardening[0].tests = {endingTest("p015kPa", "shear", 15e3, 5e3, 0.2, true)};
    hardening[0].pressures = {15e3};
    EXPECT_EQ(criticalStateOf(hardening).m.count, 0);
    EXPECT_FALSE(criticalStateOf(hardening).line.has_value());
    for (const ReportFigure& f : reportFigures(hardening)) {
        EXPECT_NE(f.name, "09_e_vs_ln_p");
    }
}

TEST(ReportFigures, ACyclicTestHasItsLoopsAndItsPressurePerCycleNotAMeanCurve) {
    // A drained test and a cyclic one of two cycles in which p' halves every cycle.
    std::vector<ReportRun> runs(1);
    runs[0].name = "seed1";
    runs[0].tests.push_back(endingTest("p025kPa", "shear", 25e3, 12e3, 0.2));
    runs[0].pressures.push_back(25e3);
    test::SeriesBuilder b("p025kPa-cyclic");
    const double strains[] = {0, 0.001, 0, -0.001, 0, 0.001, 0, -0.001, 0, 0.001};
    const double pressures[] = {25e3, 22e3, 20e3, 17e3, 14e3, 12.5e3, 10e3, 8e3, 7e3, 6.25e3};
    for (int k = 0; k < 10; ++k) {
        auto& r = b.row("cyclic 25 kPa");
        b.t.stageKinds.push_back("cyclic");
        b.at(r, "eps1") = strains[k];
        b.at(r, "p") = pressures[k];
        b.at(r, "q") = 1e6 * strains[k];
    }
    runs[0].tests.push_back(b.t);
    runs[0].pressures.push_back(25e3);
    const auto figures = reportFigures(runs);
    // The strain figures average over a grid of eps1: the cyclic test is not among their lines.
    for (const ReportLine& l : figure(figures, "01_q_over_p").lines) {
        EXPECT_NE(l.test, "p025kPa-cyclic");
    }
    const ReportFigure& loops = figure(figures, "10_p025kPa-cyclic_loops");
    ASSERT_EQ(loops.lines.size(), 1u);
    EXPECT_EQ(loops.lines[0].x.size(), 10u); // every record, as recorded
    EXPECT_EQ(loops.xLabel, "ε1 [%]");
    EXPECT_EQ(loops.lines[0].label, "seed1");
    const ReportFigure& decay = figure(figures, "10_p025kPa-cyclic_p_per_cycle");
    ASSERT_EQ(decay.lines.size(), 1u);
    // Cycle 0 at p0; cycles end at the upper peaks (records 5 and 9): 12.5 and 6.25 kPa.
    ASSERT_EQ(decay.lines[0].x, (std::vector<double>{0, 1, 2}));
    EXPECT_DOUBLE_EQ(decay.lines[0].y[1], 0.5);
    EXPECT_DOUBLE_EQ(decay.lines[0].y[2], 0.25);
    // Its end is no steady state of the critical state.
    for (const TestEndState& end : criticalStateOf(runs).ends) {
        EXPECT_NE(end.test, "p025kPa-cyclic");
    }
}

TEST(ReportFigures, AProbeSetDrawsItsResponseEnvelopeLessTheDrift) {
    // Eight probes whose responses are A u_k plus a drift that the zero probe also has: the
    // envelope drawn is A u_k (an ellipse about the origin), closed, and called elastic.
    std::vector<ReportRun> runs(1);
    runs[0].name = "seed1";
    test::SeriesBuilder b("p025kPa-probes");
    const auto directions = probeDirections(8);
    const double drift11 = 300, drift22 = -100;
    for (int k = -2; k < 8; ++k) { // the start, the zero probe, the probes
        auto& r = b.row("probes 25 kPa");
        b.t.stageKinds.push_back("probes");
        double s11 = 25e3, s22 = 25e3;
        if (k >= -1) {
            s11 += drift11;
            s22 += drift22;
        }
        if (k >= 0) {
            s11 += 2e3 * directions[std::size_t(k)][0] + 500 * directions[std::size_t(k)][1];
            s22 += 500 * directions[std::size_t(k)][0] + 1e3 * directions[std::size_t(k)][1];
        }
        b.at(r, "sigma11") = s11;
        b.at(r, "sigma22") = s22;
    }
    runs[0].tests.push_back(b.t);
    runs[0].pressures.push_back(25e3);
    const auto figures = reportFigures(runs);
    const ReportFigure& f = figure(figures, "11_p025kPa-probes_envelope");
    ASSERT_EQ(f.lines.size(), 1u);
    ASSERT_EQ(f.lines[0].x.size(), 9u);      // closed
    EXPECT_NEAR(f.lines[0].x[0], 2e3, 1e-9); // u_0 = (1, 0): the drift taken off
    EXPECT_NEAR(f.lines[0].y[0], 500, 1e-9);
    EXPECT_EQ(f.lines[0].x.back(), f.lines[0].x.front());
    EXPECT_NE(f.note.find("asymmetry"), std::string::npos) << f.note;
    EXPECT_EQ(f.xLabel, "Δσ11 [kPa]");
    for (const ReportLine& l : figure(figures, "01_q").lines) {
        EXPECT_NE(l.test, "p025kPa-probes");
    }
}

} // namespace
} // namespace grainlab
