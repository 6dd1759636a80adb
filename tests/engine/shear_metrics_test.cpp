// The metrics of one shear test against a hand-built series whose answers are known: the
// re-equilibration rows before shear must not count, values at fixed strains interpolate, the
// damping share follows from the energy balance.
#include <cmath>

#include <gtest/gtest.h>

#include "grainlab/shear_metrics.h"
#include "series_builder.h"

namespace grainlab {
namespace {

using test::SeriesBuilder;

SeriesTable syntheticTest() {
    SeriesBuilder b;
    // Re-equilibration: a huge q/p and I_uf that must be ignored.
    auto& eq = b.row("equilibration 100 kPa");
    b.at(eq, "q_over_p") = 5;
    b.at(eq, "I_uf") = 99;
    b.at(eq, "e") = 0.2;
    b.at(eq, "sigma22") = 5e5;
    // Shear: eps1 = 0, 0.01, ..., 0.12; q/p rises linearly to 0.5 at 3 % then falls by 0.01 per
    // 1 %; eps_v = -eps1 / 2; sigma22 off its target by 0.2 % at most (at 7 %).
    for (int k = 0; k <= 12; ++k) {
        auto& r = b.row("shear 100 kPa");
        const double e = 0.01 * k;
        b.at(r, "eps1") = e;
        b.at(r, "q_over_p") = k <= 3 ? 0.5 * e / 0.03 : 0.5 - (e - 0.03);
        b.at(r, "phi_deg") = 10 + k;
        b.at(r, "epsv") = -e / 2;
        b.at(r, "DI") = k == 4 ? 0.7 : 0.5;
        b.at(r, "sigma22") = 1e5 * (1 + (k == 7 ? -0.002 : 0.001));
        b.at(r, "I_uf") = k; // mean over 13 rows: 6
        b.at(r, "Z") = 4 - e;
        b.at(r, "Z_eff") = 4.5 - e;
        b.at(r, "Nv_over_Nvi") = 1 - e;
        b.at(r, "Hdev") = e;
        b.at(r, "e") = 0.2 + e;
        b.at(r, "p") = 1e5 * (1 + e);
        b.at(r, "q") = b.at(r, "q_over_p") * b.at(r, "p");
        // Energy: elastic +1 J, friction +2 J, damping +1 J over shear; kinetic unchanged.
        b.at(r, "E_kin") = 0.5;
        b.at(r, "E_elastic") = 3 + k / 12.0;
        b.at(r, "W_friction") = 10 + 2 * k / 12.0;
        b.at(r, "W_damping") = 7 + k / 12.0;
    }
    return b.t;
}

TEST(ShearMetrics, PeakAndValuesAtFixedStrainsOfAKnownCurve) {
    const ShearMetrics m = shearMetrics(syntheticTest(), 1e5);
    EXPECT_DOUBLE_EQ(*m.peakStressRatio, 0.5); // the equilibration row's 5 is not shear
    EXPECT_DOUBLE_EQ(*m.peakAxialStrain, 0.03);
    EXPECT_DOUBLE_EQ(*m.peakFrictionAngle, 13);
    EXPECT_NEAR(*m.stressRatioAt[0], 0.5 * 0.02 / 0.03, 1e-14);
    EXPECT_NEAR(*m.stressRatioAt[1], 0.48, 1e-14);
    EXPECT_NEAR(*m.stressRatioAt[2], 0.43, 1e-14);
    EXPECT_NEAR(*m.volumetricStrainAt[1], -0.025, 1e-15);
    EXPECT_DOUBLE_EQ(*m.maxDilatancy, 0.7);
    EXPECT_DOUBLE_EQ(*m.voidRatioAtStart, 0.2);
    EXPECT_NEAR(*m.coordinationAt5, 3.95, 1e-14);
    EXPECT_NEAR(*m.coordinationAt10, 3.9, 1e-14);
    EXPECT_NEAR(*m.effectiveCoordinationAt10, 4.4, 1e-14);
    EXPECT_NEAR(*m.voidCountRatioAt10, 0.9, 1e-14);
    EXPECT_NEAR(*m.fabricAt10, 0.1, 1e-14);
    EXPECT_NEAR(*m.maxLateralStressError, 0.002, 1e-12);
    EXPECT_DOUBLE_EQ(*m.meanUnbalancedForce, 6);
    EXPECT_NEAR(*m.dampingWorkFraction, 0.25, 1e-14); // 1 J of the 4 J the boundary put in
}

TEST(ShearMetrics, StrainsNotReachedAndMissingShearAreLeftEmpty) {
    SeriesTable t = syntheticTest();
    // Cut the test at eps1 = 4 %: the 5 % and 10 % values are not known.
    t.rows.resize(6);
    t.stages.resize(6);
    const ShearMetrics m = shearMetrics(t, 1e5);
    EXPECT_TRUE(m.stressRatioAt[0]);
    EXPECT_FALSE(m.stressRatioAt[1]);
    EXPECT_FALSE(m.stressRatioAt[2]);
    EXPECT_FALSE(m.coordinationAt5);
    EXPECT_FALSE(m.coordinationAt10);
    // Only the re-equilibration: no shear metrics at all, but the compacted sample's e.
    t.rows.resize(1);
    t.stages.resize(1);
    const ShearMetrics none = shearMetrics(t, 1e5);
    EXPECT_FALSE(none.peakStressRatio);
    EXPECT_FALSE(none.meanUnbalancedForce);
    EXPECT_DOUBLE_EQ(*none.voidRatioAtStart, 0.2);
}

TEST(ShearMetrics, AShearThatEndsAFractionOfAStepShortOfAMetricStrainHasItsValueThere) {
    SeriesTable t = syntheticTest();
    // Cut at eps1 = 5 %, then move the last record a hair short of it, as a shear to exactly 5 %
    // ends (its strain a sum of steps): the last record stands for 5 %.
    t.rows.resize(7);
    t.stages.resize(7);
    const auto eps1 = std::size_t(t.column("eps1"));
    t.rows.back()[eps1] = 0.05 * (1 - 2e-7);
    ShearMetrics m = shearMetrics(t, 1e5);
    ASSERT_TRUE(m.stressRatioAt[1]);
    EXPECT_DOUBLE_EQ(*m.stressRatioAt[1], t.rows.back()[std::size_t(t.column("q_over_p"))]);
    ASSERT_TRUE(m.coordinationAt5);
    EXPECT_FALSE(m.coordinationAt10);
    // A shear that stops clearly short of 5 % (by 1e-3 of it) has no value there.
    t.rows.back()[eps1] = 0.05 * (1 - 1e-3);
    m = shearMetrics(t, 1e5);
    EXPECT_FALSE(m.stressRatioAt[1]);
    EXPECT_FALSE(m.coordinationAt5);
}

TEST(ShearMetrics, TheRowsStageKindDecidesWhatIsShearWhereTheTableHasIt) {
    SeriesTable t = syntheticTest();
    // As the runner and the run file record them: the first row re-equilibration, then shear.
    t.stageKinds.assign(t.rows.size(), "shear");
    t.stageKinds[0] = "equilibration";
    EXPECT_DOUBLE_EQ(*shearMetrics(t, 1e5).peakStressRatio, 0.5);
    // The kind, not the name, counts: call the first row shear, and its q/p of 5 is the peak.
    t.stageKinds[0] = "shear";
    EXPECT_DOUBLE_EQ(*shearMetrics(t, 1e5).peakStressRatio, 5.0);
}

TEST(ShearMetrics, NamedMetricsCarryEveryValueWithItsUnit) {
    const ShearMetrics m = shearMetrics(syntheticTest(), 1e5);
    const auto named = namedMetrics(m);
    ASSERT_EQ(named.size(), 24u);
    EXPECT_EQ(named[0].name, "peak_q_over_p");
    EXPECT_DOUBLE_EQ(*named[0].value, 0.5);
    EXPECT_EQ(named[4].name, "q_over_p_at_5pc");
    EXPECT_NEAR(*named[4].value, 0.48, 1e-14);
    EXPECT_EQ(named[11].name, "Z_at_5pc");
    EXPECT_NEAR(*named[11].value, 3.95, 1e-14);
    EXPECT_EQ(named[17].name, "I_uf_mean");
    EXPECT_EQ(named[17].unit, "%");
    EXPECT_EQ(named[19].name, "q_peak");
    EXPECT_EQ(named[19].unit, "Pa");
    EXPECT_EQ(named[21].name, "M_steady");
    for (const auto& n : named) {
        // Still dilating at its end (eps_v = -eps1 / 2): no steady end, no M; no cycles.
        EXPECT_EQ(n.value.has_value(), n.name != "M_steady" && n.name != "cycles") << n.name;
    }
}

TEST(ShearMetrics, PeakDeviatorAndTheStressRatioOfASteadyEnd) {
    // q = q/p p with p = 1e5 (1 + eps1): the largest q is at 3 % (0.5 * 1.03e5 = 51500 Pa)...
    SeriesTable t = syntheticTest();
    ShearMetrics m = shearMetrics(t, 1e5);
    EXPECT_DOUBLE_EQ(*m.peakDeviator, 0.5 * 1.03e5);
    EXPECT_DOUBLE_EQ(*m.meanStressAtPeakDeviator, 1.03e5);
    EXPECT_FALSE(m.criticalStressRatio.has_value());
    // ... and with q, p and eps_v constant from 6 % on, the end is steady: M = q/p there.
    for (std::size_t k = 0; k < t.rows.size(); ++k) {
        auto& r = t.rows[k];
        if (r[std::size_t(t.column("eps1"))] >= 0.06) {
            r[std::size_t(t.column("p"))] = 2e5;
            r[std::size_t(t.column("q"))] = 0.9e5;
            r[std::size_t(t.column("epsv"))] = -0.03;
        }
    }
    m = shearMetrics(t, 1e5);
    ASSERT_TRUE(m.criticalStressRatio.has_value());
    EXPECT_DOUBLE_EQ(*m.criticalStressRatio, 0.45);
    // The lateral stress error is a drained test's: a constant-volume test has none.
    EXPECT_TRUE(m.maxLateralStressError.has_value());
    for (std::size_t k = 0; k < t.rows.size(); ++k) {
        t.stageKinds.push_back(k == 0 ? "equilibration" : "constant_volume");
    }
    EXPECT_FALSE(shearMetrics(t, 1e5).maxLateralStressError.has_value());
    // p' never fell below its first value of 1e5: p_min / p0 = 1.
    EXPECT_DOUBLE_EQ(*m.lowestPressureRatio, 1.0);
}

TEST(ShearMetrics, ACyclicTestCountsItsCyclesAndItsLowestPressure) {
    // eps1 0 -> 0.01 -> -0.01 -> 0.01 -> -0.01 -> 0.01: four reversals, two cycles; p' falls by
    // 10 % per record from 1e5.
    SeriesBuilder b("p100kPa-cyclic");
    const double strains[] = {0, 0.005, 0.01, 0, -0.01, 0, 0.01, 0, -0.01, 0, 0.01};
    double p = 1e5;
    for (double e : strains) {
        auto& r = b.row("cyclic 100 kPa");
        b.t.stageKinds.push_back("cyclic");
        b.at(r, "eps1") = e;
        b.at(r, "p") = p;
        b.at(r, "q") = 0.3 * p * (e > 0 ? 1 : -1);
        p *= 0.9;
    }
    const ShearMetrics m = shearMetrics(b.t, 1e5);
    ASSERT_TRUE(m.cyclesCompleted.has_value());
    EXPECT_EQ(*m.cyclesCompleted, 2.0);
    EXPECT_NEAR(*m.lowestPressureRatio, std::pow(0.9, 10), 1e-12);
}

} // namespace
} // namespace grainlab
