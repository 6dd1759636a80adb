// The compiled part of `import grainlab`: the errors and the experiments; the other parts are
// added by simulation_binding.cpp and run_binding.cpp (module.h). The Python package around it
// (app/python/grainlab/__init__.py) re-exports everything and adds what is plain Python.

#include "python/module.h"

#include <filesystem>

#include <fmt/format.h>
#include <pybind11/stl.h>

#include "cli/run_session.h"
#include "common/atomic_file.h"
#include "common/version.h"
#include "grainlab/experiment_file.h"
#include "grainlab/measures.h"

namespace grainlab::python {

namespace {

/// The module's exception classes (created once, at import).
PyObject* grainLabError = nullptr;
PyObject* experimentError = nullptr;
PyObject* simulationError = nullptr;
PyObject* runFolderError = nullptr;

void bindErrors(py::module_& m) {
    grainLabError = PyErr_NewExceptionWithDoc(
        "grainlab.GrainLabError",
        "Any error GrainLab reports: the message is the one the command line prints.",
        PyExc_RuntimeError, nullptr);
    py::object bases = py::make_tuple(py::handle(grainLabError), py::handle(PyExc_ValueError));
    experimentError = PyErr_NewExceptionWithDoc(
        "grainlab.ExperimentError",
        "A bad experiment (file or dict): the message names the source, the key path, the value "
        "and what is allowed. Also a ValueError.",
        bases.ptr(), nullptr);
    simulationError = PyErr_NewExceptionWithDoc(
        "grainlab.SimulationError",
        "A simulation stopped for a physical reason (blow-up): the message names the step, the "
        "grain and the cause. The simulation that raised it refuses to step again.",
        grainLabError, nullptr);
    runFolderError = PyErr_NewExceptionWithDoc(
        "grainlab.RunFolderError",
        "A run folder that cannot be taken (a run already there, no run to resume, a folder in "
        "use by another run). Nothing was written.",
        grainLabError, nullptr);
    m.add_object("GrainLabError", py::handle(grainLabError));
    m.add_object("ExperimentError", py::handle(experimentError));
    m.add_object("SimulationError", py::handle(simulationError));
    m.add_object("RunFolderError", py::handle(runFolderError));
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) {
                std::rethrow_exception(p);
            }
        } catch (const py::builtin_exception& e) {
            e.set_error(); // TypeError, ValueError, ... raised by the bindings themselves
        } catch (const JsonFileError& e) {
            PyErr_SetString(experimentError, e.what());
        } catch (const SimulationError& e) {
            PyErr_SetString(simulationError, e.what());
        } catch (const RunFolderRefused& e) {
            PyErr_SetString(runFolderError, e.what());
        } catch (const std::invalid_argument& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        } catch (const std::out_of_range& e) {
            PyErr_SetString(PyExc_IndexError, e.what());
        } catch (const std::runtime_error& e) {
            PyErr_SetString(grainLabError, e.what());
        }
    });
}

ExperimentConfig fromText(const std::string& text, const std::string& name) {
    return parseExperimentText(text, name);
}

std::vector<std::string> testKinds(const ExperimentConfig& c) {
    std::vector<std::string> out;
    for (const LoadingPath& t : c.tests) {
        out.emplace_back(loadingKindName(t.kind));
    }
    return out;
}

/// The value an experiment holds at `Path`: a member, or a member of a member.
template <auto... Path>
auto field(const ExperimentConfig& c) {
    return (c.*....*Path);
}

/// A read-only property of Experiment that gives a value the experiment holds.
struct ExperimentProperty {
    const char* name;
    py::cpp_function get;
    const char* doc;
};

std::vector<ExperimentProperty> experimentProperties() {
    using E = ExperimentConfig;
    return {
        {"text", py::cpp_function(&field<&E::sourceText>),
         "The experiment's JSON text, as stored in a run file."},
        {"name", py::cpp_function(&field<&E::name>), "Its name."},
        {"source", py::cpp_function(&field<&E::sourcePath>),
         "The file (or the name) it was read from."},
        {"grain_count", py::cpp_function(&field<&E::assembly, &AssemblySpec::grainCount>),
         "Grains in the assembly."},
        {"seed", py::cpp_function(&field<&E::assembly, &AssemblySpec::seed>),
         "The assembly's random seed."},
        {"time_step", py::cpp_function(&field<&E::parameters, &SimulationParameters::timeStep>),
         "The time step [s]."},
        {"threads", py::cpp_function(&field<&E::parameters, &SimulationParameters::threads>),
         "Engine threads the file asks for (results are the same bits for any)."},
        {"compaction_pressures",
         py::cpp_function(&field<&E::compaction, &CompactionSpec::pressures>),
         "Confining pressures of the compaction stages [Pa]."},
        {"shear_pressures", py::cpp_function(&field<&E::shear, &ShearSpec::pressures>),
         "The samples that are tested, by pressure [Pa]."},
    };
}

} // namespace

py::dict rowDict(const std::vector<double>& row) {
    py::dict d;
    std::size_t k = 0;
    for (const SeriesColumn& c : seriesColumns()) {
        if (!c.text) {
            d[py::str(c.name)] = row.at(k++);
        }
    }
    return d;
}

void bindExperiment(py::module_& m) {
    py::class_<ExperimentConfig> experiment(m, "Experiment", R"doc(
An experiment: everything one experiment file says, validated as `grainlab run` validates it.

Make one with Experiment.load(path), Experiment.from_dict(d) or Experiment.from_text(json_text);
a bad file or dict raises ExperimentError naming the key and the allowed range. An Experiment
does not change: with_changes() (added in Python) gives a new, validated one.)doc");
    experiment
        .def_static("load", &readExperimentFile, py::arg("path"),
                    "Reads and validates an experiment file (JSON).")
        .def_static("from_text", &fromText, py::arg("text"), py::arg("name") = "<text>",
                    "Validates experiment JSON text; `name` names it in error messages.");
    for (const ExperimentProperty& p : experimentProperties()) {
        experiment.def_property_readonly(p.name, p.get, p.doc);
    }
    experiment
        .def_property_readonly("tests", &testKinds,
                               "The test kinds each sample gets, in order ('drained', ...).")
        .def(
            "save",
            [](const ExperimentConfig& c, const std::string& path, bool overwrite) {
                if (!overwrite && std::filesystem::exists(path)) {
                    throw std::runtime_error(fmt::format(
                        "{}: the file exists; give overwrite=True to replace it", path));
                }
                writeFileAtomically(path, c.sourceText);
            },
            py::arg("path"), py::arg("overwrite") = false,
            "Writes the experiment's JSON text to `path` (refuses an existing file unless "
            "overwrite=True).")
        .def("__repr__", [](const ExperimentConfig& c) {
            return fmt::format("<grainlab.Experiment '{}': {} grains, seed {}, {} test(s)>", c.name,
                               c.assembly.grainCount, c.assembly.seed, c.tests.size());
        });
    m.def(
        "series_columns",
        [] {
            return listOf(seriesColumns(),
                          [](const SeriesColumn& c) { return py::make_tuple(c.name, c.unit); });
        },
        "The columns of a series (series.csv), in order, as (name, unit) pairs; 'stage' is the "
        "text column.");
}

} // namespace grainlab::python

PYBIND11_MODULE(_grainlab, m) {
    m.doc() = "GrainLab's engine, runner and run files (the compiled part of `grainlab`).";
    m.attr("__version__") = GRAINLAB_VERSION;
    m.attr("__commit__") = grainlab::buildCommit(); // as `grainlab --version` names it
    grainlab::python::bindErrors(m);
    grainlab::python::bindExperiment(m);
    grainlab::python::bindSimulation(m);
    grainlab::python::bindRuns(m);
}
