#include "grainlab/study_plan.h"

#include <algorithm>
#include <cmath>
#include <set>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "grainlab/experiment_file.h"
#include "grainlab/loading_rate.h"
#include "grainlab/oval_shape.h"
#include "grainlab/time_step.h"

namespace grainlab {
namespace {

using OrderedJson = nlohmann::ordered_json; // keeps the base file's key order

struct KnobInfo {
    KnobKind kind;
    const char* name;
};

constexpr KnobInfo kKnobs[] = {
    {KnobKind::TimeStepFraction, "time_step_fraction"},
    {KnobKind::AxialStrainPerStep, "axial_strain_per_step"},
    {KnobKind::InertialNumber, "inertial_number"},
    {KnobKind::Damping, "damping"},
    {KnobKind::GrainCount, "grain_count"},
    {KnobKind::Shape, "shape"},
    {KnobKind::NeighbourSkin, "neighbour_skin"},
    {KnobKind::Threads, "threads"},
};

/// A label safe in folder names: letters, digits, '.', '-' and '_' only.
std::string folderSafe(const std::string& s) {
    std::string out;
    for (char c : s) {
        const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                        (c >= '0' && c <= '9') || c == '.' || c == '-' || c == '_';
        out += ok ? c : '_';
    }
    return out;
}

OrderedJson& child(OrderedJson& j, const char* key) {
    if (!j.contains(key) || !j[key].is_object()) {
        j[key] = OrderedJson::object();
    }
    return j[key];
}

} // namespace

std::optional<double> knobValueIn(const std::string& experimentText, KnobKind kind) {
    const ExperimentConfig c = parseExperimentText(experimentText, "<experiment>");
    const double dt = c.parameters.timeStep;
    switch (kind) {
    case KnobKind::TimeStepFraction:
        return dt / criticalTimeStep(assemblyShapes(c.assembly), c.parameters).estimate;
    case KnobKind::AxialStrainPerStep:
        return c.shear.axialStrainPerStep;
    case KnobKind::InertialNumber: {
        const double p = *std::min_element(c.shear.pressures.begin(), c.shear.pressures.end());
        return shearInertialNumber(c, p);
    }
    case KnobKind::GrainCount:
        return double(c.assembly.grainCount);
    case KnobKind::NeighbourSkin: // 0 in the file: 0.1 of the smallest width
        return c.parameters.neighbourSkin > 0
                   ? c.parameters.neighbourSkin / c.assembly.widths.front()
                   : 0.1;
    case KnobKind::Threads:
        return double(c.parameters.threads);
    case KnobKind::Damping:
    case KnobKind::Shape:
        break;
    }
    return std::nullopt;
}

std::string knobName(KnobKind kind) {
    for (const KnobInfo& k : kKnobs) {
        if (k.kind == kind) {
            return k.name;
        }
    }
    return "?";
}

std::optional<KnobKind> knobNamed(const std::string& name) {
    for (const KnobInfo& k : kKnobs) {
        if (name == k.name) {
            return k.kind;
        }
    }
    return std::nullopt;
}

const std::vector<KnobKind>& allKnobs() {
    static const std::vector<KnobKind> all = [] {
        std::vector<KnobKind> v;
        for (const KnobInfo& k : kKnobs) {
            v.push_back(k.kind);
        }
        return v;
    }();
    return all;
}

std::string KnobLevel::label() const {
    if (object.empty()) {
        return fmt::format("{}", number);
    }
    const OrderedJson j = OrderedJson::parse(object);
    if (j.contains("kind")) { // damping
        const std::string kind = j["kind"];
        return j.contains("coefficient") ? fmt::format("{}-{}", kind, j["coefficient"].dump())
                                         : kind;
    }
    if (j.contains("aspect_ratio") && j["aspect_ratio"] == 1) {
        return "disk";
    }
    std::string s = "oval";
    for (const auto& [key, value] : j.items()) {
        s += '-';
        s += value.is_string() ? value.get<std::string>() : value.dump();
    }
    return s;
}

std::string applySetting(const std::string& baseText, const std::string& baseSource,
                         const std::map<KnobKind, KnobLevel>& levels, std::uint64_t seed) {
    OrderedJson j = OrderedJson::parse(baseText);
    j["seed"] = seed;
    for (const auto& [kind, level] : levels) {
        switch (kind) {
        case KnobKind::AxialStrainPerStep:
            child(j, "shear")["axial_strain_per_step"] = level.number;
            break;
        case KnobKind::Damping:
            j["damping"] = OrderedJson::parse(level.object);
            break;
        case KnobKind::GrainCount:
            child(j, "grains")["count"] = static_cast<std::int64_t>(std::llround(level.number));
            break;
        case KnobKind::Shape: {
            OrderedJson& grains = child(j, "grains");
            const OrderedJson shape = OrderedJson::parse(level.object);
            if (!shape.contains("end_radius_ratio")) {
                grains.erase("end_radius_ratio");
            }
            if (!shape.contains("closure")) {
                grains.erase("closure");
            }
            for (const auto& [key, value] : shape.items()) {
                grains[key] = value;
            }
            break;
        }
        case KnobKind::Threads:
            j["threads"] = static_cast<std::int64_t>(std::llround(level.number));
            break;
        case KnobKind::TimeStepFraction:
        case KnobKind::InertialNumber:
        case KnobKind::NeighbourSkin:
            break; // derived from the configuration below
        }
    }

    const auto fraction = levels.find(KnobKind::TimeStepFraction);
    const auto inertial = levels.find(KnobKind::InertialNumber);
    const auto skin = levels.find(KnobKind::NeighbourSkin);
    if (fraction != levels.end() || inertial != levels.end() || skin != levels.end()) {
        // Read the configuration as set so far; a tiny time step passes the stability check
        // whatever the shapes, and is replaced below.
        OrderedJson probe = j;
        if (fraction != levels.end()) {
            probe["time_step"] = 1e-15;
            // ... and the lateral servo's cap the largest that step allows, so that the shear's
            // strain per step, a huge rate per second at that step, passes its check too.
            child(probe, "shear")["max_strain_rate"] = 1e-3 / 1e-15;
        }
        const ExperimentConfig c = parseExperimentText(probe.dump(), baseSource);
        double dt = c.parameters.timeStep;
        if (fraction != levels.end()) {
            const double baseStep = OrderedJson::parse(baseText).at("time_step").get<double>();
            dt = fraction->second.number *
                 criticalTimeStep(assemblyShapes(c.assembly), c.parameters).estimate;
            j["time_step"] = dt;
            if (!levels.count(KnobKind::AxialStrainPerStep) && inertial == levels.end()) {
                // The loading rate is physics, the time step numerics: keep the strain rate
                // (per second) of the base, so the strain per step scales with the step.
                child(j, "shear")["axial_strain_per_step"] =
                    c.shear.axialStrainPerStep * dt / baseStep;
            }
            if (dt < baseStep) {
                // A stage's step cap is a duration: a smaller step gets as much physical time
                // (more steps) to reach equilibrium as the base gives; a larger one keeps the
                // base's cap.
                const double stretch = baseStep / dt;
                const auto stretchCap = [&](OrderedJson& criterion, std::int64_t cap) {
                    criterion["max_steps"] =
                        static_cast<std::int64_t>(std::ceil(double(cap) * stretch));
                };
                stretchCap(child(child(j, "compaction"), "criterion"),
                           c.compaction.criterion.maxSteps);
                stretchCap(child(child(j, "shear"), "equilibration"),
                           c.shear.equilibration.maxSteps);
            }
        }
        if (inertial != levels.end()) {
            // At the lowest confining pressure sheared, where the inertial number is largest.
            const double p = *std::min_element(c.shear.pressures.begin(), c.shear.pressures.end());
            child(j, "shear")["axial_strain_per_step"] =
                axialStrainRateFor(c, inertial->second.number, p) * dt;
        }
        if (skin != levels.end()) {
            j["neighbour_skin"] = skin->second.number * c.assembly.widths.front();
        }
    }
    std::string text = j.dump(2) + "\n";
    parseExperimentText(text, baseSource); // every run's experiment must be valid
    return text;
}

StudyPlan planStudy(const StudySpec& spec) {
    StudyPlan plan;
    // The reference setting: its levels, then each knob's base value (no level: as the base).
    StudySetting reference;
    reference.id = "ref";
    reference.isReference = true;
    reference.levels = spec.reference;
    plan.settings.push_back(reference);

    const auto addSetting = [&](std::map<KnobKind, KnobLevel> levels) {
        for (const StudySetting& s : plan.settings) {
            if (s.levels == levels) {
                return; // already there (e.g. a knob's level equal to the reference)
            }
        }
        StudySetting s;
        s.levels = std::move(levels);
        std::string id;
        for (const auto& [kind, level] : s.levels) {
            const auto ref = spec.reference.find(kind);
            if (ref == spec.reference.end() || !(ref->second == level)) {
                id += id.empty() ? "" : "_";
                id += knobName(kind);
                id += '-';
                id += level.label();
            }
        }
        s.id = folderSafe(id);
        plan.settings.push_back(std::move(s));
    };

    if (spec.design == StudyDesign::OneAtATime) {
        for (const Knob& knob : spec.knobs) {
            for (const KnobLevel& level : knob.levels) {
                std::map<KnobKind, KnobLevel> levels = spec.reference;
                levels[knob.kind] = level;
                addSetting(std::move(levels));
            }
        }
    } else {
        std::vector<std::map<KnobKind, KnobLevel>> combinations{spec.reference};
        for (const Knob& knob : spec.knobs) {
            std::vector<std::map<KnobKind, KnobLevel>> next;
            for (const auto& partial : combinations) {
                for (const KnobLevel& level : knob.levels) {
                    auto levels = partial;
                    levels[knob.kind] = level;
                    next.push_back(std::move(levels));
                }
            }
            combinations = std::move(next);
        }
        for (auto& levels : combinations) {
            addSetting(std::move(levels));
        }
    }

    std::set<std::string> ids;
    for (std::size_t s = 0; s < plan.settings.size(); ++s) {
        if (!ids.insert(plan.settings[s].id).second) {
            plan.settings[s].id += fmt::format("-{}", s); // two levels with one label
        }
        for (std::uint64_t seed : spec.seeds) {
            StudyRun run;
            run.id = fmt::format("{}-seed{}", plan.settings[s].id, seed);
            run.setting = static_cast<int>(s);
            run.seed = seed;
            try {
                run.experimentText = applySetting(spec.baseExperiment, spec.baseSource,
                                                  plan.settings[s].levels, seed);
            } catch (const ExperimentFileError& e) {
                throw ExperimentFileError(
                    spec.sourcePath.empty() ? spec.baseSource : spec.sourcePath, e.keyPath,
                    fmt::format("setting {} makes an invalid experiment: {}", plan.settings[s].id,
                                e.what()));
            }
            plan.runs.push_back(std::move(run));
        }
    }
    return plan;
}

} // namespace grainlab
