// The state layout of checkpoints and samples in the run file (docs/formats.md, "State
// layout"): every field of SimulationState, so that a run continues from it bit for bit.
#include <algorithm>
#include <string>
#include <vector>

#include "grainlab/enum_names.h"
#include "run_file_io.h"

namespace grainlab::hdf5io {

namespace {

/// The damping kinds as the run file names them.
constexpr EnumName<DampingKind> kDampingNames[] = {{DampingKind::None, "none"},
                                                   {DampingKind::CundallLocal, "cundall_local"},
                                                   {DampingKind::GlobalViscous, "global_viscous"}};

const char* dampingName(DampingKind kind) {
    return enumName(kDampingNames, kind, "global_viscous");
}

DampingKind dampingFromName(const std::string& name) {
    if (const auto kind = enumFromName(kDampingNames, name)) {
        return *kind;
    }
    throw std::runtime_error(fmt::format("unknown damping_kind \"{}\"", name));
}

const char* axisModeName(AxisMode mode) {
    return enumName(kAxisModeNames, mode, "strain");
}

AxisMode axisFromName(const std::string& name) {
    if (const auto mode = enumFromName(kAxisModeNames, name)) {
        return *mode;
    }
    throw std::runtime_error(fmt::format("unknown axis mode \"{}\"", name));
}

void writeParameters(H5::Group& g, const SimulationParameters& p) {
    writeAttribute(g, "time_step", p.timeStep);
    writeAttribute(g, "normal_stiffness", p.normalStiffness);
    writeAttribute(g, "tangential_stiffness", p.tangentialStiffness);
    writeAttribute(g, "friction", p.friction);
    writeAttribute(g, "density", p.density);
    writeAttribute(g, "damping_kind", std::string(dampingName(p.damping.kind)));
    writeAttribute(g, "damping_coefficient", p.damping.coefficient);
    writeAttribute(g, "servo_gain", p.servo.gain);
    writeAttribute(g, "servo_integral_gain", p.servo.integralGain);
    writeAttribute(g, "servo_max_strain_rate", p.servo.maxStrainRate);
    writeAttribute(g, "servo_interval", std::int32_t(p.servo.interval));
    writeAttribute(g, "design_coordination", std::int32_t(p.stability.designCoordination));
    writeAttribute(g, "max_overlap_fraction", p.stability.maxOverlapFraction);
    writeAttribute(g, "max_step_fraction", p.stability.maxStepFraction);
    writeAttribute(g, "neighbour_skin", p.neighbourSkin);
    writeAttribute(g, "threads", std::int32_t(p.threads));
    writeAttribute(g, "all_arc_pairs", std::uint8_t(p.allArcPairs ? 1 : 0));
}

SimulationParameters readParameters(const H5::Group& g) {
    SimulationParameters p;
    p.timeStep = readAttribute<double>(g, "time_step");
    p.normalStiffness = readAttribute<double>(g, "normal_stiffness");
    p.tangentialStiffness = readAttribute<double>(g, "tangential_stiffness");
    p.friction = readAttribute<double>(g, "friction");
    p.density = readAttribute<double>(g, "density");
    p.damping.kind = dampingFromName(readStringAttribute(g, "damping_kind"));
    p.damping.coefficient = readAttribute<double>(g, "damping_coefficient");
    p.servo.gain = readAttribute<double>(g, "servo_gain");
    p.servo.integralGain = readAttribute<double>(g, "servo_integral_gain");
    p.servo.maxStrainRate = readAttribute<double>(g, "servo_max_strain_rate");
    p.servo.interval = readAttribute<std::int32_t>(g, "servo_interval");
    p.stability.designCoordination = readAttribute<std::int32_t>(g, "design_coordination");
    p.stability.maxOverlapFraction = readAttribute<double>(g, "max_overlap_fraction");
    p.stability.maxStepFraction = readAttribute<double>(g, "max_step_fraction");
    p.neighbourSkin = readAttribute<double>(g, "neighbour_skin");
    p.threads = readAttribute<std::int32_t>(g, "threads");
    p.allArcPairs = readAttribute<std::uint8_t>(g, "all_arc_pairs") != 0;
    return p;
}

void writeShapes(H5::Group& g, const std::vector<OvalShape>& shapes) {
    const auto column = [&](const char* name, const char* unit, auto member) {
        std::vector<double> v;
        for (const auto& s : shapes) {
            v.push_back(s.*member);
        }
        writeArray(g, name, v, unit);
    };
    column("width", "m", &OvalShape::width);
    column("height", "m", &OvalShape::height);
    column("half_width", "m", &OvalShape::halfWidth);
    column("half_height", "m", &OvalShape::halfHeight);
    column("end_radius", "m", &OvalShape::endRadius);
    column("side_radius", "m", &OvalShape::sideRadius);
    column("junction_angle", "rad", &OvalShape::junctionAngle);
    column("cos_junction", "-", &OvalShape::cosJunction);
    column("sin_junction", "-", &OvalShape::sinJunction);
    column("area", "m^2", &OvalShape::area);
    column("polar_moment", "m^4", &OvalShape::polarMoment);
    std::vector<std::uint8_t> disk;
    for (const auto& s : shapes) {
        disk.push_back(s.isDisk ? 1 : 0);
    }
    writeArray(g, "is_disk", disk, "-");
}

std::vector<OvalShape> readShapes(const H5::Group& g) {
    const std::vector<double> width = readArray<double>(g, "width");
    std::vector<OvalShape> shapes(width.size());
    const auto column = [&](const char* name, auto member) {
        const std::vector<double> v = readArray<double>(g, name);
        if (v.size() != shapes.size()) {
            throw std::runtime_error(
                fmt::format("shapes/{}: {} values for {} shapes", name, v.size(), shapes.size()));
        }
        for (std::size_t i = 0; i < v.size(); ++i) {
            shapes[i].*member = v[i];
        }
    };
    column("width", &OvalShape::width);
    column("height", &OvalShape::height);
    column("half_width", &OvalShape::halfWidth);
    column("half_height", &OvalShape::halfHeight);
    column("end_radius", &OvalShape::endRadius);
    column("side_radius", &OvalShape::sideRadius);
    column("junction_angle", &OvalShape::junctionAngle);
    column("cos_junction", &OvalShape::cosJunction);
    column("sin_junction", &OvalShape::sinJunction);
    column("area", &OvalShape::area);
    column("polar_moment", &OvalShape::polarMoment);
    const std::vector<std::uint8_t> disk = readArray<std::uint8_t>(g, "is_disk");
    if (disk.size() != shapes.size()) {
        throw std::runtime_error("shapes/is_disk: wrong length");
    }
    for (std::size_t i = 0; i < disk.size(); ++i) {
        shapes[i].isDisk = disk[i] != 0;
    }
    return shapes;
}

} // namespace

void writeState(H5::Group& g, const SimulationState& s) {
    writeAttribute(g, "step", std::int64_t(s.step));
    writeAttribute(g, "time", s.time);
    writeAttribute(g, "boundary_work", s.boundaryWork);
    writeAttribute(g, "friction_work", s.frictionWork);
    writeAttribute(g, "damping_work", s.dampingWork);
    writeAttribute(g, "grain_count", std::int64_t(s.grains.size()));
    writeAttribute(g, "pair_count", std::int64_t(s.pairs.size()));

    writeArray(g, "cell", s.cell, "m");
    writeArray(g, "velocity_gradient", s.velocityGradient, "1/s");
    writeArray(g, "servo_integral", s.servoIntegral, "1/s");
    {
        H5::Group axes = g.createGroup("axes");
        const std::vector<std::string> modes = {axisModeName(s.axes[0].mode),
                                                axisModeName(s.axes[1].mode)};
        writeStringListAttribute(axes, "mode", modes);
        writeArray(axes, "strain_rate",
                   std::array<double, 2>{s.axes[0].strainRate, s.axes[1].strainRate}, "1/s");
        writeArray(axes, "target_stress",
                   std::array<double, 2>{s.axes[0].targetStress, s.axes[1].targetStress}, "Pa");
        writeArray(axes, "reference_length",
                   std::array<double, 2>{s.axes[0].referenceLength, s.axes[1].referenceLength},
                   "m");
        // The path fields are written only when an axis uses them, so a file of the other
        // modes keeps its layout; a reader defaults them to 0 when absent.
        const auto usesPath = [](const AxisControl& a) {
            return a.mode == AxisMode::ConstantArea || a.mode == AxisMode::StressPath;
        };
        const bool pathModes = usesPath(s.axes[0]) || usesPath(s.axes[1]);
        if (pathModes) {
            writeArray(axes, "reference_area",
                       std::array<double, 2>{s.axes[0].referenceArea, s.axes[1].referenceArea},
                       "m^2");
            writeArray(axes, "path_slope",
                       std::array<double, 2>{s.axes[0].pathSlope, s.axes[1].pathSlope}, "-");
            writeArray(axes, "path_origin",
                       std::array<double, 2>{s.axes[0].pathOrigin, s.axes[1].pathOrigin}, "Pa");
        }
    }
    {
        H5::Group shapes = g.createGroup("shapes");
        writeShapes(shapes, s.shapes);
    }
    {
        H5::Group grains = g.createGroup("grains");
        writeArray(grains, "x1", s.grains.x1, "m");
        writeArray(grains, "x2", s.grains.x2, "m");
        writeArray(grains, "theta", s.grains.theta, "rad");
        writeArray(grains, "v1", s.grains.v1, "m/s");
        writeArray(grains, "v2", s.grains.v2, "m/s");
        writeArray(grains, "omega", s.grains.omega, "rad/s");
        writeArray(grains, "shape", s.grains.shape, "-");
    }
    {
        H5::Group pairs = g.createGroup("pairs");
        writeArray(pairs, "first", s.pairs.first, "-");
        writeArray(pairs, "second", s.pairs.second, "-");
        writeArray(pairs, "shift1", s.pairs.shift1, "-");
        writeArray(pairs, "shift2", s.pairs.shift2, "-");
        writeArray(pairs, "tangential_force", s.pairs.tangentialForce, "N");
        writeArray(pairs, "sliding", s.pairs.sliding, "-");
    }
    {
        H5::Group neighbours = g.createGroup("neighbours");
        writeArray(neighbours, "reference_x1", s.reference1, "m");
        writeArray(neighbours, "reference_x2", s.reference2, "m");
        writeArray(neighbours, "reference_cell", s.referenceCell, "m");
    }
    {
        H5::Group parameters = g.createGroup("parameters");
        writeParameters(parameters, s.parameters);
    }
}

SimulationState readState(const H5::Group& g) {
    SimulationState s;
    s.step = readAttribute<std::int64_t>(g, "step");
    s.time = readAttribute<double>(g, "time");
    s.boundaryWork = readAttribute<double>(g, "boundary_work");
    s.frictionWork = readAttribute<double>(g, "friction_work");
    s.dampingWork = readAttribute<double>(g, "damping_work");
    s.cell = readFixed<double, 4>(g, "cell");
    s.velocityGradient = readFixed<double, 4>(g, "velocity_gradient");
    s.servoIntegral = readFixed<double, 2>(g, "servo_integral");
    {
        const H5::Group axes = g.openGroup("axes");
        const auto modes = readStringListAttribute(axes, "mode");
        const auto rates = readFixed<double, 2>(axes, "strain_rate");
        const auto targets = readFixed<double, 2>(axes, "target_stress");
        const auto lengths = readFixed<double, 2>(axes, "reference_length");
        if (modes.size() != 2) {
            throw std::runtime_error("axes/mode: expected two modes");
        }
        const auto optional = [&](const char* name) {
            return axes.nameExists(name) ? readFixed<double, 2>(axes, name)
                                         : std::array<double, 2>{};
        };
        const auto areas = optional("reference_area");
        const auto slopes = optional("path_slope");
        const auto origins = optional("path_origin");
        for (int a = 0; a < 2; ++a) {
            s.axes[a] = {axisFromName(modes[a]),
                         rates[a],
                         targets[a],
                         lengths[a],
                         areas[a],
                         slopes[a],
                         origins[a]};
        }
    }
    s.shapes = readShapes(g.openGroup("shapes"));
    {
        const H5::Group grains = g.openGroup("grains");
        s.grains.x1 = readArray<double>(grains, "x1");
        s.grains.x2 = readArray<double>(grains, "x2");
        s.grains.theta = readArray<double>(grains, "theta");
        s.grains.v1 = readArray<double>(grains, "v1");
        s.grains.v2 = readArray<double>(grains, "v2");
        s.grains.omega = readArray<double>(grains, "omega");
        s.grains.shape = readArray<std::int32_t>(grains, "shape");
    }
    {
        const H5::Group pairs = g.openGroup("pairs");
        s.pairs.first = readArray<std::int32_t>(pairs, "first");
        s.pairs.second = readArray<std::int32_t>(pairs, "second");
        s.pairs.shift1 = readArray<std::int32_t>(pairs, "shift1");
        s.pairs.shift2 = readArray<std::int32_t>(pairs, "shift2");
        s.pairs.tangentialForce = readArray<double>(pairs, "tangential_force");
        s.pairs.sliding = readArray<std::uint8_t>(pairs, "sliding");
    }
    {
        const H5::Group neighbours = g.openGroup("neighbours");
        s.reference1 = readArray<double>(neighbours, "reference_x1");
        s.reference2 = readArray<double>(neighbours, "reference_x2");
        s.referenceCell = readFixed<double, 4>(neighbours, "reference_cell");
    }
    s.parameters = readParameters(g.openGroup("parameters"));
    return s;
}

/// Next write-order index among the children of `parent` (attribute `index`).

} // namespace grainlab::hdf5io
