#include "grainlab/loading_rate.h"

#include <cmath>

#include <fmt/format.h>

#include "grainlab/assembly.h"
#include "grainlab/measures.h"

namespace grainlab {

double meanGrainDiameter(const ExperimentConfig& config) {
    const std::vector<OvalShape> shapes = assemblyShapes(config.assembly);
    const int n = config.assembly.grainCount, classes = static_cast<int>(shapes.size());
    double sum = 0;
    for (int k = 0; k < classes; ++k) {
        const int count = n / classes + (k < n % classes ? 1 : 0);
        sum += count * shapes[std::size_t(k)].equivalentDiameter();
    }
    return sum / n;
}

double shearInertialNumber(const ExperimentConfig& config, double pressure) {
    return inertialNumber(config.shear.axialStrainPerStep / config.parameters.timeStep,
                          meanGrainDiameter(config), config.parameters.density, pressure);
}

double axialStrainRateFor(const ExperimentConfig& config, double inertial, double pressure) {
    // inertialNumber() is linear in the rate: the rate of I = 1, scaled.
    return inertial /
           inertialNumber(1.0, meanGrainDiameter(config), config.parameters.density, pressure);
}

std::optional<std::string> inertialNumberWarning(const ExperimentConfig& config, double pressure) {
    const double inertial = shearInertialNumber(config, pressure);
    if (!(inertial > kQuasiStaticInertialNumber)) {
        return std::nullopt;
    }
    return fmt::format(
        "the shear at {:g} kPa runs at an inertial number I = {:.3g}, above the quasi-static "
        "limit {:.3g} measured for this protocol (at I = 1e-3 peak q/p came out 2.5 % high): "
        "its results depend on the loading rate; for quasi-static results use "
        "shear.axial_strain_per_step <= {:.3g}",
        pressure / 1000.0, inertial, kQuasiStaticInertialNumber,
        config.shear.axialStrainPerStep * kQuasiStaticInertialNumber / inertial);
}

} // namespace grainlab
