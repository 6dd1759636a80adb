// See servo_map.h.
#include "grainlab/servo_map.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "grainlab/csv_series.h"
#include "grainlab/simulation_state.h"
#include "grainlab/strict_json.h"

namespace grainlab {
namespace {

std::string shortNumber(double v) {
    return fmt::format("{:.6g}", v);
}

/// A CSV number: round-trip precision; empty for a non-finite value (never "nan" in a table).
std::string number(double v) {
    return std::isfinite(v) ? fmt::format("{:.9g}", v) : std::string();
}

std::vector<double> requiredNumbers(const JsonSection& axes, const std::string& key, Range range) {
    const auto v = axes.numbers(key, range);
    if (!v) {
        axes.missing(key, "a non-empty array of numbers " + range.text());
    }
    return *v;
}

std::vector<std::string> cellFields(const ServoCell& c, const ServoMapSpec& spec) {
    return {c.id,
            number(c.pressure),
            number(c.aspectRatio),
            std::to_string(c.interval),
            number(double(c.interval) * spec.strainPerStep),
            number(servoLagNumber(c.interval, spec.strainPerStep,
                                  SimulationParameters{}.normalStiffness, c.pressure))};
}

} // namespace

ServoMapSpec readServoPreset(const std::string& path) {
    ServoMapSpec spec = parseServoPreset(readInputFile(path, "stability preset"), path);
    spec.sourcePath = path;
    return spec;
}

ServoMapSpec parseServoPreset(const std::string& text, const std::string& file) {
    const Json root = parseStrictJson(text, file);
    ServoMapSpec spec;
    spec.sourceText = text;
    const JsonSection top(
        file, root, "",
        {"kind", "name", "description", "scene", "shear", "judge", "search", "axes"});
    top.choice("kind", {"servo"}, std::nullopt);
    spec.name = top.text("name", spec.name);
    if (spec.name.find_first_of("/\\ ") != std::string::npos) {
        top.refuse("name", top.at("name"), "a name without spaces or slashes");
    }
    top.text("description", "-");

    const JsonSection scene =
        top.child("scene",
                  {"grains", "smallest_width", "largest_width", "size_classes", "seed", "time_step",
                   "friction", "compaction_rate"},
                  false);
    spec.grains = int(scene.integer("grains", 16, 20000, spec.grains));
    spec.smallestWidth = scene.number("smallest_width", positive(), spec.smallestWidth);
    spec.largestWidth = scene.number("largest_width", Range{spec.smallestWidth, 1e300, true, true},
                                     std::max(spec.largestWidth, spec.smallestWidth));
    spec.sizeClasses = int(scene.integer("size_classes", 1, 1000, spec.sizeClasses));
    spec.seed = std::uint64_t(scene.integer("seed", 0, std::int64_t(1) << 53, 1));
    spec.timeStep = scene.number("time_step", openClosed(0, 1e-3), spec.timeStep);
    spec.friction = scene.number("friction", closed(0, 10), spec.friction);
    spec.compactionRate = scene.number("compaction_rate", openClosed(0, 1e3), spec.compactionRate);

    const JsonSection shear = top.child(
        "shear", {"strain_per_step", "max_strain_rate", "strain", "min_updates", "integral_gain"},
        false);
    spec.strainPerStep = shear.number("strain_per_step", openClosed(0, 1e-3), spec.strainPerStep);
    spec.maxStrainRate = shear.number("max_strain_rate", openClosed(0, 1e4), spec.maxStrainRate);
    spec.strain = shear.number("strain", openClosed(0, 0.5), spec.strain);
    spec.minUpdates = shear.integer("min_updates", 8, 1000000, spec.minUpdates);
    spec.integralGain = shear.number("integral_gain", closed(0, 1), spec.integralGain);

    const JsonSection judge =
        top.child("judge", {"band", "oscillation", "divergence", "transient"}, false);
    ServoThresholds& t = spec.thresholds;
    t.band = judge.number("band", open(0, 1), t.band);
    t.oscillation = judge.number("oscillation", open(0, 1), t.oscillation);
    t.divergence = judge.number("divergence", Range{t.oscillation, 100, false, true}, t.divergence);
    t.transient = judge.number("transient", Range{0, 0.9, true, true}, t.transient);

    const JsonSection search = top.child("search", {"precision"}, false);
    spec.precision = search.number("precision", Range{1e-4, 0.5, true, true}, spec.precision);

    const JsonSection axes =
        top.child("axes", {"pressure", "aspect_ratio", "interval", "gain"}, true,
                  "an object with pressure, aspect_ratio, interval "
                  "and gain");
    spec.pressures = requiredNumbers(axes, "pressure", closed(1e2, 1e8));
    spec.aspectRatios = requiredNumbers(axes, "aspect_ratio", closed(0.2, 1.0));
    spec.intervals.clear();
    for (double v : requiredNumbers(axes, "interval", closed(1, 100000))) {
        if (v != std::floor(v)) {
            axes.refuse("interval", axes.at("interval"), "integers in [1, 100000] [steps]");
        }
        spec.intervals.push_back(int(v));
    }
    spec.gains = requiredNumbers(axes, "gain", openClosed(0, 100));
    if (!std::is_sorted(spec.gains.begin(), spec.gains.end()) ||
        std::adjacent_find(spec.gains.begin(), spec.gains.end()) != spec.gains.end()) {
        axes.refuse("gain", axes.at("gain"), "gains in (0, 100], strictly ascending");
    }
    return spec;
}

std::vector<ServoCell> servoCells(const ServoMapSpec& spec) {
    std::vector<ServoCell> out;
    for (double p : spec.pressures) {
        for (double eta : spec.aspectRatios) {
            for (int n : spec.intervals) {
                out.push_back({fmt::format("servo_eta{}_p{}kPa_n{}", shortNumber(eta),
                                           shortNumber(p / 1e3), n),
                               p, eta, n});
            }
        }
    }
    return out;
}

std::int64_t servoRunSteps(const ServoMapSpec& spec, int interval) {
    const auto byStrain = std::int64_t(std::ceil(spec.strain / spec.strainPerStep));
    return std::max(byStrain, spec.minUpdates * std::int64_t(interval));
}

double ServoCellResult::smallestSteadyGain() const {
    double best = 0;
    for (const ServoRun& r : runs) {
        if (r.grid && r.response == ServoResponse::Steady && (best == 0 || r.gain < best)) {
            best = r.gain;
        }
    }
    return best;
}

double ServoCellResult::largestSteadyGain() const {
    double best = 0;
    for (const ServoRun& r : runs) {
        if (r.grid && r.response == ServoResponse::Steady) {
            best = std::max(best, r.gain);
        }
    }
    return best;
}

double ServoCellResult::bestMaxError() const {
    double best = std::numeric_limits<double>::infinity();
    for (const ServoRun& r : runs) {
        if (!servoUnstable(r.response)) {
            best = std::min(best, r.stats.maxError);
        }
    }
    return best;
}

std::string servoCellResultJson(const ServoCellResult& r) {
    Json j;
    j["kind"] = "servo";
    j["cell"] = r.cell.id;
    j["pressure"] = r.cell.pressure;
    j["aspect_ratio"] = r.cell.aspectRatio;
    j["interval"] = r.cell.interval;
    j["bracketed"] = r.limit.bracketed;
    j["limit"] = r.limit.limit;
    j["limit_low"] = r.limit.low;
    j["limit_high"] = r.limit.high;
    j["probes"] = r.limit.probes;
    j["above_limit"] = servoResponseName(r.aboveLimit);
    j["stiffness_over_pressure"] = r.stiffnessOverPressure;
    j["compaction_calm"] = r.compactionCalm;
    j["seconds"] = r.seconds;
    j["runs"] = Json::array();
    for (const ServoRun& run : r.runs) {
        const ServoErrorStats& s = run.stats;
        j["runs"].push_back({{"gain", run.gain},
                             {"grid", run.grid},
                             {"response", servoResponseName(run.response)},
                             {"transient_max", s.transientMax},
                             {"max_error", s.maxError},
                             {"mean_error", s.meanError},
                             {"rms_error", s.rmsError},
                             {"alternating", s.alternating},
                             {"reversals", s.reversals},
                             {"steps", s.steps},
                             {"updates", s.updates},
                             {"stopped", s.stopped},
                             {"stop_cause", s.stopCause}});
    }
    return j.dump(2) + "\n";
}

ServoCellResult parseServoCellResult(const std::string& text, const std::string& sourceName) {
    try {
        const Json j = Json::parse(text);
        ServoCellResult r;
        r.cell.id = j.at("cell").get<std::string>();
        r.cell.pressure = j.at("pressure").get<double>();
        r.cell.aspectRatio = j.at("aspect_ratio").get<double>();
        r.cell.interval = j.at("interval").get<int>();
        r.limit.bracketed = j.at("bracketed").get<bool>();
        r.limit.limit = j.at("limit").get<double>();
        r.limit.low = j.at("limit_low").get<double>();
        r.limit.high = j.at("limit_high").get<double>();
        r.limit.probes = j.at("probes").get<int>();
        r.aboveLimit = servoResponseFromName(j.at("above_limit").get<std::string>());
        r.stiffnessOverPressure = j.at("stiffness_over_pressure").get<double>();
        r.compactionCalm = j.at("compaction_calm").get<bool>();
        r.seconds = j.at("seconds").get<double>();
        for (const Json& run : j.at("runs")) {
            ServoRun x;
            x.gain = run.at("gain").get<double>();
            x.grid = run.at("grid").get<bool>();
            x.response = servoResponseFromName(run.at("response").get<std::string>());
            ServoErrorStats& s = x.stats;
            s.transientMax = run.at("transient_max").get<double>();
            s.maxError = run.at("max_error").get<double>();
            s.meanError = run.at("mean_error").get<double>();
            s.rmsError = run.at("rms_error").get<double>();
            s.alternating = run.at("alternating").get<double>();
            s.reversals = run.at("reversals").get<double>();
            s.steps = run.at("steps").get<std::int64_t>();
            s.updates = run.at("updates").get<std::int64_t>();
            s.stopped = run.at("stopped").get<bool>();
            s.stopCause = run.at("stop_cause").get<std::string>();
            r.runs.push_back(std::move(x));
        }
        return r;
    } catch (const std::exception& e) {
        throw std::runtime_error(
            fmt::format("{}: not a servo map cell result: {}", sourceName, e.what()));
    }
}

namespace {
const std::vector<std::string> kCellHeader = {
    "cell",         "pressure [Pa]",         "aspect_ratio [-]",
    "interval [-]", "strain_per_update [-]", "lag_number [-]"};
} // namespace

std::string servoLimitsCsv(const ServoMapSpec& spec, const std::vector<ServoCellResult>& results) {
    std::vector<std::string> header = kCellHeader;
    for (const char* h :
         {"stable_gain_limit [-]", "limit_low [-]", "limit_high [-]", "bracketed",
          "response_above_limit", "smallest_steady_gain [-]", "largest_steady_gain [-]",
          "best_max_error [-]", "stiffness_over_pressure [-]", "probes [-]", "compaction_calm",
          "cell_seconds [s]"}) {
        header.emplace_back(h);
    }
    std::string s = csvLine(header);
    for (const ServoCellResult& r : results) {
        std::vector<std::string> row = cellFields(r.cell, spec);
        const double smallest = r.smallestSteadyGain(), largest = r.largestSteadyGain();
        for (std::string f :
             {number(r.limit.limit), number(r.limit.low), number(r.limit.high),
              std::string(r.limit.bracketed ? "yes" : "no"), servoResponseName(r.aboveLimit),
              smallest > 0 ? number(smallest) : std::string(),
              largest > 0 ? number(largest) : std::string(), number(r.bestMaxError()),
              number(r.stiffnessOverPressure), std::to_string(r.limit.probes),
              std::string(r.compactionCalm ? "yes" : "no"), number(r.seconds)}) {
            row.push_back(std::move(f));
        }
        s += csvLine(row);
    }
    return s;
}

std::string servoRunsCsv(const std::vector<ServoCellResult>& results) {
    std::string s =
        csvLine({"cell", "pressure [Pa]", "aspect_ratio [-]", "interval [-]", "gain [-]", "search",
                 "response", "max_error [-]", "mean_error [-]", "rms_error [-]", "alternating [-]",
                 "reversals [-]", "transient_max [-]", "steps [-]", "updates [-]", "stopped",
                 "stop_cause"});
    for (const ServoCellResult& r : results) {
        for (const ServoRun& run : r.runs) {
            const ServoErrorStats& e = run.stats;
            s += csvLine({r.cell.id, number(r.cell.pressure), number(r.cell.aspectRatio),
                          std::to_string(r.cell.interval), number(run.gain),
                          run.grid ? "grid" : "bisection", servoResponseName(run.response),
                          number(e.maxError), number(e.meanError), number(e.rmsError),
                          number(e.alternating), number(e.reversals), number(e.transientMax),
                          std::to_string(e.steps), std::to_string(e.updates),
                          e.stopped ? "yes" : "no", e.stopCause});
        }
    }
    return s;
}

} // namespace grainlab
