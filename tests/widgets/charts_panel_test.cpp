// The charts panel plots the columns (docs/measures.md) of every test in its own colour, in display
// units, replaces curves when rows are added, drops tests that are gone, and reports the eps1 under
// the cursor and when the hover ends.
#include <cmath>

#include <QMouseEvent>
#include <QSignalSpy>
#include <QTest>
#include <QValueAxis>

#include <gtest/gtest.h>

#include "grainlab/ui/charts_panel.h"
#include "test_scenes.h"

namespace grainlab::ui {
namespace {

int chartIndex(const ChartsPanel& panel, const QString& name) {
    for (int k = 0; k < panel.chartCount(); ++k) {
        if (panel.definition(k).name == name) {
            return k;
        }
    }
    return -1;
}

TEST(ChartsPanel, OverlaysTestsInTheirColoursInDisplayUnits) {
    ChartsPanel panel;
    panel.resize(900, 900);
    const std::vector<SeriesTable> tables{testing::makeSeries("p15kPa", 200, 0.5),
                                          testing::makeSeries("p100kPa", 150, 0.4)};
    panel.setSeries(tables);
    ASSERT_EQ(panel.chartCount(), 13); // six of the shear tests, three of paths, four compaction
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
    ChartsPanel panel;
    panel.resize(900, 900);
    panel.setSeries({t});
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
