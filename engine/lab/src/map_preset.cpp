// See map_preset.h.
#include "map_preset.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace grainlab::map_preset {

std::string shortNumber(double v) {
    return fmt::format("{:.6g}", v);
}

std::string csvNumber(double v) {
    return std::isfinite(v) ? fmt::format("{:.9g}", v) : std::string();
}

std::string presetName(const JsonSection& top, const std::string& fallback) {
    std::string name = top.text("name", fallback);
    if (name.find_first_of("/\\ ") != std::string::npos) {
        top.refuse("name", top.at("name"), "a name without spaces or slashes");
    }
    top.text("description", "-");
    return name;
}

std::vector<double> requiredNumbers(const JsonSection& axes, const std::string& key, Range range) {
    const auto v = axes.numbers(key, range);
    if (!v) {
        axes.missing(key, "a non-empty array of numbers " + range.text());
    }
    return *v;
}

void readSampleGrains(const JsonSection& scene, CompactedSampleMapSpec& spec) {
    spec.grains = int(scene.integer("grains", 16, 20000, spec.grains));
    spec.smallestWidth = scene.number("smallest_width", positive(), spec.smallestWidth);
    spec.largestWidth = scene.number("largest_width", Range{spec.smallestWidth, 1e300, true, true},
                                     std::max(spec.largestWidth, spec.smallestWidth));
    spec.sizeClasses = int(scene.integer("size_classes", 1, 1000, spec.sizeClasses));
    spec.seed = std::uint64_t(scene.integer("seed", 0, std::int64_t(1) << 53, 1));
}

void writeLimit(Json& j, const StepLimit& limit) {
    j["bracketed"] = limit.bracketed;
    j["limit"] = limit.limit;
    j["limit_low"] = limit.low;
    j["limit_high"] = limit.high;
    j["probes"] = limit.probes;
}

void readLimit(const Json& j, StepLimit& limit) {
    limit.bracketed = j.at("bracketed").get<bool>();
    limit.limit = j.at("limit").get<double>();
    limit.low = j.at("limit_low").get<double>();
    limit.high = j.at("limit_high").get<double>();
    limit.probes = j.at("probes").get<int>();
}

} // namespace grainlab::map_preset
