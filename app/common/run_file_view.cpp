// See run_file_view.h.
#include "common/run_file_view.h"

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
#include "grainlab/stage_kind.h"

namespace grainlab::ui {
namespace {

/// "shear 15 kPa": the stage name the runner shows, from the checkpoint's identity.
std::string stageName(const CheckpointInfo& info) {
    if (info.stageKind.empty()) {
        return info.name; // not recorded (cannot happen in a file of this format)
    }
    return stageTitle(info.stageKind, info.pressure) + (info.peak ? ", peak of q/p" : "");
}

/// The checkpoints in write order, except that a test's peak checkpoint (written when the test
/// ended) moves to just after the last checkpoint of its test at or before its step, so that
/// the scrubber runs through each test in the order of eps1.
std::vector<CheckpointInfo> inScrubberOrder(std::vector<CheckpointInfo> infos) {
    std::vector<CheckpointInfo> out;
    std::vector<CheckpointInfo> peaks;
    for (CheckpointInfo& info : infos) {
        (info.peak ? peaks : out).push_back(std::move(info));
    }
    for (CheckpointInfo& peak : peaks) {
        std::size_t at = out.size();
        for (std::size_t k = out.size(); k-- > 0;) {
            if (out[k].test == peak.test && out[k].step <= peak.step) {
                at = k + 1;
                break;
            }
        }
        out.insert(out.begin() + static_cast<std::ptrdiff_t>(at), std::move(peak));
    }
    return out;
}

} // namespace

RunFileView openRunFile(const std::string& path) {
    RunFileView view;
    view.path = path;
    const std::vector<CheckpointInfo> infos = inScrubberOrder(listCheckpointInfo(path));
    const std::string prefix = std::filesystem::path(path).filename().string() + ": ";
    for (const std::string& test : listTests(path)) {
        SeriesTable table = readSeries(path, test);
        table.test = prefix + test;
        view.series.push_back(std::move(table));
    }
    // Each checkpoint's stage, test, step and eps1 are attributes of the checkpoint, and so is
    // the orientation at its test's start (the first checkpoint of each test is read for it).
    std::map<std::string, int> first; // test -> index into thetaAtTestStart
    for (const CheckpointInfo& info : infos) {
        view.checkpoints.push_back(info.name);
        view.checkpointStep.push_back(info.step);
        view.checkpointStage.push_back(stageName(info));
        view.checkpointKind.push_back(stageKindFromName(info.stageKind).value_or(StageKind::Done));
        view.checkpointPressure.push_back(info.pressure);
        view.checkpointTest.push_back(info.test.empty() ? std::string() : prefix + info.test);
        view.checkpointStrain.push_back(
            info.stageKind.empty() ? std::numeric_limits<double>::quiet_NaN() : info.axialStrain);
        auto it = first.find(info.test);
        if (it == first.end()) {
            view.thetaAtTestStart.push_back(
                std::make_shared<const std::vector<double>>(readThetaAtTestStart(path, info.name)));
            it = first.emplace(info.test, static_cast<int>(view.thetaAtTestStart.size()) - 1).first;
        }
        view.checkpointTestStart.push_back(it->second);
    }
    view.warnings = readWarnings(path);
    return view;
}

SnapshotPtr runFileSnapshot(const RunFileView& file, std::size_t index) {
    if (index >= file.checkpoints.size()) {
        throw std::runtime_error(file.path + ": no checkpoint " + std::to_string(index));
    }
    const std::string& name = file.checkpoints[index];
    Simulation sim(readState(file.path, checkpointGroup(name)));
    auto s = std::make_shared<Snapshot>();
    s->thetaAtTestStart = index < file.checkpointTestStart.size()
                              ? file.thetaAtTestStart[file.checkpointTestStart[index]]
                              : std::make_shared<const std::vector<double>>();
    fillSnapshotScene(*s, sim, *s->thetaAtTestStart);
    s->stage = index < file.checkpointStage.size() ? file.checkpointStage[index] : name;
    if (index < file.checkpointKind.size()) {
        s->stageKind = file.checkpointKind[index];
        s->stagePressure = file.checkpointPressure[index];
    }
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
            k >= file.checkpointKind.size() || !isTestStage(file.checkpointKind[k])) {
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
