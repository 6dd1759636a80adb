#pragma once
// What the stability maps' presets and cell results (stability_map, servo_map, geometry_map)
// share: the preset's name and description, its required axes, the grains of the sample the
// time-step and servo maps compact, the bisected limit in a cell result, and how numbers are
// written in ids and tables. Internal to the lab library.

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "grainlab/stability_bisection.h"
#include "grainlab/strict_json.h"

namespace grainlab::map_preset {

/// A number short and exact enough for ids and labels: 0.05, 15, 1e+05.
std::string shortNumber(double v);

/// A CSV number: round-trip precision; empty for a non-finite value (never "nan" in a table).
std::string csvNumber(double v);

/// Reads the preset file at `path` with `parse` (the map's own reader) and records the path.
template <class Spec>
Spec readPresetFile(const std::string& path,
                    Spec (*parse)(const std::string& text, const std::string& file)) {
    Spec spec = parse(readInputFile(path, "stability preset"), path);
    spec.sourcePath = path;
    return spec;
}

/// Reads the preset's "name" (no spaces or slashes: it names a folder) and checks its free
/// "description"; returns the name, `fallback` when absent.
std::string presetName(const JsonSection& top, const std::string& fallback);

/// The axis `key` of `axes`: a non-empty array of numbers in `range`, required.
std::vector<double> requiredNumbers(const JsonSection& axes, const std::string& key, Range range);

/// Reads the grains of a compacted sample's scene (grains, smallest_width, largest_width,
/// size_classes, seed) into `spec`, a StabilityMapSpec or a ServoMapSpec, whose values are the
/// defaults.
template <class Spec>
void readSampleGrains(const JsonSection& scene, Spec& spec) {
    spec.grains = int(scene.integer("grains", 16, 20000, spec.grains));
    spec.smallestWidth = scene.number("smallest_width", positive(), spec.smallestWidth);
    spec.largestWidth = scene.number("largest_width", Range{spec.smallestWidth, 1e300, true, true},
                                     std::max(spec.largestWidth, spec.smallestWidth));
    spec.sizeClasses = int(scene.integer("size_classes", 1, 1000, spec.sizeClasses));
    spec.seed = std::uint64_t(scene.integer("seed", 0, std::int64_t(1) << 53, 1));
}

/// The bracket of a bisected limit in a cell result's JSON: bracketed, limit, limit_low and
/// limit_high (the probe count and the detector's fields are written beside it by each map).
void writeBracket(Json& j, const StepLimit& limit);
void readBracket(const Json& j, StepLimit& limit);

} // namespace grainlab::map_preset
