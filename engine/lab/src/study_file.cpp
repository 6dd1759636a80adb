#include "grainlab/study_file.h"

#include <algorithm>
#include <filesystem>
#include <set>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "grainlab/experiment_file.h"
#include "grainlab/shear_metrics.h"
#include "grainlab/strict_json.h"
#include "grainlab/study_summary.h"

namespace grainlab {
namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kTopKeys = {"name",    "description", "base",  "knobs",
                                           "design",  "reference",   "seeds", "cost",
                                           "metrics", "deciding"};

std::vector<std::string> knobNames() {
    std::vector<std::string> out;
    for (KnobKind k : allKnobs()) {
        out.push_back(knobName(k));
    }
    return out;
}

bool isCurveMetric(const std::string& name) {
    return name == kCurveMetrics[0] || name == kCurveMetrics[1];
}

/// The default tolerances (docs/study-file.md).
std::map<std::string, Tolerance> defaultTolerances() {
    std::map<std::string, Tolerance> t;
    t["peak_q_over_p"] = {0.03, true};
    for (const char* m : {"q_over_p_at_2pc", "q_over_p_at_5pc", "q_over_p_at_10pc"}) {
        t[m] = {0.03, true};
    }
    for (const char* m : {"epsv_at_2pc", "epsv_at_5pc", "epsv_at_10pc"}) {
        t[m] = {0.002, false};
    }
    t["e_compacted"] = {0.005, false};
    t["Z_at_5pc"] = {0.05, false};
    t["Z_at_10pc"] = {0.05, false};
    t["Z_eff_at_10pc"] = {0.05, false};
    t["rms_q_over_p"] = {0.02, false};
    t["rms_epsv"] = {0.002, false};
    return t;
}

/// One level of knob `kind`: the JSON value `v` at key path `path` (e.g. "knobs.damping[1]").
KnobLevel readLevel(const std::string& file, const std::string& path, const Json& v,
                    KnobKind kind) {
    const auto refuse = [&](const std::string& allowed) {
        throw JsonFileError(file, path,
                            fmt::format("{} = {}: must be {}", path, showValue(v), allowed));
    };
    const auto number = [&](Range range) {
        if (!v.is_number()) {
            refuse(fmt::format("a number {} (got {})", range.text(), jsonTypeName(v)));
        }
        const double x = v.get<double>();
        if (!std::isfinite(x) || !range.contains(x)) {
            refuse("a number " + range.text());
        }
        return KnobLevel{x, ""};
    };
    const auto integer = [&](double lo, double hi) {
        if (!v.is_number() || std::floor(v.get<double>()) != v.get<double>() ||
            v.get<double>() < lo || v.get<double>() > hi) {
            refuse(fmt::format("an integer in [{}, {}]", lo, hi));
        }
        return KnobLevel{v.get<double>(), ""};
    };
    const auto object = [&](std::vector<std::string> keys, const char* example) {
        if (!v.is_object()) {
            refuse(fmt::format("an object like {} (got {})", example, jsonTypeName(v)));
        }
        return JsonSection(file, v, path, std::move(keys));
    };
    switch (kind) {
    case KnobKind::TimeStepFraction:
    case KnobKind::InertialNumber:
    case KnobKind::NeighbourSkin:
        return number(openClosed(0.0, 1.0));
    case KnobKind::AxialStrainPerStep:
        return number(openClosed(0.0, 0.01));
    case KnobKind::GrainCount:
        return integer(2, 1e6);
    case KnobKind::Threads:
        return integer(1, 64);
    case KnobKind::Damping: {
        const JsonSection d = object({"kind", "coefficient"}, "{\"kind\": \"none\"}");
        const std::string k =
            d.choice("kind", {"none", "global_viscous", "cundall_local"}, std::nullopt);
        Json out = {{"kind", k}};
        if (k == "none") {
            if (d.has("coefficient")) {
                d.fail("coefficient", fmt::format("{} is not used when the kind is \"none\"; "
                                                  "remove it",
                                                  d.path("coefficient")));
            }
        } else {
            out["coefficient"] = d.number("coefficient", closed(0.0, 1.0), std::nullopt);
        }
        return KnobLevel{0, out.dump()};
    }
    case KnobKind::Shape: {
        const JsonSection s =
            object({"aspect_ratio", "closure", "end_radius_ratio"}, "{\"aspect_ratio\": 1}");
        Json out = {{"aspect_ratio", s.number("aspect_ratio", openClosed(0.0, 1.0), std::nullopt)}};
        if (s.has("closure")) {
            out["closure"] = s.choice("closure", {"equal_area", "end_radius_ratio"}, std::nullopt);
        }
        if (s.has("end_radius_ratio")) {
            out["end_radius_ratio"] = s.number("end_radius_ratio", open(0.0, 0.5), std::nullopt);
        }
        return KnobLevel{0, out.dump()};
    }
    }
    return {};
}

} // namespace

std::vector<std::string> studyMetricNames() {
    std::vector<std::string> out;
    for (const NamedMetric& m : namedMetrics(ShearMetrics{})) {
        out.push_back(m.name);
    }
    for (const char* c : kCurveMetrics) {
        out.push_back(c);
    }
    return out;
}

namespace {

/// The study file's "knobs", in the order of the knob table.
void readStudyKnobs(const JsonSection& top, const std::string& sourceName, StudySpec& spec) {
    const JsonSection knobs =
        top.child("knobs", knobNames(), true, "an object of knobs, each an array of levels");
    if (top.at("knobs").empty()) {
        top.refuse("knobs", top.at("knobs"), "an object with at least one knob");
    }
    for (KnobKind kind : allKnobs()) {
        const std::string name = knobName(kind);
        if (!knobs.has(name)) {
            continue;
        }
        const Json& levels = knobs.at(name);
        if (!levels.is_array() || levels.empty()) {
            knobs.refuse(name, levels, "a non-empty array of levels");
        }
        Knob knob{kind, {}};
        for (std::size_t i = 0; i < levels.size(); ++i) {
            const std::string key = fmt::format("{}[{}]", name, i);
            const KnobLevel level = readLevel(sourceName, knobs.path(key), levels[i], kind);
            if (std::find(knob.levels.begin(), knob.levels.end(), level) != knob.levels.end()) {
                knobs.refuse(key, levels[i], "a level not given before (levels are distinct)");
            }
            knob.levels.push_back(level);
        }
        spec.knobs.push_back(std::move(knob));
    }
}

/// The study file's "seeds": a count or a list.
void readStudySeeds(const JsonSection& top, StudySpec& spec) {
    if (top.has("seeds")) {
        const Json& s = top.at("seeds");
        if (s.is_array()) {
            spec.seeds.clear();
            if (s.empty() || s.size() > 1000) {
                top.refuse("seeds", s, "a count in [1, 1000] or an array of 1 to 1000 seeds");
            }
            for (std::size_t i = 0; i < s.size(); ++i) {
                const std::string key = fmt::format("seeds[{}]", i);
                if (!s[i].is_number_unsigned() && !(s[i].is_number_integer() && s[i] >= 0)) {
                    top.refuse(key, s[i], "an integer >= 0");
                }
                const auto seed = s[i].get<std::uint64_t>();
                if (std::find(spec.seeds.begin(), spec.seeds.end(), seed) != spec.seeds.end()) {
                    top.refuse(key, s[i], "a seed not given before (seeds are distinct)");
                }
                spec.seeds.push_back(seed);
            }
        } else {
            const auto count = top.integer("seeds", 1, 1000, std::nullopt);
            spec.seeds.clear();
            for (std::int64_t k = 1; k <= count; ++k) {
                spec.seeds.push_back(std::uint64_t(k));
            }
        }
    }
}

/// The study file's "metrics" (tolerances: the defaults, each replaced by the file's) and
/// "deciding".
void readStudyTolerances(const JsonSection& top, StudySpec& spec) {
    spec.tolerances = defaultTolerances();
    const std::vector<std::string> metricNames = studyMetricNames();
    const JsonSection metrics = top.child("metrics", metricNames, false);
    for (const std::string& name : metricNames) {
        if (!metrics.has(name)) {
            continue;
        }
        const JsonSection m = metrics.child(name, {"tolerance", "relative"}, true);
        Tolerance t;
        t.value = m.number("tolerance", positive(), std::nullopt);
        if (m.has("relative") && !m.at("relative").is_boolean()) {
            m.refuse("relative", m.at("relative"), "true or false");
        }
        t.relative = m.has("relative") && m.at("relative").get<bool>();
        if (t.relative && isCurveMetric(name)) {
            m.fail("relative", fmt::format("{}: a curve error has no reference value to be "
                                           "relative to; give an absolute tolerance",
                                           m.path("relative")));
        }
        spec.tolerances[name] = t;
    }
    spec.deciding = {"peak_q_over_p", "rms_q_over_p", "rms_epsv"};
    if (top.has("deciding")) {
        const Json& d = top.at("deciding");
        if (!d.is_array() || d.empty()) {
            top.refuse("deciding", d, "a non-empty array of metric names");
        }
        spec.deciding.clear();
        for (std::size_t i = 0; i < d.size(); ++i) {
            const std::string key = fmt::format("deciding[{}]", i);
            if (!d[i].is_string() || std::find(metricNames.begin(), metricNames.end(),
                                               d[i].get<std::string>()) == metricNames.end()) {
                top.refuse(key, d[i], "the name of a metric (docs/study-file.md)");
            }
            const std::string name = d[i];
            if (!spec.tolerances.count(name)) {
                top.refuse(
                    key, d[i],
                    fmt::format("a metric with a tolerance: give metrics.{}.tolerance", name));
            }
            spec.deciding.push_back(name);
        }
    }
}

} // namespace

StudySpec parseStudyText(const std::string& text, const std::string& sourceName,
                         const std::string& folder) {
    const Json root = parseStrictJson(text, sourceName);
    const JsonSection top(sourceName, root, "", kTopKeys);
    StudySpec spec;
    spec.sourcePath = sourceName;
    spec.name = top.text("name", "study");
    if (spec.name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                    "0123456789-_.") != std::string::npos) {
        top.refuse("name", root["name"], "a name of letters, digits, '-', '_' and '.'");
    }
    if (top.has("description")) {
        top.text("description", "");
    }

    // The base experiment: a path (relative to the study file) or an object written inline.
    if (!top.has("base")) {
        top.missing("base", "a path to an experiment file, or an experiment object");
    }
    Json inlined = root;
    const Json& base = top.at("base");
    if (base.is_string()) {
        const fs::path p = fs::path(base.get<std::string>());
        const std::string path = (p.is_absolute() ? p : fs::path(folder) / p).string();
        spec.baseExperiment = readInputFile(path, "experiment file");
        spec.baseSource = path;
        inlined["base"] = parseStrictJson(spec.baseExperiment, path);
    } else if (base.is_object()) {
        spec.baseExperiment = base.dump(2);
        spec.baseSource = sourceName + ": base";
    } else {
        top.refuse("base", base,
                   fmt::format("a path to an experiment file, or an experiment object (got {})",
                               jsonTypeName(base)));
    }
    try {
        parseExperimentText(spec.baseExperiment, spec.baseSource);
    } catch (const ExperimentFileError& e) {
        throw ExperimentFileError(sourceName, "base." + e.keyPath,
                                  fmt::format("base experiment: {}", e.what()));
    }

    readStudyKnobs(top, sourceName, spec);

    spec.design =
        top.choice("design", {"one_at_a_time", "grid"}, std::string("one_at_a_time")) == "grid"
            ? StudyDesign::Grid
            : StudyDesign::OneAtATime;
    const JsonSection reference = top.child("reference", knobNames(), false);
    for (KnobKind kind : allKnobs()) {
        const std::string name = knobName(kind);
        if (reference.has(name)) {
            spec.reference[kind] =
                readLevel(sourceName, reference.path(name), reference.at(name), kind);
        }
    }

    readStudySeeds(top, spec);
    spec.costMeasure = top.choice("cost", {"cpu_seconds", "wall_seconds", "grain_steps"},
                                  std::string("cpu_seconds"));

    readStudyTolerances(top, spec);
    spec.sourceText = inlined.dump(2) + "\n";
    return spec;
}

StudySpec readStudyFile(const std::string& path) {
    const std::string text = readInputFile(path, "study file");
    return parseStudyText(text, path, fs::path(path).parent_path().string());
}

} // namespace grainlab
