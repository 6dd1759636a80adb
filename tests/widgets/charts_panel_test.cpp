// The charts panel plots the columns (docs/measures.md) of every test in its own colour, in display
// units, replaces curves when rows are added, drops tests that are gone, and reports the eps1 under
// the cursor and when the hover ends.
#include <cmath>

#include <QChart>
#include <QImage>
#include <QMouseEvent>
#include <QSignalSpy>
#include <QTest>
#include <QValueAxis>
#include <QXYSeries>

#include <gtest/gtest.h>

#include "chart_index.h"
#include "grainlab/ui/charts_panel.h"
#include "test_scenes.h"

namespace grainlab::ui {
namespace {

using testing::chartIndex;

/// A charts panel of `width` x 900 showing `tables`.
class PanelOf : public ChartsPanel {
public:
    explicit PanelOf(const std::vector<SeriesTable>& tables, int width = 900) {
        resize(width, 900);
        setSeries(tables);
    }
};

TEST(ChartsPanel, OverlaysTestsInTheirColoursInDisplayUnits) {
    const std::vector<SeriesTable> tables{testing::makeSeries("p15kPa", 200, 0.5),
                                          testing::makeSeries("p100kPa", 150, 0.4)};
    PanelOf panel(tables);
    ASSERT_EQ(panel.chartCount(), 15); // six of the shear tests, five of paths, four compaction
    const int q = chartIndex(panel, QStringLiteral("q_over_p"));
    const int v = chartIndex(panel, QStringLiteral("epsv"));
    const int f = chartIndex(panel, QStringLiteral("fabric"));
    const int z = chartIndex(panel, QStringLiteral("z_eff_vs_void_cells"));
    ASSERT_GE(q, 0);
    const auto points = panel.curvePoints(q, "p15kPa", "q_over_p");
    ASSERT_EQ(points.size(), 200);
    EXPECT_DOUBLE_EQ(points.back().x(), 100.0 * tables[0].rows.back()[0]); // eps1 in percent
    EXPECT_DOUBLE_EQ(points.back().y(), tables[0].rows.back()[2]);
    EXPECT_DOUBLE_EQ(panel.curvePoints(v, "p100kPa", "epsv").back().y(),
                     100.0 * tables[1].rows.back()[1]);
    EXPECT_EQ(panel.curvePoints(f, "p15kPa", "Hsdev").size(), 200);
    EXPECT_EQ(panel.curvePoints(f, "p15kPa", "Hwdev").size(), 200);
    EXPECT_EQ(panel.curvePoints(z, "p100kPa", "Z_eff").size(), 150);
    EXPECT_NE(panel.testColour("p15kPa"), panel.testColour("p100kPa"));
    // Axes are labelled with units and cover the data.
    auto* x = static_cast<QValueAxis*>(panel.chartView(q)->chart()->axes(Qt::Horizontal).front());
    auto* y = static_cast<QValueAxis*>(panel.chartView(q)->chart()->axes(Qt::Vertical).front());
    EXPECT_EQ(x->titleText(), QStringLiteral("ε1 [%]"));
    EXPECT_EQ(y->titleText(), QStringLiteral("q/p [-]"));
    EXPECT_LE(x->min(), 0.0);
    EXPECT_GE(x->max(), 15.0);
    EXPECT_GE(y->max(), 0.49);

    // More rows: replaced; a test gone: removed.
    panel.setSeries({testing::makeSeries("p15kPa", 300, 0.5)});
    EXPECT_EQ(panel.curvePoints(q, "p15kPa", "q_over_p").size(), 300);
    EXPECT_TRUE(panel.curvePoints(q, "p100kPa", "q_over_p").isEmpty());
    EXPECT_EQ(panel.chartView(q)->chart()->series().size(), 1);
}

TEST(ChartsPanel, StressPathsOfEveryTestKindInQAgainstPAndEAgainstLnP) {
    // A constant-volume test's rows: p' moves, e does not; drawn in kPa and against ln p'.
    SeriesTable t;
    t.test = "p025kPa-constant-volume";
    for (const char* column : {"eps1", "p", "q", "e"}) {
        t.columns.push_back({column, "-"});
    }
    for (int k = 0; k < 20; ++k) {
        t.rows.push_back({0.001 * k, 25e3 + 2e3 * k, 1.5e3 * k, 0.16});
        t.stages.push_back("constant_volume 25 kPa");
        t.stageKinds.push_back("constant_volume");
    }
    PanelOf panel({t});
    const int qp = chartIndex(panel, QStringLiteral("q_vs_p"));
    const int ep = chartIndex(panel, QStringLiteral("e_vs_ln_p"));
    ASSERT_GE(qp, 0);
    ASSERT_GE(ep, 0);
    EXPECT_EQ(panel.definition(qp).page, QStringLiteral("Stress paths"));
    const auto path = panel.curvePoints(qp, t.test, "q");
    ASSERT_EQ(path.size(), 20);
    EXPECT_DOUBLE_EQ(path.back().x(), 1e-3 * (25e3 + 2e3 * 19));
    EXPECT_DOUBLE_EQ(path.back().y(), 1e-3 * 1.5e3 * 19);
    const auto ends = panel.curvePoints(ep, t.test, "e");
    ASSERT_EQ(ends.size(), 20);
    EXPECT_DOUBLE_EQ(ends.front().x(), std::log(25e3));
    EXPECT_DOUBLE_EQ(ends.back().y(), 0.16);
    // A test of another kind is charted on the shear page too, and its stage leads there.
    EXPECT_EQ(panel.pageOfStage(StageKind::ConstantVolume), QStringLiteral("Shear tests"));
    EXPECT_EQ(panel.pageOfStage(StageKind::Cyclic), QStringLiteral("Shear tests"));
    // q against eps1 keeps the records' order: a cyclic test's strain going back draws a loop.
    const int qe = chartIndex(panel, QStringLiteral("q_vs_eps1"));
    ASSERT_GE(qe, 0);
    EXPECT_EQ(panel.curvePoints(qe, t.test, "q").size(), 20);
}

TEST(ChartsPanel, ShearOnlySkipsCompactionRows) {
    ChartsPanel panel;
    SeriesTable t = testing::makeSeries("p50kPa", 10, 0.5);
    t.stages[0] = t.stages[1] = "compaction 50 kPa";
    t.stageKinds[0] = t.stageKinds[1] = "compaction";
    panel.setSeries({t});
    EXPECT_EQ(panel.curvePoints(0, "p50kPa", "q_over_p").size(), 8);
    panel.setShearOnly(false);
    panel.setSeries({t});
    EXPECT_EQ(panel.curvePoints(0, "p50kPa", "q_over_p").size(), 10);
}

TEST(ChartsPanel, ChartsTheCompactionAgainstStepOnItsOwnPage) {
    ChartsPanel panel;
    panel.resize(900, 900);
    panel.show();
    const SeriesTable compaction = testing::makeCompactionSeries(40);
    panel.setSeries({compaction, testing::makeSeries("p015kPa", 50, 0.5)});
    ASSERT_EQ(panel.pages(),
              (QStringList{QStringLiteral("Shear tests"), QStringLiteral("Stress paths"),
                           QStringLiteral("Compaction")}));
    EXPECT_EQ(panel.pageOfStage(StageKind::Compaction), QStringLiteral("Compaction"));
    EXPECT_EQ(panel.pageOfStage(StageKind::Shear), QStringLiteral("Shear tests"));
    EXPECT_EQ(panel.pageOfStage(StageKind::Equilibration), QString());
    const int p = chartIndex(panel, QStringLiteral("compaction_p"));
    const int e = chartIndex(panel, QStringLiteral("compaction_e"));
    const int z = chartIndex(panel, QStringLiteral("compaction_Z"));
    const int iuf = chartIndex(panel, QStringLiteral("compaction_I_uf"));
    ASSERT_GE(p, 0);
    ASSERT_GE(e, 0);
    ASSERT_GE(z, 0);
    ASSERT_GE(iuf, 0);
    // Every compaction row, against step, p in kPa.
    const auto pressure = panel.curvePoints(p, "compaction", "p");
    ASSERT_EQ(pressure.size(), 40);
    EXPECT_EQ(pressure.back().x(), compaction.rows.back()[0]);
    EXPECT_DOUBLE_EQ(pressure.back().y(), 1e-3 * compaction.rows.back()[2]);
    EXPECT_EQ(panel.curvePoints(e, "compaction", "e").size(), 40);
    EXPECT_EQ(panel.curvePoints(z, "compaction", "Z").size(), 40);
    EXPECT_DOUBLE_EQ(panel.curvePoints(iuf, "compaction", "I_uf").front().y(),
                     compaction.rows.front()[5]);
    EXPECT_EQ(panel.chartView(p)->chart()->series().size(), 1); // the shear test is not here
    // The shear charts draw the shear test only (the compaction's rows are no shear rows).
    EXPECT_TRUE(panel.curvePoints(0, "compaction", "q_over_p").isEmpty());
    EXPECT_EQ(panel.curvePoints(0, "p015kPa", "q_over_p").size(), 50);

    // Drawn: the compaction page's p chart shows the test's colour.
    panel.showPage(QStringLiteral("Compaction"));
    EXPECT_EQ(panel.currentPage(), QStringLiteral("Compaction"));
    QTest::qWait(20);
    EXPECT_TRUE(panel.chartView(p)->isVisible());
    EXPECT_FALSE(panel.chartView(0)->isVisible());
    const QImage image = panel.chartView(p)->grab().toImage();
    const QColor colour = panel.testColour("compaction");
    int coloured = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            coloured += std::abs(c.red() - colour.red()) + std::abs(c.green() - colour.green()) +
                            std::abs(c.blue() - colour.blue()) <
                        40;
        }
    }
    EXPECT_GT(coloured, 200);
}

TEST(ChartsPanel, HoverReportsAxialStrainAndMarksEveryStrainChart) {
    ChartsPanel panel;
    panel.resize(900, 900);
    panel.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&panel));
    panel.setSeries({testing::makeSeries("p15kPa", 200, 0.5)});
    QApplication::processEvents();
    HoverChartView* view = panel.chartView(0);
    QSignalSpy spy(&panel, &ChartsPanel::hoveredAxialStrain);
    const QRectF area = view->chart()->plotArea();
    const QPointF target = view->chart()->mapToPosition(QPointF(5.0, 0.3)); // eps1 = 5 %
    ASSERT_TRUE(area.contains(target));
    // A synthetic move event (QTest::mouseMove goes through the window system's cursor, which
    // is asynchronous on a real X server).
    const QPointF local = view->mapFromScene(target);
    QMouseEvent move(QEvent::MouseMove, local, view->viewport()->mapToGlobal(local), Qt::NoButton,
                     Qt::NoButton, Qt::NoModifier);
    QApplication::sendEvent(view->viewport(), &move);
    ASSERT_GE(spy.count(), 1);
    EXPECT_NEAR(spy.back().front().toDouble(), 0.05, 0.002);
    EXPECT_NEAR(panel.chartView(1)->marker(), 5.0, 0.2);

    // The cursor leaves the chart: the hover ends and every mark goes.
    QSignalSpy ended(&panel, &ChartsPanel::hoverEnded);
    QEvent leave(QEvent::Leave);
    QApplication::sendEvent(view, &leave);
    EXPECT_EQ(ended.count(), 1);
    EXPECT_TRUE(std::isnan(view->marker()));
    EXPECT_TRUE(std::isnan(panel.chartView(1)->marker()));
}

} // namespace
} // namespace grainlab::ui

namespace grainlab::ui {
namespace {

/// A test's table of the columns the stress-path charts read, without rows.
SeriesTable pathTable(const std::string& test) {
    SeriesTable t;
    t.test = test;
    for (const char* column : {"eps1", "p", "q", "e", "epsv", "sigma11", "sigma22"}) {
        t.columns.push_back({column, "-"});
    }
    return t;
}

void addRow(SeriesTable& t, const std::string& kind, double eps1, double p, double q, double e,
            double epsv = 0.0, double s11 = 0.0, double s22 = 0.0) {
    t.rows.push_back({eps1, p, q, e, epsv, s11, s22});
    t.stages.push_back(kind + " 25 kPa");
    t.stageKinds.push_back(kind);
}

/// A drained test that hardens to q = m p by eps1 = 0.05 and then stays there to 0.2 at
/// constant volume (a steady end), ending at void ratio `e`.
SeriesTable steadyTest(const std::string& test, double p, double m, double e) {
    SeriesTable t = pathTable(test);
    for (int k = 0; k <= 200; ++k) {
        const double eps1 = 0.001 * k;
        const double q = m * p * std::min(1.0, eps1 / 0.05);
        addRow(t, "shear", eps1, p, q, e, 0.0);
    }
    return t;
}

QImage grabbed(ChartsPanel& panel, int chart) {
    panel.showPage(panel.definition(chart).page);
    QTest::qWait(20);
    return panel.chartView(chart)->grab().toImage();
}

/// True when a dark pixel (the black dashed line) lies within 3 pixels of `at`.
bool darkNear(const QImage& image, QPointF at) {
    for (int dy = -3; dy <= 3; ++dy) {
        for (int dx = -3; dx <= 3; ++dx) {
            const QColor c = image.pixelColor(int(at.x()) + dx, int(at.y()) + dy);
            if (c.red() < 60 && c.green() < 60 && c.blue() < 60) {
                return true;
            }
        }
    }
    return false;
}

// The critical state of the steady tests shown: M over their ends, q = M p′ drawn from the origin
// in the q - p′ chart, and the line through their ends in the e - ln p′ chart (with two ends, the
// line through both: closed form); pixels of the dashed line where the chart maps it. A test
// still hardening at its end draws no line.
TEST(ChartsPanel, DrawsTheCriticalStateOfTheSteadyTestsShown) {
    ChartsPanel panel;
    panel.resize(1000, 900);
    panel.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&panel));
    const std::vector<SeriesTable> tables{steadyTest("p025kPa", 25e3, 0.9, 0.20),
                                          steadyTest("p100kPa", 100e3, 0.9, 0.17)};
    panel.setSeries(tables);
    const int qp = chartIndex(panel, QStringLiteral("q_vs_p"));
    const int ep = chartIndex(panel, QStringLiteral("e_vs_ln_p"));
    ASSERT_GE(qp, 0);
    ASSERT_GE(ep, 0);
    EXPECT_EQ(panel.criticalState().steadyCount(), 2);
    EXPECT_NEAR(panel.criticalState().m.mean, 0.9, 1e-12);
    const auto mLine = panel.criticalStatePoints(qp);
    ASSERT_EQ(mLine.size(), 2);
    EXPECT_EQ(mLine.front(), QPointF(0.0, 0.0));
    EXPECT_NEAR(mLine.back().y() / mLine.back().x(), 0.9, 1e-12); // kPa against kPa
    EXPECT_NEAR(mLine.back().x(), 100.0, 1e-9);
    const double lambda = (0.20 - 0.17) / (std::log(100e3) - std::log(25e3));
    const auto csl = panel.criticalStatePoints(ep);
    ASSERT_EQ(csl.size(), 2);
    for (const QPointF& point : csl) {
        EXPECT_NEAR(point.y(), 0.20 - lambda * (point.x() - std::log(25e3)), 1e-12);
    }
    EXPECT_NEAR(csl.front().x(), std::log(25e3), 1e-12);
    EXPECT_NEAR(csl.back().x(), std::log(100e3), 1e-12);
    // Drawn: dark pixels at the middle of each line, where the chart maps it.
    for (const int chart : {qp, ep}) {
        const QImage image = grabbed(panel, chart);
        QChart* c = panel.chartView(chart)->chart();
        const auto line = panel.criticalStatePoints(chart);
        QAbstractSeries* series = nullptr;
        for (QAbstractSeries* s : c->series()) {
            if (static_cast<QXYSeries*>(s)->points() == line) {
                series = s;
            }
        }
        ASSERT_NE(series, nullptr);
        const QPointF middle = c->mapToPosition((line.front() + line.back()) / 2.0, series);
        const QPointF pixel = panel.chartView(chart)->mapFromScene(middle);
        EXPECT_TRUE(darkNear(image, pixel)) << panel.definition(chart).name.toStdString();
    }

    // A test still hardening at its end: not steady, no line.
    SeriesTable hardening = pathTable("p050kPa");
    for (int k = 0; k <= 200; ++k) {
        addRow(hardening, "shear", 0.001 * k, 50e3, 50e3 * 0.005 * k, 0.18);
    }
    panel.setSeries({hardening});
    EXPECT_EQ(panel.criticalState().steadyCount(), 0);
    EXPECT_TRUE(panel.criticalStatePoints(qp).isEmpty());
    EXPECT_TRUE(panel.criticalStatePoints(ep).isEmpty());
}

// A cyclic test: p′/p0 at the end of each cycle against the cycle (its upper peaks of eps1), and
// its live cycle, from its last upper peak on, drawn bold over its q - eps1 loops.
TEST(ChartsPanel, ChartsACyclicTestsPressurePerCycleAndItsLiveCycle) {
    // eps1 a triangle wave of amplitude 0.01 in steps of 0.001 (40 records a cycle), p falling
    // by 10 % a cycle: a quarter up, then 2 whole cycles ending at an upper peak.
    SeriesTable t = pathTable("p025kPa-cyclic");
    const int quarter = 10, records = 9 * quarter + 1;
    std::vector<int> upper; // indices of the upper peaks
    for (int k = 0; k < records; ++k) {
        const int phase = (k + quarter) % (4 * quarter); // starts at eps1 = 0 going up
        const double eps1 = 0.001 * (phase <= 2 * quarter ? phase - quarter : 3 * quarter - phase);
        if (phase == 2 * quarter) {
            upper.push_back(k);
        }
        const double cycle = double(k) / (4 * quarter);
        const double p = 25e3 * std::pow(0.9, cycle);
        addRow(t, "cyclic", eps1, p, 3e4 * eps1, 0.2);
    }
    ASSERT_EQ(upper, (std::vector<int>{10, 50, 90}));
    PanelOf panel({t}, 1000);
    const int pc = chartIndex(panel, QStringLiteral("p_per_cycle"));
    const int qe = chartIndex(panel, QStringLiteral("q_vs_eps1"));
    ASSERT_GE(pc, 0);
    const auto perCycle = panel.curvePoints(pc, t.test, "p_over_p0");
    ASSERT_EQ(perCycle.size(), 3); // the start, the ends of the cycles 10-50 and 50-90
    EXPECT_EQ(perCycle[0], QPointF(0.0, 1.0));
    EXPECT_EQ(perCycle[1].x(), 1.0);
    EXPECT_NEAR(perCycle[1].y(), std::pow(0.9, 50.0 / 40), 1e-12);
    EXPECT_EQ(perCycle[2].x(), 2.0);
    EXPECT_NEAR(perCycle[2].y(), std::pow(0.9, 90.0 / 40), 1e-12);
    // The live cycle: from the last upper peak that is a reversal (50) to the end, over the
    // whole loop's 91 records.
    EXPECT_EQ(panel.curvePoints(qe, t.test, "q").size(), records);
    const auto live = panel.liveCyclePoints(qe, t.test);
    ASSERT_EQ(live.size(), records - 50);
    EXPECT_DOUBLE_EQ(live.front().x(), 100.0 * 0.01);
    // A monotonic test has no live cycle and no points per cycle.
    panel.setSeries({steadyTest("p025kPa", 25e3, 0.9, 0.2)});
    EXPECT_TRUE(panel.liveCyclePoints(qe, "p025kPa").isEmpty());
    EXPECT_TRUE(panel.curvePoints(pc, "p025kPa", "p_over_p0").isEmpty());
    EXPECT_TRUE(panel.curvePoints(pc, t.test, "p_over_p0").isEmpty()); // gone with its test
}

// A probe set's responses (each probe's stress minus the zero probe's) fill the envelope chart
// as they come: 3 of 8, then all 8, on the circle they were made on.
TEST(ChartsPanel, TheProbeEnvelopeFillsInAsTheProbesComeIn) {
    SeriesTable t = pathTable("p025kPa-probes");
    const double s0 = 25e3, radius = 2e3;
    addRow(t, "probes", 0.02, s0, 0.0, 0.2, 0.0, s0 + 10.0, s0 - 10.0); // the start
    addRow(t, "probes", 0.02, s0, 0.0, 0.2, 0.0, s0 + 5.0, s0 - 5.0);   // the zero probe
    ChartsPanel panel;
    panel.resize(1000, 900);
    const int env = chartIndex(panel, QStringLiteral("probe_envelope"));
    ASSERT_GE(env, 0);
    for (int k = 0; k < 8; ++k) {
        const double a = 2.0 * M_PI * k / 8;
        addRow(t, "probes", 0.02, s0, 0.0, 0.2, 0.0, s0 + 5.0 + radius * std::cos(a),
               s0 - 5.0 + radius * std::sin(a));
        panel.setSeries({t});
        const auto points = panel.curvePoints(env, t.test, "d_sigma22");
        ASSERT_EQ(points.size(), k + 1);
        EXPECT_NEAR(points.back().x(), 1e-3 * radius * std::cos(a), 1e-9);
        EXPECT_NEAR(points.back().y(), 1e-3 * radius * std::sin(a), 1e-9);
    }
}

} // namespace
} // namespace grainlab::ui
