// Steady-state criterion, critical stress ratio and critical state line (critical_state.h).
#include "grainlab/critical_state.h"

#include <cmath>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>

#include "grainlab/report_data.h"

namespace grainlab {

namespace {

/// Least-squares slope dy/dx of the points (x, y); 0 when every x is the same.
double slopeOf(const std::vector<double>& x, const std::vector<double>& y) {
    const std::optional<LinearFit> fit = fitLine(x, y);
    return fit ? fit->slope : 0.0;
}

} // namespace

SteadyStateResult steadyState(const std::vector<double>& eps1, const std::vector<double>& q,
                              const std::vector<double>& p, const std::vector<double>& epsV,
                              const SteadyStateCriterion& criterion) {
    SteadyStateResult r;
    const std::size_t n = eps1.size();
    if (q.size() != n || p.size() != n || epsV.size() != n) {
        throw std::invalid_argument("steady state: series of unequal length");
    }
    if (n == 0 || std::fabs(eps1.back() - eps1.front()) < criterion.window) {
        r.reason =
            fmt::format("the test spans less than the window of {} axial strain", criterion.window);
        return r;
    }
    std::size_t begin = n - 1;
    while (begin > 0 && std::fabs(eps1.back() - eps1[begin - 1]) <= criterion.window) {
        --begin;
    }
    r.samples = n - begin;
    if (r.samples < 3) {
        r.reason = "fewer than 3 records in the window";
        return r;
    }
    const std::vector<double> e(eps1.begin() + long(begin), eps1.end());
    const std::vector<double> qw(q.begin() + long(begin), q.end());
    const std::vector<double> vw(epsV.begin() + long(begin), epsV.end());
    double meanP = 0;
    for (std::size_t i = begin; i < n; ++i) {
        meanP += p[i];
    }
    meanP /= double(r.samples);
    if (!(meanP > 0.0)) {
        r.reason = "the mean stress p over the last window is not positive";
        return r;
    }
    r.stressSlope = slopeOf(e, qw) / meanP;
    r.volumeSlope = slopeOf(e, vw);
    if (!(std::fabs(r.stressSlope) < criterion.maxStressSlope)) {
        r.reason = fmt::format("|dq/deps1| / p = {:.3g} over the last window, above {}",
                               std::fabs(r.stressSlope), criterion.maxStressSlope);
    } else if (!(std::fabs(r.volumeSlope) < criterion.maxVolumeSlope)) {
        r.reason = fmt::format("|deps_v/deps1| = {:.3g} over the last window, above {}",
                               std::fabs(r.volumeSlope), criterion.maxVolumeSlope);
    } else {
        r.steady = true;
    }
    return r;
}

double CriticalStateLine::voidRatioAt(double p) const {
    return eGamma - lambda * std::log(p);
}

std::string CriticalStateLine::equation() const {
    return fmt::format("e = {:.4g} - {:.4g} ln(p'/1 Pa)", eGamma, lambda);
}

CriticalStateLine fitCriticalStateLine(const std::vector<double>& p, const std::vector<double>& e) {
    if (p.size() != e.size() || p.size() < 2) {
        throw std::invalid_argument(
            "critical state line: needs at least two (p', e) points of equal count");
    }
    std::vector<double> x(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (!(p[i] > 0.0)) {
            throw std::invalid_argument(fmt::format("critical state line: p' = {} <= 0", p[i]));
        }
        x[i] = std::log(p[i]);
    }
    const std::optional<LinearFit> fit = fitLine(x, e);
    if (!fit) {
        throw std::invalid_argument("critical state line: all p' are equal");
    }
    CriticalStateLine line;
    line.points = fit->count;
    line.lambda = -fit->slope;
    line.eGamma = fit->intercept;
    line.rSquared = fit->r2;
    return line;
}

} // namespace grainlab
