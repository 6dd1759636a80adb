#pragma once
// The loading rate of a shear test as an inertial number, and the measured limit above which a
// test is no longer quasi-static. Used by the experiment runner (its warning), the study plan
// (the inertial-number knob) and the experiment file's documentation. Pure functions, any thread.

#include <optional>
#include <string>

#include "grainlab/experiment.h"

namespace grainlab {

/// The largest inertial number I = (axial strain rate) d sqrt(rho / p) at which the measured
/// loading-rate study (docs/speed-vs-accuracy.md, "The loading rate") found peak q/p, the q/p
/// curve and eps_v of 2000-oval samples within the seed-to-seed noise band of a three times
/// slower reference, at 15 and 100 kPa (each in its own I); at I = 10^-3 peak q/p was 2.5 % high
/// at 15 kPa, outside the band. Above it a shear test is not quasi-static.
inline constexpr double kQuasiStaticInertialNumber = 3e-4;

/// The mean equivalent diameter sqrt(4 A / pi) over an experiment's grains (its size classes
/// with their counts) [m].
double meanGrainDiameter(const ExperimentConfig& config);

/// The inertial number (inertialNumber() of measures.h) of a shear test of `config` at the
/// start of its shear at confining pressure `pressure` [Pa], where the mean stress p equals
/// the confining pressure: its axial strain rate (strain per step over the time step) times
/// the mean grain diameter times sqrt(density / pressure) [-]. While the axial stress rises
/// above the confining one p grows, so this is the largest I of the test's shear.
double shearInertialNumber(const ExperimentConfig& config, double pressure);

/// The axial strain rate [1/s] at which a shear test of `config` at confining pressure
/// `pressure` [Pa] starts at inertial number `inertial`: the inverse of shearInertialNumber().
double axialStrainRateFor(const ExperimentConfig& config, double inertial, double pressure);

/// The warning text for a shear test at `pressure` whose inertial number is above
/// kQuasiStaticInertialNumber; nothing when it is at or below it.
std::optional<std::string> inertialNumberWarning(const ExperimentConfig& config, double pressure);

} // namespace grainlab
