#pragma once
// Experiment-file fixtures for the reader's and the runner's tests.

#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

namespace grainlab::test {

/// The smallest valid experiment file: only the required keys.
inline nlohmann::json minimalExperiment() {
    return nlohmann::json::parse(R"({
        "seed": 7,
        "grains": {"count": 50, "width_min": 1.0e-3, "width_max": 2.0e-3, "size_classes": 3,
                   "aspect_ratio": 0.6},
        "material": {"normal_stiffness": 1e8, "tangential_stiffness": 1e8, "density": 2650},
        "time_step": 1e-6,
        "compaction": {"pressures": [15e3, 25e3]},
        "shear": {"target_axial_strain": 0.1}
    })");
}

/// The quick preset (resources/experiments/quick.json) as shipped.
inline nlohmann::json quickExperiment() {
    std::ifstream in(std::string(GRAINLAB_SOURCE_DIR) + "/resources/experiments/quick.json");
    std::stringstream text;
    text << in.rdbuf();
    return nlohmann::json::parse(text.str());
}

/// The quick experiment made small: 120 grains, two pressures, a short shear.
inline nlohmann::json smallQuickExperiment() {
    nlohmann::json j = quickExperiment();
    j["grains"]["count"] = 120;
    j["compaction"]["pressures"] = {25e3, 50e3};
    j["shear"]["pressures"] = {25e3, 50e3};
    j["shear"]["target_axial_strain"] = 0.002;
    j["shear"]["max_strain_rate"] = 20.0;
    return j;
}

/// The small quick experiment at one pressure: compacted and sheared at 25 kPa.
inline nlohmann::json smallQuickExperimentAt25kPa() {
    nlohmann::json j = smallQuickExperiment();
    j["compaction"]["pressures"] = {25e3};
    j["shear"]["pressures"] = {25e3};
    return j;
}

} // namespace grainlab::test
