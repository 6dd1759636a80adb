// See edited_experiment.h.
#include "gui/edited_experiment.h"

#include <stdexcept>

#include <nlohmann/json.hpp>

#include "grainlab/experiment_file.h"

namespace grainlab::ui {

namespace {

using OrderedJson = nlohmann::ordered_json; // keeps the file's key order

/// The tests the panel edits (kind and slope) are the same.
bool sameTests(const ExperimentConfig& a, const ExperimentConfig& b) {
    if (a.tests.size() != b.tests.size()) {
        return false;
    }
    for (std::size_t k = 0; k < a.tests.size(); ++k) {
        if (a.tests[k].kind != b.tests[k].kind || a.tests[k].slope != b.tests[k].slope ||
            a.tests[k].extension != b.tests[k].extension) {
            return false;
        }
    }
    return true;
}

bool sameEditedKeys(const ExperimentConfig& a, const ExperimentConfig& b) {
    return a.assembly.grainCount == b.assembly.grainCount &&
           a.shear.pressures == b.shear.pressures && a.shear.friction == b.shear.friction &&
           a.shear.targetAxialStrain == b.shear.targetAxialStrain && sameTests(a, b);
}

} // namespace

std::string editedExperimentText(const ExperimentConfig& base, const ExperimentConfig& edited) {
    if (base.sourceText.empty()) {
        throw std::runtime_error(
            "the experiment was not read from a file, so there is no experiment text to save or "
            "record; open an experiment file first");
    }
    if (sameEditedKeys(base, edited)) {
        return base.sourceText;
    }
    OrderedJson j = OrderedJson::parse(base.sourceText, nullptr, false);
    if (j.is_discarded() || !j.is_object()) {
        throw std::runtime_error("the experiment text of " + base.sourcePath +
                                 " is not a JSON object");
    }
    j["grains"]["count"] = edited.assembly.grainCount;
    OrderedJson& shear = j["shear"];
    shear["pressures"] = edited.shear.pressures;
    shear["friction"] = edited.shear.friction;
    shear["target_axial_strain"] = edited.shear.targetAxialStrain;
    if (!sameTests(base, edited)) {
        // The panel edits one test (a list of several is kept as the file has it).
        const LoadingPath& t = edited.tests.front();
        if (t.kind == LoadingPath::Kind::Drained && !t.extension) {
            j.erase("test"); // the drained test is a file without one, the same bits
        } else {
            OrderedJson test{{"kind", loadingKindName(t.kind)}};
            if (t.kind == LoadingPath::Kind::StressPath) {
                test["slope"] = t.slope;
            }
            if (t.extension) {
                test["direction"] = "extension";
            }
            j["test"] = test;
        }
    }
    // nlohmann writes doubles in the shortest form that reads back to the same bits.
    return j.dump(2) + "\n";
}

ExperimentConfig editedExperiment(const ExperimentConfig& base, const ExperimentConfig& edited,
                                  const std::string& sourceName) {
    return parseExperimentText(editedExperimentText(base, edited), sourceName);
}

} // namespace grainlab::ui
