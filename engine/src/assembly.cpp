#include "grainlab/assembly.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "grainlab/random.h"

namespace grainlab {

std::vector<double> evenlySpacedWidths(double smallest, double largest, int count) {
    if (count < 1) {
        throw std::invalid_argument(fmt::format("size classes: {}: must be >= 1", count));
    }
    std::vector<double> widths(count);
    for (int k = 0; k < count; ++k) {
        widths[k] = count == 1 ? smallest : smallest + (largest - smallest) * k / (count - 1);
    }
    return widths;
}

std::vector<OvalShape> assemblyShapes(const AssemblySpec& spec) {
    std::vector<OvalShape> shapes;
    for (double w : spec.widths) {
        shapes.push_back(makeOval(w, spec.aspectRatio, spec.closure, spec.endRadiusRatio));
    }
    return shapes;
}

SimulationState generateGridAssembly(const AssemblySpec& spec, const SimulationParameters& p) {
    if (spec.grainCount < 1) {
        throw std::invalid_argument(fmt::format("grain count {}: must be >= 1", spec.grainCount));
    }
    if (spec.widths.empty()) {
        throw std::invalid_argument("size classes: at least one width is needed");
    }
    if (!(spec.gap >= 0.0)) {
        throw std::invalid_argument(fmt::format("grid gap {}: must be >= 0", spec.gap));
    }
    if (!(spec.cellAspectRatio > 0.0)) {
        throw std::invalid_argument(
            fmt::format("cell aspect ratio {}: must be > 0", spec.cellAspectRatio));
    }
    SimulationState s;
    s.parameters = p;
    s.shapes = assemblyShapes(spec);
    const double wMax = *std::max_element(spec.widths.begin(), spec.widths.end());
    const double spacing = wMax * (1.0 + spec.gap);
    // Columns along x2, rows along x1, so that L1 / L2 ~ cellAspectRatio.
    const int n = spec.grainCount;
    int columns = std::max(1, static_cast<int>(std::ceil(std::sqrt(n / spec.cellAspectRatio))));
    int rows = (n + columns - 1) / columns;
    columns = std::max(columns, 3);
    rows = std::max(rows, 3);
    s.cell = {rows * spacing, 0.0, 0.0, columns * spacing};
    s.axes = {AxisControl{}, AxisControl{}};

    // Sizes: class k for grain k mod classes, then shuffled; orientations uniform.
    Random random(spec.seed);
    std::vector<std::int32_t> shape(n);
    for (int i = 0; i < n; ++i) {
        shape[i] = i % static_cast<int>(spec.widths.size());
    }
    for (int i = n - 1; i > 0; --i) {
        std::swap(shape[i], shape[random.below(std::uint64_t(i) + 1)]);
    }
    s.grains.resize(n);
    for (int i = 0; i < n; ++i) {
        const int row = i / columns, column = i % columns;
        s.grains.x1[i] = (row + 0.5) * spacing;
        s.grains.x2[i] = (column + 0.5) * spacing;
        s.grains.theta[i] = random.uniform(0.0, std::numbers::pi);
        s.grains.shape[i] = shape[i];
    }
    return s;
}

} // namespace grainlab
