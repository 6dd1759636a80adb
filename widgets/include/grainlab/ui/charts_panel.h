#pragma once
// Live charts of the recorded series (Qt Charts), on two pages. "Shear tests": q/p and volumetric
// strain against axial strain, fabric anisotropy H11 - H22 of all / strong / weak contacts,
// coordination Z, Z_eff and sliding index S, void-cell count N_v/N_vi, and Z_eff against
// N_v/N_vi, drawn from the rows recorded during shear. "Compaction": mean stress p, void ratio e,
// coordination Z and unbalanced-force index I_uf against step, drawn from the rows recorded
// during compaction (the compaction series). "Stress paths": q against p′ and e against ln p′
// with the critical state of the steady tests shown (report_data.h: criticalStateOf), q against
// eps1 with a cyclic test's live cycle in bold, p′/p0 at the end of each cycle of a cyclic test,
// and a probe set's response envelope as it fills. Several tests overlay
// in one chart, one colour per test, one line style per quantity. Column names are the CSV
// contract of docs/measures.md. Hovering a chart marks the point under the cursor and reports
// its eps1, and reports when the hover ends (the cursor leaves the plot area).
// GUI thread only; series are replaced wholesale (QXYSeries::replace), never appended point by
// point.

#include <map>
#include <string>
#include <tuple>
#include <vector>

#include <QChartView>
#include <QLineSeries>
#include <QString>
#include <QWidget>

#include "grainlab/report_data.h"
#include "grainlab/series.h"
#include "grainlab/stage_kind.h"

class QTabWidget;

namespace grainlab::ui {

/// One line of a chart: a column plotted against the chart's x column.
struct ChartCurve {
    std::string column; ///< y column, e.g. "Hsdev"
    QString label;      ///< legend text, e.g. "strong"
    double scale = 1.0; ///< display factor (100 for percent)
    Qt::PenStyle style = Qt::SolidLine;
};

struct ChartDefinition {
    QString name;        ///< file-safe name, e.g. "q_over_p"
    QString title;       ///< chart title
    std::string xColumn; ///< e.g. "eps1"
    QString xLabel;      ///< with unit, e.g. "ε1 [%]"
    double xScale = 1.0; ///< display factor of x
    QString yLabel;      ///< with unit
    std::vector<ChartCurve> curves;
    /// The rows drawn: those of stages of this kind (the series' stage_kind); Shear: of every
    /// test kind (isTestStage).
    StageKind stage = StageKind::Shear;
    /// The page the chart is on (charts of one page share a grid).
    QString page = QObject::tr("Shear tests");
    /// x drawn as ln(xScale * value) (a value <= 0 is left out), e.g. ln(p′ / 1 Pa).
    bool xLogarithm = false;
    /// Points computed from a whole table instead of read from two columns: p′/p0 at the end
    /// of each cycle of a cyclic test (x the cycle), or the responses of a probe set (Δσ11,
    /// Δσ22, drawn as points as the probes come in).
    enum class Derived { None, PressurePerCycle, ProbeEnvelope };
    Derived derived = Derived::None;
    /// A cyclic test's live cycle (from its last upper peak of ε1 on) drawn over its curve in a
    /// thicker line.
    bool liveCycle = false;
    /// The critical state of the monotonic tests shown (their steady ends) drawn as a dashed
    /// black line: q = M p′ in a q - p′ chart, e = e_Γ − λ ln p′ in an e - ln p′ chart.
    enum class CriticalState { None, StressRatio, VoidRatio };
    CriticalState criticalState = CriticalState::None;
};

/// The charts in display order: the six of the shear tests, then the four of the compaction.
std::vector<ChartDefinition> defaultChartDefinitions();

/// A chart view that shows a vertical marker and the values under the cursor.
class HoverChartView : public QChartView {
    Q_OBJECT
public:
    explicit HoverChartView(QChart* chart, QWidget* parent = nullptr);
    /// Marks data x (display units) or clears the mark (NaN).
    void setMarker(double x);
    double marker() const { return marker_; }

signals:
    /// The data x under the cursor (display units).
    void hovered(double x);
    /// The cursor left the plot area (or the chart): the mark is gone.
    void hoverEnded();

protected:
    void mouseMoveEvent(QMouseEvent* event) override;
    void leaveEvent(QEvent* event) override;
    void drawForeground(QPainter* painter, const QRectF& rect) override;

private:
    double marker_;
};

class ChartsPanel : public QWidget {
    Q_OBJECT
public:
    explicit ChartsPanel(QWidget* parent = nullptr,
                         std::vector<ChartDefinition> charts = defaultChartDefinitions());

    /// Shows these tables (every test: live and loaded). A table's curves are updated only when
    /// its row count changed. Tests no longer present are removed.
    void setSeries(const std::vector<SeriesTable>& tables);
    /// Plot only the rows of each chart's stage (ChartDefinition::stage); default true. False
    /// plots every row of a table in every chart.
    void setShearOnly(bool shearOnly);

    /// The pages, in order ("Shear tests", "Compaction").
    QStringList pages() const;
    /// Shows page `page` (a name from pages()); the shown page's name.
    void showPage(const QString& page);
    QString currentPage() const;
    /// The page of the charts that draw the rows of stages of `kind`, or "".
    QString pageOfStage(StageKind kind) const;

    int chartCount() const { return static_cast<int>(views_.size()); }
    const ChartDefinition& definition(int chart) const { return definitions_[chart]; }
    HoverChartView* chartView(int chart) const { return views_[chart]; }
    /// Points of the curve of `column` of test `test` in chart `chart` (display units).
    QList<QPointF> curvePoints(int chart, const std::string& test, const std::string& column) const;
    /// The colour given to a test (stable while the test is shown).
    QColor testColour(const std::string& test) const;
    /// The live cycle drawn over the curve of `test` in chart `chart` (display units); empty
    /// when the chart draws none or the test is not cyclic.
    QList<QPointF> liveCyclePoints(int chart, const std::string& test) const;
    /// True when chart `chart` draws something (a test's curve or points).
    bool hasCurves(int chart) const;
    /// The critical-state line drawn in chart `chart` (display units), empty when there is none;
    /// and what it was computed from: the steady ends of the monotonic tests shown.
    QList<QPointF> criticalStatePoints(int chart) const;
    const CriticalStateSummary& criticalState() const { return criticalState_; }

    /// Writes chart `chart` to `path` (.png, .svg or .pdf) at `size` pixels. Returns false and
    /// sets `error` on failure.
    bool exportChart(int chart, const QString& path, QSize size, QString* error = nullptr) const;

signals:
    /// Axial strain eps1 [-] under the cursor in a chart drawn against eps1.
    void hoveredAxialStrain(double eps1);
    /// The cursor left the chart it was hovering (every chart's mark is cleared).
    void hoverEnded();

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    struct Curve {
        QXYSeries* series = nullptr;
        std::size_t rows = 0;
        bool seen = false;
    };
    void rescale(int chart);
    /// The curve (chart, test, key), made on first use in the test's colour.
    Curve& curveFor(int chart, const std::string& test, const std::string& key, bool legend,
                    const QPen& pen, bool points = false);
    /// The critical state of `tables` drawn in the charts that show it.
    void drawCriticalState(const std::vector<SeriesTable>& tables);

    std::vector<ChartDefinition> definitions_;
    std::vector<HoverChartView*> views_;
    std::map<std::string, int> testColours_;
    /// (chart, test, column) -> curve.
    std::map<std::tuple<int, std::string, std::string>, Curve> curves_;
    bool shearOnly_ = true;
    CriticalStateSummary criticalState_;
    std::map<int, QLineSeries*> criticalStateLines_; ///< chart -> its line
    QTabWidget* tabs_ = nullptr;
};

} // namespace grainlab::ui
