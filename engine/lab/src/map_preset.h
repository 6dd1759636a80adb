#pragma once
// What the stability maps' presets and cell results (stability_map, servo_map, geometry_map)
// share: the preset's name and description, its required axes, the grains of the sample the
// time-step and servo maps compact, what every cell result holds and its timing, and how numbers
// are written in ids and tables. Internal to the lab library.

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "grainlab/map_sample.h"
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

/// Parses a preset's text (`file` names it in messages): the top object, whose keys are kind,
/// name, description and `keys`; its kind, `kind` (when absent `defaultKind`, or refused when
/// there is none); its name; then the map's own keys (`readOwn(file, top, spec)`).
template <class Spec>
Spec parsePreset(const std::string& text, const std::string& file, const std::string& kind,
                 const std::optional<std::string>& defaultKind, std::vector<std::string> keys,
                 void (*readOwn)(const std::string& file, const JsonSection& top, Spec& spec)) {
    const Json root = parseStrictJson(text, file);
    Spec spec;
    spec.sourceText = text;
    keys.insert(keys.begin(), {"kind", "name", "description"});
    const JsonSection top(file, root, "", std::move(keys));
    top.choice("kind", {kind}, defaultKind);
    spec.name = presetName(top, spec.name);
    readOwn(file, top, spec);
    return spec;
}

/// The axis `key` of `axes`: a non-empty array of numbers in `range`, required.
std::vector<double> requiredNumbers(const JsonSection& axes, const std::string& key, Range range);

/// Reads the grains of a compacted sample's scene (grains, smallest_width, largest_width,
/// size_classes, seed) into `spec`, whose values are the defaults.
void readSampleGrains(const JsonSection& scene, CompactedSampleMapSpec& spec);

/// The bisected limit in a cell result's JSON: bracketed, limit, limit_low, limit_high and
/// probes (the detector's fields are written beside it by the time-step map).
void writeLimit(Json& j, const StepLimit& limit);
void readLimit(const Json& j, StepLimit& limit);

/// A cell result (a StabilityCellResult or a ServoCellResult) as JSON text: the fields every map
/// writes (cell, the limit, compaction_calm, seconds), then the map's own (`writeOwn(j)`).
template <class Result, class WriteOwn>
std::string cellResultText(const Result& r, WriteOwn writeOwn) {
    Json j;
    j["cell"] = r.cell.id;
    writeLimit(j, r.limit);
    j["compaction_calm"] = r.compactionCalm;
    j["seconds"] = r.seconds;
    writeOwn(j);
    return j.dump(2) + "\n";
}

/// The cell result in `text`: the fields every map writes, then the map's own
/// (`readOwn(j, r)`). An `Error` on the way becomes std::runtime_error naming `sourceName` and
/// the map (`what`).
template <class Result, class Error, class ReadOwn>
Result parseCellResultText(const std::string& text, const std::string& sourceName, const char* what,
                           ReadOwn readOwn) {
    try {
        const Json j = Json::parse(text);
        Result r;
        r.cell.id = j.at("cell").get<std::string>();
        readLimit(j, r.limit);
        r.compactionCalm = j.at("compaction_calm").get<bool>();
        r.seconds = j.at("seconds").get<double>();
        readOwn(j, r);
        return r;
    } catch (const Error& e) {
        throw std::runtime_error(
            fmt::format("{}: not a {} cell result: {}", sourceName, what, e.what()));
    }
}

/// A cell measured by `measure(out)`, `out.cell` set before and its wall time in `out.seconds`.
template <class Result, class Cell, class Measure>
Result timedCell(const Cell& cell, Measure measure) {
    const auto start = std::chrono::steady_clock::now();
    Result out;
    out.cell = cell;
    measure(out);
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

} // namespace grainlab::map_preset
