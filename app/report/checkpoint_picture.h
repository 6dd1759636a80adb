#pragma once
// `grainlab export picture` (GUI builds): one checkpoint of a run file drawn by the window's
// scene renderer into a PNG, SVG or PDF, headless: the test's checkpoint nearest an axial
// strain, its grains coloured as the window colours them, force chains and void cells as chosen.
// Main thread; starts an offscreen Qt application when none runs.

#include <string>

namespace grainlab {

struct CheckpointPictureOptions {
    std::string run;                    ///< run folder or its run.h5
    std::string test;                   ///< e.g. "p015kPa"
    double strain = 0.0;                ///< eps1 of the checkpoint wanted (the nearest is drawn)
    std::string out;                    ///< .png, .svg or .pdf; must not exist
    std::string colouring = "rotation"; ///< rotation, size, coordination, load-bearing, uniform
    std::string chains = "strong";      ///< off, strong, all
    std::string voidCells = "off";      ///< off, valence, area
    int size = 1000;                    ///< pixels of the square picture
    double rotationRange = 0.2;         ///< |rotation| at the ends of the colour scale [rad]
};

/// Draws the picture; returns 0, or 2 with a message naming the file for input refused (no such
/// run or test, --out existing), 1 when writing fails.
int runCheckpointPictureCommand(const CheckpointPictureOptions& options);

} // namespace grainlab
