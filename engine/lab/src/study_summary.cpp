#include "grainlab/study_summary.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>

#include "grainlab/shear_metrics.h"

namespace grainlab {
namespace {

constexpr const char* kCurveColumns[] = {"q_over_p", "epsv"};

/// Curves of column `column` of test `test` over the given runs.
std::vector<Curve> curvesOf(const std::vector<const RunResult*>& runs, const std::string& test,
                            const char* column) {
    std::vector<Curve> out;
    for (const RunResult* r : runs) {
        for (const SeriesTable& t : r->tests) {
            if (t.test == test) {
                out.push_back(shearCurve(t, column));
            }
        }
    }
    return out;
}

Curve meanOf(const std::vector<Curve>& curves, const std::vector<double>& grid) {
    const CurveBand band = meanCurve(curves, grid);
    return Curve{band.x, band.mean};
}

/// 2 x the root-mean-square over the grid of the reference band's standard deviation.
std::optional<double> curveNoise(const std::vector<Curve>& curves,
                                 const std::vector<double>& grid) {
    const CurveBand band = meanCurve(curves, grid);
    if (band.x.empty()) {
        return std::nullopt;
    }
    double squares = 0;
    for (double sd : band.sd) {
        squares += sd * sd;
    }
    return 2.0 * std::sqrt(squares / double(band.sd.size()));
}

} // namespace

double costOf(const RunCost& cost, const std::string& measure) {
    if (measure == "cpu_seconds") {
        return cost.cpuSeconds;
    }
    if (measure == "wall_seconds") {
        return cost.wallSeconds;
    }
    if (measure == "grain_steps") {
        return double(cost.grainSteps);
    }
    throw std::invalid_argument("cost measure " + measure +
                                ": must be cpu_seconds, wall_seconds or grain_steps");
}

std::map<std::string, std::optional<double>>
runMetrics(const RunResult& result, const std::map<std::string, Curve>& referenceQ,
           const std::map<std::string, Curve>& referenceV,
           const std::map<std::string, std::vector<double>>& grids) {
    std::map<std::string, std::optional<double>> out;
    for (std::size_t k = 0; k < result.tests.size(); ++k) {
        const SeriesTable& t = result.tests[k];
        const double p = k < result.pressures.size() ? result.pressures[k] : 0.0;
        for (const NamedMetric& m : namedMetrics(shearMetrics(t, p))) {
            out[t.test + "." + m.name] = m.value;
        }
        const std::map<std::string, Curve>* refs[] = {&referenceQ, &referenceV};
        for (int c = 0; c < 2; ++c) {
            const auto ref = refs[c]->find(t.test);
            const auto grid = grids.find(t.test);
            out[t.test + "." + kCurveMetrics[c]] =
                ref == refs[c]->end() || grid == grids.end()
                    ? std::nullopt
                    : rmsDifference(shearCurve(t, kCurveColumns[c]), ref->second, grid->second);
        }
    }
    return out;
}

StudySummary summariseStudy(const StudySpec& spec, const StudyPlan& plan,
                            const std::vector<RunResult>& results, const std::string& costMeasure,
                            int curveGrid) {
    StudySummary summary;
    std::vector<std::vector<const RunResult*>> bySetting(plan.settings.size());
    for (const RunResult& r : results) {
        bySetting.at(std::size_t(plan.runs.at(std::size_t(r.run)).setting)).push_back(&r);
    }

    // Tests in order of appearance, and the strain range every run reached in each.
    std::map<std::string, double> reach;
    for (const RunResult& r : results) {
        for (const SeriesTable& t : r.tests) {
            const Curve q = shearCurve(t, "q_over_p");
            const double end = q.x.empty() ? 0.0 : q.x.back();
            if (!reach.count(t.test)) {
                summary.tests.push_back(t.test);
                reach[t.test] = end;
            }
            reach[t.test] = std::min(reach[t.test], end);
        }
    }
    std::map<std::string, std::vector<double>> grids;
    std::map<std::string, Curve> refQ, refV;
    std::map<std::string, std::optional<double>> noiseQ, noiseV;
    const auto& reference = bySetting.front();
    for (const std::string& test : summary.tests) {
        grids[test] =
            reach[test] > 0 ? evenlySpaced(0.0, reach[test], curveGrid) : std::vector<double>{};
        const std::vector<Curve> q = curvesOf(reference, test, "q_over_p");
        const std::vector<Curve> v = curvesOf(reference, test, "epsv");
        refQ[test] = meanOf(q, grids[test]);
        refV[test] = meanOf(v, grids[test]);
        noiseQ[test] = curveNoise(q, grids[test]);
        noiseV[test] = curveNoise(v, grids[test]);
    }

    // Every run's metrics (curve metrics against the reference mean, on its test's grid).
    std::vector<std::map<std::string, std::optional<double>>> metricsOf;
    for (const RunResult& r : results) {
        metricsOf.push_back(runMetrics(r, refQ, refV, grids));
    }
    std::map<const RunResult*, std::size_t> indexOf;
    for (std::size_t i = 0; i < results.size(); ++i) {
        indexOf[&results[i]] = i;
    }
    const auto scatterAt = [&](const std::vector<const RunResult*>& runs, const std::string& key) {
        std::vector<std::optional<double>> values;
        for (const RunResult* r : runs) {
            const auto& m = metricsOf[indexOf[r]];
            const auto it = m.find(key);
            values.push_back(it == m.end() ? std::nullopt : it->second);
        }
        return scatterOf(values);
    };

    // The metric names and units, from any run's named metrics (fixed order).
    std::vector<std::pair<std::string, std::string>> names;
    for (const NamedMetric& m : namedMetrics(ShearMetrics{})) {
        names.emplace_back(m.name, m.unit);
    }
    for (const char* c : kCurveMetrics) {
        names.emplace_back(c, "-");
    }

    const Scatter refCost = [&] {
        std::vector<double> costs;
        for (const RunResult* r : reference) {
            costs.push_back(costOf(r->cost, costMeasure));
        }
        return scatterOf(costs);
    }();

    for (std::size_t s = 0; s < plan.settings.size(); ++s) {
        SettingSummary out;
        out.setting = static_cast<int>(s);
        const auto& runs = bySetting[s];
        out.runsDone = static_cast<int>(runs.size());
        std::vector<double> wall, cpu, cost;
        for (const RunResult* r : runs) {
            wall.push_back(r->cost.wallSeconds);
            cpu.push_back(r->cost.cpuSeconds);
            cost.push_back(costOf(r->cost, costMeasure));
        }
        out.wallSeconds = scatterOf(wall);
        out.cpuSeconds = scatterOf(cpu);
        out.cost = scatterOf(cost);
        if (out.cost.count > 0 && out.cost.mean > 0 && refCost.count > 0) {
            out.speedUp = refCost.mean / out.cost.mean;
        }

        bool valid = !runs.empty() && !reference.empty();
        for (const std::string& test : summary.tests) {
            for (const auto& [name, unit] : names) {
                MetricSummary m;
                m.test = test;
                m.metric = name;
                m.unit = unit;
                const std::string key = test + "." + name;
                m.scatter = scatterAt(runs, key);
                const Scatter ref = scatterAt(reference, key);
                const bool curve = name == kCurveMetrics[0] || name == kCurveMetrics[1];
                if (curve) {
                    const char* column = name == kCurveMetrics[0] ? "q_over_p" : "epsv";
                    const Curve mean = meanOf(curvesOf(runs, test, column), grids[test]);
                    if (!runs.empty() && !reference.empty()) {
                        m.error = rmsDifference(
                            mean, name == kCurveMetrics[0] ? refQ[test] : refV[test], grids[test]);
                    }
                    m.noise = name == kCurveMetrics[0] ? noiseQ[test] : noiseV[test];
                } else if (m.scatter.count > 0 && ref.count > 0) {
                    m.error = m.scatter.mean - ref.mean;
                    m.noise = 2.0 * ref.sd;
                }
                m.withinNoise = m.error && m.noise && std::abs(*m.error) <= *m.noise;
                const auto tol = spec.tolerances.find(name);
                if (tol != spec.tolerances.end() && m.error) {
                    const double allowed = tol->second.relative
                                               ? tol->second.value * std::abs(ref.mean)
                                               : tol->second.value;
                    // One run of the setting must be as good as one of the reference: the
                    // shift of the mean and any seed scatter beyond the reference's together
                    // stay within the tolerance (a curve error is already of mean curves).
                    const double widening = curve ? 0.0 : std::max(0.0, m.scatter.sd - ref.sd);
                    m.withinTolerance = std::abs(*m.error) + widening <= allowed;
                }
                if (std::find(spec.deciding.begin(), spec.deciding.end(), name) !=
                    spec.deciding.end()) {
                    valid = valid && m.withinTolerance.value_or(false);
                }
                out.metrics.push_back(std::move(m));
            }
        }
        out.valid = valid;
        summary.settings.push_back(std::move(out));
    }
    summary.perRun = std::move(metricsOf);

    double cheapest = std::numeric_limits<double>::infinity();
    for (const SettingSummary& s : summary.settings) {
        if (s.valid && s.cost.count > 0 && s.cost.mean < cheapest) {
            cheapest = s.cost.mean;
            summary.recommended = s.setting;
        }
    }
    return summary;
}

} // namespace grainlab
