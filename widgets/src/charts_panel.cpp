// See charts_panel.h.
#include "grainlab/ui/charts_panel.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <QChart>
#include <QGraphicsLayout>
#include <QGridLayout>
#include <QLegendMarker>
#include <QMouseEvent>
#include <QScatterSeries>
#include <QTabWidget>
#include <QTimer>
#include <QVBoxLayout>
#include <QValueAxis>

#include "grainlab/path_measures.h"
#include "grainlab/report_data.h"
#include "grainlab/shear_metrics.h"
#include "grainlab/ui/colour_maps.h"
#include "grainlab/ui/figure_export.h"

namespace grainlab::ui {

namespace {

ChartCurve solid(const char* column, const QString& label, double scale = 1.0) {
    return {column, label, scale, Qt::SolidLine};
}

/// A chart against ε1 in percent, on the shear tests' page.
ChartDefinition strainChart(const char* name, const QString& title, const QString& yLabel,
                            std::vector<ChartCurve> curves) {
    ChartDefinition chart;
    chart.name = QString::fromLatin1(name);
    chart.title = title;
    chart.xColumn = "eps1";
    chart.xLabel = QStringLiteral("ε1 [%]");
    chart.xScale = 100.0;
    chart.yLabel = yLabel;
    chart.curves = std::move(curves);
    return chart;
}

/// A chart of one column against another.
ChartDefinition columnChart(const char* name, const QString& title, const char* xColumn,
                            const QString& xLabel, double xScale, const QString& yLabel,
                            ChartCurve curve) {
    ChartDefinition chart = strainChart(name, title, yLabel, {std::move(curve)});
    chart.xColumn = xColumn;
    chart.xLabel = xLabel;
    chart.xScale = xScale;
    return chart;
}

/// A chart of the stress-paths page.
ChartDefinition pathChart(ChartDefinition chart) {
    chart.page = QObject::tr("Stress paths");
    return chart;
}

/// A compaction chart: one column against the step.
ChartDefinition compactionChart(const char* name, const QString& title, const char* column,
                                const QString& label, const QString& yLabel, double scale) {
    ChartDefinition chart = columnChart(name, title, "step", QStringLiteral("step"), 1.0, yLabel,
                                        solid(column, label, scale));
    chart.stage = StageKind::Compaction;
    chart.page = QObject::tr("Compaction");
    return chart;
}

} // namespace

std::vector<ChartDefinition> defaultChartDefinitions() {
    const QString voidCells = QStringLiteral("N_v / N_vi [-]");
    std::vector<ChartDefinition> charts{
        strainChart("q_over_p", QObject::tr("Stress ratio"), QStringLiteral("q/p [-]"),
                    {solid("q_over_p", QStringLiteral("q/p"))}),
        strainChart("epsv", QObject::tr("Volumetric strain (dilation negative)"),
                    QStringLiteral("εv [%]"), {solid("epsv", QStringLiteral("εv"), 100.0)}),
        strainChart("fabric", QObject::tr("Fabric: all —, strong - -, weak ···"),
                    QStringLiteral("H11 − H22 [-]"),
                    {solid("Hdev", QStringLiteral("all")),
                     {"Hsdev", QStringLiteral("strong"), 1.0, Qt::DashLine},
                     {"Hwdev", QStringLiteral("weak"), 1.0, Qt::DotLine}}),
        strainChart("coordination", QObject::tr("Z —, Z̄ - -, sliding S ···"),
                    QStringLiteral("Z, Z̄, S [-]"),
                    {solid("Z", QStringLiteral("Z")),
                     {"Z_eff", QStringLiteral("Z̄"), 1.0, Qt::DashLine},
                     {"S", QStringLiteral("S"), 1.0, Qt::DotLine}}),
        strainChart("void_cells", QObject::tr("Void cells"), voidCells,
                    {solid("Nv_over_Nvi", QStringLiteral("N_v/N_vi"))}),
        columnChart("z_eff_vs_void_cells", QObject::tr("Z̄ against void cells"), "Nv_over_Nvi",
                    voidCells, 1.0, QStringLiteral("Z̄ [-]"), solid("Z_eff", QStringLiteral("Z̄"))),
    };
    ChartDefinition qp = pathChart(
        columnChart("q_vs_p", QObject::tr("Stress path: q against p′ (critical state - -)"), "p",
                    QStringLiteral("p′ [kPa]"), 1e-3, QStringLiteral("q [kPa]"),
                    solid("q", QStringLiteral("q"), 1e-3)));
    qp.criticalState = ChartDefinition::CriticalState::StressRatio;
    ChartDefinition qe = pathChart(strainChart(
        "q_vs_eps1", QObject::tr("Deviator stress (a cyclic test's loops, its live cycle bold)"),
        QStringLiteral("q [kPa]"), {solid("q", QStringLiteral("q"), 1e-3)}));
    qe.liveCycle = true;
    ChartDefinition ep = pathChart(
        columnChart("e_vs_ln_p", QObject::tr("Void ratio against ln p′ (critical state line - -)"),
                    "p", QStringLiteral("ln(p′ / 1 Pa)"), 1.0, QStringLiteral("e [-]"),
                    solid("e", QStringLiteral("e"))));
    ep.xLogarithm = true;
    ep.criticalState = ChartDefinition::CriticalState::VoidRatio;
    ChartDefinition cycles = pathChart(columnChart(
        "p_per_cycle", QObject::tr("Cyclic tests: mean stress at the end of each cycle"), "cycle",
        QStringLiteral("cycle"), 1.0, QStringLiteral("p′/p0 [-]"),
        solid("p_over_p0", QStringLiteral("p′/p0"))));
    cycles.derived = ChartDefinition::Derived::PressurePerCycle;
    ChartDefinition envelope = pathChart(
        columnChart("probe_envelope", QObject::tr("Stress probes: response envelope"), "d_sigma11",
                    QStringLiteral("Δσ11 [kPa]"), 1e-3, QStringLiteral("Δσ22 [kPa]"),
                    solid("d_sigma22", QStringLiteral("Δσ22"), 1e-3)));
    envelope.derived = ChartDefinition::Derived::ProbeEnvelope;
    for (ChartDefinition* chart : {&qp, &qe, &ep, &cycles, &envelope}) {
        charts.push_back(std::move(*chart));
    }
    charts.push_back(compactionChart("compaction_p", QObject::tr("Compaction: mean stress"), "p",
                                     QStringLiteral("p"), QStringLiteral("p [kPa]"), 1e-3));
    charts.push_back(compactionChart("compaction_e", QObject::tr("Compaction: void ratio"), "e",
                                     QStringLiteral("e"), QStringLiteral("e [-]"), 1.0));
    charts.push_back(compactionChart("compaction_Z", QObject::tr("Compaction: coordination"), "Z",
                                     QStringLiteral("Z"), QStringLiteral("Z [-]"), 1.0));
    charts.push_back(compactionChart("compaction_I_uf", QObject::tr("Compaction: unbalanced force"),
                                     "I_uf", QStringLiteral("I_uf"), QStringLiteral("I_uf [%]"),
                                     1.0));
    return charts;
}

// ---- HoverChartView ----

HoverChartView::HoverChartView(QChart* chart, QWidget* parent)
    : QChartView(chart, parent), marker_(std::numeric_limits<double>::quiet_NaN()) {
    setRenderHint(QPainter::Antialiasing);
    setMouseTracking(true);
    setMinimumSize(260, 200);
}

void HoverChartView::setMarker(double x) {
    marker_ = x;
    scene()->update();
    viewport()->update();
}

void HoverChartView::mouseMoveEvent(QMouseEvent* event) {
    const QPointF scenePoint = mapToScene(event->position().toPoint());
    if (chart()->plotArea().contains(scenePoint) && !chart()->series().isEmpty()) {
        const double x = chart()->mapToValue(scenePoint, chart()->series().front()).x();
        setMarker(x);
        emit hovered(x);
    } else if (!std::isnan(marker_)) {
        setMarker(std::numeric_limits<double>::quiet_NaN());
        emit hoverEnded();
    }
    QChartView::mouseMoveEvent(event);
}

void HoverChartView::leaveEvent(QEvent* event) {
    if (!std::isnan(marker_)) {
        setMarker(std::numeric_limits<double>::quiet_NaN());
        emit hoverEnded();
    }
    QChartView::leaveEvent(event);
}

void HoverChartView::drawForeground(QPainter* painter, const QRectF& rect) {
    QChartView::drawForeground(painter, rect);
    if (std::isnan(marker_) || chart()->series().isEmpty()) {
        return;
    }
    const QRectF area = chart()->plotArea();
    const double px = chart()->mapToPosition(QPointF(marker_, 0.0), chart()->series().front()).x();
    if (px < area.left() || px > area.right()) {
        return;
    }
    painter->save();
    painter->setPen(QPen(QColor(80, 80, 80), 1.0, Qt::DashLine));
    painter->drawLine(QPointF(px, area.top()), QPointF(px, area.bottom()));
    // The point nearest in x of each visible curve.
    QStringList lines;
    lines << QStringLiteral("x = %1").arg(marker_, 0, 'g', 4);
    for (QAbstractSeries* abstract : chart()->series()) {
        auto* series = static_cast<QXYSeries*>(abstract);
        const auto points = series->points();
        if (points.isEmpty()) {
            continue;
        }
        const auto nearest = std::min_element(points.begin(), points.end(), [&](auto a, auto b) {
            return std::fabs(a.x() - marker_) < std::fabs(b.x() - marker_);
        });
        const QPointF dot = chart()->mapToPosition(*nearest, series);
        painter->setPen(series->pen().color());
        painter->setBrush(series->pen().color());
        painter->drawEllipse(dot, 3.0, 3.0);
        lines << QStringLiteral("%1: %2").arg(series->name()).arg(nearest->y(), 0, 'g', 4);
    }
    const QString text = lines.mid(0, 9).join(QLatin1Char('\n'));
    const QRectF box = painter->fontMetrics().boundingRect(area.toRect(), Qt::AlignLeft, text);
    QRectF placed(area.left() + 6.0, area.top() + 6.0, box.width() + 10.0, box.height() + 6.0);
    if (px < area.left() + placed.width() + 20.0) {
        placed.moveRight(area.right() - 6.0);
    }
    painter->setPen(QColor(120, 120, 120));
    painter->setBrush(QColor(255, 255, 255, 225));
    painter->drawRect(placed);
    painter->setPen(Qt::black);
    painter->drawText(placed.adjusted(5, 3, -5, -3), Qt::AlignLeft, text);
    painter->restore();
}

// ---- ChartsPanel ----

ChartsPanel::ChartsPanel(QWidget* parent, std::vector<ChartDefinition> charts)
    : QWidget(parent), definitions_(std::move(charts)) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    tabs_ = new QTabWidget(this);
    tabs_->setDocumentMode(true);
    layout->addWidget(tabs_);
    std::map<QString, std::pair<QGridLayout*, int>> grids; // page -> its grid, charts on it
    for (std::size_t k = 0; k < definitions_.size(); ++k) {
        const ChartDefinition& d = definitions_[k];
        auto& [grid, placed] = grids[d.page];
        if (!grid) {
            auto* page = new QWidget;
            page->setObjectName(d.page);
            grid = new QGridLayout(page);
            grid->setContentsMargins(0, 0, 0, 0);
            grid->setSpacing(2);
            tabs_->addTab(page, d.page);
        }
        auto* chart = new QChart();
        chart->setTitle(d.title);
        chart->layout()->setContentsMargins(0, 0, 0, 0);
        chart->setMargins(QMargins(4, 4, 4, 4));
        chart->legend()->setAlignment(Qt::AlignBottom);
        QFont small = chart->legend()->font();
        small.setPointSizeF(small.pointSizeF() * 0.85);
        chart->legend()->setFont(small);
        auto* x = new QValueAxis();
        x->setTitleText(d.xLabel);
        x->setLabelFormat(QStringLiteral("%.3g"));
        auto* y = new QValueAxis();
        y->setTitleText(d.yLabel);
        y->setLabelFormat(QStringLiteral("%.3g"));
        chart->addAxis(x, Qt::AlignBottom);
        chart->addAxis(y, Qt::AlignLeft);
        auto* view = new HoverChartView(chart, this);
        const bool againstAxialStrain = d.xColumn == "eps1";
        const double xScale = d.xScale;
        connect(view, &HoverChartView::hovered, this,
                [this, view, againstAxialStrain, xScale](double v) {
                    if (againstAxialStrain) {
                        // Mark the same moment in every chart drawn against eps1.
                        for (auto* other : views_) {
                            if (other != view && other->property("eps1").toBool()) {
                                other->setMarker(v);
                            }
                        }
                        emit hoveredAxialStrain(v / xScale);
                    }
                });
        connect(view, &HoverChartView::hoverEnded, this, [this] {
            for (auto* other : views_) {
                other->setMarker(std::numeric_limits<double>::quiet_NaN());
            }
            emit hoverEnded();
        });
        view->setProperty("eps1", againstAxialStrain);
        views_.push_back(view);
        grid->addWidget(view, placed / 2, placed % 2);
        ++placed;
    }
    // Only one page is shown: the others' charts get their size when shown.
    connect(tabs_, &QTabWidget::currentChanged, this, [this] {
        QTimer::singleShot(0, this, [this] {
            for (int k = 0; k < chartCount(); ++k) {
                rescale(k);
            }
        });
    });
}

QStringList ChartsPanel::pages() const {
    QStringList out;
    for (int i = 0; i < tabs_->count(); ++i) {
        out << tabs_->tabText(i);
    }
    return out;
}

void ChartsPanel::showPage(const QString& page) {
    for (int i = 0; i < tabs_->count(); ++i) {
        if (tabs_->tabText(i) == page) {
            tabs_->setCurrentIndex(i);
        }
    }
}

QString ChartsPanel::pageOfStage(StageKind kind) const {
    for (const ChartDefinition& d : definitions_) {
        if (d.stage == (isTestStage(kind) ? StageKind::Shear : kind)) {
            return d.page;
        }
    }
    return {};
}

QString ChartsPanel::currentPage() const {
    return tabs_->tabText(tabs_->currentIndex());
}

void ChartsPanel::setShearOnly(bool shearOnly) {
    shearOnly_ = shearOnly;
}

QColor ChartsPanel::testColour(const std::string& test) const {
    const auto it = testColours_.find(test);
    return categoryColour(it == testColours_.end() ? 0 : it->second);
}

ChartsPanel::Curve& ChartsPanel::curveFor(int k, const std::string& test, const std::string& key,
                                          bool legend, const QPen& pen, bool points) {
    Curve& curve = curves_[{k, test, key}];
    curve.seen = true;
    if (!curve.series) {
        QChart* chart = views_[k]->chart();
        if (points) {
            auto* scatter = new QScatterSeries();
            scatter->setMarkerSize(7.0);
            scatter->setColor(pen.color());
            scatter->setBorderColor(pen.color());
            curve.series = scatter;
        } else {
            curve.series = new QLineSeries();
            curve.series->setPen(pen);
        }
        curve.series->setName(QString::fromStdString(test));
        chart->addSeries(curve.series);
        curve.series->attachAxis(chart->axes(Qt::Horizontal).front());
        curve.series->attachAxis(chart->axes(Qt::Vertical).front());
        curve.rows = static_cast<std::size_t>(-1);
        // One legend entry per test (its colour); the line styles are named in the title.
        for (QLegendMarker* marker : chart->legend()->markers(curve.series)) {
            marker->setVisible(legend);
            marker->setLabel(QString::fromStdString(test));
        }
    }
    return curve;
}

namespace {

/// The points of a derived chart (ChartDefinition::Derived) of one table, in display units;
/// nothing when the table is not of the chart's sort.
std::optional<QList<QPointF>> derivedPoints(const ChartDefinition& d, const SeriesTable& table) {
    QList<QPointF> points;
    const double yScale = d.curves.front().scale;
    if (d.derived == ChartDefinition::Derived::PressurePerCycle) {
        if (!isCyclicTable(table)) {
            return std::nullopt;
        }
        const PressurePerCycle perCycle = pressurePerCycle(table);
        for (std::size_t k = 0; k < perCycle.cycle.size(); ++k) {
            points.append(QPointF(perCycle.cycle[k] * d.xScale, perCycle.ratio[k] * yScale));
        }
    } else if (d.derived == ChartDefinition::Derived::ProbeEnvelope) {
        if (!isProbesTable(table)) {
            return std::nullopt;
        }
        // The probes recorded so far: the envelope fills in as they come.
        const auto responses = probeResponses(table, false);
        for (const auto& r : responses.value_or(std::vector<std::array<double, 2>>{})) {
            points.append(QPointF(r[0] * d.xScale, r[1] * yScale));
        }
    }
    return points;
}

/// The points of a cyclic test's live cycle: from its last upper peak of x (a reversal of even
/// index, as a cycle runs from one to the next) to its end; all of them before the first.
QList<QPointF> liveCycleOf(const QList<QPointF>& points) {
    std::vector<double> x;
    x.reserve(std::size_t(points.size()));
    for (const QPointF& p : points) {
        x.push_back(p.x());
    }
    const std::vector<std::size_t> turns = reversalIndices(x);
    std::size_t start = 0;
    for (std::size_t k = 0; k < turns.size(); k += 2) {
        start = turns[k];
    }
    return points.mid(qsizetype(start));
}

} // namespace

void ChartsPanel::setSeries(const std::vector<SeriesTable>& tables) {
    for (auto& [key, curve] : curves_) {
        curve.seen = false;
    }
    for (const SeriesTable& table : tables) {
        if (!testColours_.count(table.test)) {
            const int next = static_cast<int>(testColours_.size());
            testColours_[table.test] = next;
        }
        const QColor colour = testColour(table.test);
        // Rows to plot, per stage the charts draw.
        std::map<StageKind, std::vector<std::size_t>> rowsOf;
        for (std::size_t k = 0; k < definitions_.size(); ++k) {
            const ChartDefinition& d = definitions_[k];
            if (rowsOf.count(d.stage)) {
                continue;
            }
            std::vector<std::size_t>& rows = rowsOf[d.stage];
            for (std::size_t r = 0; r < table.rows.size(); ++r) {
                const std::optional<StageKind> kind = r < table.stageKinds.size()
                                                          ? stageKindFromName(table.stageKinds[r])
                                                          : std::nullopt;
                // The test charts (stage Shear) draw every test kind's rows.
                const bool inStage = kind && (*kind == d.stage ||
                                              (d.stage == StageKind::Shear && isTestStage(*kind)));
                if (!shearOnly_ || inStage) {
                    rows.push_back(r);
                }
            }
        }
        const bool cyclic = isCyclicTable(table);
        for (std::size_t k = 0; k < definitions_.size(); ++k) {
            const ChartDefinition& d = definitions_[k];
            const int chart = static_cast<int>(k);
            if (d.derived != ChartDefinition::Derived::None) {
                if (table.column(d.derived == ChartDefinition::Derived::PressurePerCycle
                                     ? "p"
                                     : "sigma11") < 0) {
                    continue;
                }
                const bool envelope = d.derived == ChartDefinition::Derived::ProbeEnvelope;
                const std::optional<QList<QPointF>> points = derivedPoints(d, table);
                if (!points) {
                    continue;
                }
                Curve& curve = curveFor(chart, table.test, d.curves.front().column, true,
                                        QPen(colour, 1.6), envelope);
                if (curve.rows != table.rows.size()) {
                    curve.series->replace(*points);
                    curve.rows = table.rows.size();
                }
                continue;
            }
            const std::vector<std::size_t>& rows = rowsOf[d.stage];
            const int xc = table.column(d.xColumn);
            if (xc < 0 || rows.empty()) {
                continue;
            }
            for (const ChartCurve& c : d.curves) {
                const int yc = table.column(c.column);
                if (yc < 0) {
                    continue;
                }
                const bool first = &c == &d.curves.front();
                Curve& curve =
                    curveFor(chart, table.test, c.column, first, QPen(colour, 1.6, c.style));
                if (d.curves.size() > 1) {
                    curve.series->setName(
                        QStringLiteral("%1 %2").arg(QString::fromStdString(table.test), c.label));
                }
                Curve* live = d.liveCycle && cyclic && first
                                  ? &curveFor(chart, table.test, c.column + "/live cycle", false,
                                              QPen(colour.darker(130), 3.4, c.style))
                                  : nullptr;
                if (curve.rows == rows.size()) {
                    continue;
                }
                QList<QPointF> points;
                points.reserve(static_cast<qsizetype>(rows.size()));
                for (std::size_t r : rows) {
                    double x = table.rows[r][xc] * d.xScale;
                    if (d.xLogarithm) {
                        x = x > 0.0 ? std::log(x) : std::numeric_limits<double>::quiet_NaN();
                    }
                    const double y = table.rows[r][yc] * c.scale;
                    if (std::isfinite(x) && std::isfinite(y)) {
                        points.append(QPointF(x, y));
                    }
                }
                curve.series->replace(points);
                curve.rows = rows.size();
                if (live) {
                    live->series->setName(QString::fromStdString(table.test) + tr(" live cycle"));
                    live->series->replace(liveCycleOf(points));
                    live->rows = rows.size();
                }
            }
        }
    }
    // Drop the curves of tests that are gone.
    for (auto it = curves_.begin(); it != curves_.end();) {
        if (!it->second.seen) {
            views_[std::get<0>(it->first)]->chart()->removeSeries(it->second.series);
            delete it->second.series;
            it = curves_.erase(it);
        } else {
            ++it;
        }
    }
    drawCriticalState(tables);
    for (int k = 0; k < chartCount(); ++k) {
        rescale(k);
    }
}

void ChartsPanel::drawCriticalState(const std::vector<SeriesTable>& tables) {
    try {
        criticalState_ = criticalStateOf({ReportRun{"window", tables, {}}});
    } catch (const std::exception&) {
        criticalState_ = {}; // series the criterion cannot read: no line drawn
    }
    for (int k = 0; k < chartCount(); ++k) {
        const ChartDefinition& d = definitions_[std::size_t(k)];
        if (d.criticalState == ChartDefinition::CriticalState::None) {
            continue;
        }
        // Across the tests' points in this chart.
        double xMin = std::numeric_limits<double>::infinity(), xMax = -xMin;
        for (const auto& [key, curve] : curves_) {
            if (std::get<0>(key) != k) {
                continue;
            }
            for (const QPointF& p : curve.series->points()) {
                xMin = std::min(xMin, p.x());
                xMax = std::max(xMax, p.x());
            }
        }
        QList<QPointF> line;
        QString name;
        const double yScale = d.curves.front().scale;
        if (xMin <= xMax && d.criticalState == ChartDefinition::CriticalState::StressRatio &&
            criticalState_.m.count > 0) {
            // q = M p′, both in their display units.
            const double m = criticalState_.m.mean;
            line = {QPointF(0.0, 0.0), QPointF(xMax, m * (xMax / d.xScale) * yScale)};
            name = tr("critical state M = %1").arg(m, 0, 'f', 3);
        } else if (xMin < xMax && d.criticalState == ChartDefinition::CriticalState::VoidRatio &&
                   criticalState_.line) {
            // e = e_Γ − λ ln p′, against ln p′ (x drawn as ln(xScale p′)).
            const CriticalStateLine& csl = *criticalState_.line;
            for (const double x : {xMin, xMax}) {
                line.append(QPointF(x, csl.voidRatioAt(std::exp(x) / d.xScale) * yScale));
            }
            name = QString::fromStdString(csl.equation());
        }
        QChart* chart = views_[std::size_t(k)]->chart();
        QLineSeries*& series = criticalStateLines_[k];
        if (line.isEmpty()) {
            if (series) {
                chart->removeSeries(series);
                delete series;
                series = nullptr;
            }
            continue;
        }
        if (!series) {
            series = new QLineSeries();
            series->setPen(QPen(Qt::black, 1.4, Qt::DashLine));
            chart->addSeries(series);
            series->attachAxis(chart->axes(Qt::Horizontal).front());
            series->attachAxis(chart->axes(Qt::Vertical).front());
        }
        series->setName(name);
        series->replace(line);
    }
}

QList<QPointF> ChartsPanel::liveCyclePoints(int chart, const std::string& test) const {
    const ChartDefinition& d = definitions_[std::size_t(chart)];
    const auto it = curves_.find({chart, test, d.curves.front().column + "/live cycle"});
    return it == curves_.end() ? QList<QPointF>{} : it->second.series->points();
}

bool ChartsPanel::hasCurves(int chart) const {
    for (const auto& [key, curve] : curves_) {
        if (std::get<0>(key) == chart && !curve.series->points().isEmpty()) {
            return true;
        }
    }
    return false;
}

QList<QPointF> ChartsPanel::criticalStatePoints(int chart) const {
    const auto it = criticalStateLines_.find(chart);
    return it == criticalStateLines_.end() || !it->second ? QList<QPointF>{} : it->second->points();
}

void ChartsPanel::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    // Tick spacing follows the plot size, known once the charts are laid out.
    QTimer::singleShot(0, this, [this] {
        for (int k = 0; k < chartCount(); ++k) {
            rescale(k);
        }
    });
}

void ChartsPanel::rescale(int k) {
    QChart* chart = views_[k]->chart();
    double xMin = 1e300, xMax = -1e300, yMin = 1e300, yMax = -1e300;
    for (QAbstractSeries* s : chart->series()) {
        for (const QPointF& p : static_cast<QXYSeries*>(s)->points()) {
            xMin = std::min(xMin, p.x());
            xMax = std::max(xMax, p.x());
            yMin = std::min(yMin, p.y());
            yMax = std::max(yMax, p.y());
        }
    }
    if (xMin > xMax) {
        return;
    }
    // Ticks at multiples of a 1-2-5 step anchored at zero, so labels are round numbers; an
    // axis whose data are all >= 0 does not reach below zero.
    // About one tick per 45 pixels of plot height (80 of width), so labels never crowd.
    const QRectF area = chart->plotArea();
    const int xIntervals = std::clamp(static_cast<int>(area.width() / 80.0), 2, 8);
    const int yIntervals = std::clamp(static_cast<int>(area.height() / 45.0), 2, 8);
    auto ticks = [](QValueAxis* axis, double lo, double hi, int intervals) {
        const bool nonNegative = lo >= 0.0;
        double span = hi - lo;
        if (!(span > 0.0)) {
            span = std::max(1e-6, 0.1 * std::fabs(hi));
            lo -= 0.5 * span;
            hi += 0.5 * span;
        }
        const double raw = span / intervals;
        const double decade = std::pow(10.0, std::floor(std::log10(raw)));
        double step = decade;
        for (double f : {2.0, 5.0, 10.0}) {
            if (decade * f <= raw * 1.0001) {
                step = decade * f;
            }
        }
        lo = std::floor((lo - 0.02 * span) / step) * step;
        hi = std::ceil((hi + 0.02 * span) / step) * step;
        if (nonNegative) {
            lo = std::max(lo, 0.0);
        }
        axis->setLabelFormat(
            step >= 1.0 ? QStringLiteral("%.0f")
                        : QStringLiteral("%.%1f").arg(int(std::ceil(-std::log10(step) - 1e-9))));
        axis->setTickType(QValueAxis::TicksDynamic);
        axis->setTickAnchor(0.0);
        axis->setTickInterval(step);
        axis->setRange(lo, hi);
    };
    ticks(static_cast<QValueAxis*>(chart->axes(Qt::Horizontal).front()), xMin, xMax, xIntervals);
    ticks(static_cast<QValueAxis*>(chart->axes(Qt::Vertical).front()), yMin, yMax, yIntervals);
}

QList<QPointF> ChartsPanel::curvePoints(int chart, const std::string& test,
                                        const std::string& column) const {
    const auto it = curves_.find({chart, test, column});
    return it == curves_.end() ? QList<QPointF>{} : it->second.series->points();
}

bool ChartsPanel::exportChart(int k, const QString& path, QSize size, QString* error) const {
    QChart* chart = views_[k]->chart();
    return exportFigure(
        path, size,
        [chart](QPainter& painter, QSize target) {
            // Lay the chart out at the target size, paint it, and put it back.
            const QSizeF old = chart->size();
            chart->resize(QSizeF(target));
            if (chart->layout()) {
                chart->layout()->activate();
            }
            chart->scene()->render(&painter, QRectF(QPointF(0, 0), QSizeF(target)),
                                   QRectF(chart->pos(), QSizeF(target)));
            chart->resize(old);
            if (chart->layout()) {
                chart->layout()->activate();
            }
        },
        error);
}

} // namespace grainlab::ui
