#pragma once
// Statistics over repeated runs: the scatter of a number over seeds, curves sampled on a common
// axis, their mean with a band, and the RMS difference between two curves. Plain computations on
// plain numbers, used by the many-run commands (study, stability maps, report), the window and
// the tests alike; no state, any thread.
//
// A difference between two settings means something only against the seed-to-seed scatter: the
// "noise" test here is |Δ| <= 2 σ of the reference seeds.

#include <optional>
#include <vector>

namespace grainlab {

/// Mean and sample standard deviation of a set of values.
struct Scatter {
    double mean = 0; ///< arithmetic mean
    double sd = 0;   ///< sample standard deviation (n - 1 in the denominator); 0 when n < 2
    int count = 0;   ///< n
};

/// The scatter of `values`; count 0 (mean and sd 0) for an empty set.
Scatter scatterOf(const std::vector<double>& values);
/// The scatter of the values that are present (missing ones are skipped).
Scatter scatterOf(const std::vector<std::optional<double>>& values);

/// True when `difference` is within the noise of a reference with scatter `reference`:
/// |difference| <= factor * reference.sd (factor 2 by default). A reference of one seed has no
/// scatter, so only an exact zero is within its noise.
bool withinNoise(double difference, const Scatter& reference, double factor = 2.0);

/// A curve y(x) given at increasing x (e.g. q/p against eps1). x must not decrease.
struct Curve {
    std::vector<double> x;
    std::vector<double> y;
};

/// y at `x` by linear interpolation between the bracketing points; nothing when `x` lies
/// outside [x.front(), x.back()] or the curve is empty. Equal x values: the last point counts.
std::optional<double> valueAt(const Curve& curve, double x);

/// `count` evenly spaced points from `from` to `to`, both included (count >= 2).
std::vector<double> evenlySpaced(double from, double to, int count);

/// The mean curve of several curves on the common axis `grid` with the sample standard
/// deviation at each point: the ±1σ band of a curve over seeds. Grid points that some curve
/// does not reach use the curves that do (count says how many).
struct CurveBand {
    std::vector<double> x;
    std::vector<double> mean;
    std::vector<double> sd;
    std::vector<int> count;
};
CurveBand meanCurve(const std::vector<Curve>& curves, const std::vector<double>& grid);

/// Root-mean-square difference of `curve` from `reference` over the grid points both reach:
/// sqrt(mean over x of (y(x) - y_ref(x))^2). Nothing when they share no grid point.
std::optional<double> rmsDifference(const Curve& curve, const Curve& reference,
                                    const std::vector<double>& grid);

} // namespace grainlab
