// grainlab.Runner, grainlab.run()/resume() and grainlab.RunFolder: experiments played by the
// runner `grainlab run` uses (into a run folder, through the same RunSession, or in memory),
// and run folders read back.

#include <filesystem>

#include <fmt/format.h>
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "cli/run_session.h"
#include "grainlab/experiment_file.h"
#include "grainlab/measures.h"
#include "grainlab/run_file.h"
#include "python/module.h"

namespace grainlab::python {

namespace {

namespace fs = std::filesystem;
using namespace pybind11::literals;

/// An experiment played from Python: into a run folder (a RunSession, as `grainlab run`) or in
/// memory (no output).
struct PyRunner {
    std::unique_ptr<RunSession> session;      ///< with a run folder
    std::unique_ptr<ExperimentRunner> memory; ///< without
    std::string failure;
    bool closed = false;

    ExperimentRunner& runner() {
        if (closed) {
            throw std::runtime_error("this runner is closed");
        }
        return session ? session->runner() : *memory;
    }
    ExperimentRunner& usable() {
        if (!failure.empty()) {
            throw std::runtime_error("this run failed (" + failure +
                                     "); resume its run folder, or start a new run");
        }
        return runner();
    }
};

py::dict progressDict(const RunProgress& p) {
    return py::dict("stage"_a = p.stage, "kind"_a = stageKindName(p.kind), "test"_a = p.test,
                    "pressure"_a = p.pressure, "step"_a = p.step, "axial_strain"_a = p.axialStrain,
                    "fraction"_a = p.fraction, "finished"_a = p.finished);
}

py::dict tableDict(const SeriesTable& t) {
    py::list names, units;
    for (const SeriesColumn& c : t.columns) {
        names.append(c.name);
        units.append(c.unit);
    }
    py::array_t<double> values(
        {static_cast<py::ssize_t>(t.rows.size()), static_cast<py::ssize_t>(t.columns.size())});
    auto w = values.mutable_unchecked<2>();
    for (std::size_t r = 0; r < t.rows.size(); ++r) {
        for (std::size_t c = 0; c < t.columns.size(); ++c) {
            w(r, c) = t.rows[r][c];
        }
    }
    return py::dict("test"_a = t.test, "columns"_a = names, "units"_a = units, "values"_a = values,
                    "stages"_a = t.stages);
}

py::list warningsList(const std::vector<RunWarning>& all) {
    return listOf(all, [](const RunWarning& w) {
        return py::dict("kind"_a = w.kind, "test"_a = w.test, "step"_a = w.step,
                        "axial_strain"_a = w.axialStrain, "text"_a = w.text);
    });
}

/// Advances with the GIL released; a blow-up marks the runner failed (its folder keeps the last
/// good checkpoint).
bool advance(PyRunner& r, std::int64_t steps) {
    if (steps < 0) {
        throw std::invalid_argument(fmt::format("advance({}): steps must be >= 0", steps));
    }
    ExperimentRunner& runner = r.usable();
    try {
        py::gil_scoped_release release;
        return r.session ? r.session->advance(steps) : runner.advance(steps);
    } catch (const std::exception& e) {
        r.failure = e.what();
        if (r.session) {
            r.session->saveCostAfterFailure();
        }
        throw;
    }
}

/// Plays the experiment to its end in chunks, calling `progress` after each; a callback that
/// returns False stops the run (a checkpoint "interrupted" in a run folder), as Ctrl-C does.
bool play(PyRunner& r, const std::function<py::object(py::dict)>& progress, std::int64_t chunk) {
    if (chunk < 1) {
        throw std::invalid_argument(fmt::format("chunk {}: must be >= 1 step", chunk));
    }
    while (true) {
        const bool more = advance(r, chunk);
        if (PyErr_CheckSignals() != 0) {
            if (r.session && more) {
                r.session->interrupt();
            }
            throw py::error_already_set();
        }
        bool stop = false;
        if (progress) {
            const py::object answer = progress(progressDict(r.runner().progress()));
            stop = !answer.is_none() && !answer.cast<bool>();
        }
        if (!more) {
            return true;
        }
        if (stop) {
            if (r.session) {
                r.session->interrupt();
            }
            return false;
        }
    }
}

/// Ends a runner: a finished run's files are closed and its cost record says so; an unfinished
/// one writes a checkpoint "interrupted", to resume from.
void close(PyRunner& r) {
    if (r.closed) {
        return;
    }
    if (r.session && r.failure.empty()) {
        if (r.session->runner().finished()) {
            r.session->finish();
        } else {
            r.session->interrupt();
        }
    }
    r.closed = true;
}

std::string runFileOf(const std::string& folder) {
    fs::path p(folder);
    if (fs::is_directory(p)) {
        p /= "run.h5";
    }
    if (!fs::is_regular_file(p)) {
        throw std::runtime_error(
            fmt::format("{}: not a run folder (no run file {})", folder, p.string()));
    }
    return p.string();
}

struct PyRunFolder {
    std::string folder;
    std::string runFile;
};

py::dict storedContactsDict(const StoredContacts& c) {
    const auto arr = [](const auto& v) {
        using T = typename std::decay_t<decltype(v)>::value_type;
        return py::array(py::dtype::of<T>(), {static_cast<py::ssize_t>(v.size())}, {sizeof(T)},
                         v.data());
    };
    return py::dict(
        "first"_a = arr(c.first), "second"_a = arr(c.second), "shift1"_a = arr(c.shift1),
        "shift2"_a = arr(c.shift2), "normal1"_a = arr(c.normal1), "normal2"_a = arr(c.normal2),
        "point1"_a = arr(c.point1), "point2"_a = arr(c.point2), "branch1"_a = arr(c.branch1),
        "branch2"_a = arr(c.branch2), "overlap"_a = arr(c.overlap),
        "normal_force"_a = arr(c.normalForce), "tangential_force"_a = arr(c.tangentialForce),
        "sliding"_a = arr(c.sliding), "strong"_a = arr(c.strong),
        "load_bearing"_a = arr(c.loadBearing), "centre1"_a = arr(c.centre1),
        "centre2"_a = arr(c.centre2), "strong_threshold"_a = c.strongThreshold);
}

/// A method of RunFolder: what `Read` reads from the run file under `key`, as `Convert` gives it.
template <auto Read, auto Convert>
py::dict fromRunFile(const PyRunFolder& f, const std::string& key) {
    return Convert(Read(f.runFile, key));
}

} // namespace

namespace {

void bindRunner(py::module_& m) {
    py::class_<PyRunner>(m, "Runner", R"doc(
An experiment played stage by stage, by the runner `grainlab run` uses.

Runner(experiment) plays it in memory (nothing written); Runner(experiment, out=FOLDER) writes
the run folder exactly as `grainlab run --out FOLDER` does (run file, series CSVs, cost record),
and Runner.resume(FOLDER) continues one. advance(n) releases the GIL. Use it as a context
manager, or call close(): a finished run's files are then closed, an unfinished one keeps a
checkpoint "interrupted" to resume from.)doc")
        .def(py::init([](const ExperimentConfig& config, std::optional<std::string> out, bool force,
                         int threads) {
                 if (threads < 0) {
                     throw std::invalid_argument(
                         fmt::format("threads {}: must be >= 0 (0: as the file says)", threads));
                 }
                 auto r = std::make_unique<PyRunner>();
                 if (out) {
                     r->session = RunSession::create(config, *out, force, threads);
                     r->session->start();
                 } else {
                     ExperimentConfig c = config;
                     if (threads > 0) {
                         c.parameters.threads = threads;
                     }
                     r->memory = std::make_unique<ExperimentRunner>(std::move(c));
                 }
                 return r;
             }),
             py::arg("experiment"), py::arg("out") = py::none(), py::kw_only(),
             py::arg("force") = false, py::arg("threads") = 0)
        .def_static(
            "resume",
            [](const std::string& folder, int threads) {
                auto r = std::make_unique<PyRunner>();
                r->session = RunSession::resume(folder, threads);
                if (r->session->finishedAlready()) {
                    r->session->completeCostRecord();
                    throw std::runtime_error(
                        fmt::format("{}: the run is finished; nothing to resume", folder));
                }
                r->session->start();
                return r;
            },
            py::arg("folder"), py::kw_only(), py::arg("threads") = 0,
            "Continues the run in `folder` from its last checkpoint, bit for bit.")
        .def("advance", &advance, py::arg("steps"),
             "Advances at most `steps` steps (GIL released); False once the experiment is "
             "finished.")
        .def("run", &play, py::arg("progress") = nullptr, py::kw_only(), py::arg("chunk") = 1000,
             R"doc(Plays the experiment to its end in chunks of `chunk` steps, calling
progress(p) after each with a dict (stage, kind, test, pressure, step, axial_strain, fraction,
finished). A callback returning False stops the run (in a run folder: a checkpoint
"interrupted"), as does Ctrl-C (KeyboardInterrupt is raised). Returns True when finished.)doc")
        .def("close", &close, "Closes the run's files (see the class).")
        .def("__enter__", [](py::object self) { return self; })
        .def("__exit__",
             [](PyRunner& r, py::object, py::object, py::object) {
                 close(r);
                 return false;
             })
        .def_property_readonly("finished", [](PyRunner& r) { return r.runner().finished(); })
        .def_property_readonly(
            "folder", [](PyRunner& r) { return r.session ? r.session->folder() : std::string(); },
            "The run folder ('' in memory).")
        .def_property_readonly(
            "progress", [](PyRunner& r) { return progressDict(r.runner().progress()); },
            "Where the run is: stage, kind, test, pressure, step, axial_strain, fraction.")
        .def_property_readonly("steps_taken", [](PyRunner& r) { return r.runner().stepsTaken(); })
        .def_property_readonly(
            "times",
            [](PyRunner& r) {
                const RunnerTimes t = r.runner().times();
                py::dict d;
                for (const RunnerTimesPart& part : kRunnerTimesParts) {
                    d[part.name] = t.*part.seconds;
                }
                return d;
            },
            "Where this runner's wall time has gone [s]: stepping, records, checkpoints and the "
            "stages' other events (as cost.json's seconds).")
        .def(
            "measures", [](PyRunner& r) { return rowDict(r.runner().measuresNow()); },
            "Every numeric column of a series row for now, exactly as a record made now would "
            "hold it (strains of the current test, DI since the last record, Nv/Nvi), as a "
            "dict.")
        .def(
            "contacts",
            [](PyRunner& r) { return contactsDict(r.runner().simulation().contactNetwork()); },
            "The current contacts as a dict of arrays (as Simulation.contacts()).")
        .def(
            "simulation",
            [](PyRunner& r) {
                return std::make_unique<PySimulation>(r.runner().simulation().state());
            },
            "A new Simulation from a copy of the current state (stepping it leaves the run "
            "alone).")
        .def(
            "tables", [](PyRunner& r) { return listOf(r.runner().series(), tableDict); },
            "Every test's series so far, raw (see series()).")
        .def_property_readonly(
            "row_counts",
            [](PyRunner& r) {
                py::dict d;
                for (const SeriesTable& t : r.runner().series()) {
                    d[py::str(t.test)] = t.rows.size();
                }
                return d;
            },
            "Rows recorded so far per test (cheap: no series is copied).")
        .def_property_readonly(
            "warnings", [](PyRunner& r) { return warningsList(r.runner().warnings()); },
            "Every warning given so far: dicts of kind, test, step, axial_strain, text.")
        .def(
            "checkpoint",
            [](PyRunner& r, const std::string& name) {
                if (!r.session) {
                    throw std::runtime_error("a runner in memory writes no checkpoint; give out=");
                }
                r.usable().checkpointNow(name);
            },
            py::arg("name"), "Writes a checkpoint of now into the run file.");
}

void bindRunFolder(py::module_& m) {
    py::class_<PyRunFolder>(m, "RunFolder", R"doc(
A run folder (or its run.h5) read back: the experiment, every test's series, the checkpoints
with the state, contacts and void cells stored in each, the compacted samples, the warnings.
Every read opens the file read-only for that call: a run folder may be read while its run goes
on (what is read is what was flushed).)doc")
        .def(py::init([](const std::string& folder) {
                 PyRunFolder f{folder, runFileOf(folder)};
                 readExperimentText(f.runFile); // refuses a file that is not a run file
                 return f;
             }),
             py::arg("path"))
        .def_property_readonly("path", [](const PyRunFolder& f) { return f.folder; })
        .def_property_readonly("run_file", [](const PyRunFolder& f) { return f.runFile; })
        .def_property_readonly(
            "experiment",
            [](const PyRunFolder& f) {
                return parseExperimentText(readExperimentText(f.runFile),
                                           f.runFile + ":/experiment");
            },
            "The experiment the run played.")
        .def_property_readonly("software_version",
                               [](const PyRunFolder& f) { return readSoftwareVersion(f.runFile); })
        .def_property_readonly(
            "tests", [](const PyRunFolder& f) { return listTests(f.runFile); },
            "Test (series) names in the order they were first recorded.")
        .def_property_readonly(
            "samples", [](const PyRunFolder& f) { return listSamples(f.runFile); },
            "Pressures [Pa] of the compacted samples.")
        .def_property_readonly(
            "finished",
            [](const PyRunFolder& f) {
                const std::vector<std::string> names = listCheckpoints(f.runFile);
                for (auto it = names.rbegin(); it != names.rend(); ++it) {
                    const std::string state = readRunnerState(f.runFile, checkpointGroup(*it));
                    if (!state.empty()) {
                        return ExperimentRunner::finishedAt(state);
                    }
                }
                return false;
            },
            "True when the run reached its end.")
        .def_property_readonly(
            "checkpoints",
            [](const PyRunFolder& f) {
                return listOf(listCheckpointInfo(f.runFile), [](const CheckpointInfo& c) {
                    return py::dict("name"_a = c.name, "kind"_a = c.stageKind, "test"_a = c.test,
                                    "pressure"_a = c.pressure, "step"_a = c.step,
                                    "axial_strain"_a = c.axialStrain, "peak"_a = c.peak,
                                    "peak_stress_ratio"_a = c.peakStressRatio);
                });
            },
            "Every complete checkpoint in write order: dicts of name, kind, test, pressure, "
            "step, axial_strain, peak (the checkpoint at the peak of q/p of its test).")
        .def("table", &fromRunFile<readSeries, tableDict>, py::arg("test"),
             "The series of `test`, raw (see series()).")
        .def_property_readonly(
            "warnings", [](const PyRunFolder& f) { return warningsList(readWarnings(f.runFile)); })
        .def(
            "simulation",
            [](const PyRunFolder& f, std::optional<std::string> checkpoint,
               std::optional<double> sample) {
                if (checkpoint.has_value() == sample.has_value()) {
                    throw std::invalid_argument(
                        "give one of checkpoint= (a name from .checkpoints) or sample= (a "
                        "pressure from .samples)");
                }
                const std::string group =
                    checkpoint ? checkpointGroup(*checkpoint) : sampleGroup(*sample);
                return std::make_unique<PySimulation>(readState(f.runFile, group));
            },
            py::kw_only(), py::arg("checkpoint") = py::none(), py::arg("sample") = py::none(),
            "A Simulation from a checkpoint's state or a compacted sample, bit for bit as "
            "stored (stepping it continues the run's physics).")
        .def("contacts", &fromRunFile<readContacts, storedContactsDict>, py::arg("checkpoint"),
             "The contacts stored with a checkpoint, as the run file holds them: a dict of "
             "arrays (first, second, normal1/2, point1/2, normal_force, tangential_force, "
             "sliding, strong, ...).")
        .def("__repr__", [](const PyRunFolder& f) {
            return fmt::format("<grainlab.RunFolder '{}'>", f.folder);
        });
}

} // namespace

void bindRuns(py::module_& m) {
    bindRunner(m);
    bindRunFolder(m);
}

} // namespace grainlab::python
