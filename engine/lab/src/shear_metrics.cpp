#include "grainlab/shear_metrics.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "grainlab/critical_state.h"
#include "grainlab/path_measures.h"
#include "grainlab/stage_kind.h"

namespace grainlab {
namespace {

/// True for a stage kind's name that is a test's (isTestStage).
bool isTestName(const std::string& kind) {
    const std::optional<StageKind> k = stageKindFromName(kind);
    return k && isTestStage(*k);
}

/// The row of `rows` where `sign` times `column` is largest (the first of equal maxima).
std::size_t rowOfLargest(const SeriesTable& t, const std::vector<std::size_t>& rows, int column,
                         double sign = 1.0) {
    std::size_t best = rows.front();
    for (std::size_t k : rows) {
        if (sign * t.rows[k][std::size_t(column)] > sign * t.rows[best][std::size_t(column)]) {
            best = k;
        }
    }
    return best;
}

/// Column `name` at row k, or nothing when the table has no such column.
std::optional<double> cell(const SeriesTable& t, int column, std::size_t k) {
    if (column < 0) {
        return std::nullopt;
    }
    return t.rows[k][std::size_t(column)];
}

/// y at the metric strain `strain`. A shear run to exactly that strain ends a fraction of a
/// step's strain short of it (the strain is a sum of steps: 0.04999999 for 5 %); its last record
/// then stands for the strain when it lies within 1e-4 of it (relative), so that a study's
/// shear to 5 % has its values at 5 %.
std::optional<double> valueAtStrain(const Curve& curve, double strain) {
    if (const auto v = valueAt(curve, strain)) {
        return v;
    }
    const std::size_t n = std::min(curve.x.size(), curve.y.size());
    if (n > 0 && curve.x[n - 1] < strain && curve.x[n - 1] >= strain * (1 - 1e-4)) {
        return curve.y[n - 1];
    }
    return std::nullopt;
}

} // namespace

std::vector<std::size_t> shearRows(const SeriesTable& t) {
    const bool identified = t.stageKinds.size() == t.rows.size();
    std::vector<std::size_t> rows;
    for (std::size_t k = 0; k < t.rows.size(); ++k) {
        const bool shear =
            identified
                ? isTestName(t.stageKinds[k])
                : k < t.stages.size() && isTestName(t.stages[k].substr(0, t.stages[k].find(' ')));
        if (shear) {
            rows.push_back(k);
        }
    }
    return rows;
}

Curve shearCurve(const SeriesTable& test, const std::string& column) {
    Curve c;
    const int e = test.column("eps1");
    const int y = test.column(column);
    if (e < 0 || y < 0) {
        return c;
    }
    for (std::size_t k : shearRows(test)) {
        c.x.push_back(test.rows[k][std::size_t(e)]);
        c.y.push_back(test.rows[k][std::size_t(y)]);
    }
    return c;
}

bool isCyclicTable(const SeriesTable& t) {
    return std::find(t.stageKinds.begin(), t.stageKinds.end(), "cyclic") != t.stageKinds.end();
}

bool isProbesTable(const SeriesTable& t) {
    return std::find(t.stageKinds.begin(), t.stageKinds.end(), "probes") != t.stageKinds.end();
}

bool isMonotonicTable(const SeriesTable& t) {
    return !isCyclicTable(t) && !isProbesTable(t);
}

ShearMetrics shearMetrics(const SeriesTable& test, double confiningPressure) {
    ShearMetrics m;
    if (!test.rows.empty()) {
        m.voidRatioAtStart = cell(test, test.column("e"), 0);
    }
    const std::vector<std::size_t> rows = shearRows(test);
    if (rows.empty()) {
        return m;
    }

    const int ratio = test.column("q_over_p"), eps1 = test.column("eps1");
    const int phi = test.column("phi_deg"), di = test.column("DI");
    const int s22 = test.column("sigma22"), iuf = test.column("I_uf");
    // A test in extension (eps1 < 0 at its end): its peak is the largest -q (or -q/p), and its
    // values at a metric strain are at eps1 = -strain.
    // (Cyclic tests and probes go both ways: never mirrored.)
    const double sign =
        isMonotonicTable(test) && eps1 >= 0 && test.rows[rows.back()][std::size_t(eps1)] < 0 ? -1.0
                                                                                             : 1.0;
    const auto shearCurve = [&](const std::string& column) {
        Curve c = grainlab::shearCurve(test, column);
        for (double& x : c.x) {
            x *= sign;
        }
        return c;
    };
    if (ratio >= 0 && eps1 >= 0) {
        const std::size_t peak = rowOfLargest(test, rows, ratio, sign);
        m.peakStressRatio = cell(test, ratio, peak);
        m.peakAxialStrain = cell(test, eps1, peak);
        m.peakFrictionAngle = cell(test, phi, peak);
    }
    const Curve q = shearCurve("q_over_p"), ev = shearCurve("epsv");
    for (int s = 0; s < 3; ++s) {
        m.stressRatioAt[s] = valueAtStrain(q, kMetricStrains[s]);
        m.volumetricStrainAt[s] = valueAtStrain(ev, kMetricStrains[s]);
    }
    const double at10 = kMetricStrains[2];
    m.coordinationAt5 = valueAtStrain(shearCurve("Z"), kMetricStrains[1]);
    m.coordinationAt10 = valueAtStrain(shearCurve("Z"), at10);
    m.effectiveCoordinationAt10 = valueAtStrain(shearCurve("Z_eff"), at10);
    m.voidCountRatioAt10 = valueAtStrain(shearCurve("Nv_over_Nvi"), at10);
    m.fabricAt10 = valueAtStrain(shearCurve("Hdev"), at10);

    // Which kind of test the rows are: only a drained test holds sigma22 at the pressure.
    const bool drained =
        test.stageKinds.size() != test.rows.size() || test.stageKinds[rows.back()] == "shear";
    double maxDi = -INFINITY, maxError = 0, sumIuf = 0;
    for (std::size_t k : rows) {
        const auto& r = test.rows[k];
        if (di >= 0) {
            maxDi = std::max(maxDi, r[std::size_t(di)]);
        }
        if (s22 >= 0 && confiningPressure > 0 && drained) {
            maxError = std::max(maxError, std::abs(r[std::size_t(s22)] - confiningPressure) /
                                              confiningPressure);
        }
        if (iuf >= 0) {
            sumIuf += r[std::size_t(iuf)];
        }
    }
    if (di >= 0) {
        m.maxDilatancy = maxDi;
    }
    if (s22 >= 0 && confiningPressure > 0 && drained) {
        m.maxLateralStressError = maxError;
    }

    const int qc = test.column("q"), pc = test.column("p");
    if (qc >= 0 && pc >= 0) {
        const std::size_t peak = rowOfLargest(test, rows, qc, sign);
        m.peakDeviator = cell(test, qc, peak);
        m.meanStressAtPeakDeviator = cell(test, pc, peak);
        const Curve qCurve = shearCurve("q"), pCurve = shearCurve("p");
        const Curve vCurve = shearCurve("epsv");
        if (pCurve.y.front() > 0) {
            double lowest = pCurve.y.front();
            for (double v : pCurve.y) {
                lowest = std::min(lowest, v);
            }
            m.lowestPressureRatio = lowest / pCurve.y.front();
        }
        if (test.stageKinds.size() == test.rows.size() &&
            test.stageKinds[rows.back()] == "cyclic") {
            m.cyclesCompleted = 0.5 * double(reversalIndices(qCurve.x).size());
        }
        if (vCurve.y.size() == qCurve.y.size() &&
            steadyState(qCurve.x, qCurve.y, pCurve.y, vCurve.y).steady && pCurve.y.back() > 0) {
            // |q|/p: in 2D the Mohr-Coulomb criterion gives the same |q|/p = sin(phi) in
            // compression and in extension.
            m.criticalStressRatio = std::abs(qCurve.y.back()) / pCurve.y.back();
        }
    }
    if (iuf >= 0) {
        m.meanUnbalancedForce = sumIuf / double(rows.size());
    }

    // Energy balance over shear: what the boundary put in went into stored or dissipated energy.
    const int kin = test.column("E_kin"), el = test.column("E_elastic");
    const int fr = test.column("W_friction"), dmp = test.column("W_damping");
    if (kin >= 0 && el >= 0 && fr >= 0 && dmp >= 0 && rows.size() >= 2) {
        const auto& a = test.rows[rows.front()];
        const auto& b = test.rows[rows.back()];
        const auto change = [&](int c) { return b[std::size_t(c)] - a[std::size_t(c)]; };
        const double damping = change(dmp);
        const double boundary = change(kin) + change(el) + change(fr) + damping;
        if (boundary > 0) {
            m.dampingWorkFraction = damping / boundary;
        }
    }
    return m;
}

std::vector<NamedMetric> namedMetrics(const ShearMetrics& m) {
    std::vector<NamedMetric> out{
        {"peak_q_over_p", "-", m.peakStressRatio},
        {"eps1_at_peak", "-", m.peakAxialStrain},
        {"phi_at_peak", "deg", m.peakFrictionAngle},
    };
    for (int s = 0; s < 3; ++s) {
        const int percent = int(std::lround(100 * kMetricStrains[s]));
        out.push_back({fmt::format("q_over_p_at_{}pc", percent), "-", m.stressRatioAt[s]});
    }
    for (int s = 0; s < 3; ++s) {
        const int percent = int(std::lround(100 * kMetricStrains[s]));
        out.push_back({fmt::format("epsv_at_{}pc", percent), "-", m.volumetricStrainAt[s]});
    }
    out.push_back({"DI_max", "-", m.maxDilatancy});
    out.push_back({"e_compacted", "-", m.voidRatioAtStart});
    out.push_back({"Z_at_5pc", "-", m.coordinationAt5});
    out.push_back({"Z_at_10pc", "-", m.coordinationAt10});
    out.push_back({"Z_eff_at_10pc", "-", m.effectiveCoordinationAt10});
    out.push_back({"Nv_over_Nvi_at_10pc", "-", m.voidCountRatioAt10});
    out.push_back({"Hdev_at_10pc", "-", m.fabricAt10});
    out.push_back({"lateral_stress_error_max", "-", m.maxLateralStressError});
    out.push_back({"I_uf_mean", "%", m.meanUnbalancedForce});
    out.push_back({"damping_work_fraction", "-", m.dampingWorkFraction});
    out.push_back({"q_peak", "Pa", m.peakDeviator});
    out.push_back({"p_at_q_peak", "Pa", m.meanStressAtPeakDeviator});
    out.push_back({"M_steady", "-", m.criticalStressRatio});
    out.push_back({"cycles", "-", m.cyclesCompleted});
    out.push_back({"p_min_over_p0", "-", m.lowestPressureRatio});
    return out;
}

} // namespace grainlab
