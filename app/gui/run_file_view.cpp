// See run_file_view.h.
#include "gui/run_file_view.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <map>
#include <stdexcept>

#include "grainlab/measures.h"
#include "grainlab/run_file.h"
#include "grainlab/simulation.h"

namespace grainlab::ui {
namespace {

/// "000012-shear-15-kPa-step88000" -> "shear 15 kPa" (the runner's checkpoint names).
std::string stageOfCheckpoint(const std::string& name) {
    std::string stage = name;
    const auto dash = stage.find('-');
    if (dash != std::string::npos && dash < 8) {
        stage = stage.substr(dash + 1);
    }
    const auto step = stage.rfind("-step");
    if (step != std::string::npos) {
        stage = stage.substr(0, step);
    }
    std::replace(stage.begin(), stage.end(), '-', ' ');
    return stage;
}

/// The test a stage belongs to, as far as rotation goes: "compaction" for every compaction
/// stage, the pressure ("15 kPa") for a test's equilibration and shear; "" for anything else
/// (e.g. an "interrupted" checkpoint, which belongs to the test before it).
std::string testOfStage(const std::string& stage) {
    if (stage.rfind("compaction", 0) == 0) {
        return "compaction";
    }
    for (const char* prefix : {"equilibration ", "shear "}) {
        if (stage.rfind(prefix, 0) == 0) {
            return stage.substr(std::string(prefix).size());
        }
    }
    return {};
}

} // namespace

RunFileView openRunFile(const std::string& path) {
    RunFileView view;
    view.path = path;
    view.checkpoints = listCheckpoints(path);
    const std::string prefix = std::filesystem::path(path).filename().string() + ": ";
    for (const std::string& test : listTests(path)) {
        SeriesTable table = readSeries(path, test);
        table.test = prefix + test;
        view.series.push_back(std::move(table));
    }
    for (const std::string& name : view.checkpoints) {
        const auto at = name.rfind("-step");
        const std::int64_t step = at == std::string::npos ? -1 : std::atoll(name.c_str() + at + 5);
        const std::string stage = stageOfCheckpoint(name);
        std::string test;
        double strain = std::numeric_limits<double>::quiet_NaN();
        for (const SeriesTable& table : view.series) {
            const int stepColumn = table.column("step"), eps1 = table.column("eps1");
            if (stepColumn < 0 || eps1 < 0) {
                continue;
            }
            for (std::size_t r = 0; r < table.rows.size(); ++r) {
                if (table.rows[r][stepColumn] == double(step) &&
                    (r >= table.stages.size() || table.stages[r] == stage)) {
                    strain = table.rows[r][eps1];
                    test = table.test;
                }
            }
        }
        view.checkpointStep.push_back(step);
        view.checkpointStage.push_back(stage);
        view.checkpointTest.push_back(test);
        view.checkpointStrain.push_back(strain);
    }
    // Rotation counts from the first checkpoint of each test: the runner writes one as a test
    // starts (the sample it equilibrates), holding exactly the orientations its live snapshots
    // count rotation from.
    std::map<std::string, int> first; // test of the stage -> index into thetaAtTestStart
    std::string current;
    for (std::size_t k = 0; k < view.checkpoints.size(); ++k) {
        const std::string test = testOfStage(view.checkpointStage[k]);
        if (!test.empty()) {
            current = test;
        }
        auto it = first.find(current);
        if (it == first.end()) {
            const SimulationState state = readState(path, checkpointGroup(view.checkpoints[k]));
            view.thetaAtTestStart.push_back(state.grains.theta);
            it = first.emplace(current, static_cast<int>(view.thetaAtTestStart.size()) - 1).first;
        }
        view.checkpointTestStart.push_back(it->second);
    }
    return view;
}

SnapshotPtr runFileSnapshot(const RunFileView& file, std::size_t index) {
    if (index >= file.checkpoints.size()) {
        throw std::runtime_error(file.path + ": no checkpoint " + std::to_string(index));
    }
    const std::string& name = file.checkpoints[index];
    Simulation sim(readState(file.path, checkpointGroup(name)));
    auto s = std::make_shared<Snapshot>();
    static const std::vector<double> none;
    const std::vector<double>& thetaAtStart =
        index < file.checkpointTestStart.size()
            ? file.thetaAtTestStart[file.checkpointTestStart[index]]
            : none;
    fillSnapshotScene(*s, sim, thetaAtStart);
    s->stage = stageOfCheckpoint(name);
    if (index < file.checkpointStrain.size() && !std::isnan(file.checkpointStrain[index])) {
        s->axialStrain = file.checkpointStrain[index];
        s->test = file.checkpointTest[index];
    }
    s->progress =
        file.checkpoints.size() > 1 ? double(index) / double(file.checkpoints.size() - 1) : 1.0;
    s->series = file.series;
    return s;
}

int nearestCheckpoint(const RunFileView& file, const std::string& test, double eps1) {
    int best = -1;
    double distance = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < file.checkpointStrain.size(); ++k) {
        const double strain = file.checkpointStrain[k];
        if (std::isnan(strain) || (!test.empty() && file.checkpointTest[k] != test) ||
            file.checkpointStage[k].rfind("shear", 0) != 0) {
            continue;
        }
        if (std::fabs(strain - eps1) < distance) {
            distance = std::fabs(strain - eps1);
            best = static_cast<int>(k);
        }
    }
    return best;
}

} // namespace grainlab::ui
