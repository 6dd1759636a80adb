#pragma once
// What the time-step and servo maps' specs share (stability_map.h, servo_map.h): the preset's
// name and source, and the grains of the sample each of their cells compacts. Plain data.

#include <cstdint>
#include <string>

namespace grainlab {

/// A map preset's name and source, and the grains of the compacted sample its cells start from
/// (each map sets its own default name and grain count).
struct CompactedSampleMapSpec {
    std::string name;
    std::string sourcePath, sourceText;
    int grains = 0;              ///< N [-]
    double smallestWidth = 1e-3; ///< [m]
    double largestWidth = 2e-3;  ///< [m]
    int sizeClasses = 11;        ///< widths evenly spaced between the two [-]
    std::uint64_t seed = 1;
};

} // namespace grainlab
