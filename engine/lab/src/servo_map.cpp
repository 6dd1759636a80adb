// See servo_map.h.
#include "grainlab/servo_map.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "grainlab/csv_series.h"
#include "grainlab/simulation_state.h"
#include "grainlab/strict_json.h"
#include "map_preset.h"

namespace grainlab {
namespace {

using map_preset::csvNumber;
using map_preset::requiredNumbers;
using map_preset::shortNumber;

std::vector<std::string> cellFields(const ServoCell& c, const ServoMapSpec& spec) {
    return {c.id,
            csvNumber(c.pressure),
            csvNumber(c.aspectRatio),
            std::to_string(c.interval),
            csvNumber(double(c.interval) * spec.strainPerStep),
            csvNumber(servoLagNumber(c.interval, spec.strainPerStep,
                                     SimulationParameters{}.normalStiffness, c.pressure))};
}

/// The servo preset's own keys.
void readServoKeys(const std::string& /*file*/, const JsonSection& top, ServoMapSpec& spec) {
    const JsonSection scene =
        top.child("scene",
                  {"grains", "smallest_width", "largest_width", "size_classes", "seed", "time_step",
                   "friction", "compaction_rate"},
                  false);
    map_preset::readSampleGrains(scene, spec);
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
}

/// The real-valued fields of a run's error statistics, by their key in a cell result.
constexpr std::pair<const char*, double ServoErrorStats::*> kStatsNumbers[] = {
    {"transient_max", &ServoErrorStats::transientMax}, {"max_error", &ServoErrorStats::maxError},
    {"mean_error", &ServoErrorStats::meanError},       {"rms_error", &ServoErrorStats::rmsError},
    {"alternating", &ServoErrorStats::alternating},    {"reversals", &ServoErrorStats::reversals},
};

} // namespace

ServoMapSpec readServoPreset(const std::string& path) {
    return map_preset::readPresetFile(path, parseServoPreset);
}

ServoMapSpec parseServoPreset(const std::string& text, const std::string& file) {
    return map_preset::parsePreset<ServoMapSpec>(text, file, "servo", std::nullopt,
                                                 {"scene", "shear", "judge", "search", "axes"},
                                                 readServoKeys);
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
    return map_preset::cellResultText(r, [&](Json& j) {
        j["kind"] = "servo";
        j["pressure"] = r.cell.pressure;
        j["aspect_ratio"] = r.cell.aspectRatio;
        j["interval"] = r.cell.interval;
        j["above_limit"] = servoResponseName(r.aboveLimit);
        j["stiffness_over_pressure"] = r.stiffnessOverPressure;
        j["runs"] = Json::array();
        for (const ServoRun& run : r.runs) {
            const ServoErrorStats& s = run.stats;
            Json out = {{"gain", run.gain},
                        {"grid", run.grid},
                        {"response", servoResponseName(run.response)},
                        {"steps", s.steps},
                        {"updates", s.updates},
                        {"stopped", s.stopped},
                        {"stop_cause", s.stopCause}};
            for (const auto& [key, field] : kStatsNumbers) {
                out[key] = s.*field;
            }
            j["runs"].push_back(std::move(out));
        }
    });
}

ServoCellResult parseServoCellResult(const std::string& text, const std::string& sourceName) {
    return map_preset::parseCellResultText<ServoCellResult, std::exception>(
        text, sourceName, "servo map", [](const Json& j, ServoCellResult& r) {
            r.cell.pressure = j.at("pressure").get<double>();
            r.cell.aspectRatio = j.at("aspect_ratio").get<double>();
            r.cell.interval = j.at("interval").get<int>();
            r.aboveLimit = servoResponseFromName(j.at("above_limit").get<std::string>());
            r.stiffnessOverPressure = j.at("stiffness_over_pressure").get<double>();
            for (const Json& run : j.at("runs")) {
                ServoRun x;
                x.gain = run.at("gain").get<double>();
                x.grid = run.at("grid").get<bool>();
                x.response = servoResponseFromName(run.at("response").get<std::string>());
                ServoErrorStats& s = x.stats;
                for (const auto& [key, field] : kStatsNumbers) {
                    s.*field = run.at(key).get<double>();
                }
                s.steps = run.at("steps").get<std::int64_t>();
                s.updates = run.at("updates").get<std::int64_t>();
                s.stopped = run.at("stopped").get<bool>();
                s.stopCause = run.at("stop_cause").get<std::string>();
                r.runs.push_back(std::move(x));
            }
        });
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
             {csvNumber(r.limit.limit), csvNumber(r.limit.low), csvNumber(r.limit.high),
              std::string(r.limit.bracketed ? "yes" : "no"), servoResponseName(r.aboveLimit),
              smallest > 0 ? csvNumber(smallest) : std::string(),
              largest > 0 ? csvNumber(largest) : std::string(), csvNumber(r.bestMaxError()),
              csvNumber(r.stiffnessOverPressure), std::to_string(r.limit.probes),
              std::string(r.compactionCalm ? "yes" : "no"), csvNumber(r.seconds)}) {
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
            s += csvLine({r.cell.id, csvNumber(r.cell.pressure), csvNumber(r.cell.aspectRatio),
                          std::to_string(r.cell.interval), csvNumber(run.gain),
                          run.grid ? "grid" : "bisection", servoResponseName(run.response),
                          csvNumber(e.maxError), csvNumber(e.meanError), csvNumber(e.rmsError),
                          csvNumber(e.alternating), csvNumber(e.reversals),
                          csvNumber(e.transientMax), std::to_string(e.steps),
                          std::to_string(e.updates), e.stopped ? "yes" : "no", e.stopCause});
        }
    }
    return s;
}

} // namespace grainlab
