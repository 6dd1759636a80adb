// The state layout of checkpoints and samples in the run file (docs/formats.md, "State
// layout"): every field of SimulationState, so that a run continues from it bit for bit.
#include <algorithm>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include "grainlab/enum_names.h"
#include "run_file_io.h"

namespace grainlab::hdf5io {

namespace {

/// The damping kinds as the run file names them.
constexpr EnumName<DampingKind> kDampingNames[] = {{DampingKind::None, "none"},
                                                   {DampingKind::CundallLocal, "cundall_local"},
                                                   {DampingKind::GlobalViscous, "global_viscous"}};

/// The value `name` names in `names`; std::runtime_error "unknown <what> "<name>"" for none.
template <class Enum, std::size_t N>
Enum named(const EnumName<Enum> (&names)[N], const std::string& name, const char* what) {
    if (const auto value = enumFromName(names, name)) {
        return *value;
    }
    throw std::runtime_error(fmt::format("unknown {} \"{}\"", what, name));
}

void writeParameters(H5::Group& g, const SimulationParameters& p) {
    writeAttribute(g, "time_step", p.timeStep);
    writeAttribute(g, "normal_stiffness", p.normalStiffness);
    writeAttribute(g, "tangential_stiffness", p.tangentialStiffness);
    writeAttribute(g, "friction", p.friction);
    writeAttribute(g, "density", p.density);
    writeAttribute(g, "damping_kind",
                   std::string(enumName(kDampingNames, p.damping.kind, "global_viscous")));
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
    p.damping.kind = named(kDampingNames, readStringAttribute(g, "damping_kind"), "damping_kind");
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

/// A column of a structure-of-arrays group of the state: its name, the member holding it and
/// its unit.
template <class S, class T>
struct Column {
    using Value = T;
    const char* name;
    std::vector<T> S::*member;
    const char* unit;
};
template <class S, class T>
Column(const char*, std::vector<T> S::*, const char*) -> Column<S, T>;

/// The columns of the groups grains and pairs, in the file's order.
constexpr std::tuple kGrainColumns{
    Column{"x1", &GrainArrays::x1, "m"},         Column{"x2", &GrainArrays::x2, "m"},
    Column{"theta", &GrainArrays::theta, "rad"}, Column{"v1", &GrainArrays::v1, "m/s"},
    Column{"v2", &GrainArrays::v2, "m/s"},       Column{"omega", &GrainArrays::omega, "rad/s"},
    Column{"shape", &GrainArrays::shape, "-"}};
constexpr std::tuple kPairColumns{Column{"first", &PairArrays::first, "-"},
                                  Column{"second", &PairArrays::second, "-"},
                                  Column{"shift1", &PairArrays::shift1, "-"},
                                  Column{"shift2", &PairArrays::shift2, "-"},
                                  Column{"tangential_force", &PairArrays::tangentialForce, "N"},
                                  Column{"sliding", &PairArrays::sliding, "-"}};

/// Writes `data` as the group `name` of `g`, one dataset per column.
template <class S, class Columns>
void writeColumns(H5::Group& g, const char* name, const S& data, const Columns& columns) {
    H5::Group group = g.createGroup(name);
    std::apply([&](const auto&... c) { (writeArray(group, c.name, data.*c.member, c.unit), ...); },
               columns);
}

/// Reads the group written by writeColumns.
template <class S, class Columns>
void readColumns(const H5::Group& g, const char* name, S& data, const Columns& columns) {
    const H5::Group group = g.openGroup(name);
    std::apply(
        [&](const auto&... c) {
            ((data.*c.member = readArray<typename std::decay_t<decltype(c)>::Value>(group, c.name)),
             ...);
        },
        columns);
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
        const std::vector<std::string> modes = {enumName(kAxisModeNames, s.axes[0].mode, "strain"),
                                                enumName(kAxisModeNames, s.axes[1].mode, "strain")};
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
    writeColumns(g, "grains", s.grains, kGrainColumns);
    writeColumns(g, "pairs", s.pairs, kPairColumns);
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
            s.axes[a] = {named(kAxisModeNames, modes[a], "axis mode"),
                         rates[a],
                         targets[a],
                         lengths[a],
                         areas[a],
                         slopes[a],
                         origins[a]};
        }
    }
    s.shapes = readShapes(g.openGroup("shapes"));
    readColumns(g, "grains", s.grains, kGrainColumns);
    readColumns(g, "pairs", s.pairs, kPairColumns);
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
