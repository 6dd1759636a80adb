#include "grainlab/experiment_file.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <optional>
#include <set>
#include <sstream>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "grainlab/oval_shape.h"
#include "grainlab/time_step.h"

namespace grainlab {

ExperimentFileError::ExperimentFileError(std::string file_, std::string keyPath_,
                                         const std::string& message)
    : std::runtime_error(file_ + ": " + message), file(std::move(file_)),
      keyPath(std::move(keyPath_)) {}

namespace {

using Json = nlohmann::json;

constexpr double kInf = std::numeric_limits<double>::infinity();

/// An interval of allowed real values; infinite ends mean unbounded.
struct Range {
    double lo = -kInf;
    double hi = kInf;
    bool loClosed = false;
    bool hiClosed = false;

    bool contains(double v) const {
        const bool aboveLo = loClosed ? v >= lo : v > lo;
        const bool belowHi = hiClosed ? v <= hi : v < hi;
        return aboveLo && belowHi;
    }
    std::string text() const {
        if (hi == kInf) {
            return fmt::format("{} {}", loClosed ? ">=" : ">", lo);
        }
        return fmt::format("in {}{}, {}{}", loClosed ? "[" : "(", lo, hi, hiClosed ? "]" : ")");
    }
};

Range positive() {
    return {0.0, kInf, false, false};
}
Range nonNegative() {
    return {0.0, kInf, true, false};
}
Range openClosed(double lo, double hi) {
    return {lo, hi, false, true};
}
Range open(double lo, double hi) {
    return {lo, hi, false, false};
}
Range closed(double lo, double hi) {
    return {lo, hi, true, true};
}

std::string joinPath(const std::string& parent, const std::string& key) {
    return parent.empty() ? key : parent + "." + key;
}

/// The value as written in JSON, shortened for messages.
std::string showValue(const Json& v) {
    std::string s = v.dump();
    if (s.size() > 60) {
        s = s.substr(0, 57) + "...";
    }
    return s;
}

std::string jsonTypeName(const Json& v) {
    switch (v.type()) {
    case Json::value_t::null:
        return "null";
    case Json::value_t::boolean:
        return "a boolean";
    case Json::value_t::string:
        return "a string";
    case Json::value_t::array:
        return "an array";
    case Json::value_t::object:
        return "an object";
    default:
        return "a number";
    }
}

std::size_t editDistance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) {
        row[j] = j;
    }
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
            diagonal = above;
        }
    }
    return row[b.size()];
}

/// One JSON object of the file with its key path and the keys it may hold. Every getter names
/// the file, the key path, the value and the allowed range when it refuses.
class Section {
public:
    Section(const std::string& file, const Json& node, std::string path,
            std::vector<std::string> known)
        : file_(file), node_(node), path_(std::move(path)), known_(std::move(known)) {
        if (!node_.is_object()) {
            throw ExperimentFileError(file_, path_,
                                      fmt::format("{} = {}: must be an object {{...}} (got {})",
                                                  path_, showValue(node_), jsonTypeName(node_)));
        }
        for (const auto& item : node_.items()) {
            if (std::find(known_.begin(), known_.end(), item.key()) == known_.end()) {
                refuseUnknown(item.key());
            }
        }
    }

    const std::string& path() const { return path_; }
    std::string path(const std::string& key) const { return joinPath(path_, key); }
    bool has(const std::string& key) const { return node_.contains(key); }
    const Json& at(const std::string& key) const { return node_.at(key); }

    [[noreturn]] void fail(const std::string& key, const std::string& message) const {
        throw ExperimentFileError(file_, path(key), message);
    }
    [[noreturn]] void refuse(const std::string& key, const Json& value,
                             const std::string& allowed) const {
        fail(key, fmt::format("{} = {}: must be {}", path(key), showValue(value), allowed));
    }
    [[noreturn]] void missing(const std::string& key, const std::string& allowed) const {
        fail(key, fmt::format("missing required key {} ({})", path(key), allowed));
    }

    /// A real number in `range`; `fallback` is the default, none means required.
    double number(const std::string& key, Range range, std::optional<double> fallback) const {
        const std::string allowed = "a number " + range.text();
        if (!has(key)) {
            if (!fallback) {
                missing(key, allowed);
            }
            return *fallback;
        }
        const Json& v = at(key);
        if (!v.is_number()) {
            refuse(key, v, fmt::format("{} (got {})", allowed, jsonTypeName(v)));
        }
        const double x = v.get<double>();
        if (!std::isfinite(x) || !range.contains(x)) {
            refuse(key, v, allowed);
        }
        return x;
    }

    /// An integer in [lo, hi]; an exactly integral real such as 2e6 is accepted.
    std::int64_t integer(const std::string& key, std::int64_t lo, std::int64_t hi,
                         std::optional<std::int64_t> fallback) const {
        // Bounds that only keep the value representable are not worth a reader's attention.
        const std::string allowed = hi == std::numeric_limits<std::int64_t>::max()
                                        ? fmt::format("an integer >= {}", lo)
                                    : hi >= std::numeric_limits<std::int32_t>::max()
                                        ? fmt::format("an integer >= {} (at most {})", lo, hi)
                                        : fmt::format("an integer in [{}, {}]", lo, hi);
        if (!has(key)) {
            if (!fallback) {
                missing(key, allowed);
            }
            return *fallback;
        }
        const Json& v = at(key);
        std::int64_t n = 0;
        if (v.is_number_unsigned()) {
            const auto u = v.get<std::uint64_t>();
            if (u > static_cast<std::uint64_t>(hi)) {
                refuse(key, v, allowed);
            }
            n = static_cast<std::int64_t>(u);
        } else if (v.is_number_integer()) {
            n = v.get<std::int64_t>();
        } else if (v.is_number_float()) {
            const double x = v.get<double>();
            // Exact integers only; the bound keeps the conversion defined.
            if (!(std::fabs(x) < 9.0e18) || std::floor(x) != x) {
                refuse(key, v, allowed);
            }
            n = static_cast<std::int64_t>(x);
        } else {
            refuse(key, v, fmt::format("{} (got {})", allowed, jsonTypeName(v)));
        }
        if (n < lo || n > hi) {
            refuse(key, v, allowed);
        }
        return n;
    }

    /// One of `allowed` (strings).
    std::string choice(const std::string& key, const std::vector<std::string>& allowed,
                       std::optional<std::string> fallback) const {
        std::string list;
        for (const auto& a : allowed) {
            list += (list.empty() ? "" : ", ") + ("\"" + a + "\"");
        }
        const std::string text = "one of " + list;
        if (!has(key)) {
            if (!fallback) {
                missing(key, text);
            }
            return *fallback;
        }
        const Json& v = at(key);
        if (!v.is_string()) {
            refuse(key, v, fmt::format("{} (got {})", text, jsonTypeName(v)));
        }
        const auto s = v.get<std::string>();
        if (std::find(allowed.begin(), allowed.end(), s) == allowed.end()) {
            refuse(key, v, text);
        }
        return s;
    }

    std::string text(const std::string& key, const std::string& fallback) const {
        if (!has(key)) {
            return fallback;
        }
        const Json& v = at(key);
        if (!v.is_string() || v.get<std::string>().empty()) {
            refuse(key, v, fmt::format("a non-empty string (got {})", jsonTypeName(v)));
        }
        return v.get<std::string>();
    }

    /// A non-empty array of real numbers, each in `range`; absent gives nullopt.
    std::optional<std::vector<double>> numbers(const std::string& key, Range range) const {
        if (!has(key)) {
            return std::nullopt;
        }
        const Json& v = at(key);
        const std::string allowed = "a non-empty array of numbers " + range.text();
        if (!v.is_array() || v.empty()) {
            refuse(key, v,
                   fmt::format("{} (got {})", allowed,
                               v.is_array() ? "an empty array" : jsonTypeName(v)));
        }
        std::vector<double> out;
        for (std::size_t i = 0; i < v.size(); ++i) {
            const Json& e = v[i];
            const std::string element = fmt::format("{}[{}]", key, i);
            if (!e.is_number()) {
                refuse(element, e,
                       fmt::format("a number {} (got {})", range.text(), jsonTypeName(e)));
            }
            const double x = e.get<double>();
            if (!std::isfinite(x) || !range.contains(x)) {
                refuse(element, e, "a number " + range.text());
            }
            out.push_back(x);
        }
        return out;
    }

    /// A nested object; absent gives an empty section (all defaults) unless required.
    Section child(const std::string& key, std::vector<std::string> known, bool required,
                  const std::string& requiredWhat = "an object") const {
        static const Json kEmpty = Json::object();
        if (!has(key)) {
            if (required) {
                missing(key, requiredWhat);
            }
            return Section(file_, kEmpty, path(key), std::move(known));
        }
        return Section(file_, at(key), path(key), std::move(known));
    }

private:
    [[noreturn]] void refuseUnknown(const std::string& key) const {
        std::string nearest;
        std::size_t best = std::max<std::size_t>(2, key.size() / 3) + 1;
        std::string list;
        for (const auto& k : known_) {
            list += (list.empty() ? "" : ", ") + k;
            const std::size_t d = editDistance(key, k);
            if (d < best) {
                best = d;
                nearest = k;
            }
        }
        const std::string where = path_.empty() ? "at the top level" : "in " + path_;
        fail(key, fmt::format("unknown key {}{}; the keys allowed {} are: {}", path(key),
                              nearest.empty() ? "" : " (did you mean " + path(nearest) + "?)",
                              where, list));
    }

    const std::string& file_;
    const Json& node_;
    std::string path_;
    std::vector<std::string> known_;
};

const std::vector<std::string> kCriterionKeys = {"stress_tolerance", "unbalanced_force_max",
                                                 "check_interval", "calm_checks", "max_steps"};

constexpr std::int64_t kMaxInt = std::numeric_limits<std::int32_t>::max();
constexpr std::int64_t kMaxInt64 = std::numeric_limits<std::int64_t>::max();

EquilibriumCriterion readCriterion(const Section& s) {
    EquilibriumCriterion c;
    const EquilibriumCriterion d;
    c.stressTolerance = s.number("stress_tolerance", open(0.0, 1.0), d.stressTolerance);
    c.unbalancedForceMax = s.number("unbalanced_force_max", positive(), d.unbalancedForceMax);
    c.checkInterval = s.integer("check_interval", 1, kMaxInt64, d.checkInterval);
    c.calmChecks = static_cast<int>(s.integer("calm_checks", 1, kMaxInt, d.calmChecks));
    c.maxSteps = s.integer("max_steps", 1, kMaxInt64, d.maxSteps);
    return c;
}

void readGrains(const Section& g, AssemblySpec& a) {
    a.grainCount = static_cast<int>(g.integer("count", 1, kMaxInt, std::nullopt));
    if (g.has("widths")) {
        for (const char* k : {"width_min", "width_max", "size_classes"}) {
            if (g.has(k)) {
                g.fail(k, fmt::format("{} and {} exclude each other: give either the list of "
                                      "widths or width_min, width_max and size_classes",
                                      g.path(k), g.path("widths")));
            }
        }
        a.widths = *g.numbers("widths", positive());
    } else {
        const double wMin = g.number("width_min", positive(), std::nullopt);
        const double wMax = g.number("width_max", {wMin, kInf, true, false}, std::nullopt);
        const int classes = static_cast<int>(g.integer("size_classes", 1, kMaxInt, std::nullopt));
        if (classes == 1 && wMax != wMin) {
            g.refuse("width_max", g.at("width_max"),
                     fmt::format("equal to width_min ({}) when size_classes is 1", wMin));
        }
        a.widths = evenlySpacedWidths(wMin, wMax, classes);
    }
    a.aspectRatio = g.number("aspect_ratio", openClosed(0.0, 1.0), std::nullopt);
    const std::string closure =
        g.choice("closure", {"equal_area", "end_radius_ratio"}, std::string("equal_area"));
    if (closure == "end_radius_ratio") {
        a.closure = OvalClosure::EndRadiusRatio;
        a.endRadiusRatio =
            g.number("end_radius_ratio", open(0.0, a.aspectRatio / 2.0), std::nullopt);
    } else {
        a.closure = OvalClosure::EqualArea;
        a.endRadiusRatio = 0.0;
        if (g.has("end_radius_ratio")) {
            g.fail("end_radius_ratio",
                   fmt::format("{} is only used with \"closure\": \"end_radius_ratio\" (closure "
                               "is \"equal_area\")",
                               g.path("end_radius_ratio")));
        }
    }
    a.gap = g.number("grid_gap", nonNegative(), 0.1);
    a.cellAspectRatio = g.number("cell_aspect_ratio", positive(), 1.0);
}

void readDamping(const Section& d, DampingParameters& damping) {
    const std::string kind = d.choice("kind", {"global_viscous", "cundall_local", "none"},
                                      std::string("global_viscous"));
    if (kind == "none") {
        damping.kind = DampingKind::None;
        if (d.has("coefficient")) {
            d.fail("coefficient", fmt::format("{} is not used when damping.kind is \"none\"; "
                                              "remove it",
                                              d.path("coefficient")));
        }
        damping.coefficient = 0.0;
        return;
    }
    damping.kind = kind == "cundall_local" ? DampingKind::CundallLocal : DampingKind::GlobalViscous;
    damping.coefficient = d.number("coefficient", closed(0.0, 1.0), 0.05);
}

void readPressures(const Section& c, CompactionSpec& compaction) {
    const auto pressures = c.numbers("pressures", positive());
    if (!pressures) {
        c.missing("pressures", "a non-empty array of pressures > 0, ascending [Pa]");
    }
    for (std::size_t i = 1; i < pressures->size(); ++i) {
        if (!((*pressures)[i] > (*pressures)[i - 1])) {
            c.refuse(fmt::format("pressures[{}]", i), c.at("pressures")[i],
                     fmt::format("greater than pressures[{}] = {} (pressures strictly ascending)",
                                 i - 1, (*pressures)[i - 1]));
        }
    }
    compaction.pressures = *pressures;
}

void readShearPressures(const Section& s, const CompactionSpec& compaction, ShearSpec& shear) {
    const auto pressures = s.numbers("pressures", positive());
    if (!pressures) {
        shear.pressures = compaction.pressures;
        return;
    }
    std::string list;
    for (double p : compaction.pressures) {
        list += (list.empty() ? "" : ", ") + fmt::format("{}", p);
    }
    for (std::size_t i = 0; i < pressures->size(); ++i) {
        const double p = (*pressures)[i];
        const std::string key = fmt::format("pressures[{}]", i);
        if (std::find(compaction.pressures.begin(), compaction.pressures.end(), p) ==
            compaction.pressures.end()) {
            s.refuse(key, s.at("pressures")[i],
                     fmt::format("one of the compaction pressures ({})", list));
        }
        if (std::find(pressures->begin(), pressures->begin() + i, p) != pressures->begin() + i) {
            s.refuse(key, s.at("pressures")[i], "listed once (it appears twice)");
        }
    }
    shear.pressures = *pressures;
}

/// Parses JSON, refusing duplicate keys (nlohmann keeps the last one silently).
Json parseStrict(const std::string& text, const std::string& file) {
    struct Frame {
        bool object;
        std::string path;
        std::set<std::string> keys;
        std::string lastKey;
        std::size_t index = 0;
    };
    std::vector<Frame> stack;
    std::string duplicate;
    const auto childPath = [&]() -> std::string {
        if (stack.empty()) {
            return "";
        }
        const Frame& f = stack.back();
        return f.object ? joinPath(f.path, f.lastKey) : fmt::format("{}[{}]", f.path, f.index);
    };
    const auto nextElement = [&] {
        if (!stack.empty() && !stack.back().object) {
            ++stack.back().index;
        }
    };
    using Event = Json::parse_event_t;
    const Json::parser_callback_t callback = [&](int, Event event, Json& parsed) {
        switch (event) {
        case Event::object_start:
        case Event::array_start: {
            std::string p = childPath();
            stack.push_back({event == Event::object_start, std::move(p), {}, {}, 0});
            break;
        }
        case Event::key: {
            Frame& f = stack.back();
            f.lastKey = parsed.get<std::string>();
            if (!f.keys.insert(f.lastKey).second && duplicate.empty()) {
                duplicate = joinPath(f.path, f.lastKey);
            }
            break;
        }
        case Event::object_end:
        case Event::array_end:
            stack.pop_back();
            nextElement();
            break;
        case Event::value:
            nextElement();
            break;
        }
        return true;
    };
    Json root;
    try {
        root = Json::parse(text, callback, true, false);
    } catch (const Json::parse_error& e) {
        // Line and column of the byte where parsing failed (1-based).
        std::size_t line = 1, column = 1;
        const std::size_t end = std::min<std::size_t>(e.byte > 0 ? e.byte - 1 : 0, text.size());
        for (std::size_t i = 0; i < end; ++i) {
            if (text[i] == '\n') {
                ++line;
                column = 1;
            } else {
                ++column;
            }
        }
        std::string detail = e.what();
        const auto colon = detail.find(": ", detail.find("column"));
        if (colon != std::string::npos) {
            detail = detail.substr(colon + 2);
        }
        throw ExperimentFileError(
            file, "",
            fmt::format("JSON syntax error at line {}, column {}: {}", line, column, detail));
    } catch (const Json::exception& e) {
        throw ExperimentFileError(file, "", fmt::format("not valid JSON: {}", e.what()));
    }
    if (!duplicate.empty()) {
        throw ExperimentFileError(
            file, duplicate,
            fmt::format("duplicate key {}: each key may appear once per object", duplicate));
    }
    return root;
}

std::string fileStem(const std::string& path) {
    const auto slash = path.find_last_of("/\\");
    std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
    const auto dot = name.find_last_of('.');
    if (dot != std::string::npos && dot > 0) {
        name = name.substr(0, dot);
    }
    return name.empty() ? "experiment" : name;
}

} // namespace

ExperimentConfig parseExperimentText(const std::string& text, const std::string& sourceName) {
    const Json root = parseStrict(text, sourceName);
    const Section top(sourceName, root, "",
                      {"name", "description", "seed", "threads", "grains", "material", "time_step",
                       "damping", "servo", "stability", "neighbour_skin", "compaction", "shear",
                       "record"});
    if (top.has("description") && !top.at("description").is_string()) {
        top.refuse("description", top.at("description"),
                   fmt::format("a string (got {})", jsonTypeName(top.at("description"))));
    }

    ExperimentConfig config;
    config.sourcePath = sourceName;
    config.sourceText = text;
    config.name = top.text("name", fileStem(sourceName));
    config.assembly.seed =
        static_cast<std::uint64_t>(top.integer("seed", 0, kMaxInt64, std::nullopt));

    SimulationParameters& p = config.parameters;
    p.threads = static_cast<int>(top.integer("threads", 1, 1024, 1));

    readGrains(
        top.child("grains",
                  {"count", "widths", "width_min", "width_max", "size_classes", "aspect_ratio",
                   "closure", "end_radius_ratio", "grid_gap", "cell_aspect_ratio"},
                  true,
                  "an object with count, width_min, width_max, size_classes and "
                  "aspect_ratio"),
        config.assembly);

    const Section material =
        top.child("material", {"normal_stiffness", "tangential_stiffness", "density"}, true,
                  "an object with normal_stiffness, tangential_stiffness and density");
    p.normalStiffness = material.number("normal_stiffness", positive(), std::nullopt);
    p.tangentialStiffness = material.number("tangential_stiffness", positive(), std::nullopt);
    p.density = material.number("density", positive(), std::nullopt);

    p.timeStep = top.number("time_step", positive(), std::nullopt);
    readDamping(top.child("damping", {"kind", "coefficient"}, false), p.damping);

    const Section servo = top.child("servo", {"gain", "integral_gain", "interval"}, false);
    const ServoParameters servoDefaults;
    p.servo.gain = servo.number("gain", openClosed(0.0, 0.5), servoDefaults.gain);
    p.servo.integralGain =
        servo.number("integral_gain", closed(0.0, 1.0), servoDefaults.integralGain);
    p.servo.interval = static_cast<int>(servo.integer("interval", 1, kMaxInt, 1));

    const Section stability = top.child(
        "stability", {"design_coordination", "max_overlap_fraction", "max_step_fraction"}, false);
    const StabilityParameters stabilityDefaults;
    p.stability.designCoordination = static_cast<int>(
        stability.integer("design_coordination", 1, 64, stabilityDefaults.designCoordination));
    p.stability.maxOverlapFraction = stability.number("max_overlap_fraction", openClosed(0.0, 1.0),
                                                      stabilityDefaults.maxOverlapFraction);
    p.stability.maxStepFraction = stability.number("max_step_fraction", openClosed(0.0, 1.0),
                                                   stabilityDefaults.maxStepFraction);
    p.neighbourSkin = top.number("neighbour_skin", nonNegative(), 0.0);

    const Section compaction =
        top.child("compaction", {"friction", "pressures", "max_strain_rate", "criterion"}, true,
                  "an object with at least pressures");
    config.compaction.friction = compaction.number("friction", nonNegative(), 0.0);
    readPressures(compaction, config.compaction);
    config.compaction.maxStrainRate = compaction.number("max_strain_rate", positive(), 20.0);
    config.compaction.criterion =
        readCriterion(compaction.child("criterion", kCriterionKeys, false));

    const Section shear = top.child("shear",
                                    {"friction", "pressures", "axial_strain_per_step",
                                     "target_axial_strain", "max_strain_rate", "equilibration"},
                                    true, "an object with at least target_axial_strain");
    config.shear.friction = shear.number("friction", nonNegative(), 0.5);
    readShearPressures(shear, config.compaction, config.shear);
    config.shear.targetAxialStrain =
        shear.number("target_axial_strain", open(0.0, 1.0), std::nullopt);
    config.shear.axialStrainPerStep =
        shear.number("axial_strain_per_step", open(0.0, config.shear.targetAxialStrain), 2e-7);
    config.shear.maxStrainRate = shear.number("max_strain_rate", positive(), 1.0);
    config.shear.equilibration = readCriterion(shear.child("equilibration", kCriterionKeys, false));

    const Section record = top.child(
        "record",
        {"strain_interval", "step_interval", "snapshot_strain_interval", "snapshot_step_interval"},
        false);
    const RecordSpec recordDefaults;
    config.record.strainInterval =
        record.number("strain_interval", positive(), recordDefaults.strainInterval);
    config.record.stepInterval =
        record.integer("step_interval", 1, kMaxInt64, recordDefaults.stepInterval);
    config.record.snapshotStrainInterval = record.number("snapshot_strain_interval", positive(),
                                                         recordDefaults.snapshotStrainInterval);
    config.record.snapshotStepInterval =
        record.integer("snapshot_step_interval", 1, kMaxInt64, recordDefaults.snapshotStepInterval);

    // The first stage is compaction: the state starts with its friction and rate cap; the
    // runner sets both per stage.
    p.friction = config.compaction.friction;
    p.servo.maxStrainRate = config.compaction.maxStrainRate;

    // The shapes the file implies, and the time step against their stable limit (SPEC §3.7).
    std::vector<OvalShape> shapes;
    try {
        for (double w : config.assembly.widths) {
            shapes.push_back(makeOval(w, config.assembly.aspectRatio, config.assembly.closure,
                                      config.assembly.endRadiusRatio));
        }
    } catch (const std::invalid_argument& e) {
        const std::string key = config.assembly.closure == OvalClosure::EndRadiusRatio
                                    ? "grains.end_radius_ratio"
                                    : "grains.aspect_ratio";
        throw ExperimentFileError(sourceName, key,
                                  fmt::format("{}: no valid oval: {}", key, e.what()));
    }
    try {
        checkTimeStep(shapes, p);
    } catch (const std::invalid_argument& e) {
        throw ExperimentFileError(sourceName, "time_step",
                                  fmt::format("time_step = {}: {}", p.timeStep, e.what()));
    }
    return config;
}

ExperimentConfig readExperimentFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw ExperimentFileError(path, "", "cannot open the experiment file for reading");
    }
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) {
        throw ExperimentFileError(path, "", "read error while reading the experiment file");
    }
    return parseExperimentText(text.str(), path);
}

} // namespace grainlab
