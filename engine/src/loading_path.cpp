// Reading the "test" object of an experiment file, and the cyclic reversal schedules
// (loading_path.h).
#include "grainlab/loading_path.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

#include <fmt/format.h>

namespace grainlab {
namespace {

using Kind = LoadingPath::Kind;

const std::vector<std::string> kKindNames = {"drained",     "constant_volume", "constant_p",
                                             "stress_path", "cyclic",          "probes"};

// The keys each kind may hold besides "kind"; any other known key is refused for that kind.
const std::map<std::string, std::vector<Kind>>& keyKinds() {
    static const std::map<std::string, std::vector<Kind>> keys = [] {
        // The kinds that take each group of keys.
        const std::pair<std::vector<Kind>, std::vector<const char*>> groups[] = {
            {{Kind::StressPath}, {"slope"}},
            {{Kind::Drained, Kind::ConstantVolume, Kind::ConstantP, Kind::StressPath},
             {"direction"}},
            {{Kind::Cyclic},
             {"control", "drainage", "amplitude", "mean", "cycles", "stop_strain_amplitude",
              "stop_pressure_fraction"}},
            {{Kind::Probes}, {"count", "increment", "plane", "start", "start_strain"}},
        };
        std::map<std::string, std::vector<Kind>> out;
        for (const auto& [kinds, names] : groups) {
            for (const char* name : names) {
                out[name] = kinds;
            }
        }
        return out;
    }();
    return keys;
}

// Strains beyond 0.5 leave the regime the cell's affine deformation is meant for.
constexpr double kMaxStrain = 0.5;

} // namespace

bool isMonotonicKind(LoadingPath::Kind kind) {
    return kind != Kind::Cyclic && kind != Kind::Probes;
}

const char* loadingKindName(LoadingPath::Kind kind) {
    return kKindNames[std::size_t(kind)].c_str();
}

namespace {

std::vector<std::string> testKeys() {
    std::vector<std::string> known = {"kind"};
    for (const auto& [key, kinds] : keyKinds()) {
        known.push_back(key);
    }
    return known;
}

LoadingPath readTest(const JsonSection& t);

} // namespace

LoadingPath readLoadingPath(const JsonSection& experiment) {
    return readTest(experiment.child("test", testKeys(), false));
}

std::vector<LoadingPath> readLoadingPaths(const JsonSection& experiment) {
    std::vector<LoadingPath> paths;
    std::vector<std::string> names;
    for (const JsonSection& t : experiment.objects("test", testKeys())) {
        paths.push_back(readTest(t));
        const std::string name = testSuffix(paths.back());
        if (std::find(names.begin(), names.end(), name) != names.end()) {
            t.fail("kind", fmt::format("{}: a second test of the same kind{} (each test of a "
                                       "sample needs its own kind or slope)",
                                       t.path(),
                                       paths.back().kind == Kind::StressPath ? " and slope" : ""));
        }
        names.push_back(name);
    }
    if (paths.empty()) {
        paths.push_back(LoadingPath{});
    }
    return paths;
}

namespace {

/// The kind's part of testSuffix().
std::string kindSuffix(const LoadingPath& path) {
    switch (path.kind) {
    case Kind::Drained:
        return "";
    case Kind::StressPath:
        return fmt::format("-path{:+g}", path.slope);
    default: {
        std::string name = loadingKindName(path.kind);
        std::replace(name.begin(), name.end(), '_', '-');
        return "-" + name;
    }
    }
}

} // namespace

std::string testSuffix(const LoadingPath& path) {
    return kindSuffix(path) + (path.extension ? "-extension" : "");
}

namespace {

LoadingPath readTest(const JsonSection& t) {
    LoadingPath path;
    const std::string kindName = t.choice("kind", kKindNames, "drained");
    path.kind =
        Kind(std::find(kKindNames.begin(), kKindNames.end(), kindName) - kKindNames.begin());
    for (const auto& [key, kinds] : keyKinds()) {
        if (t.has(key) && std::find(kinds.begin(), kinds.end(), path.kind) == kinds.end()) {
            std::string allowed;
            for (Kind k : kinds) {
                allowed += fmt::format("{}\"{}\"", allowed.empty() ? "" : ", ", loadingKindName(k));
            }
            t.fail(key, fmt::format("{} applies to kind{} {} only, not \"{}\"", t.path(key),
                                    kinds.size() > 1 ? "s" : "", allowed, kindName));
        }
    }
    path.extension =
        t.choice("direction", {"compression", "extension"}, "compression") == "extension";
    switch (path.kind) {
    case Kind::StressPath:
        // |a| <= 10 spans the paths between and well beyond drained (0) and constant p (-1);
        // steeper paths reach sigma22 <= 0 within a few percent of axial stress change.
        path.slope = t.number("slope", closed(-10.0, 10.0), std::nullopt);
        break;
    case Kind::Cyclic: {
        path.control = t.choice("control", {"strain", "stress"}, "strain") == "strain"
                           ? LoadingPath::Control::Strain
                           : LoadingPath::Control::Stress;
        path.drainage = t.choice("drainage", {"drained", "constant_volume"}, "drained") == "drained"
                            ? LoadingPath::Drainage::Drained
                            : LoadingPath::Drainage::ConstantVolume;
        if (path.control == LoadingPath::Control::Strain) {
            path.amplitude = t.number("amplitude", openClosed(0.0, kMaxStrain), std::nullopt);
            path.mean = t.number("mean", closed(-kMaxStrain, kMaxStrain), 0.0);
        } else {
            path.amplitude = t.number("amplitude", positive(), std::nullopt);
            path.mean = t.number("mean", Range{}, 0.0);
        }
        path.cycles = t.integer("cycles", 1, 100000, 10);
        if (t.has("stop_strain_amplitude") && path.control == LoadingPath::Control::Strain) {
            t.fail("stop_strain_amplitude",
                   fmt::format("{} applies to control \"stress\" only: under strain control the "
                               "amplitude is imposed",
                               t.path("stop_strain_amplitude")));
        }
        if (t.has("stop_strain_amplitude")) {
            path.stopStrainAmplitude =
                t.number("stop_strain_amplitude", openClosed(0.0, kMaxStrain), std::nullopt);
        } else if (path.control == LoadingPath::Control::Stress) {
            // A bound of q the sample cannot reach would strain it without end.
            path.stopStrainAmplitude = kMaxStrain;
        }
        if (t.has("stop_pressure_fraction")) {
            path.stopPressureFraction =
                t.number("stop_pressure_fraction", open(0.0, 1.0), std::nullopt);
        }
        break;
    }
    case Kind::Probes: {
        path.probeCount = t.integer("count", 4, 360, 16);
        if (path.probeCount % 2 != 0) {
            t.refuse("count", t.at("count"), "an even integer in [4, 360]");
        }
        path.increment = t.number("increment", openClosed(0.0, 0.01), 1e-4);
        path.plane = t.choice("plane", {"strain", "stress"}, "strain") == "strain"
                         ? LoadingPath::Plane::Strain
                         : LoadingPath::Plane::Stress;
        const std::string start = t.choice("start", {"strain", "peak", "end"}, "end");
        path.start = start == "strain" ? LoadingPath::Start::Strain
                     : start == "peak" ? LoadingPath::Start::Peak
                                       : LoadingPath::Start::End;
        if (path.start == LoadingPath::Start::Strain) {
            path.startStrain = t.number("start_strain", openClosed(0.0, kMaxStrain), std::nullopt);
        } else if (t.has("start_strain")) {
            t.fail("start_strain", fmt::format("{} applies to start \"strain\" only, not \"{}\"",
                                               t.path("start_strain"), start));
        }
        break;
    }
    default:
        break;
    }
    return path;
}

} // namespace

CyclicStrainSchedule::CyclicStrainSchedule(double eps0, double mean, double amplitude,
                                           double strainPerStep)
    : eps0_(eps0), d_(strainPerStep) {
    if (!(amplitude > 0.0) || !(strainPerStep > 0.0) || !(strainPerStep <= amplitude) ||
        !std::isfinite(eps0) || !std::isfinite(mean) || !std::isfinite(amplitude)) {
        throw std::invalid_argument(fmt::format(
            "cyclic strain: amplitude {} and strain per step {} must satisfy 0 < d <= amplitude",
            amplitude, strainPerStep));
    }
    const double toPeak = mean + amplitude - eps0;
    first_ = std::llround(std::fabs(toPeak) / d_);
    firstDirection_ = toPeak >= 0.0 ? 1 : -1;
    half_ = std::max<std::int64_t>(1, std::llround(2.0 * amplitude / d_));
}

std::int64_t CyclicStrainSchedule::stepCount(std::int64_t n) const {
    if (n <= first_) {
        return firstDirection_ * n;
    }
    const std::int64_t peak = firstDirection_ * first_;
    const std::int64_t m = n - first_;
    const std::int64_t leg = m / half_;
    const std::int64_t into = m % half_;
    return leg % 2 == 0 ? peak - into : peak - half_ + into;
}

int CyclicStrainSchedule::direction(std::int64_t n) const {
    if (n < first_) {
        return firstDirection_;
    }
    return ((n - first_) / half_) % 2 == 0 ? -1 : 1;
}

std::int64_t CyclicStrainSchedule::cyclesCompleted(std::int64_t n) const {
    return n <= first_ ? 0 : (n - first_) / (2 * half_);
}

int cyclicStressDirection(double q, int direction, double qMin, double qMax) {
    if (direction > 0 && q >= qMax) {
        return -1;
    }
    if (direction < 0 && q <= qMin) {
        return 1;
    }
    return direction;
}

} // namespace grainlab
