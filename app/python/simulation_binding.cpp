// grainlab.Simulation: the engine step by step from Python, its state as NumPy arrays (live
// read-only views where the engine's layout allows, copies otherwise), its contacts, void cells
// and every measure of a series row computed by the code that computes the rows.

#include <cmath>

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "grainlab/enum_names.h"
#include "grainlab/experiment_runner.h"
#include "grainlab/measures.h"
#include "python/module.h"

namespace grainlab::python {

namespace {

using Array = py::array_t<double>;
using namespace pybind11::literals;

/// A read-only NumPy view of an engine array, keeping `owner` (the Python Simulation) alive.
template <typename T>
py::array view(const std::vector<T>& v, py::handle owner) {
    py::array a(py::dtype::of<T>(), {static_cast<py::ssize_t>(v.size())}, {sizeof(T)}, v.data(),
                owner);
    py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
    return a;
}

/// An (n, 2) array of two columns (a copy).
Array pairs(const std::vector<double>& a, const std::vector<double>& b) {
    Array out({static_cast<py::ssize_t>(a.size()), py::ssize_t(2)});
    auto w = out.mutable_unchecked<2>();
    for (std::size_t i = 0; i < a.size(); ++i) {
        w(i, 0) = a[i];
        w(i, 1) = b[i];
    }
    return out;
}

template <typename T>
py::array copyOf(const std::vector<T>& v) {
    return py::array(py::dtype::of<T>(), {static_cast<py::ssize_t>(v.size())}, {sizeof(T)},
                     v.data());
}

py::array boolsOf(const std::vector<std::uint8_t>& v) {
    py::array_t<bool> out(static_cast<py::ssize_t>(v.size()));
    auto w = out.mutable_unchecked<1>();
    for (std::size_t i = 0; i < v.size(); ++i) {
        w(i) = v[i] != 0;
    }
    return out;
}

Array cellMatrix(const std::array<double, 4>& h) {
    Array out({py::ssize_t(2), py::ssize_t(2)});
    auto w = out.mutable_unchecked<2>();
    w(0, 0) = h[0]; // column-major (h11, h21, h12, h22)
    w(1, 0) = h[1];
    w(0, 1) = h[2];
    w(1, 1) = h[3];
    return out;
}

/// `value` as a NumPy array of real numbers (ints and floats; refuses strings, objects, bools
/// and complex numbers with TypeError).
py::array numericArray(const py::object& value, const char* name) {
    const py::array a = py::array::ensure(value);
    if (!a) {
        throw py::type_error(fmt::format("{}: not convertible to an array", name));
    }
    const char kind = a.dtype().kind();
    if (kind != 'f' && kind != 'i' && kind != 'u') {
        throw py::type_error(fmt::format("{}: dtype {} is not a real number type (float or int)",
                                         name, py::str(a.dtype()).cast<std::string>()));
    }
    return a;
}

/// A copy (or the array itself) as C-ordered doubles.
py::array_t<double, py::array::c_style> asDoubles(const py::array& a) {
    return py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
}

std::string shapeText(const py::array& a) {
    std::string out = "(";
    for (py::ssize_t k = 0; k < a.ndim(); ++k) {
        out += fmt::format("{}{}", k ? ", " : "", a.shape(k));
    }
    return out + (a.ndim() == 1 ? ",)" : ")");
}

/// `value` (`name` in messages) as C-ordered doubles, one row of `columns` values per grain of
/// `n` (a 1-d array of n values for one column); refuses another shape with ValueError.
py::array_t<double, py::array::c_style> perGrain(const py::object& value, const char* name,
                                                 std::size_t n, int columns) {
    const py::array a = numericArray(value, name);
    const bool fits = columns == 1
                          ? a.ndim() == 1 && a.shape(0) == py::ssize_t(n)
                          : a.ndim() == 2 && a.shape(0) == py::ssize_t(n) && a.shape(1) == columns;
    if (!fits) {
        throw std::invalid_argument(
            columns == 1 ? fmt::format("{}: shape {}; must be ({},), one value per grain", name,
                                       shapeText(a), n)
                         : fmt::format("{}: shape {}; must be ({}, {}), one row per grain", name,
                                       shapeText(a), n, columns));
    }
    return asDoubles(a);
}

PySimulation& usable(PySimulation& s) {
    if (!s.failure.empty()) {
        throw std::runtime_error("this simulation failed (" + s.failure +
                                 "); make a new one, e.g. from a checkpoint of a run file");
    }
    if (s.busy.load()) {
        throw std::runtime_error(
            "this simulation is being stepped in another thread; one thread drives a simulation");
    }
    return s;
}

void step(PySimulation& s, std::int64_t steps) {
    if (steps < 0) {
        throw std::invalid_argument(
            fmt::format("step({}): the number of steps must be >= 0", steps));
    }
    usable(s);
    s.busy.store(true);
    try {
        py::gil_scoped_release release;
        s.sim->advance(steps);
    } catch (const SimulationError& e) {
        s.failure = e.what();
        s.busy.store(false);
        throw;
    } catch (...) {
        s.busy.store(false);
        throw;
    }
    s.busy.store(false);
}

/// The row of a record made now, with strains counted from the simulation's reference cell.
std::vector<double> measureRow(const PySimulation& s, const MeasureSet& m) {
    const Simulation& sim = *s.sim;
    const auto& h0 = s.referenceCell;
    const auto& h = sim.cell();
    RecordInputs in;
    in.step = sim.stepCount();
    in.time = sim.time();
    in.eps1 = (h0[0] - h[0]) / h0[0];
    in.eps2 = (h0[3] - h[3]) / h0[3];
    const double a0 = h0[0] * h0[3] - h0[1] * h0[2];
    in.epsv = (a0 - sim.cellArea()) / a0;
    in.stress = sim.stress();
    const auto& L = sim.stateRef().velocityGradient;
    in.strainRate1 = -L[0];
    in.strainRate2 = -L[3];
    in.density = sim.stateRef().parameters.density;
    in.energies = sim.energies();
    return seriesRow(m, in);
}

/// Member `member` of each void cell, in the cells' order.
template <typename T>
std::vector<T> cellColumn(const std::vector<VoidCell>& cells, T VoidCell::*member) {
    std::vector<T> out;
    out.reserve(cells.size());
    for (const VoidCell& c : cells) {
        out.push_back(c.*member);
    }
    return out;
}

py::dict voidCellsDict(const VoidCellSet& set) {
    py::list polygons, grains;
    for (const VoidCell& c : set.cells) {
        std::vector<double> v1(c.vertices1), v2(c.vertices2);
        for (std::size_t j = 0; j < v1.size(); ++j) {
            v1[j] += c.centroid1;
            v2[j] += c.centroid2;
        }
        polygons.append(pairs(v1, v2));
        grains.append(copyOf(c.grains));
    }
    const auto column = [&](auto member) { return copyOf(cellColumn(set.cells, member)); };
    return py::dict("valence"_a = column(&VoidCell::valence), "area"_a = column(&VoidCell::area),
                    "elongation"_a = column(&VoidCell::elongation),
                    "direction"_a = column(&VoidCell::direction),
                    "centroid"_a = pairs(cellColumn(set.cells, &VoidCell::centroid1),
                                         cellColumn(set.cells, &VoidCell::centroid2)),
                    "polygons"_a = polygons, "grains"_a = grains,
                    "valence_histogram"_a = copyOf(set.valenceHistogram),
                    "cellular"_a = set.cellular, "problem"_a = set.problem);
}

AxisControl axisControl(const std::string& mode, double rate, double stress, double slope,
                        double origin, double area, double length) {
    AxisControl c;
    if (const auto m = enumFromName(kAxisModeNames, mode)) {
        c.mode = *m;
    } else {
        throw std::invalid_argument(fmt::format(
            "mode '{}': must be 'strain', 'stress', 'constant_area' or 'stress_path'", mode));
    }
    c.strainRate = rate;
    c.targetStress = stress;
    c.pathSlope = slope;
    c.pathOrigin = origin;
    c.referenceArea = area;
    c.referenceLength = length;
    return c;
}

const char* modeName(AxisMode m) {
    return enumName(kAxisModeNames, m, "?");
}

} // namespace

py::dict contactsDict(const ContactNetwork& net) {
    const std::size_t n = net.contacts.size();
    const ContactColumns c = contactColumns(net);
    std::vector<double> f1(n), f2(n);
    for (std::size_t k = 0; k < n; ++k) {
        const auto f = net.contacts[k].force();
        f1[k] = f[0];
        f2[k] = f[1];
    }
    py::array_t<std::int32_t> shift({static_cast<py::ssize_t>(n), py::ssize_t(2)});
    auto w = shift.mutable_unchecked<2>();
    for (std::size_t k = 0; k < n; ++k) {
        w(k, 0) = c.shift1[k];
        w(k, 1) = c.shift2[k];
    }
    return py::dict("first"_a = copyOf(c.first), "second"_a = copyOf(c.second), "shift"_a = shift,
                    "normal"_a = pairs(c.normal1, c.normal2), "point"_a = pairs(c.point1, c.point2),
                    "branch"_a = pairs(c.branch1, c.branch2), "overlap"_a = copyOf(c.overlap),
                    "normal_force"_a = copyOf(c.normalForce),
                    "tangential_force"_a = copyOf(c.tangentialForce), "force"_a = pairs(f1, f2),
                    "sliding"_a = boolsOf(c.sliding));
}

PySimulation::PySimulation(SimulationState state)
    : sim(std::make_unique<Simulation>(std::move(state))), referenceCell(sim->cell()) {}

namespace {

/// Member `member` of each grain's shape, in the grains' order (a copy).
py::array shapeColumn(const PySimulation& s, double OvalShape::*member) {
    const SimulationState& st = s.sim->stateRef();
    std::vector<double> out(st.grains.size());
    for (std::size_t i = 0; i < out.size(); ++i) {
        out[i] = st.shapes[st.grains.shape[i]].*member;
    }
    return copyOf(out);
}

/// A live read-only view of the grain array `Member` of the Simulation `self`.
template <auto Member>
py::array grainView(py::object self) {
    return view(self.cast<PySimulation&>().sim->stateRef().grains.*Member, self);
}

/// A property of Simulation that is a live read-only view of a grain array.
struct GrainView {
    const char* name;
    py::array (*get)(py::object self);
    const char* doc;
};

const GrainView kGrainViews[] = {
    {"x1", &grainView<&GrainArrays::x1>,
     "Grain centres along x1 (axial) [m], a live read-only view."},
    {"x2", &grainView<&GrainArrays::x2>, "Grain centres along x2 [m], a live read-only view."},
    {"theta", &grainView<&GrainArrays::theta>,
     "Orientations of the grains' long axes from x1 [rad], a live read-only view."},
    {"v1", &grainView<&GrainArrays::v1>,
     "Fluctuating velocities along x1 [m/s] (the cell's affine motion excluded), a view."},
    {"v2", &grainView<&GrainArrays::v2>,
     "Fluctuating velocities along x2 [m/s], a live read-only view."},
    {"omega", &grainView<&GrainArrays::omega>,
     "Angular velocities [rad/s], a live read-only view."},
    {"shape", &grainView<&GrainArrays::shape>,
     "Each grain's index into the shape table (widths, heights), a live read-only view."},
};

/// Making one, stepping it, and its state and arrays.
void bindSimulationState(py::class_<PySimulation>& simulation) {
    simulation
        .def_static(
            "from_experiment",
            [](const ExperimentConfig& config) {
                // The runner's first stage is the generated grid (nothing is written).
                const ExperimentRunner runner(config);
                return std::make_unique<PySimulation>(runner.simulation().state());
            },
            py::arg("experiment"),
            "The experiment's generated assembly, before compaction, with the compaction's "
            "friction and both axes at rest.")
        .def("step", &step, py::arg("n") = 1,
             "Advances n time steps (GIL released). Raises SimulationError on blow-up; the "
             "simulation then refuses to step again.")
        .def_property_readonly(
            "step_count", [](PySimulation& s) { return s.sim->stepCount(); },
            "Steps since the state was generated.")
        .def_property_readonly(
            "time", [](PySimulation& s) { return s.sim->time(); }, "Simulated time [s].")
        .def_property_readonly("grain_count", [](PySimulation& s) { return s.sim->grainCount(); })
        .def_property_readonly(
            "time_step", [](PySimulation& s) { return s.sim->stateRef().parameters.timeStep; },
            "[s]")
        .def_property_readonly(
            "friction", [](PySimulation& s) { return s.sim->stateRef().parameters.friction; },
            "Contact friction coefficient mu [-].")
        .def_property_readonly(
            "failure", [](PySimulation& s) { return s.failure; },
            "Why the simulation failed ('' while it has not).");
    for (const GrainView& v : kGrainViews) {
        simulation.def_property_readonly(v.name, v.get, v.doc);
    }
    simulation
        .def_property_readonly(
            "positions",
            [](PySimulation& s) {
                return pairs(s.sim->stateRef().grains.x1, s.sim->stateRef().grains.x2);
            },
            "Grain centres, an (N, 2) copy [m] (unwrapped: they may lie outside the cell).")
        .def_property_readonly(
            "velocities",
            [](PySimulation& s) {
                return pairs(s.sim->stateRef().grains.v1, s.sim->stateRef().grains.v2);
            },
            "Fluctuating velocities, an (N, 2) copy [m/s].")
        .def_property_readonly(
            "widths", [](PySimulation& s) { return shapeColumn(s, &OvalShape::width); },
            "Grain widths W (long axis) [m], a copy.")
        .def_property_readonly(
            "heights", [](PySimulation& s) { return shapeColumn(s, &OvalShape::height); },
            "Grain heights H (short axis) [m], a copy; H/W is the aspect ratio.")
        .def_property_readonly(
            "masses", [](PySimulation& s) { return copyOf(s.sim->grainMass()); },
            "Grain masses [kg] (unit thickness), a copy.")
        .def_property_readonly(
            "cell", [](PySimulation& s) { return cellMatrix(s.sim->cell()); },
            "The cell matrix h (columns: the cell vectors) [m], a copy.")
        .def_property_readonly(
            "cell_area", [](PySimulation& s) { return s.sim->cellArea(); }, "[m^2]")
        .def_property_readonly(
            "stress",
            [](PySimulation& s) {
                const Stress st = s.sim->stress();
                Array out({py::ssize_t(2), py::ssize_t(2)});
                auto w = out.mutable_unchecked<2>();
                w(0, 0) = st.s11;
                w(0, 1) = w(1, 0) = st.s12;
                w(1, 1) = st.s22;
                return out;
            },
            "The Love-Weber stress (compression positive), 2x2 [Pa].");
}

/// Driving it between steps, and what it measures.
void bindSimulationControls(py::class_<PySimulation>& simulation) {
    simulation
        .def(
            "axis",
            [](PySimulation& s, int axis) {
                if (axis != 1 && axis != 2) {
                    throw std::invalid_argument(fmt::format("axis {}: must be 1 or 2", axis));
                }
                const AxisControl& c = s.sim->stateRef().axes[axis - 1];
                return py::dict("mode"_a = modeName(c.mode), "rate"_a = c.strainRate,
                                "stress"_a = c.targetStress, "slope"_a = c.pathSlope,
                                "origin"_a = c.pathOrigin, "area"_a = c.referenceArea,
                                "length"_a = c.referenceLength);
            },
            py::arg("axis"), "How axis 1 (x1) or 2 (x2) is driven, as a dict.")
        .def(
            "set_axis",
            [](PySimulation& s, int axis, const std::string& mode, double rate, double stress,
               double slope, double origin, double area, double length) {
                usable(s);
                if (axis != 1 && axis != 2) {
                    throw std::invalid_argument(fmt::format("axis {}: must be 1 or 2", axis));
                }
                s.sim->setAxisControl(axis - 1,
                                      axisControl(mode, rate, stress, slope, origin, area, length));
            },
            py::arg("axis"), py::arg("mode"), py::kw_only(), py::arg("rate") = 0.0,
            py::arg("stress") = 0.0, py::arg("slope") = 0.0, py::arg("origin") = 0.0,
            py::arg("area") = 0.0, py::arg("length") = 0.0,
            R"doc(Changes how axis 1 or 2 is driven, between steps (compression positive).

mode 'strain': the compressive strain `rate` [1/s] (`length` > 0 makes it an engineering rate
of that reference length); 'stress': sigma_ii held at `stress` [Pa] by the servo;
'constant_area' (axis 2): the cell's area held at `area` [m^2]; 'stress_path': sigma_ii held at
`stress` + `slope` (sigma_jj - `origin`). Refused with ValueError as an experiment file would be.)doc")
        .def(
            "set_friction",
            [](PySimulation& s, double mu) {
                usable(s);
                s.sim->setFriction(mu);
            },
            py::arg("mu"), "Sets the contact friction coefficient (>= 0) between steps.")
        .def(
            "clear_velocities", [](PySimulation& s) { usable(s).sim->clearVelocities(); },
            "Zeroes every fluctuating velocity and spin.")
        .def(
            "set_velocities",
            [](PySimulation& s, const py::object& velocities, const py::object& omega) {
                usable(s);
                const SimulationState& st = s.sim->stateRef();
                const std::size_t n = st.grains.size();
                std::vector<double> v1 = st.grains.v1, v2 = st.grains.v2, w = st.grains.omega;
                if (!velocities.is_none()) {
                    const auto converted = perGrain(velocities, "velocities", n, 2);
                    const auto v = converted.unchecked<2>();
                    for (std::size_t i = 0; i < n; ++i) {
                        v1[i] = v(i, 0);
                        v2[i] = v(i, 1);
                    }
                }
                if (!omega.is_none()) {
                    const auto converted = perGrain(omega, "omega", n, 1);
                    const auto o = converted.unchecked<1>();
                    for (std::size_t i = 0; i < n; ++i) {
                        w[i] = o(i);
                    }
                }
                s.sim->setVelocities(v1, v2, w);
            },
            py::arg("velocities") = py::none(), py::arg("omega") = py::none(),
            "Replaces the fluctuating velocities ((N, 2) [m/s]) and/or the spins ((N,) "
            "[rad/s]) between steps. Refuses another shape, a non-numeric dtype and non-finite "
            "values; the views keep showing the engine's arrays.")
        .def(
            "reset_strain_reference", [](PySimulation& s) { s.referenceCell = s.sim->cell(); },
            "Counts the strains of measures() from the cell as it is now.")
        .def(
            "contacts", [](PySimulation& s) { return contactsDict(s.sim->contactNetwork()); },
            R"doc(The touching contacts, as a dict of arrays (copies), one entry per contact in the
engine's order: first, second (grain ids), shift (N, 2: the periodic image of `second`),
normal (unit, from first to second), point (contact point), branch (x_second + h shift -
x_first), overlap [m], normal_force, tangential_force [N], force (on `second`, (N, 2)) [N] and
sliding (at the Coulomb limit).)doc")
        .def(
            "void_cells",
            [](PySimulation& s) {
                const MeasureSet ms = computeMeasures(s.sim->contactNetwork());
                return voidCellsDict(ms.voidCells);
            },
            R"doc(The void cells of the load-bearing contact network, as a dict: valence, area [m^2],
elongation, direction [rad], centroid (N, 2) [m], polygons (a list of (2 valence, 2) arrays:
grain centre, contact point, ... counter-clockwise) and grains (the grains around each cell),
valence_histogram, and cellular (True when the cells tile the periodic cell).)doc")
        .def(
            "measures",
            [](PySimulation& s) {
                return rowDict(measureRow(s, computeMeasures(s.sim->contactNetwork())));
            },
            R"doc(Every numeric column of a series row for the current state, as a dict name -> value,
computed by the code that computes the rows. Strains count from the cell at creation (or at
reset_strain_reference()); DI (which needs the previous record) and Nv_over_Nvi (which needs
the test's first record) are 0 here: Runner.measures() gives them as a run records them.)doc")
        .def(
            "identical",
            [](PySimulation& s, PySimulation& other) {
                return identicalDynamics(s.sim->stateRef(), other.sim->stateRef());
            },
            py::arg("other"),
            "True when both hold the same bits in everything that evolves (grains, contacts "
            "with their history, cell, servo, step, time, energies).")
        .def("__repr__", [](PySimulation& s) {
            return fmt::format("<grainlab.Simulation: {} grains, step {}, eps1 {:.6g}{}>",
                               s.sim->grainCount(), s.sim->stepCount(),
                               (s.referenceCell[0] - s.sim->cell()[0]) / s.referenceCell[0],
                               s.failure.empty() ? "" : ", failed");
        });
}

} // namespace

void bindSimulation(py::module_& m) {
    py::class_<PySimulation> simulation(m, "Simulation", R"doc(
The engine, stepped from Python: grains in a deforming periodic cell (docs/physics.md).

Make one with Simulation.from_experiment(experiment) (the generated assembly a run starts from)
or RunFolder.simulation(checkpoint=...) / RunFolder.simulation(sample=pressure). step(n)
releases the GIL: other Python threads run meanwhile, and two simulations step in parallel on
two threads with the same bits as one after the other. One thread drives one simulation.

Arrays: x1, x2, theta, v1, v2, omega and shape are live read-only views of the engine's arrays
(no copy): they always show the current state, also after step(), and stay valid as long as
the Simulation. Every other array (positions, contacts(), void_cells(), ...) is a copy made by
the call.)doc");
    bindSimulationState(simulation);
    bindSimulationControls(simulation);
}

} // namespace grainlab::python
