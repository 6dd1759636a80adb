#include "grainlab/experiment_file.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "grainlab/experiment_limits.h"
#include "grainlab/oval_shape.h"
#include "grainlab/strict_json.h"
#include "grainlab/time_step.h"

namespace grainlab {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

const std::vector<std::string> kCriterionKeys = {"stress_tolerance", "unbalanced_force_max",
                                                 "check_interval", "calm_checks", "max_steps"};

constexpr std::int64_t kMaxInt = std::numeric_limits<std::int32_t>::max();
constexpr std::int64_t kMaxInt64 = std::numeric_limits<std::int64_t>::max();

/// Relative tolerance of the derived bounds below: a bound computed from the file's values
/// (2 x 5e-4 / 1e-6 s = 1000.0000000000001 /s) must let the round number it stands for pass.
constexpr double kBoundTolerance = 1e-9;

/// Refuses a servo rate cap `rate` [1/s] above kMaxStrainPerStep per time step, the cell strain
/// per step that the neighbour list follows (checked once the time step is known stable).
void checkStrainRate(const JsonSection& s, double rate, double timeStep) {
    const double cap = kMaxStrainPerStep / timeStep;
    if (rate > cap * (1.0 + kBoundTolerance)) {
        const std::string allowed =
            fmt::format("a number in (0, {:g}] [1/s]: with time_step = {:g} s, a cell strain of "
                        "at most {} per step, which the neighbour list follows",
                        cap, timeStep, kMaxStrainPerStep);
        if (!s.has("max_strain_rate")) {
            s.fail("max_strain_rate", fmt::format("{} (default {:g}) must be {}; set it",
                                                  s.path("max_strain_rate"), rate, allowed));
        }
        s.refuse("max_strain_rate", s.at("max_strain_rate"), allowed);
    }
}

/// The lateral servo's rate cap must exceed the axial strain rate by this factor: a sample
/// sheared at eps1_rate widens at eps1_rate (1 + DI), DI the dilatancy index (on dense ovals
/// about 0.7 on average over the shear, about 1 at its largest). Measured below it: 8450 ovals
/// sheared at 1.6 /s with the cap at 1 /s were squeezed until the overlap guard stopped them; 2000
/// ovals at 4.7 /s with the cap at 5 /s could not dilate (eps_v rose where the slow reference's
/// fell).
constexpr double kLateralServoMargin = 2.0;

/// Refuses a shear whose lateral servo cannot follow the axial loading.
void checkLateralServoFollows(const JsonSection& s, const ShearSpec& shear, double timeStep) {
    const double axialRate = shear.axialStrainPerStep / timeStep;
    if (shear.maxStrainRate >= kLateralServoMargin * axialRate * (1.0 - kBoundTolerance)) {
        return;
    }
    const std::string allowed = fmt::format(
        "at least {:g} /s, {:g} times the axial strain rate shear.axial_strain_per_step / "
        "time_step = {:g} /s: a dilating sample widens faster than it is shortened, and a "
        "slower lateral servo holds it from dilating or squeezes the grains until they overlap",
        kLateralServoMargin * axialRate, kLateralServoMargin, axialRate);
    if (!s.has("max_strain_rate")) {
        s.fail("max_strain_rate",
               fmt::format("{} (default {:g}) must be {}; set it", s.path("max_strain_rate"),
                           shear.maxStrainRate, allowed));
    }
    s.refuse("max_strain_rate", s.at("max_strain_rate"), allowed);
}

/// Refuses a servo interval above 1 whose lag number per unit gain passes kMaxServoLagPerGain,
/// where the servo map measured the lateral stress out of its 1 % band in shear: the servo costs
/// nothing per step, so a longer interval only lets the error build up.
void checkServoInterval(const JsonSection& servo, const ExperimentConfig& c) {
    const int interval = c.parameters.servo.interval;
    if (interval == 1 || c.shear.pressures.empty()) {
        return;
    }
    const double gain = c.parameters.servo.gain;
    const double lowest = *std::min_element(c.shear.pressures.begin(), c.shear.pressures.end());
    const double lagOfOne =
        servoLagNumber(1, c.shear.axialStrainPerStep, c.parameters.normalStiffness, lowest);
    const double largest = std::max(1.0, std::floor(kMaxServoLagPerGain * gain / lagOfOne));
    if (double(interval) <= largest) {
        return;
    }
    servo.refuse(
        "interval", servo.at("interval"),
        fmt::format("an integer in [1, {:.0f}] for this file: over one interval the axial loading "
                    "builds up a lateral stress error that the servo removes at the rate of its "
                    "gain, in proportion to the lag number interval x shear.axial_strain_per_step "
                    "x material.normal_stiffness / (lowest shear pressure x 1 m) over servo.gain, "
                    "here {:.3g}; the servo map (docs/stability.md) measured the lateral stress "
                    "out of its 1 % band from {} on, and the bound is {} (a margin of {:.2g})",
                    largest, double(interval) * lagOfOne / gain, kMeasuredServoLagPerGain,
                    kMaxServoLagPerGain, kMeasuredServoLagPerGain / kMaxServoLagPerGain));
}

bool finitePositive(double x) {
    return std::isfinite(x) && x > 0.0;
}

/// Every quantity the engine derives from a shape and the density is a finite positive number.
bool finiteShape(const OvalShape& s, double density) {
    return finitePositive(s.halfWidth) && finitePositive(s.halfHeight) &&
           finitePositive(s.endRadius) && finitePositive(s.sideRadius) && finitePositive(s.area) &&
           finitePositive(s.polarMoment) && finitePositive(density * s.area) &&
           finitePositive(density * s.polarMoment) && std::isfinite(s.cosJunction) &&
           std::isfinite(s.sinJunction);
}

EquilibriumCriterion readCriterion(const JsonSection& s) {
    EquilibriumCriterion c;
    const EquilibriumCriterion d;
    c.stressTolerance = s.number("stress_tolerance", open(0.0, 1.0), d.stressTolerance);
    c.unbalancedForceMax = s.number("unbalanced_force_max", positive(), d.unbalancedForceMax);
    c.checkInterval = s.integer("check_interval", 1, kMaxInt64, d.checkInterval);
    c.calmChecks = static_cast<int>(s.integer("calm_checks", 1, kMaxInt, d.calmChecks));
    c.maxSteps = s.integer("max_steps", 1, kMaxInt64, d.maxSteps);
    return c;
}

void readGrains(const JsonSection& g, AssemblySpec& a) {
    // Bounded by this machine's memory: a count it cannot hold would allocate until it runs out.
    const std::int64_t count = g.integer("count", 1, kMaxInt64, std::nullopt);
    if (count > maxGrainCount()) {
        g.refuse("count", g.at("count"),
                 fmt::format("an integer in [1, {}] (this machine's memory, {:.1f} GiB, at {} KiB "
                             "per grain)",
                             maxGrainCount(),
                             double(maxGrainCount()) * kBytesPerGrain / (1024.0 * 1024 * 1024),
                             kBytesPerGrain / 1024));
    }
    a.grainCount = static_cast<int>(count);
    const Range width = closed(kMinGrainWidth, kMaxGrainWidth);
    // One shape per size class is built before the run: no more classes than grains.
    const std::int64_t maxClasses = std::min<std::int64_t>(count, kMaxSizeClasses);
    if (g.has("widths")) {
        for (const char* k : {"width_min", "width_max", "size_classes"}) {
            if (g.has(k)) {
                g.fail(k, fmt::format("{} and {} exclude each other: give either the list of "
                                      "widths or width_min, width_max and size_classes",
                                      g.path(k), g.path("widths")));
            }
        }
        a.widths = *g.numbers("widths", width);
        if (std::int64_t(a.widths.size()) > maxClasses) {
            g.fail("widths",
                   fmt::format("{} lists {} widths: at most {} (no more size classes "
                               "than grains, and at most {})",
                               g.path("widths"), a.widths.size(), maxClasses, kMaxSizeClasses));
        }
    } else {
        const double wMin = g.number("width_min", width, std::nullopt);
        const double wMax = g.number("width_max", closed(wMin, kMaxGrainWidth), std::nullopt);
        const int classes =
            static_cast<int>(g.integer("size_classes", 1, maxClasses, std::nullopt));
        if (classes == 1 && wMax != wMin) {
            g.refuse("width_max", g.at("width_max"),
                     fmt::format("equal to width_min ({}) when size_classes is 1", wMin));
        }
        a.widths = evenlySpacedWidths(wMin, wMax, classes);
    }
    a.aspectRatio = g.number("aspect_ratio", openClosed(0.0, 1.0), std::nullopt);
    const std::string closure =
        g.choice("closure", {"equal_area", "end_radius_ratio"}, std::string("equal_area"));
    if (closure == "end_radius_ratio") {
        a.closure = OvalClosure::EndRadiusRatio;
        a.endRadiusRatio =
            g.number("end_radius_ratio", open(0.0, a.aspectRatio / 2.0), std::nullopt);
    } else {
        a.closure = OvalClosure::EqualArea;
        a.endRadiusRatio = 0.0;
        if (g.has("end_radius_ratio")) {
            g.fail("end_radius_ratio",
                   fmt::format("{} is only used with \"closure\": \"end_radius_ratio\" (closure "
                               "is \"equal_area\")",
                               g.path("end_radius_ratio")));
        }
    }
    // Bounded so that the initial cell's lengths stay finite and the cell holds more than one
    // grid row each way.
    a.gap = g.number("grid_gap", closed(0.0, kMaxGridGap), 0.1);
    a.cellAspectRatio =
        g.number("cell_aspect_ratio", closed(1.0 / kMaxCellAspectRatio, kMaxCellAspectRatio), 1.0);
}

void readDamping(const JsonSection& d, DampingParameters& damping) {
    const std::string kind = d.choice("kind", {"global_viscous", "cundall_local", "none"},
                                      std::string("global_viscous"));
    if (kind == "none") {
        damping.kind = DampingKind::None;
        if (d.has("coefficient")) {
            d.fail("coefficient", fmt::format("{} is not used when damping.kind is \"none\"; "
                                              "remove it",
                                              d.path("coefficient")));
        }
        damping.coefficient = 0.0;
        return;
    }
    damping.kind = kind == "cundall_local" ? DampingKind::CundallLocal : DampingKind::GlobalViscous;
    damping.coefficient = d.number("coefficient", closed(0.0, 1.0), 0.05);
}

void readPressures(const JsonSection& c, CompactionSpec& compaction) {
    const auto pressures = c.numbers("pressures", positive());
    if (!pressures) {
        c.missing("pressures", "a non-empty array of pressures > 0, ascending [Pa]");
    }
    for (std::size_t i = 1; i < pressures->size(); ++i) {
        if (!((*pressures)[i] > (*pressures)[i - 1])) {
            c.refuse(fmt::format("pressures[{}]", i), c.at("pressures")[i],
                     fmt::format("greater than pressures[{}] = {} (pressures strictly ascending)",
                                 i - 1, (*pressures)[i - 1]));
        }
    }
    compaction.pressures = *pressures;
}

void readShearPressures(const JsonSection& s, const CompactionSpec& compaction, ShearSpec& shear) {
    const auto pressures = s.numbers("pressures", positive());
    if (!pressures) {
        shear.pressures = compaction.pressures;
        return;
    }
    std::size_t bad = 0;
    if (const std::string allowed = shearPressureRule(compaction.pressures, *pressures, bad);
        !allowed.empty()) {
        s.refuse(fmt::format("pressures[{}]", bad), s.at("pressures")[bad], allowed);
    }
    shear.pressures = *pressures;
}

std::string fileStem(const std::string& path) {
    const auto slash = path.find_last_of("/\\");
    std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
    const auto dot = name.find_last_of('.');
    if (dot != std::string::npos && dot > 0) {
        name = name.substr(0, dot);
    }
    return name.empty() ? "experiment" : name;
}

/// The grain shapes the file implies, each derived quantity finite: a width is blamed when its
/// disk is already out of range, the shape's ratio when only the oval is, the density when only
/// the masses are.
std::vector<OvalShape> grainShapes(const JsonSection& top, const ExperimentConfig& config,
                                   const std::string& sourceName) {
    const SimulationParameters& p = config.parameters;
    std::vector<OvalShape> shapes;
    const std::string ratioKey = config.assembly.closure == OvalClosure::EndRadiusRatio
                                     ? "grains.end_radius_ratio"
                                     : "grains.aspect_ratio";
    const auto refuseShape = [&](const std::string& key, const std::string& why) {
        throw ExperimentFileError(sourceName, key, fmt::format("{}: {}", key, why));
    };
    for (std::size_t i = 0; i < config.assembly.widths.size(); ++i) {
        const double w = config.assembly.widths[i];
        const std::string widthKey = top.has("grains") && top.at("grains").contains("widths")
                                         ? fmt::format("grains.widths[{}]", i)
                                     : i + 1 == config.assembly.widths.size() ? "grains.width_max"
                                                                              : "grains.width_min";
        OvalShape disk;
        try {
            disk = makeOval(w, 1.0);
        } catch (const std::invalid_argument& e) {
            refuseShape(widthKey, fmt::format("no valid grain of width {} m: {}", w, e.what()));
        }
        // The width alone (unit density): a density that leaves no finite mass is blamed below.
        if (!finiteShape(disk, 1.0)) {
            refuseShape(widthKey,
                        fmt::format("a grain of width {} m has no finite area, mass and moment of "
                                    "inertia; widths must be in [{}, {}] m",
                                    w, kMinGrainWidth, kMaxGrainWidth));
        }
        try {
            shapes.push_back(makeOval(w, config.assembly.aspectRatio, config.assembly.closure,
                                      config.assembly.endRadiusRatio));
        } catch (const std::invalid_argument& e) {
            refuseShape(ratioKey, fmt::format("no valid oval: {}", e.what()));
        }
        if (!finiteShape(shapes.back(), 1.0)) {
            refuseShape(ratioKey, fmt::format("the oval of width {} m has non-finite or zero arc "
                                              "radii, area or moment of inertia; every derived "
                                              "quantity must be finite (use a larger ratio)",
                                              w));
        }
        if (!finiteShape(shapes.back(), p.density)) {
            refuseShape("material.density",
                        fmt::format("density {} kg/m^3 gives a grain of width {} m no finite "
                                    "mass or moment of inertia",
                                    p.density, w));
        }
    }
    return shapes;
}

/// What the tests' order must satisfy (probes from a strain or a peak follow a monotonic test),
/// and their keys that depend on the shear section.
void checkTestOrder(const JsonSection& top, const ExperimentConfig& config,
                    const std::string& sourceName) {
    for (std::size_t k = 0; k < config.tests.size(); ++k) {
        const LoadingPath& t = config.tests[k];
        const std::string at =
            top.has("test") && top.at("test").is_array() ? fmt::format("test[{}].", k) : "test.";
        if (t.kind == LoadingPath::Kind::Probes && t.start != LoadingPath::Start::End) {
            const bool afterMonotonic = k > 0 && isMonotonicKind(config.tests[k - 1].kind);
            if (!afterMonotonic) {
                throw ExperimentFileError(
                    sourceName, at + "start",
                    fmt::format("{}start = \"{}\": probes from a strain or the peak of a test must "
                                "follow that test in the list, and it must be drained, "
                                "constant_volume, constant_p or stress_path (\"end\" starts "
                                "anywhere)",
                                at, t.start == LoadingPath::Start::Peak ? "peak" : "strain"));
            }
            if (t.start == LoadingPath::Start::Strain &&
                !(t.startStrain <= config.shear.targetAxialStrain)) {
                throw ExperimentFileError(
                    sourceName, at + "start_strain",
                    fmt::format("{}start_strain = {:g}: must be in (0, {:g}], the test's "
                                "shear.target_axial_strain",
                                at, t.startStrain, config.shear.targetAxialStrain));
            }
        }
        if (t.kind == LoadingPath::Kind::Probes && t.plane == LoadingPath::Plane::Stress) {
            throw ExperimentFileError(sourceName, at + "plane",
                                      fmt::format("{}plane = \"stress\": not available in this "
                                                  "version (available: \"strain\")",
                                                  at));
        }
        if (t.kind == LoadingPath::Kind::Cyclic && t.control == LoadingPath::Control::Strain &&
            !(config.shear.axialStrainPerStep <= t.amplitude)) {
            throw ExperimentFileError(
                sourceName, at + "amplitude",
                fmt::format("{}amplitude = {:g}: must be at least shear.axial_strain_per_step "
                            "({:g}), the strain of one step",
                            at, t.amplitude, config.shear.axialStrainPerStep));
        }
    }
}

} // namespace

ExperimentConfig parseExperimentText(const std::string& text, const std::string& sourceName) {
    const Json root = parseStrictJson(text, sourceName);
    const JsonSection top(sourceName, root, "",
                          {"name", "description", "seed", "threads", "grains", "material",
                           "time_step", "damping", "servo", "stability", "neighbour_skin",
                           "compaction", "shear", "record", "test"});
    if (top.has("description") && !top.at("description").is_string()) {
        top.refuse("description", top.at("description"),
                   fmt::format("a string (got {})", jsonTypeName(top.at("description"))));
    }

    ExperimentConfig config;
    config.sourcePath = sourceName;
    config.sourceText = text;
    config.name = top.text("name", fileStem(sourceName));
    config.assembly.seed =
        static_cast<std::uint64_t>(top.integer("seed", 0, kMaxInt64, std::nullopt));

    SimulationParameters& p = config.parameters;
    p.threads = static_cast<int>(top.integer("threads", 1, 1024, 1));

    readGrains(
        top.child("grains",
                  {"count", "widths", "width_min", "width_max", "size_classes", "aspect_ratio",
                   "closure", "end_radius_ratio", "grid_gap", "cell_aspect_ratio"},
                  true,
                  "an object with count, width_min, width_max, size_classes and "
                  "aspect_ratio"),
        config.assembly);

    const JsonSection material =
        top.child("material", {"normal_stiffness", "tangential_stiffness", "density"}, true,
                  "an object with normal_stiffness, tangential_stiffness and density");
    p.normalStiffness = material.number("normal_stiffness", positive(), std::nullopt);
    p.tangentialStiffness = material.number("tangential_stiffness", positive(), std::nullopt);
    p.density = material.number("density", positive(), std::nullopt);

    p.timeStep = top.number("time_step", positive(), std::nullopt);
    readDamping(top.child("damping", {"kind", "coefficient"}, false), p.damping);

    const JsonSection servo = top.child("servo", {"gain", "integral_gain", "interval"}, false);
    const ServoParameters servoDefaults;
    p.servo.gain = servo.number("gain", positive(), servoDefaults.gain);
    if (p.servo.gain > kMaxServoGain) {
        servo.refuse(
            "gain", servo.at("gain"),
            fmt::format(
                "a number in (0, {}]: the lateral stress control of a shear was measured "
                "to oscillate or diverge from g = {} on (the smallest stable limit over "
                "confining pressures, grain shapes and servo intervals, docs/stability.md); "
                "the bound keeps a margin of {:.2g} below it",
                kMaxServoGain, kMeasuredServoGainLimit, kMeasuredServoGainLimit / kMaxServoGain));
    }
    p.servo.integralGain =
        servo.number("integral_gain", closed(0.0, 1.0), servoDefaults.integralGain);
    p.servo.interval = static_cast<int>(servo.integer("interval", 1, kMaxInt, 1));

    const JsonSection stability = top.child(
        "stability", {"design_coordination", "max_overlap_fraction", "max_step_fraction"}, false);
    const StabilityParameters stabilityDefaults;
    p.stability.designCoordination = static_cast<int>(
        stability.integer("design_coordination", 1, 64, stabilityDefaults.designCoordination));
    p.stability.maxOverlapFraction = stability.number("max_overlap_fraction", openClosed(0.0, 1.0),
                                                      stabilityDefaults.maxOverlapFraction);
    p.stability.maxStepFraction = stability.number("max_step_fraction", openClosed(0.0, 1.0),
                                                   stabilityDefaults.maxStepFraction);
    p.neighbourSkin = top.number("neighbour_skin", nonNegative(), 0.0);

    const JsonSection compaction =
        top.child("compaction", {"friction", "pressures", "max_strain_rate", "criterion"}, true,
                  "an object with at least pressures");
    config.compaction.friction = compaction.number("friction", nonNegative(), 0.0);
    readPressures(compaction, config.compaction);
    config.compaction.maxStrainRate = compaction.number("max_strain_rate", positive(), 20.0);
    config.compaction.criterion =
        readCriterion(compaction.child("criterion", kCriterionKeys, false));

    const JsonSection shear = top.child("shear",
                                        {"friction", "pressures", "axial_strain_per_step",
                                         "target_axial_strain", "max_strain_rate", "equilibration"},
                                        true, "an object with at least target_axial_strain");
    config.shear.friction = shear.number("friction", nonNegative(), 0.5);
    readShearPressures(shear, config.compaction, config.shear);
    config.shear.targetAxialStrain =
        shear.number("target_axial_strain", open(0.0, 1.0), std::nullopt);
    config.shear.axialStrainPerStep =
        shear.number("axial_strain_per_step", open(0.0, config.shear.targetAxialStrain), 2e-7);
    if (config.shear.axialStrainPerStep > kMaxStrainPerStep) {
        shear.refuse("axial_strain_per_step", shear.at("axial_strain_per_step"),
                     fmt::format("a number in (0, {}]: the neighbour list follows a cell strain of "
                                 "at most {} per step",
                                 kMaxStrainPerStep, kMaxStrainPerStep));
    }
    config.shear.maxStrainRate = shear.number("max_strain_rate", positive(), 1.0);
    config.shear.equilibration = readCriterion(shear.child("equilibration", kCriterionKeys, false));

    const JsonSection record = top.child(
        "record",
        {"strain_interval", "step_interval", "snapshot_strain_interval", "snapshot_step_interval"},
        false);
    const RecordSpec recordDefaults;
    config.record.strainInterval =
        record.number("strain_interval", positive(), recordDefaults.strainInterval);
    config.record.stepInterval =
        record.integer("step_interval", 1, kMaxInt64, recordDefaults.stepInterval);
    config.record.snapshotStrainInterval = record.number("snapshot_strain_interval", positive(),
                                                         recordDefaults.snapshotStrainInterval);
    config.record.snapshotStepInterval =
        record.integer("snapshot_step_interval", 1, kMaxInt64, recordDefaults.snapshotStepInterval);

    // The first stage is compaction: the state starts with its friction and rate cap; the
    // runner sets both per stage.
    p.friction = config.compaction.friction;
    p.servo.maxStrainRate = config.compaction.maxStrainRate;

    try {
        checkTimeStep(grainShapes(top, config, sourceName), p);
    } catch (const std::invalid_argument& e) {
        throw ExperimentFileError(sourceName, "time_step",
                                  fmt::format("time_step = {}: {}", p.timeStep, e.what()));
    }
    checkStrainRate(compaction, config.compaction.maxStrainRate, p.timeStep);
    checkStrainRate(shear, config.shear.maxStrainRate, p.timeStep);
    checkLateralServoFollows(shear, config.shear, p.timeStep);
    checkServoInterval(servo, config);
    config.tests = readLoadingPaths(top);
    checkTestOrder(top, config, sourceName);
    return config;
}

ExperimentConfig readExperimentFile(const std::string& path) {
    return parseExperimentText(readInputFile(path, "experiment file"), path);
}

std::string shearPressureRule(const std::vector<double>& compaction,
                              const std::vector<double>& shear, std::size_t& index) {
    std::string list;
    for (double p : compaction) {
        list += (list.empty() ? "" : ", ") + fmt::format("{}", p);
    }
    for (index = 0; index < shear.size(); ++index) {
        const double p = shear[index];
        if (std::find(compaction.begin(), compaction.end(), p) == compaction.end()) {
            return fmt::format("one of the compaction pressures ({})", list);
        }
        if (std::find(shear.begin(), shear.begin() + index, p) != shear.begin() + index) {
            return "listed once (it appears twice)";
        }
    }
    return "";
}

} // namespace grainlab
