// See stability_map.h.
#include "grainlab/stability_map.h"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "grainlab/strict_json.h"
#include "map_preset.h"

namespace grainlab {
namespace {

using map_preset::csvNumber;
using map_preset::readSampleGrains;
using map_preset::requiredNumbers;
using map_preset::shortNumber;

/// The object at index i of the array `key` of `parent`, as a section.
JsonSection element(const std::string& file, const JsonSection& parent, const std::string& key,
                    std::size_t i, std::vector<std::string> known) {
    return JsonSection(file, parent.at(key)[i], fmt::format("{}[{}]", parent.path(key), i),
                       std::move(known));
}

/// The array at `key` of `parent`, non-empty; refuses anything else.
std::size_t arrayLength(const JsonSection& parent, const std::string& key,
                        const std::string& what) {
    if (!parent.has(key)) {
        parent.missing(key, "a non-empty array of " + what);
    }
    const Json& v = parent.at(key);
    if (!v.is_array() || v.empty()) {
        parent.refuse(key, v, "a non-empty array of " + what);
    }
    return v.size();
}

/// The choice `key` of `s`; when it is the first of `allowed` (none, gas), `valueKey` (its
/// coefficient, its pressure) must be absent.
std::string kindWithoutValue(const JsonSection& s, const std::string& key,
                             const std::vector<std::string>& allowed, const std::string& valueKey) {
    const std::string kind = s.choice(key, allowed, std::nullopt);
    if (kind == allowed.front() && s.has(valueKey)) {
        s.refuse(valueKey, s.at(valueKey),
                 fmt::format("absent ({} {} takes no {})", key, kind, valueKey));
    }
    return kind;
}

DampingParameters readDamping(const JsonSection& s) {
    const std::string kind =
        kindWithoutValue(s, "kind", {"none", "viscous", "local"}, "coefficient");
    if (kind == "none") {
        return {DampingKind::None, 0.0};
    }
    DampingParameters d;
    d.kind = kind == "viscous" ? DampingKind::GlobalViscous : DampingKind::CundallLocal;
    // Viscous: a fraction of the critical damping; local: Cundall's alpha, below 1.
    d.coefficient =
        s.number("coefficient", kind == "viscous" ? openClosed(0, 1) : open(0, 1), std::nullopt);
    return d;
}

PackingState readPacking(const JsonSection& s) {
    PackingState p;
    const std::string state = kindWithoutValue(s, "state", {"gas", "dense", "shear"}, "pressure");
    if (state == "gas") {
        return p;
    }
    p.kind = state == "dense" ? PackingKind::Dense : PackingKind::Shear;
    p.pressure = s.number("pressure", closed(1e2, 1e8), std::nullopt);
    return p;
}

const char* packingName(PackingKind k) {
    return k == PackingKind::Gas ? "gas" : (k == PackingKind::Dense ? "dense" : "shear");
}

const char* dampingName(DampingKind k) {
    return k == DampingKind::None ? "none"
                                  : (k == DampingKind::GlobalViscous ? "viscous" : "local");
}

/// A CSV field: quoted when it holds a comma or a quote.
std::string field(const std::string& s) {
    if (s.find_first_of(",\"") == std::string::npos) {
        return s;
    }
    std::string out = "\"";
    for (char c : s) {
        out += c == '"' ? std::string("\"\"") : std::string(1, c);
    }
    return out + "\"";
}

std::string axesFields(const StabilityCell& c) {
    return fmt::format("{},{},{},{},{},{},{},{}", field(c.id), csvNumber(c.aspectRatio),
                       csvNumber(c.stiffnessRatio), dampingName(c.damping.kind),
                       csvNumber(c.damping.coefficient), packingName(c.packing.kind),
                       csvNumber(c.packing.pressure),
                       field(dampingLabel(c.damping) + " / " + packingLabel(c.packing)));
}

const char* kAxesHeader = "cell,aspect_ratio [-],stiffness_ratio [-],damping,"
                          "damping_coefficient [-],packing,pressure [Pa],label";

/// The time-step preset's own keys.
void readStabilityKeys(const std::string& file, const JsonSection& top, StabilityMapSpec& spec) {
    const JsonSection scene =
        top.child("scene",
                  {"grains", "smallest_width", "largest_width", "size_classes", "seed", "friction",
                   "gas", "shear", "compaction_rate"},
                  false);
    readSampleGrains(scene, spec);
    spec.friction = scene.number("friction", closed(0, 10), spec.friction);
    spec.compactionRate = scene.number("compaction_rate", openClosed(0, 1e3), spec.compactionRate);
    const JsonSection gas = scene.child("gas", {"gap", "speed"}, false);
    spec.gasGap = gas.number("gap", closed(0, 100), spec.gasGap);
    spec.gasSpeed = gas.number("speed", openClosed(0, 1e3), spec.gasSpeed);
    const JsonSection shear = scene.child("shear", {"strain_rate", "pre_strain"}, false);
    spec.shearStrainRate = shear.number("strain_rate", openClosed(0, 1e3), spec.shearStrainRate);
    spec.shearPreStrain = shear.number("pre_strain", closed(0, 0.5), spec.shearPreStrain);

    const JsonSection probe =
        top.child("probe", {"steps", "precision", "bracket", "accuracy_fractions"}, false);
    spec.steps = probe.integer("steps", 100, 10000000, spec.steps);
    spec.precision = probe.number("precision", Range{1e-6, 0.5, true, true}, spec.precision);
    if (const auto b = probe.numbers("bracket", open(0, 1e3))) {
        if (b->size() != 2 || !((*b)[0] < (*b)[1])) {
            probe.refuse("bracket", probe.at("bracket"),
                         "two numbers [low, high] with 0 < low < high < 1000 (in units of "
                         "sqrt(m_min / k_n))");
        }
        spec.lowBound = (*b)[0];
        spec.highBound = (*b)[1];
    }
    if (const auto f = probe.numbers("accuracy_fractions", open(0, 1))) {
        spec.accuracyFractions = *f;
    }

    const JsonSection axes =
        top.child("axes", {"aspect_ratio", "stiffness_ratio", "damping", "packing"}, true,
                  "an object with aspect_ratio, stiffness_ratio, damping and packing");
    spec.aspectRatios = requiredNumbers(axes, "aspect_ratio", Range{0.2, 1.0, true, true});
    spec.stiffnessRatios = requiredNumbers(axes, "stiffness_ratio", Range{0.01, 100, true, true});
    spec.dampings.clear();
    for (std::size_t i = 0, n = arrayLength(axes, "damping", "damping objects"); i < n; ++i) {
        spec.dampings.push_back(
            readDamping(element(file, axes, "damping", i, {"kind", "coefficient"})));
    }
    spec.packings.clear();
    for (std::size_t i = 0, n = arrayLength(axes, "packing", "packing objects"); i < n; ++i) {
        spec.packings.push_back(
            readPacking(element(file, axes, "packing", i, {"state", "pressure"})));
    }
}

} // namespace

std::string stabilityPresetKind(const std::string& text, const std::string& file) {
    const Json root = parseStrictJson(text, file);
    if (!root.is_object()) {
        throw JsonFileError(file, "", fmt::format("{}: a stability preset is a JSON object", file));
    }
    // Only the kind is read here; each kind's reader checks every other key.
    const Json kindOnly = root.contains("kind") ? Json{{"kind", root.at("kind")}} : Json::object();
    const JsonSection top(file, kindOnly, "", {"kind"});
    return top.choice("kind", {"time_step", "servo", "geometry"}, std::string("time_step"));
}

StabilityMapSpec readStabilityPreset(const std::string& path) {
    return map_preset::readPresetFile(path, parseStabilityPreset);
}

StabilityMapSpec parseStabilityPreset(const std::string& text, const std::string& file) {
    return map_preset::parsePreset<StabilityMapSpec>(text, file, "time_step",
                                                     std::string("time_step"),
                                                     {"scene", "probe", "axes"}, readStabilityKeys);
}

std::string dampingLabel(const DampingParameters& d) {
    if (d.kind == DampingKind::None) {
        return "none";
    }
    return fmt::format("{} {}", dampingName(d.kind), shortNumber(d.coefficient));
}

std::string packingLabel(const PackingState& p) {
    if (p.kind == PackingKind::Gas) {
        return "gas";
    }
    return fmt::format("{} {} kPa", packingName(p.kind), shortNumber(p.pressure / 1e3));
}

std::vector<StabilityCell> stabilityCells(const StabilityMapSpec& spec) {
    std::vector<StabilityCell> out;
    for (double eta : spec.aspectRatios) {
        for (double kt : spec.stiffnessRatios) {
            for (const DampingParameters& d : spec.dampings) {
                for (const PackingState& p : spec.packings) {
                    StabilityCell c{{}, eta, kt, d, p};
                    std::string damping = d.kind == DampingKind::None
                                              ? "none"
                                              : dampingName(d.kind) + shortNumber(d.coefficient);
                    std::string packing =
                        p.kind == PackingKind::Gas
                            ? "gas"
                            : packingName(p.kind) + shortNumber(p.pressure / 1e3) + "kPa";
                    c.id = fmt::format("eta{}_kt{}_{}_{}", shortNumber(eta), shortNumber(kt),
                                       damping, packing);
                    out.push_back(std::move(c));
                }
            }
        }
    }
    return out;
}

std::string cellResultJson(const StabilityCellResult& r) {
    return map_preset::cellResultText(r, [&](Json& j) {
        j["aspect_ratio"] = r.cell.aspectRatio;
        j["stiffness_ratio"] = r.cell.stiffnessRatio;
        j["damping"] = dampingName(r.cell.damping.kind);
        j["damping_coefficient"] = r.cell.damping.coefficient;
        j["packing"] = packingName(r.cell.packing.kind);
        j["pressure"] = r.cell.packing.pressure;
        j["time_unit"] = r.timeUnit;
        j["detector"] = blowUpName(r.limit.detector);
        j["detector_step"] = r.limit.detectorStep;
        j["detector_detail"] = r.limit.detail;
        j["estimate"] = r.estimate;
        j["estimate_translational"] = r.estimateTranslational;
        j["estimate_rotational"] = r.estimateRotational;
        j["accuracy"] = Json::array();
        for (const AccuracyPoint& a : r.accuracy) {
            j["accuracy"].push_back({{"fraction", a.fraction},
                                     {"step", a.step},
                                     {"stable", a.stable},
                                     {"max_residual", a.maxResidual},
                                     {"final_residual", a.finalResidual}});
        }
    });
}

StabilityCellResult parseCellResult(const std::string& text, const std::string& sourceName) {
    return map_preset::parseCellResultText<StabilityCellResult, Json::exception>(
        text, sourceName, "stability", [](const Json& j, StabilityCellResult& r) {
            r.cell.aspectRatio = j.at("aspect_ratio").get<double>();
            r.cell.stiffnessRatio = j.at("stiffness_ratio").get<double>();
            const std::string damping = j.at("damping").get<std::string>();
            r.cell.damping.kind = damping == "none"      ? DampingKind::None
                                  : damping == "viscous" ? DampingKind::GlobalViscous
                                                         : DampingKind::CundallLocal;
            r.cell.damping.coefficient = j.at("damping_coefficient").get<double>();
            const std::string packing = j.at("packing").get<std::string>();
            r.cell.packing.kind = packing == "gas"     ? PackingKind::Gas
                                  : packing == "dense" ? PackingKind::Dense
                                                       : PackingKind::Shear;
            r.cell.packing.pressure = j.at("pressure").get<double>();
            r.timeUnit = j.at("time_unit").get<double>();
            const std::string detector = j.at("detector").get<std::string>();
            for (BlowUp b : {BlowUp::None, BlowUp::NonFinite, BlowUp::Displacement, BlowUp::Overlap,
                             BlowUp::KineticEnergy, BlowUp::EnergyResidual, BlowUp::UnbalancedFloor,
                             BlowUp::EngineStop}) {
                if (blowUpName(b) == detector) {
                    r.limit.detector = b;
                }
            }
            r.limit.detectorStep = j.at("detector_step").get<std::int64_t>();
            r.limit.detail = j.at("detector_detail").get<std::string>();
            r.estimate = j.at("estimate").get<double>();
            r.estimateTranslational = j.at("estimate_translational").get<double>();
            r.estimateRotational = j.at("estimate_rotational").get<double>();
            for (const Json& a : j.at("accuracy")) {
                r.accuracy.push_back({a.at("fraction").get<double>(), a.at("step").get<double>(),
                                      a.at("stable").get<bool>(),
                                      a.at("max_residual").get<double>(),
                                      a.at("final_residual").get<double>()});
            }
        });
}

std::string limitsCsv(const std::vector<StabilityCellResult>& results) {
    std::string s = kAxesHeader;
    s += ",limit [sqrt(m_min/k_n)],limit_low [sqrt(m_min/k_n)],limit_high [sqrt(m_min/k_n)],"
         "bracketed,estimate [sqrt(m_min/k_n)],estimate_translational [sqrt(m_min/k_n)],"
         "estimate_rotational [sqrt(m_min/k_n)],limit_over_estimate [-],limit [s],"
         "time_unit [s],detector,detector_step [-],probes [-],compaction_calm,cell_seconds [s]\n";
    for (const StabilityCellResult& r : results) {
        s += axesFields(r.cell);
        s += fmt::format(",{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n",
                         csvNumber(r.limit.limit), csvNumber(r.limit.low), csvNumber(r.limit.high),
                         r.limit.bracketed ? "yes" : "no", csvNumber(r.estimate),
                         csvNumber(r.estimateTranslational), csvNumber(r.estimateRotational),
                         csvNumber(r.estimate > 0 ? r.limit.limit / r.estimate : NAN),
                         csvNumber(r.limit.limit * r.timeUnit), csvNumber(r.timeUnit),
                         blowUpName(r.limit.detector), r.limit.detectorStep, r.limit.probes,
                         r.compactionCalm ? "yes" : "no", csvNumber(r.seconds));
    }
    return s;
}

std::string accuracyCsv(const std::vector<StabilityCellResult>& results) {
    std::string s = kAxesHeader;
    s += ",fraction_of_limit [-],step [sqrt(m_min/k_n)],stable,max_residual [-],"
         "final_residual [-]\n";
    for (const StabilityCellResult& r : results) {
        for (const AccuracyPoint& a : r.accuracy) {
            s += axesFields(r.cell);
            s += fmt::format(",{},{},{},{},{}\n", csvNumber(a.fraction), csvNumber(a.step),
                             a.stable ? "yes" : "no", csvNumber(a.maxResidual),
                             csvNumber(a.finalResidual));
        }
    }
    return s;
}

} // namespace grainlab
