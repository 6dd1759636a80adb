#pragma once
// The loading path of a test: what axis x2 does while axis x1 is strained (drained, constant
// volume, constant mean stress, linear stress path), cyclic loading and stress probes, as read
// from the "test" object of an experiment file; and the reversal schedule of a strain-controlled
// cyclic test. Value types and pure functions: the experiment reader builds a LoadingPath, the
// runner's stages read it; safe on any thread. Simple shear would be one more Kind.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "grainlab/strict_json.h"

namespace grainlab {

struct LoadingPath {
    enum class Kind {
        Drained,        ///< sigma22 held at the confining pressure (the default)
        ConstantVolume, ///< the cell's area held exactly (the undrained analogue)
        ConstantP,      ///< sigma22 servoed so that p = (sigma11 + sigma22) / 2 stays
        StressPath,     ///< sigma22 = sigma22_0 + slope (sigma11 - sigma11_0)
        Cyclic,         ///< eps1 or q cycled about a mean
        Probes,         ///< small increments in evenly spread directions from one state
    };
    enum class Control { Strain, Stress }; ///< what a cyclic test cycles
    enum class Drainage { Drained, ConstantVolume };
    enum class Plane { Strain, Stress };    ///< the plane of the probe directions
    enum class Start { Strain, Peak, End }; ///< where probes start in the parent test

    Kind kind = Kind::Drained;
    double slope = 0; ///< a = d sigma22 / d sigma11, StressPath [-]
    /// Drained, ConstantVolume, ConstantP, StressPath: axis 1 lengthened (eps1 < 0) instead of
    /// shortened, at the same strain per step.
    bool extension = false;

    // Cyclic.
    Control control = Control::Strain;
    Drainage drainage = Drainage::Drained;
    double amplitude = 0;     ///< eps1 amplitude [-] (strain control) or q amplitude [Pa] (stress)
    double mean = 0;          ///< mean eps1 [-] (strain control) or mean q [Pa] (stress control)
    std::int64_t cycles = 10; ///< stop after this many cycles
    /// Stress control: stop when |eps1| exceeds it (0.5 when the file gives none) [-]
    std::optional<double> stopStrainAmplitude;
    std::optional<double> stopPressureFraction; ///< stop when p' < fraction p0 [-]

    // Probes.
    std::int64_t probeCount = 16; ///< K directions, even so that each has its opposite
    /// |d eps| (strain plane) or |d sigma| / p at the start (stress plane) [-]
    double increment = 1e-4;
    Plane plane = Plane::Strain;
    Start start = Start::End;
    double startStrain = 0; ///< eps1 of the start state, Start::Strain [-]
};

/// The name of a kind as written in files: "drained", "constant_volume", ...
const char* loadingKindName(LoadingPath::Kind kind);
/// A test that loads one way to its target strain (drained, constant volume, constant p, a
/// stress path), in compression or extension; not cyclic, not probes.
bool isMonotonicKind(LoadingPath::Kind kind);

/// Reads the optional "test" object of `experiment` (a section that lists "test" among its
/// keys). Absent: a drained test, exactly the behaviour of a file without it. Refuses unknown
/// keys, keys of another kind, and values out of range, naming the file, the key and the range.
LoadingPath readLoadingPath(const JsonSection& experiment);
/// Reads "test" as one object or a list of them (the tests each sample gets, in order); one
/// drained test when absent. Refuses two tests of one name (testSuffix()).
std::vector<LoadingPath> readLoadingPaths(const JsonSection& experiment);
/// What a test adds to its sample's series name ("p015kPa"): "" for the drained test,
/// "-constant-volume", "-constant-p", "-path-0.5" (a stress path of slope -0.5), "-cyclic", ...;
/// a test in extension adds "-extension" ("-extension", "-constant-volume-extension").
std::string testSuffix(const LoadingPath& path);

/// The triangular eps1 waveform of a strain-controlled cyclic test, on the grid of a constant
/// strain per step d: from eps0 to the upper peak mean + amplitude, then between the peaks. Peaks
/// fall on whole step counts (the first leg's and the half-cycle's counts are rounded), so the
/// stage reverses the axis-x1 rate at exact steps and eps1 at step n is eps0 + d s(n) with s an
/// integer: no strain accumulates off the waveform. Compression positive.
class CyclicStrainSchedule {
public:
    /// Refuses amplitude <= 0, d <= 0 or d > amplitude (std::invalid_argument).
    CyclicStrainSchedule(double eps0, double mean, double amplitude, double strainPerStep);

    std::int64_t firstLegSteps() const { return first_; } ///< steps to the first (upper) peak
    std::int64_t halfCycleSteps() const { return half_; } ///< steps from one peak to the other
    /// Step index of reversal k (k = 0: the first upper peak; odd k: lower peaks).
    std::int64_t reversalStep(std::int64_t k) const { return first_ + k * half_; }
    /// Reversals at steps <= n; reversalStep(reversalsBy(n)) is the next one after n.
    std::int64_t reversalsBy(std::int64_t n) const {
        return n < first_ ? 0 : (n - first_) / half_ + 1;
    }
    /// True when the strain turns at step n.
    bool isReversal(std::int64_t n) const { return n >= first_ && (n - first_) % half_ == 0; }
    /// Signed step count s(n): eps1(n) = eps0 + d s(n).
    std::int64_t stepCount(std::int64_t n) const;
    double strainAt(std::int64_t n) const { return eps0_ + d_ * double(stepCount(n)); }
    /// +1 when the step from n to n + 1 compresses (eps1 grows), -1 when it extends.
    int direction(std::int64_t n) const;
    /// Whole cycles completed at step n (a cycle: upper peak to upper peak).
    std::int64_t cyclesCompleted(std::int64_t n) const;
    /// The peaks actually reached, on the step grid.
    double upperPeak() const { return strainAt(first_); }
    double lowerPeak() const { return strainAt(first_ + half_); }

private:
    double eps0_, d_;
    std::int64_t first_ = 0, half_ = 1;
    int firstDirection_ = 1;
};

/// Stress-controlled cycling: the direction of eps1 for the next step given the current q and
/// direction (+1 compressing). Reverses to -1 when q >= qMax while compressing and to +1 when
/// q <= qMin while extending; otherwise keeps the direction.
int cyclicStressDirection(double q, int direction, double qMin, double qMax);

} // namespace grainlab
