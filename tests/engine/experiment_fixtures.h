#pragma once
// Experiment-file fixtures for the reader's tests.

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

} // namespace grainlab::test
