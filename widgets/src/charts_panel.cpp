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
#include <QTabWidget>
#include <QTimer>
#include <QVBoxLayout>
#include <QValueAxis>

#include "grainlab/ui/colour_maps.h"
#include "grainlab/ui/figure_export.h"

namespace grainlab::ui {

std::vector<ChartDefinition> defaultChartDefinitions() {
    const QString eps1 = QStringLiteral("ε1 [%]");
    const QString compaction = QObject::tr("Compaction");
    const QString paths = QObject::tr("Stress paths");
    return {
        {"q_over_p",
         QObject::tr("Stress ratio"),
         "eps1",
         eps1,
         100.0,
         QStringLiteral("q/p [-]"),
         {{"q_over_p", QStringLiteral("q/p"), 1.0, Qt::SolidLine}}},
        {"epsv",
         QObject::tr("Volumetric strain (dilation negative)"),
         "eps1",
         eps1,
         100.0,
         QStringLiteral("εv [%]"),
         {{"epsv", QStringLiteral("εv"), 100.0, Qt::SolidLine}}},
        {"fabric",
         QObject::tr("Fabric: all —, strong - -, weak ···"),
         "eps1",
         eps1,
         100.0,
         QStringLiteral("H11 − H22 [-]"),
         {{"Hdev", QStringLiteral("all"), 1.0, Qt::SolidLine},
          {"Hsdev", QStringLiteral("strong"), 1.0, Qt::DashLine},
          {"Hwdev", QStringLiteral("weak"), 1.0, Qt::DotLine}}},
        {"coordination",
         QObject::tr("Z —, Z̄ - -, sliding S ···"),
         "eps1",
         eps1,
         100.0,
         QStringLiteral("Z, Z̄, S [-]"),
         {{"Z", QStringLiteral("Z"), 1.0, Qt::SolidLine},
          {"Z_eff", QStringLiteral("Z̄"), 1.0, Qt::DashLine},
          {"S", QStringLiteral("S"), 1.0, Qt::DotLine}}},
        {"void_cells",
         QObject::tr("Void cells"),
         "eps1",
         eps1,
         100.0,
         QStringLiteral("N_v / N_vi [-]"),
         {{"Nv_over_Nvi", QStringLiteral("N_v/N_vi"), 1.0, Qt::SolidLine}}},
        {"z_eff_vs_void_cells",
         QObject::tr("Z̄ against void cells"),
         "Nv_over_Nvi",
         QStringLiteral("N_v / N_vi [-]"),
         1.0,
         QStringLiteral("Z̄ [-]"),
         {{"Z_eff", QStringLiteral("Z̄"), 1.0, Qt::SolidLine}}},
        {"q_vs_p",
         QObject::tr("Stress path: q against p′"),
         "p",
         QStringLiteral("p′ [kPa]"),
         1e-3,
         QStringLiteral("q [kPa]"),
         {{"q", QStringLiteral("q"), 1e-3, Qt::SolidLine}},
         StageKind::Shear,
         paths},
        {"q_vs_eps1",
         QObject::tr("Deviator stress (a cyclic test's loops)"),
         "eps1",
         eps1,
         100.0,
         QStringLiteral("q [kPa]"),
         {{"q", QStringLiteral("q"), 1e-3, Qt::SolidLine}},
         StageKind::Shear,
         paths},
        {"e_vs_ln_p",
         QObject::tr("Void ratio against ln p′"),
         "p",
         QStringLiteral("ln(p′ / 1 Pa)"),
         1.0,
         QStringLiteral("e [-]"),
         {{"e", QStringLiteral("e"), 1.0, Qt::SolidLine}},
         StageKind::Shear,
         paths,
         true},
        {"compaction_p",
         QObject::tr("Compaction: mean stress"),
         "step",
         QStringLiteral("step"),
         1.0,
         QStringLiteral("p [kPa]"),
         {{"p", QStringLiteral("p"), 1e-3, Qt::SolidLine}},
         StageKind::Compaction,
         compaction},
        {"compaction_e",
         QObject::tr("Compaction: void ratio"),
         "step",
         QStringLiteral("step"),
         1.0,
         QStringLiteral("e [-]"),
         {{"e", QStringLiteral("e"), 1.0, Qt::SolidLine}},
         StageKind::Compaction,
         compaction},
        {"compaction_Z",
         QObject::tr("Compaction: coordination"),
         "step",
         QStringLiteral("step"),
         1.0,
         QStringLiteral("Z [-]"),
         {{"Z", QStringLiteral("Z"), 1.0, Qt::SolidLine}},
         StageKind::Compaction,
         compaction},
        {"compaction_I_uf",
         QObject::tr("Compaction: unbalanced force"),
         "step",
         QStringLiteral("step"),
         1.0,
         QStringLiteral("I_uf [%]"),
         {{"I_uf", QStringLiteral("I_uf"), 1.0, Qt::SolidLine}},
         StageKind::Compaction,
         compaction},
    };
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
                const std::optional<StageKind> kind =
                    r < table.stageKinds.size() ? stageKindFromName(table.stageKinds[r])
                                                : std::nullopt;
                // The test charts (stage Shear) draw every test kind's rows.
                const bool inStage =
                    kind && (*kind == d.stage ||
                             (d.stage == StageKind::Shear && isTestStage(*kind)));
                if (!shearOnly_ || inStage) {
                    rows.push_back(r);
                }
            }
        }
        for (std::size_t k = 0; k < definitions_.size(); ++k) {
            const ChartDefinition& d = definitions_[k];
            const std::vector<std::size_t>& rows = rowsOf[d.stage];
            const int xc = table.column(d.xColumn);
            if (xc < 0 || rows.empty()) {
                continue;
            }
            QChart* chart = views_[k]->chart();
            for (const ChartCurve& c : d.curves) {
                const int yc = table.column(c.column);
                if (yc < 0) {
                    continue;
                }
                Curve& curve = curves_[{static_cast<int>(k), table.test, c.column}];
                curve.seen = true;
                if (!curve.series) {
                    curve.series = new QLineSeries();
                    curve.series->setName(d.curves.size() > 1
                                              ? QStringLiteral("%1 %2").arg(
                                                    QString::fromStdString(table.test), c.label)
                                              : QString::fromStdString(table.test));
                    QPen pen(colour, 1.6, c.style);
                    curve.series->setPen(pen);
                    chart->addSeries(curve.series);
                    curve.series->attachAxis(chart->axes(Qt::Horizontal).front());
                    curve.series->attachAxis(chart->axes(Qt::Vertical).front());
                    curve.rows = static_cast<std::size_t>(-1);
                    // One legend entry per test (its colour); the line styles are named in
                    // the chart title.
                    for (QLegendMarker* marker : chart->legend()->markers(curve.series)) {
                        marker->setVisible(&c == &d.curves.front());
                        marker->setLabel(QString::fromStdString(table.test));
                    }
                }
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
    for (int k = 0; k < chartCount(); ++k) {
        rescale(k);
    }
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
