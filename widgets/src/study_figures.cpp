// See study_figures.h.
#include "grainlab/ui/study_figures.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <QObject>
#include <QPainter>

#include "grainlab/measures.h"
#include "grainlab/shear_metrics.h"
#include "grainlab/ui/colour_maps.h"
#include "grainlab/ui/figure_export.h"

namespace grainlab::ui {
namespace {

QString q(const std::string& s) {
    return QString::fromStdString(s);
}

QString costTitle(const std::string& measure) {
    if (measure == "wall_seconds") {
        return QObject::tr("cost: wall time per run [s]");
    }
    if (measure == "grain_steps") {
        return QObject::tr("cost: grain-steps per run");
    }
    return QObject::tr("cost: processor time per run [s]");
}

} // namespace

const MetricSummary* findMetricSummary(const SettingSummary& setting, const std::string& test,
                                       const std::string& metric) {
    for (const MetricSummary& m : setting.metrics) {
        if (m.test == test && m.metric == metric) {
            return &m;
        }
    }
    return nullptr;
}

PlotPainter errorCostPlot(const StudySpec& spec, const StudyPlan& plan, const StudySummary& summary,
                          const std::string& test, const std::string& metric) {
    PlotPainter plot;
    plot.title = QObject::tr("%1 at %2: error against cost").arg(q(metric), q(test));
    plot.xAxis = {costTitle(spec.costMeasure), true, {}, {}};
    plot.yAxis = {QObject::tr("|error| against the reference mean"), true, {}, {}};
    // Errors of exactly 0 (the reference, a cost-only knob) sit on the floor of the axis.
    double smallest = std::numeric_limits<double>::infinity();
    std::optional<double> noise;
    for (const SettingSummary& s : summary.settings) {
        if (const MetricSummary* m = findMetricSummary(s, test, metric)) {
            if (m->error && std::abs(*m->error) > 0) {
                smallest = std::min(smallest, std::abs(*m->error));
            }
            if (m->noise && *m->noise > 0) {
                smallest = std::min(smallest, *m->noise);
                noise = m->noise;
            }
        }
    }
    const double floor = std::isfinite(smallest) ? smallest / 10 : 1e-6;
    plot.yAxis.min = floor / 2;
    if (noise) {
        plot.bands.push_back({floor / 2, *noise, QObject::tr("reference noise (2σ of its seeds)"),
                              QColor(150, 150, 150, 90)});
    }
    const auto tol = spec.tolerances.find(metric);
    for (const SettingSummary& s : summary.settings) {
        const MetricSummary* m = findMetricSummary(s, test, metric);
        if (!m || !m->error || s.cost.count == 0) {
            continue;
        }
        PlotPoint p;
        p.x = s.cost.mean;
        p.xError = s.cost.sd;
        p.y = std::max(std::abs(*m->error), floor);
        p.yError = m->scatter.sd;
        const StudySetting& setting = plan.settings[std::size_t(s.setting)];
        p.label = q(setting.id);
        p.colour = setting.isReference                  ? QColor(60, 60, 60)
                   : m->withinTolerance.value_or(false) ? QColor(44, 160, 44)
                                                        : QColor(214, 39, 40);
        p.highlighted = summary.recommended == s.setting;
        plot.points.push_back(p);
    }
    // The reference last, so that a setting with the same error and cost (a cost-only knob)
    // does not hide it.
    std::stable_partition(plot.points.begin(), plot.points.end(), [&](const PlotPoint& p) {
        return p.label != q(plan.settings.front().id);
    });
    if (tol != spec.tolerances.end() && !tol->second.relative) {
        plot.bands.push_back({tol->second.value * 0.995, tol->second.value * 1.005,
                              QObject::tr("tolerance"), QColor(44, 160, 44, 160)});
    }
    return plot;
}

PlotPainter metricKnobPlot(const StudySpec& spec, const StudyPlan& plan,
                           const StudySummary& summary, KnobKind knob, const std::string& test,
                           const std::string& metric) {
    PlotPainter plot;
    plot.title = QObject::tr("%1 at %2 against %3").arg(q(metric), q(test), q(knobName(knob)));
    plot.xAxis.title = q(knobName(knob));
    plot.yAxis.title = q(metric);
    const StudySetting& ref = plan.settings.front();
    // The settings that differ from the reference in this knob only (and the reference).
    std::vector<const Knob*> knobs;
    const Knob* turned = nullptr;
    for (const Knob& k : spec.knobs) {
        if (k.kind == knob) {
            turned = &k;
        }
    }
    if (!turned) {
        return plot;
    }
    const bool numeric = turned->levels.front().object.empty();
    for (const SettingSummary& s : summary.settings) {
        const StudySetting& setting = plan.settings[std::size_t(s.setting)];
        bool onlyThisKnob = true;
        for (const auto& [kind, level] : setting.levels) {
            const auto r = ref.levels.find(kind);
            if (kind != knob && (r == ref.levels.end() || !(r->second == level))) {
                onlyThisKnob = false;
            }
        }
        for (const auto& [kind, level] : ref.levels) {
            if (kind != knob && !setting.levels.count(kind)) {
                onlyThisKnob = false;
            }
        }
        const MetricSummary* m = findMetricSummary(s, test, metric);
        if (!onlyThisKnob || !m || m->scatter.count == 0) {
            continue;
        }
        const auto level = setting.levels.find(knob);
        PlotPoint p;
        if (level == setting.levels.end()) {
            // The base's own value of the knob (e.g. its grain count), from its experiment.
            p.label = QObject::tr("base");
            p.x = -1;
            if (numeric) {
                const auto run =
                    std::find_if(plan.runs.begin(), plan.runs.end(),
                                 [&](const StudyRun& r) { return r.setting == s.setting; });
                const std::optional<double> value =
                    run == plan.runs.end() ? std::nullopt : knobValueIn(run->experimentText, knob);
                p.x = value.value_or(0);
                p.label = QObject::tr("base (%1)").arg(p.x, 0, 'g', 6);
            }
        } else if (numeric) {
            p.x = level->second.number;
            p.label = q(level->second.label());
        } else {
            const auto it = std::find(turned->levels.begin(), turned->levels.end(), level->second);
            p.x = double(it - turned->levels.begin());
            p.label = q(level->second.label());
        }
        p.y = m->scatter.mean;
        p.yError = m->scatter.sd;
        p.colour = setting.isReference ? QColor(60, 60, 60) : QColor(31, 119, 180);
        p.highlighted = setting.isReference;
        plot.points.push_back(p);
        if (setting.isReference && m->noise) {
            plot.bands.push_back({m->scatter.mean - *m->noise, m->scatter.mean + *m->noise,
                                  QObject::tr("reference ± noise"), QColor(150, 150, 150, 90)});
        }
    }
    if (!numeric) {
        plot.xAxis.title += QObject::tr(" (levels in file order)");
    }
    return plot;
}

PlotPainter curvesPlot(const StudyPlan& plan, const std::vector<RunResult>& results,
                       const std::string& test, const std::string& column) {
    PlotPainter plot;
    const AxisLabel x = axisLabelOf("eps1"), y = axisLabelOf(column);
    plot.title = QObject::tr("%1 against ε1 at %2").arg(q(column), q(test));
    plot.xAxis.title = q(x.text);
    plot.yAxis.title = q(y.text);
    std::vector<std::vector<Curve>> bySetting(plan.settings.size());
    double reach = std::numeric_limits<double>::infinity();
    for (const RunResult& r : results) {
        for (const SeriesTable& t : r.tests) {
            if (t.test == test) {
                Curve c = shearCurve(t, column);
                if (!c.x.empty()) {
                    reach = std::min(reach, c.x.back());
                    bySetting[std::size_t(plan.runs[std::size_t(r.run)].setting)].push_back(
                        std::move(c));
                }
            }
        }
    }
    if (!std::isfinite(reach) || reach <= 0) {
        return plot;
    }
    const std::vector<double> grid = evenlySpaced(0, reach, 201);
    for (std::size_t s = 0; s < bySetting.size(); ++s) {
        if (bySetting[s].empty()) {
            continue;
        }
        const CurveBand band = meanCurve(bySetting[s], grid);
        PlotCurve c;
        for (std::size_t k = 0; k < band.x.size(); ++k) {
            c.x.push_back(band.x[k] * x.scale);
            c.y.push_back(band.mean[k] * y.scale);
        }
        c.label = q(plan.settings[s].id);
        if (plan.settings[s].isReference) {
            for (double sd : band.sd) {
                c.band.push_back(sd * y.scale);
            }
            c.colour = QColor(60, 60, 60);
            c.width = 2.5;
            c.label += QObject::tr(" (± 1σ)");
        } else {
            c.colour = categoryColour(int(s));
        }
        plot.curves.push_back(std::move(c));
    }
    return plot;
}

QStringList writeStudyFigures(const QString& folder, const StudySpec& spec, const StudyPlan& plan,
                              const std::vector<RunResult>& results, const StudySummary& summary,
                              QString* error, const QStringList& formats, QSize size) {
    QStringList written;
    if (!makeFigureFolder(folder, error)) {
        return written;
    }
    const auto save = [&](const PlotPainter& plot, const QString& name) {
        return exportFigureFormats(
            folder, name, formats, size, [&](QPainter& p, const QRectF& r) { plot.paint(p, r); },
            written, error);
    };
    for (const std::string& test : summary.tests) {
        for (const std::string& metric : spec.deciding) {
            if (!save(errorCostPlot(spec, plan, summary, test, metric),
                      q("error-cost_" + metric + "_" + test))) {
                return written;
            }
        }
        for (const Knob& knob : spec.knobs) {
            for (const NamedMetric& m : namedMetrics(ShearMetrics{})) {
                if (!save(metricKnobPlot(spec, plan, summary, knob.kind, test, m.name),
                          q(m.name + "_vs_" + knobName(knob.kind) + "_" + test))) {
                    return written;
                }
            }
        }
        for (const char* column : {"q_over_p", "epsv"}) {
            if (!save(curvesPlot(plan, results, test, column),
                      q(std::string("curves_") + column + "_" + test))) {
                return written;
            }
        }
    }
    return written;
}

} // namespace grainlab::ui
