#pragma once
// The Python module `grainlab` (its compiled part, grainlab._grainlab): what the binding files
// share. Each binding file adds one part of the API to the module: experiments and errors
// (module.cpp), the engine step by step with its state as NumPy arrays and its measures
// (simulation_binding.cpp), runs and run folders (run_binding.cpp). No Qt.

#include <array>
#include <atomic>
#include <memory>
#include <string>

#include <pybind11/pybind11.h>

#include "grainlab/simulation.h"

namespace grainlab::python {

namespace py = pybind11;

/// A simulation driven from Python: the engine object, the cell its strains count from, and
/// whether it failed (a failed simulation refuses to step) or is being stepped (by another
/// Python thread: refused too, since one thread drives a simulation).
struct PySimulation {
    explicit PySimulation(SimulationState state);
    std::unique_ptr<Simulation> sim;
    std::array<double, 4> referenceCell{}; ///< eps1, eps2 and eps_v count from this cell
    std::string failure;                   ///< why it failed ("" while it has not)
    std::atomic<bool> busy{false};
};

void bindExperiment(py::module_& m);
void bindSimulation(py::module_& m);
void bindRuns(py::module_& m);

/// A list of `make(item)` for each of `items`, in their order.
template <typename Items, typename Make>
py::list listOf(const Items& items, Make&& make) {
    py::list out;
    for (const auto& item : items) {
        out.append(make(item));
    }
    return out;
}

/// The columns of a series row (seriesColumns() without `stage`), as a dict name -> value.
py::dict rowDict(const std::vector<double>& row);
/// The touching contacts as a dict of arrays (Simulation.contacts()).
py::dict contactsDict(const ContactNetwork& network);

} // namespace grainlab::python
