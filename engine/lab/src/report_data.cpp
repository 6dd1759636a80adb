#include "grainlab/report_data.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>

#include <fmt/format.h>

#include "grainlab/measures.h"
#include "grainlab/path_measures.h"
#include "grainlab/shear_metrics.h"

namespace grainlab {
namespace {

struct TestKey {
    std::string test;
    double pressure = 0;
};

/// Every test of the runs (by name) of one sort (monotonic: drained, constant volume, paths;
/// cyclic; probes), in the order of their confining pressures.
std::vector<TestKey> testsOf(const std::vector<ReportRun>& runs,
                             bool (*sort)(const SeriesTable&) = isMonotonicTable) {
    std::vector<TestKey> keys;
    for (const ReportRun& r : runs) {
        for (std::size_t t = 0; t < r.tests.size(); ++t) {
            if (!sort(r.tests[t])) {
                continue;
            }
            const std::string& name = r.tests[t].test;
            const bool known = std::any_of(keys.begin(), keys.end(),
                                           [&](const TestKey& k) { return k.test == name; });
            if (!known) {
                keys.push_back({name, t < r.pressures.size() ? r.pressures[t] : 0.0});
            }
        }
    }
    std::stable_sort(keys.begin(), keys.end(),
                     [](const TestKey& a, const TestKey& b) { return a.pressure < b.pressure; });
    return keys;
}

std::string pressureLabel(double pressure) {
    return fmt::format("{:g} kPa", pressure / 1e3);
}

/// The table of test `test` in each run that has it with shear rows, with its pressure.
std::vector<std::pair<const SeriesTable*, double>> tablesOf(const std::vector<ReportRun>& runs,
                                                            const std::string& test) {
    std::vector<std::pair<const SeriesTable*, double>> out;
    for (const ReportRun& r : runs) {
        for (std::size_t t = 0; t < r.tests.size(); ++t) {
            if (r.tests[t].test == test && !shearCurve(r.tests[t], "eps1").x.empty()) {
                out.emplace_back(&r.tests[t], t < r.pressures.size() ? r.pressures[t] : 0.0);
            }
        }
    }
    return out;
}

/// Each run's curve of `column` against eps1 for test `test` (runs without it left out), in
/// increasing eps1: a test in extension (eps1 falling from 0) is read from its end.
std::vector<Curve> curvesOf(const std::vector<ReportRun>& runs, const std::string& test,
                            const std::string& column) {
    std::vector<Curve> curves;
    for (const auto& [table, pressure] : tablesOf(runs, test)) {
        Curve c = shearCurve(*table, column);
        if (c.x.size() > 1 && c.x.back() < c.x.front()) {
            std::reverse(c.x.begin(), c.x.end());
            std::reverse(c.y.begin(), c.y.end());
        }
        if (!c.x.empty()) {
            curves.push_back(std::move(c));
        }
    }
    return curves;
}

/// The common eps1 axis of `curves`: from the smallest first to the largest last strain.
std::vector<double> gridOf(const std::vector<Curve>& curves, int points) {
    double lo = 0, hi = 0;
    bool first = true;
    for (const Curve& c : curves) {
        lo = first ? c.x.front() : std::min(lo, c.x.front());
        hi = first ? c.x.back() : std::max(hi, c.x.back());
        first = false;
    }
    if (first || !(hi > lo)) {
        return first ? std::vector<double>{} : std::vector<double>{lo};
    }
    return evenlySpaced(lo, hi, std::max(points, 2));
}

/// The band's value at each point of `grid` (the band holds the grid points some curve reaches,
/// in order): index into the band, or -1.
std::vector<int> onGrid(const CurveBand& band, const std::vector<double>& grid) {
    std::vector<int> at(grid.size(), -1);
    std::size_t b = 0;
    for (std::size_t k = 0; k < grid.size() && b < band.x.size(); ++k) {
        if (band.x[b] == grid[k]) {
            at[k] = int(b++);
        }
    }
    return at;
}

/// An empty line of test `key`, labelled with its pressure.
/// "25 kPa" for the drained test of a sample, "25 kPa constant volume" for another kind (its
/// series name after the sample's: "p025kPa-constant-volume").
std::string testLabel(const TestKey& key) {
    const std::size_t dash = key.test.find('-');
    if (dash == std::string::npos) {
        return pressureLabel(key.pressure);
    }
    std::string kind = key.test.substr(dash + 1);
    if (kind.rfind("path", 0) == 0) {
        return fmt::format("{} stress path, slope {}", pressureLabel(key.pressure), kind.substr(4));
    }
    std::replace(kind.begin(), kind.end(), '-', ' ');
    return pressureLabel(key.pressure) + " " + kind;
}

ReportLine lineOf(const TestKey& key) {
    ReportLine line;
    line.label = testLabel(key);
    line.test = key.test;
    line.pressure = key.pressure;
    return line;
}

/// A line of mean ± sd at the grid points that at least one run reaches.
ReportLine bandLine(const CurveBand& band, const TestKey& key) {
    ReportLine line = lineOf(key);
    line.x = band.x;
    line.y = band.mean;
    line.sd = band.sd;
    line.runs = band.count;
    return line;
}

ReportLine strainLine(const std::vector<ReportRun>& runs, const TestKey& key,
                      const std::string& column, const ReportOptions& options) {
    const std::vector<Curve> curves = curvesOf(runs, key.test, column);
    return bandLine(meanCurve(curves, gridOf(curves, options.gridPoints)), key);
}

/// `yColumn` against `xColumn`, both taken as the mean over runs at each eps1 of the grid.
ReportLine parametricLine(const std::vector<ReportRun>& runs, const TestKey& key,
                          const std::string& xColumn, const std::string& yColumn,
                          const ReportOptions& options) {
    const std::vector<Curve> xs = curvesOf(runs, key.test, xColumn);
    const std::vector<Curve> ys = curvesOf(runs, key.test, yColumn);
    const std::vector<double> grid = gridOf(ys, options.gridPoints);
    const CurveBand bx = meanCurve(xs, grid), by = meanCurve(ys, grid);
    const std::vector<int> ix = onGrid(bx, grid), iy = onGrid(by, grid);
    ReportLine line = lineOf(key);
    for (std::size_t k = 0; k < grid.size(); ++k) {
        if (ix[k] >= 0 && iy[k] >= 0) {
            const std::size_t a = std::size_t(ix[k]), b = std::size_t(iy[k]);
            line.x.push_back(bx.mean[a]);
            line.xSd.push_back(bx.sd[a]);
            line.y.push_back(by.mean[b]);
            line.sd.push_back(by.sd[b]);
            line.runs.push_back(by.count[b]);
        }
    }
    return line;
}

/// -d eps_v / d eps1 by a central difference over `window` of eps1, on `grid` (where the
/// window lies within the curve).
Curve smoothedDilatancy(const Curve& epsv, const std::vector<double>& grid, double window) {
    Curve out;
    for (double x : grid) {
        const auto above = valueAt(epsv, x + window / 2), below = valueAt(epsv, x - window / 2);
        if (above && below) {
            out.x.push_back(x);
            out.y.push_back(-(*above - *below) / window);
        }
    }
    return out;
}

ReportLine dilatancyLine(const std::vector<ReportRun>& runs, const TestKey& key,
                         const ReportOptions& options) {
    const std::vector<Curve> epsv = curvesOf(runs, key.test, "epsv");
    const std::vector<Curve> raw = curvesOf(runs, key.test, "DI");
    const std::vector<double> grid = gridOf(epsv, options.gridPoints);
    std::vector<Curve> smoothed;
    for (const Curve& c : epsv) {
        smoothed.push_back(smoothedDilatancy(c, grid, options.dilatancyWindow));
    }
    const CurveBand s = meanCurve(smoothed, grid), r = meanCurve(raw, grid);
    const std::vector<int> is = onGrid(s, grid), ir = onGrid(r, grid);
    ReportLine line = lineOf(key);
    std::vector<double> rawMean, rawSd;
    for (std::size_t k = 0; k < grid.size(); ++k) {
        if (is[k] >= 0 && ir[k] >= 0) {
            const std::size_t a = std::size_t(is[k]), b = std::size_t(ir[k]);
            line.x.push_back(grid[k]);
            line.y.push_back(s.mean[a]);
            line.sd.push_back(s.sd[a]);
            line.runs.push_back(s.count[a]);
            rawMean.push_back(r.mean[b]);
            rawSd.push_back(r.sd[b]);
        }
    }
    line.extra = {{"DI_raw mean [-]", rawMean}, {"DI_raw sd [-]", rawSd}};
    return line;
}

/// One run's points of a test as a line of its own (no scatter: one run at each point).
ReportLine runLine(const ReportRun& run, const TestKey& key, std::vector<double> x,
                   std::vector<double> y) {
    ReportLine line;
    line.label = run.name;
    line.test = key.test;
    line.pressure = key.pressure;
    line.x = std::move(x);
    line.y = std::move(y);
    line.sd.assign(line.y.size(), 0.0);
    line.runs.assign(line.y.size(), 1);
    return line;
}

/// A figure of `yColumn` against `xColumn`, labelled as a paper would (axisLabelOf).
ReportFigure figureOf(std::string name, std::string title, const std::string& xColumn,
                      const std::string& yColumn) {
    const AxisLabel x = axisLabelOf(xColumn), y = axisLabelOf(yColumn);
    ReportFigure f;
    f.name = std::move(name);
    f.title = std::move(title);
    f.xColumn = xColumn;
    f.xLabel = x.text;
    f.yColumn = yColumn;
    f.yLabel = y.text;
    f.xScale = x.scale;
    f.yScale = y.scale;
    return f;
}

ReportFigure strainFigure(const std::vector<ReportRun>& runs, const std::vector<TestKey>& keys,
                          std::string name, std::string title, const std::string& column,
                          const ReportOptions& options) {
    ReportFigure f = figureOf(std::move(name), std::move(title), "eps1", column);
    for (const TestKey& key : keys) {
        ReportLine line = strainLine(runs, key, column, options);
        if (!line.x.empty()) {
            f.lines.push_back(std::move(line));
        }
    }
    return f;
}

/// The mean over the shear records of `a` - `b` (e.g. Z_eff - Z), or nothing.
std::optional<double> meanDifference(const SeriesTable& t, const std::string& a,
                                     const std::string& b) {
    const Curve ca = shearCurve(t, a), cb = shearCurve(t, b);
    if (ca.y.empty() || ca.y.size() != cb.y.size()) {
        return std::nullopt;
    }
    double sum = 0;
    for (std::size_t k = 0; k < ca.y.size(); ++k) {
        sum += ca.y[k] - cb.y[k];
    }
    return sum / double(ca.y.size());
}

/// Appends the shear records' N_v/N_vi to `x` and Z_eff to `y` (the points of the fit).
void appendFitRecords(const SeriesTable& t, std::vector<double>& x, std::vector<double>& y) {
    const Curve cx = shearCurve(t, "Nv_over_Nvi"), cy = shearCurve(t, "Z_eff");
    x.insert(x.end(), cx.y.begin(), cx.y.end());
    y.insert(y.end(), cy.y.begin(), cy.y.end());
}

std::optional<LinearFit> fitOfTest(const SeriesTable& t) {
    std::vector<double> x, y;
    appendFitRecords(t, x, y);
    return fitLine(x, y);
}

} // namespace

std::optional<std::vector<std::array<double, 2>>> probeResponses(const SeriesTable& t,
                                                                 bool complete) {
    const std::vector<std::size_t> rows = shearRows(t);
    const int s11 = t.column("sigma11"), s22 = t.column("sigma22");
    const bool enough =
        complete ? rows.size() >= 6 && (rows.size() - 2) % 2 == 0 : rows.size() >= 3;
    if (!enough || s11 < 0 || s22 < 0) {
        return std::nullopt;
    }
    const auto& zero = t.rows[rows[1]];
    std::vector<std::array<double, 2>> out;
    for (std::size_t k = 2; k < rows.size(); ++k) {
        out.push_back({t.rows[rows[k]][std::size_t(s11)] - zero[std::size_t(s11)],
                       t.rows[rows[k]][std::size_t(s22)] - zero[std::size_t(s22)]});
    }
    return out;
}

std::vector<std::size_t> upperPeaks(const std::vector<double>& eps1) {
    // Reversals 0, 2, 4, ..., and the last record when the test ended on one (a test that made
    // all its cycles ends at an upper peak).
    const std::vector<std::size_t> turns = reversalIndices(eps1);
    std::vector<std::size_t> peaks;
    for (std::size_t k = 0; k < turns.size(); k += 2) {
        peaks.push_back(turns[k]);
    }
    if (!turns.empty() && turns.size() % 2 == 0 && eps1.back() >= eps1[turns.front()] - 1e-12) {
        peaks.push_back(eps1.size() - 1);
    }
    return peaks;
}

PressurePerCycle pressurePerCycle(const SeriesTable& t) {
    const Curve eps1 = shearCurve(t, "eps1"), p = shearCurve(t, "p");
    PressurePerCycle out;
    if (p.y.empty()) {
        return out;
    }
    out.cycle = {0.0};
    out.ratio = {1.0};
    const double p0 = p.y.front();
    const std::vector<std::size_t> peaks = upperPeaks(eps1.y);
    for (std::size_t k = 1; k < peaks.size(); ++k) {
        out.cycle.push_back(double(k));
        out.ratio.push_back(p0 > 0 ? p.y[peaks[k]] / p0 : 0.0);
    }
    return out;
}

std::optional<LinearFit> fitLine(const std::vector<double>& x, const std::vector<double>& y) {
    const std::size_t n = std::min(x.size(), y.size());
    if (n < 2) {
        return std::nullopt;
    }
    double mx = 0, my = 0;
    for (std::size_t k = 0; k < n; ++k) {
        mx += x[k];
        my += y[k];
    }
    mx /= double(n);
    my /= double(n);
    double sxx = 0, sxy = 0, syy = 0;
    for (std::size_t k = 0; k < n; ++k) {
        sxx += (x[k] - mx) * (x[k] - mx);
        sxy += (x[k] - mx) * (y[k] - my);
        syy += (y[k] - my) * (y[k] - my);
    }
    if (!(sxx > 0)) {
        return std::nullopt;
    }
    LinearFit fit;
    fit.slope = sxy / sxx;
    fit.intercept = my - fit.slope * mx;
    double residual = 0;
    for (std::size_t k = 0; k < n; ++k) {
        const double r = y[k] - (fit.slope * x[k] + fit.intercept);
        residual += r * r;
    }
    fit.r2 = syy > 0 ? 1.0 - residual / syy : 1.0;
    fit.count = n;
    return fit;
}

int CriticalStateSummary::steadyCount() const {
    return int(std::count_if(ends.begin(), ends.end(),
                             [](const TestEndState& e) { return e.steady.steady; }));
}

CriticalStateSummary criticalStateOf(const std::vector<ReportRun>& runs,
                                     const SteadyStateCriterion& criterion) {
    CriticalStateSummary out;
    out.criterion = criterion;
    std::vector<double> all, drained, constantVolume, lineP, lineE;
    for (const ReportRun& run : runs) {
        for (std::size_t t = 0; t < run.tests.size(); ++t) {
            const SeriesTable& table = run.tests[t];
            if (!isMonotonicTable(table)) {
                continue; // its end is a point of a loop or a probe, not a steady state
            }
            const Curve q = shearCurve(table, "q"), p = shearCurve(table, "p");
            const Curve epsv = shearCurve(table, "epsv"), e = shearCurve(table, "e");
            if (q.y.empty() || p.y.size() != q.y.size() || epsv.y.size() != q.y.size() ||
                e.y.size() != q.y.size()) {
                continue; // a table without the columns the criterion reads
            }
            TestEndState end;
            end.run = run.name;
            end.test = table.test;
            end.pressure = t < run.pressures.size() ? run.pressures[t] : 0.0;
            const std::vector<std::size_t> rows = shearRows(table);
            end.kind =
                table.stageKinds.size() == table.rows.size()
                    ? table.stageKinds[rows.back()]
                    : table.stages[rows.back()].substr(0, table.stages[rows.back()].find(' '));
            end.steady = steadyState(q.x, q.y, p.y, epsv.y, criterion);
            end.q = q.y.back();
            end.p = p.y.back();
            end.e = e.y.back();
            // |q|/p: M is the same for a test in extension (q < 0) in 2D.
            end.stressRatio = end.p > 0 ? std::abs(end.q) / end.p : 0.0;
            if (end.steady.steady) {
                all.push_back(end.stressRatio);
                (end.kind == "constant_volume" ? constantVolume : drained)
                    .push_back(end.stressRatio);
                lineP.push_back(end.p);
                lineE.push_back(end.e);
            }
            out.ends.push_back(std::move(end));
        }
    }
    out.m = scatterOf(all);
    out.mDrained = scatterOf(drained);
    out.mConstantVolume = scatterOf(constantVolume);
    try {
        out.line = fitCriticalStateLine(lineP, lineE);
    } catch (const std::invalid_argument&) {
        // fewer than two steady ends of distinct p': no line
    }
    return out;
}

std::vector<ReportFigure> reportFigures(const std::vector<ReportRun>& runs,
                                        const ReportOptions& options) {
    const std::vector<TestKey> keys = testsOf(runs);
    std::vector<ReportFigure> figures;
    const auto add = [&](ReportFigure f) { figures.push_back(std::move(f)); };

    // 1. q and q/p against eps1.
    add(strainFigure(runs, keys, "01_q", "Deviator stress", "q", options));
    add(strainFigure(runs, keys, "01_q_over_p", "Stress ratio", "q_over_p", options));

    // 2. phi at the peak of q/p against the confining pressure.
    {
        ReportFigure f =
            figureOf("02_phi_peak", "Friction angle at the peak", "pressure", "phi_deg");
        f.xLabel = "confining pressure [kPa]"; // the points' x is in kPa already
        f.yLabel = "φ at the peak [°]";
        ReportLine line;
        line.label = "mean ± 1σ over runs";
        line.points = true;
        for (const TestKey& key : keys) {
            std::vector<std::optional<double>> values;
            for (const auto& [table, pressure] : tablesOf(runs, key.test)) {
                values.push_back(shearMetrics(*table, pressure).peakFrictionAngle);
            }
            const Scatter s = scatterOf(values);
            if (s.count > 0) {
                line.x.push_back(key.pressure / 1e3);
                line.y.push_back(s.mean);
                line.sd.push_back(s.sd);
                line.runs.push_back(s.count);
            }
        }
        f.lines.push_back(std::move(line));
        add(std::move(f));
    }

    // 3. eps_v and the dilatancy index against eps1.
    add(strainFigure(runs, keys, "03_epsv", "Volumetric strain", "epsv", options));
    {
        ReportFigure f = figureOf("03_DI", "Dilatancy index", "eps1", "DI");
        f.note = fmt::format("smoothed: central difference of εv over an ε1 window of {:g} % "
                             "(the recorded finite difference between records is the "
                             "DI_raw columns of the CSV)",
                             100.0 * options.dilatancyWindow);
        for (const TestKey& key : keys) {
            ReportLine line = dilatancyLine(runs, key, options);
            if (!line.x.empty()) {
                f.lines.push_back(std::move(line));
            }
        }
        add(std::move(f));
    }

    // 4. Z, Z_eff and S against eps1; Z and Z_eff together at the lowest and highest pressure.
    add(strainFigure(runs, keys, "04_Z", "Coordination number", "Z", options));
    add(strainFigure(runs, keys, "04_Z_eff", "Load-bearing coordination number", "Z_eff", options));
    add(strainFigure(runs, keys, "04_S", "Sliding contacts", "S", options));
    {
        ReportFigure f =
            figureOf("04_Z_and_Z_eff", "Z and Z̄ at the lowest and highest pressure", "eps1", "Z");
        f.yLabel = "Z, Z̄";
        std::vector<TestKey> ends;
        if (!keys.empty()) {
            ends.push_back(keys.front());
            if (keys.size() > 1) {
                ends.push_back(keys.back());
            }
        }
        for (const TestKey& key : ends) {
            for (const std::string column : {"Z", "Z_eff"}) {
                ReportLine line = strainLine(runs, key, column, options);
                line.label = fmt::format("{} {}", column == "Z" ? "Z" : "Z̄", line.label);
                if (!line.x.empty()) {
                    f.lines.push_back(std::move(line));
                }
            }
        }
        add(std::move(f));
    }

    // 6. N_v/N_vi against eps1; Z_eff against N_v/N_vi with the pooled fit.
    add(strainFigure(runs, keys, "06_Nv_over_Nvi", "Void cells per initial void cell",
                     "Nv_over_Nvi", options));
    {
        ReportFigure f =
            figureOf("06_Z_eff_vs_Nv_over_Nvi", "Z̄ against N_v/N_vi", "Nv_over_Nvi", "Z_eff");
        std::vector<double> x, y;
        for (const TestKey& key : keys) {
            ReportLine line = parametricLine(runs, key, "Nv_over_Nvi", "Z_eff", options);
            if (!line.x.empty()) {
                f.lines.push_back(std::move(line));
            }
            for (const auto& [table, pressure] : tablesOf(runs, key.test)) {
                appendFitRecords(*table, x, y);
            }
        }
        f.fit = fitLine(x, y);
        f.note = "the fit is pooled over every shear record of every test and run";
        add(std::move(f));
    }

    // 7. H11 - H22 against eps1: all, strong and weak contacts.
    add(strainFigure(runs, keys, "07_Hdev", "Fabric anisotropy, all contacts", "Hdev", options));
    add(strainFigure(runs, keys, "07_Hsdev", "Fabric anisotropy, strong contacts", "Hsdev",
                     options));
    add(strainFigure(runs, keys, "07_Hwdev", "Fabric anisotropy, weak contacts", "Hwdev", options));

    // 8. q/p against the fabric's anisotropy ratio, all and strong contacts.
    for (const auto& [name, column, which] :
         {std::tuple{"08_q_over_p_vs_Hratio", "Hratio", "all contacts"},
          std::tuple{"08_q_over_p_vs_Hsratio", "Hsratio", "strong contacts"}}) {
        ReportFigure f =
            figureOf(name, fmt::format("Stress ratio against fabric anisotropy, {}", which), column,
                     "q_over_p");
        for (const TestKey& key : keys) {
            ReportLine line = parametricLine(runs, key, column, "q_over_p", options);
            if (!line.x.empty()) {
                f.lines.push_back(std::move(line));
            }
        }
        add(std::move(f));
    }

    // 9. The critical state: q against p' of every test with the line q = M p' through the
    // steady ends, and the steady ends in the e - ln p' plane with the critical state line.
    const CriticalStateSummary cs = criticalStateOf(runs);
    {
        ReportFigure f = figureOf("09_q_vs_p", "Stress paths in the q − p′ plane", "p", "q");
        f.xLabel = "p′ [kPa]";
        f.bands = false;
        for (const TestKey& key : keys) {
            ReportLine line = parametricLine(runs, key, "p", "q", options);
            if (!line.x.empty()) {
                f.lines.push_back(std::move(line));
            }
        }
        if (cs.m.count > 0) {
            f.fit = LinearFit{cs.m.mean, 0.0, 0.0, std::size_t(cs.m.count)};
            f.fitLabel = fmt::format("critical state q = M p′, M = {:.3f} ± {:.3f} ({} steady "
                                     "tests)",
                                     cs.m.mean, cs.m.sd, cs.m.count);
        }
        f.note = fmt::format("a test is steady when, over its last {:g} of ε1, |dq/dε1| / p < {:g} "
                             "and |dεv/dε1| < {:g}: {} of {} test ends are",
                             cs.criterion.window, cs.criterion.maxStressSlope,
                             cs.criterion.maxVolumeSlope, cs.steadyCount(), cs.ends.size());
        add(std::move(f));
    }
    if (cs.steadyCount() > 0) {
        ReportFigure f =
            figureOf("09_e_vs_ln_p", "Steady ends in the e − ln p′ plane", "ln_p", "e");
        f.xLabel = "ln(p′ / 1 Pa)";
        for (const TestKey& key : keys) {
            std::vector<double> lnP, e;
            for (const TestEndState& end : cs.ends) {
                if (end.test == key.test && end.steady.steady) {
                    lnP.push_back(std::log(end.p));
                    e.push_back(end.e);
                }
            }
            if (lnP.empty()) {
                continue;
            }
            ReportLine line = lineOf(key);
            line.points = true;
            const Scatter x = scatterOf(lnP), y = scatterOf(e);
            line.x = {x.mean};
            line.xSd = {x.sd};
            line.y = {y.mean};
            line.sd = {y.sd};
            line.runs = {y.count};
            f.lines.push_back(std::move(line));
        }
        if (cs.line) {
            f.fit =
                LinearFit{-cs.line->lambda, cs.line->eGamma, cs.line->rSquared, cs.line->points};
            f.fitLabel = fmt::format("{} (R² = {:.3f})", cs.line->equation(), cs.line->rSquared);
        }
        f.note = "each point: a test's steady end, mean ± 1σ over the runs";
        add(std::move(f));
    }

    // 10. Each cyclic test: its q - eps1 loops and p'/p0 at the end of each cycle, run by run
    // (a loop is no curve against eps1, so no mean over runs is drawn).
    for (const TestKey& key : testsOf(runs, isCyclicTable)) {
        ReportFigure loops =
            figureOf("10_" + key.test + "_loops", "q against ε1, " + testLabel(key), "eps1", "q");
        loops.bands = false;
        ReportFigure cycles =
            figureOf("10_" + key.test + "_p_per_cycle",
                     "p′ at the end of each cycle, " + testLabel(key), "cycle", "p_over_p0");
        cycles.xLabel = "cycle";
        cycles.yLabel = "p′/p0";
        cycles.bands = false;
        for (const ReportRun& run : runs) {
            for (const SeriesTable& t : run.tests) {
                if (t.test != key.test) {
                    continue;
                }
                const Curve q = shearCurve(t, "q"), p = shearCurve(t, "p");
                if (q.x.empty()) {
                    continue;
                }
                loops.lines.push_back(runLine(run, key, q.x, q.y));
                PressurePerCycle perCycle = pressurePerCycle(t);
                cycles.lines.push_back(
                    runLine(run, key, std::move(perCycle.cycle), std::move(perCycle.ratio)));
            }
        }
        cycles.note = "p′/p0 at each upper peak of ε1 (a cycle's end), cycle 0 the test's start";
        add(std::move(loops));
        add(std::move(cycles));
    }

    // 11. Each probe set: its response envelope (d sigma11, d sigma22), run by run, with how
    // far it is from an elastic one (opposite responses to opposite inputs, an ellipse).
    for (const TestKey& key : testsOf(runs, isProbesTable)) {
        ReportFigure f = figureOf("11_" + key.test + "_envelope",
                                  "Response envelope, " + testLabel(key), "d_sigma11", "d_sigma22");
        f.xLabel = "Δσ11 [kPa]";
        f.yLabel = "Δσ22 [kPa]";
        f.xScale = f.yScale = 1e-3;
        f.bands = false;
        std::string measures;
        for (const ReportRun& run : runs) {
            for (const SeriesTable& t : run.tests) {
                if (t.test != key.test) {
                    continue;
                }
                const std::optional<std::vector<std::array<double, 2>>> r = probeResponses(t);
                if (!r) {
                    continue;
                }
                const ResponseEnvelope env = responseEnvelope(*r);
                std::vector<double> x, y;
                for (std::size_t k = 0; k <= r->size(); ++k) { // closed: back to the first
                    x.push_back((*r)[k % r->size()][0]);
                    y.push_back((*r)[k % r->size()][1]);
                }
                f.lines.push_back(runLine(run, key, std::move(x), std::move(y)));
                measures += fmt::format("{}{}: asymmetry {:.3g}, ellipse residual {:.3g}",
                                        measures.empty() ? "" : "; ", run.name, env.asymmetry,
                                        env.ellipseResidual);
            }
        }
        f.note = "responses to strain increments in evenly spread directions, each minus the "
                 "drift of the zero probe (0 for an elastic response: " +
                 measures + ")";
        add(std::move(f));
    }
    return figures;
}

PublishedValue publishedVoidRatio() {
    return {kPublishedVoidRatio, false, "0.126"};
}
PublishedValue publishedFitSlope() {
    return {kPublishedFitSlope, false, "3.45"};
}
PublishedValue publishedFitIntercept() {
    return {kPublishedFitIntercept, false, "2.1"};
}
PublishedValue publishedUnbalancedForce() {
    return {kPublishedUnbalancedForceMax, true, "< 0.4 %"};
}

Comparison compare(const Scatter& measured, const PublishedValue& published) {
    Comparison c;
    c.difference = measured.mean - published.value;
    const double band = 2.0 * measured.sd;
    if (published.upperBound) {
        c.agrees = measured.mean < published.value;
        c.beyondScatter = measured.mean - band >= published.value;
    } else {
        c.beyondScatter = !(std::abs(c.difference) <= band);
        c.agrees = !c.beyondScatter;
    }
    return c;
}

namespace {

/// A headline value that is one of the test's shear metrics.
template <std::optional<double> ShearMetrics::*Field>
std::optional<double> shearMetric(const SeriesTable& t, double p) {
    return shearMetrics(t, p).*Field;
}

/// A headline value that is a coefficient of the test's fit of Z̄ on N_v/N_vi.
template <double LinearFit::*Field>
std::optional<double> fitCoefficient(const SeriesTable& t, double) {
    const auto f = fitOfTest(t);
    return f ? std::optional<double>((*f).*Field) : std::nullopt;
}

} // namespace

std::vector<HeadlineRow> headlineTable(const std::vector<ReportRun>& runs) {
    const std::vector<TestKey> keys = testsOf(runs);
    using Extract = std::optional<double> (*)(const SeriesTable&, double);
    struct Spec {
        const char* key;
        const char* label;
        const char* unit;
        Extract value;
        std::optional<PublishedValue> published;
    };
    const Spec specs[] = {
        {"e_compacted", "e after compaction", "-", shearMetric<&ShearMetrics::voidRatioAtStart>,
         publishedVoidRatio()},
        {"peak_q_over_p", "peak q/p", "-", shearMetric<&ShearMetrics::peakStressRatio>, {}},
        {"phi_at_peak", "φ at peak", "deg", shearMetric<&ShearMetrics::peakFrictionAngle>, {}},
        {"eps1_at_peak", "ε1 at peak", "-", shearMetric<&ShearMetrics::peakAxialStrain>, {}},
        {"epsv_at_10pc",
         "εv at ε1 = 10 %",
         "-",
         [](const SeriesTable& t, double p) { return shearMetrics(t, p).volumetricStrainAt[2]; },
         {}},
        {"Z_eff_minus_Z",
         "Z̄ − Z averaged over shear",
         "-",
         [](const SeriesTable& t, double) { return meanDifference(t, "Z_eff", "Z"); },
         {}},
        {"Nv_over_Nvi_at_10pc",
         "N_v/N_vi at ε1 = 10 %",
         "-",
         shearMetric<&ShearMetrics::voidCountRatioAt10>,
         {}},
        {"fit_slope", "slope of Z̄ on N_v/N_vi", "-", fitCoefficient<&LinearFit::slope>,
         publishedFitSlope()},
        {"fit_intercept", "intercept of Z̄ on N_v/N_vi", "-", fitCoefficient<&LinearFit::intercept>,
         publishedFitIntercept()},
        {"I_uf_mean", "mean I_uf during shear", "%",
         shearMetric<&ShearMetrics::meanUnbalancedForce>, publishedUnbalancedForce()},
        {"lateral_stress_error_max",
         "largest lateral-stress error",
         "-",
         shearMetric<&ShearMetrics::maxLateralStressError>,
         {}},
    };
    std::vector<HeadlineRow> rows;
    for (const Spec& spec : specs) {
        HeadlineRow row{spec.key, spec.label, spec.unit, {}, spec.published};
        for (const TestKey& key : keys) {
            std::vector<std::optional<double>> values;
            for (const auto& [table, pressure] : tablesOf(runs, key.test)) {
                values.push_back(spec.value(*table, pressure));
            }
            row.values.push_back({key.test, key.pressure, scatterOf(values)});
        }
        rows.push_back(std::move(row));
    }
    return rows;
}

PooledFitScatter pooledFitOverRuns(const std::vector<ReportRun>& runs) {
    std::vector<double> slopes, intercepts, r2s;
    for (const ReportRun& r : runs) {
        std::vector<double> x, y;
        for (const SeriesTable& t : r.tests) {
            if (isMonotonicTable(t)) {
                appendFitRecords(t, x, y);
            }
        }
        if (const auto fit = fitLine(x, y)) {
            slopes.push_back(fit->slope);
            intercepts.push_back(fit->intercept);
            r2s.push_back(fit->r2);
        }
    }
    return {scatterOf(slopes), scatterOf(intercepts), scatterOf(r2s)};
}

} // namespace grainlab
