// The runner played as stages (engine/src/stage.h): the runner state written by a run reads back
// to the same text, a runner state in the format of earlier files reads, a run resumed from a
// checkpoint in the middle of a test or at a stage's end reports the same progress and
// identity as the unbroken run at the same step and ends with the same series, and the
// identity of the stage travels in RunProgress and the snapshot as data.
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "grainlab/experiment_file.h"
#include "grainlab/experiment_runner.h"
#include "grainlab/stage_kind.h"
#include "experiment_fixtures.h"
#include "runner_state.h"

namespace grainlab {
namespace {

/// The quick experiment made small: 120 grains, two pressures, a short shear.
ExperimentConfig smallQuick() {
    nlohmann::json j = test::smallQuickExperiment();
    j["record"]["snapshot_strain_interval"] = 0.0005;
    return parseExperimentText(j.dump(), "small-quick.json");
}

struct Kept {
    std::string name;
    StageIdentity identity;
    SimulationState state;
    std::string runnerState;
    std::map<double, SimulationState> samples; ///< as they were when it was written
    std::vector<SeriesTable> series;
    std::optional<SimulationState> runningPeak;
};

/// Keeps everything in memory, as a run file would.
class MemoryOutput : public RunOutput {
public:
    void record(const SeriesTable& table) override {
        for (SeriesTable& t : series) {
            if (t.test == table.test) {
                t = table;
                return;
            }
        }
        series.push_back(table);
    }
    void checkpoint(const std::string&, const SimulationState&, const std::string&) override {}
    void sample(double pressure, const SimulationState& state) override {
        samples[pressure] = state;
    }
    void checkpoint(const CheckpointData& data) override {
        Kept k{data.name, data.identity, *data.state, data.runnerState, samples, series, {}};
        if (data.runningPeak) {
            peaks[data.name] = *data.runningPeak;
        }
        kept.push_back(std::move(k));
    }
    ResumePoint resumeFrom(const Kept& k) const {
        ResumePoint r;
        r.state = k.state;
        r.runnerState = k.runnerState;
        r.samples = k.samples;
        r.series = k.series;
        const std::string in = ExperimentRunner::runningPeakCheckpoint(k.runnerState);
        if (!in.empty()) {
            r.runningPeak = peaks.at(in);
        }
        return r;
    }

    std::vector<SeriesTable> series;
    std::map<double, SimulationState> samples;
    std::vector<Kept> kept;
    std::map<std::string, SimulationState> peaks;
};

using Where = std::tuple<std::string, std::string, std::int64_t>; // stage, test, step

/// Runs to the end, noting the progress at every simulation step that is a multiple of 200
/// (so that a resumed run stops at the same steps as the unbroken one).
std::map<Where, RunProgress> runAll(ExperimentRunner& runner) {
    std::map<Where, RunProgress> seen;
    do {
        const RunProgress p = runner.progress();
        seen[{p.stage, p.test, p.step}] = p;
    } while (runner.advance(200 - runner.progress().step % 200));
    const RunProgress p = runner.progress();
    seen[{p.stage, p.test, p.step}] = p;
    return seen;
}

TEST(ExperimentRunnerStages, ARunnerStateReadsBackToTheSameText) {
    MemoryOutput out;
    ExperimentRunner runner(smallQuick(), &out);
    while (runner.advance(2000)) {
    }
    int checked = 0;
    for (const Kept& k : out.kept) {
        if (k.identity.peak) {
            EXPECT_TRUE(k.runnerState.empty()) << k.name;
            continue;
        }
        EXPECT_EQ(runnerStateText(parseRunnerState(k.runnerState)), k.runnerState) << k.name;
        ++checked;
    }
    EXPECT_GT(checked, 10);
    EXPECT_TRUE(ExperimentRunner::finishedAt(out.kept.back().runnerState));
}

TEST(ExperimentRunnerStages, ARunnerStateOfEarlierFilesReads) {
    // The keys of run files written before warnings and unbalanced_low were stored.
    const std::string old =
        R"({"area_at0":1e-4,"calm":3,"checkpoint_counter":7,"current_series":"p025kPa",)"
        R"("have_last":true,"index":1,"last_eps1":0.001,"last_epsv":-0.0002,)"
        R"("length1_at0":0.01,"length2_at0":0.01,"next_record_step":1200,)"
        R"("next_snapshot_step":1500,"phase":2,"series_rows":{"compaction":40,"p025kPa":12},)"
        R"("stage_done":false,"stage_start_step":1000,"theta_at_run_start":[],)"
        R"("theta_at_test_start":[0.5,1.5],"voids_at_start":17.0,)"
        R"("peak":{"q_over_p":0.6,"step":1100,"eps1":0.0009,"kept_in":"000006-x"}})";
    const RunnerState s = parseRunnerState(old);
    EXPECT_EQ(static_cast<StageKind>(s.phase), StageKind::Shear);
    EXPECT_EQ(s.index, 1);
    EXPECT_EQ(s.calm, 3);
    EXPECT_EQ(s.seriesRows.at("p025kPa"), 12u);
    EXPECT_EQ(s.thetaAtTestStart, (std::vector<double>{0.5, 1.5}));
    EXPECT_EQ(s.voidsAtStart, 17.0);
    EXPECT_TRUE(s.warnings.empty());
    EXPECT_EQ(s.unbalancedLow, (std::array<double, 4>{-1, -1, -1, -1}));
    ASSERT_TRUE(s.peak.has_value());
    EXPECT_EQ(s.peak->keptIn, "000006-x");
    EXPECT_EQ(s.peak->step, 1100);
    EXPECT_FALSE(ExperimentRunner::finishedAt(old));
    EXPECT_EQ(ExperimentRunner::runningPeakCheckpoint(old), "000006-x");
    EXPECT_EQ(ExperimentRunner::seriesRowsAtCheckpoint(old).at("compaction"), 40u);
}

TEST(ExperimentRunnerStages, AResumedRunReportsWhatTheUnbrokenOneDidAndEndsTheSame) {
    const ExperimentConfig config = smallQuick();
    MemoryOutput out;
    ExperimentRunner unbroken(config, &out);
    const std::map<Where, RunProgress> seen = runAll(unbroken);

    // Progress over a whole run, in the order it goes: 0 at its start, 1 at its end, never
    // decreasing.
    {
        double last = -1;
        ExperimentRunner again(config);
        EXPECT_EQ(again.progress().fraction, 0.0);
        do {
            const double f = again.progress().fraction;
            ASSERT_GE(f, last) << again.progress().stage << " step " << again.progress().step;
            last = f;
        } while (again.advance(700));
        EXPECT_EQ(again.progress().fraction, 1.0);
        EXPECT_EQ(again.progress().kind, StageKind::Done);
    }

    // One checkpoint in the middle of the second test's shear, one at a compaction's end.
    const Kept* midShear = nullptr;
    const Kept* stageEnd = nullptr;
    for (const Kept& k : out.kept) {
        if (k.identity.peak || k.runnerState.empty()) {
            continue;
        }
        const RunnerState s = parseRunnerState(k.runnerState);
        if (k.identity.kind == "shear" && s.index == 1 && !s.stageDone && k.identity.step > 0 &&
            k.identity.axialStrain > 0 && !midShear) {
            midShear = &k;
        }
        if (s.stageDone && k.identity.kind == "compaction" && !stageEnd) {
            stageEnd = &k;
        }
    }
    ASSERT_NE(midShear, nullptr);
    ASSERT_NE(stageEnd, nullptr);
    for (const Kept* from : {midShear, stageEnd}) {
        MemoryOutput again;
        ExperimentRunner resumed(config, out.resumeFrom(*from), &again);
        const std::map<Where, RunProgress> after = runAll(resumed);
        int compared = 0;
        for (const auto& [where, p] : after) {
            const auto it = seen.find(where);
            if (it == seen.end()) {
                continue;
            }
            EXPECT_EQ(p.fraction, it->second.fraction) << std::get<0>(where) << " " << p.step;
            EXPECT_EQ(p.kind, it->second.kind);
            EXPECT_EQ(p.pressure, it->second.pressure);
            EXPECT_EQ(p.axialStrain, it->second.axialStrain);
            ASSERT_TRUE(p.thetaAtTestStart && it->second.thetaAtTestStart);
            EXPECT_EQ(*p.thetaAtTestStart, *it->second.thetaAtTestStart);
            ++compared;
        }
        EXPECT_GE(compared, 5) << from->name;
        ASSERT_EQ(resumed.series().size(), unbroken.series().size());
        for (std::size_t t = 0; t < resumed.series().size(); ++t) {
            EXPECT_EQ(resumed.series()[t].rows, unbroken.series()[t].rows) << from->name;
            EXPECT_EQ(resumed.series()[t].stages, unbroken.series()[t].stages);
        }
        EXPECT_EQ(resumed.simulation().stateRef().grains.x1,
                  unbroken.simulation().stateRef().grains.x1);
    }
}

TEST(ExperimentRunnerStages, TheStageIdentityTravelsAsData) {
    const ExperimentConfig config = smallQuick();
    MemoryOutput out;
    ExperimentRunner runner(config, &out);
    RunProgress p = runner.progress();
    EXPECT_EQ(p.kind, StageKind::Compaction);
    EXPECT_EQ(p.pressure, 25e3);
    ASSERT_TRUE(p.thetaAtTestStart);
    EXPECT_TRUE(p.thetaAtTestStart->empty());
    while (runner.progress().kind != StageKind::Shear) {
        ASSERT_TRUE(runner.advance(500));
    }
    p = runner.progress();
    EXPECT_EQ(p.pressure, 25e3);
    EXPECT_EQ(p.test, "p025kPa");
    EXPECT_EQ(p.stage, "shear 25 kPa");
    // The orientation at the test's start is the sample's (its equilibration's start).
    ASSERT_TRUE(p.thetaAtTestStart);
    EXPECT_EQ(*p.thetaAtTestStart, out.samples.at(25e3).grains.theta);
    // Snapshots of one test share it, and their rotation counts from it.
    const auto a = runner.snapshot(SnapshotMeasures::Later);
    runner.advance(100);
    const auto b = runner.snapshot(SnapshotMeasures::Later);
    EXPECT_EQ(a->stageKind, StageKind::Shear);
    EXPECT_EQ(a->stagePressure, 25e3);
    EXPECT_EQ(a->thetaAtTestStart.get(), b->thetaAtTestStart.get());
    ASSERT_EQ(b->rotation.size(), b->thetaAtTestStart->size());
    for (const StageKind k :
         {StageKind::Compaction, StageKind::Equilibration, StageKind::Shear, StageKind::Done}) {
        EXPECT_EQ(stageKindFromName(stageKindName(k)), k);
    }
    EXPECT_FALSE(stageKindFromName("shear 25 kPa").has_value());
}

} // namespace
} // namespace grainlab
