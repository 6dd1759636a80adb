#include "runner_state.h"

#include <nlohmann/json.hpp>

namespace grainlab {

std::string runnerStateText(const RunnerState& s) {
    // Each value keeps the JSON number type it has always had (integers as integers,
    // voids_at_start as a double), so the text is the same for the same state.
    nlohmann::json j;
    j["phase"] = s.phase;
    j["index"] = s.index;
    j["calm"] = s.calm;
    j["stage_start_step"] = s.stageStartStep;
    j["length1_at0"] = s.length1At0;
    j["length2_at0"] = s.length2At0;
    j["area_at0"] = s.areaAt0;
    j["voids_at_start"] = s.voidsAtStart;
    j["have_last"] = s.haveLast;
    j["last_eps1"] = s.lastEps1;
    j["last_epsv"] = s.lastEpsv;
    j["next_record_step"] = s.nextRecordStep;
    j["next_snapshot_step"] = s.nextSnapshotStep;
    j["checkpoint_counter"] = s.checkpointCounter;
    j["stage_done"] = s.stageDone;
    j["theta_at_test_start"] = s.thetaAtTestStart;
    j["theta_at_run_start"] = s.thetaAtRunStart;
    j["current_series"] = s.currentSeries;
    nlohmann::json rows = nlohmann::json::object();
    for (const auto& [test, count] : s.seriesRows) {
        rows[test] = count;
    }
    j["series_rows"] = rows;
    nlohmann::json given = nlohmann::json::array();
    for (const RunWarning& w : s.warnings) {
        given.push_back({{"kind", w.kind},
                         {"test", w.test},
                         {"step", w.step},
                         {"eps1", w.axialStrain},
                         {"text", w.text}});
    }
    j["warnings"] = given;
    j["unbalanced_low"] = s.unbalancedLow;
    if (s.probeStartStep != 0) { // written by a probes stage only: earlier texts stay the same
        j["probe"] = s.probe;
        j["probe_start_step"] = s.probeStartStep;
    }
    if (s.cyclicDirection != 0) { // a stress-controlled cyclic test's only
        j["cyclic_direction"] = s.cyclicDirection;
        j["cyclic_reversals"] = s.cyclicReversals;
    }
    if (s.probeStartState) { // only between a probe start state and the probes' start
        j["probe_start"] = {{"step", s.probeStartState->step},
                            {"kept_in", s.probeStartState->keptIn}};
    }
    if (s.peak) {
        nlohmann::json p;
        p["q_over_p"] = s.peak->stressRatio;
        p["step"] = s.peak->step;
        p["eps1"] = s.peak->eps1;
        p["kept_in"] = s.peak->keptIn;
        j["peak"] = p;
    }
    return j.dump();
}

RunnerState parseRunnerState(const std::string& text) {
    const nlohmann::json j = nlohmann::json::parse(text);
    RunnerState s;
    s.phase = j.at("phase").get<int>();
    s.index = j.at("index");
    s.calm = j.at("calm");
    s.stageStartStep = j.at("stage_start_step");
    s.length1At0 = j.at("length1_at0");
    s.length2At0 = j.at("length2_at0");
    s.areaAt0 = j.at("area_at0");
    s.voidsAtStart = j.at("voids_at_start");
    s.haveLast = j.at("have_last");
    s.lastEps1 = j.at("last_eps1");
    s.lastEpsv = j.at("last_epsv");
    s.nextRecordStep = j.at("next_record_step");
    s.nextSnapshotStep = j.at("next_snapshot_step");
    s.checkpointCounter = j.at("checkpoint_counter");
    s.stageDone = j.at("stage_done");
    s.thetaAtTestStart = j.at("theta_at_test_start").get<std::vector<double>>();
    s.thetaAtRunStart = j.at("theta_at_run_start").get<std::vector<double>>();
    s.currentSeries = j.at("current_series");
    for (const auto& [name, count] : j.at("series_rows").items()) {
        s.seriesRows[name] = count.get<std::size_t>();
    }
    // Runner states written before warnings existed have neither key.
    if (j.contains("warnings")) {
        for (const auto& w : j.at("warnings")) {
            s.warnings.push_back(
                {w.at("kind"), w.at("test"), w.at("step"), w.at("eps1"), w.at("text")});
        }
    }
    if (j.contains("unbalanced_low")) {
        s.unbalancedLow = j.at("unbalanced_low").get<std::array<double, 4>>();
    }
    if (j.contains("cyclic_direction")) {
        s.cyclicDirection = j.at("cyclic_direction");
        s.cyclicReversals = j.at("cyclic_reversals");
    }
    if (j.contains("probe")) {
        s.probe = j.at("probe");
        s.probeStartStep = j.at("probe_start_step");
    }
    if (j.contains("probe_start")) {
        const nlohmann::json& p = j.at("probe_start");
        s.probeStartState = ProbeStartRecord{p.at("step"), p.at("kept_in")};
    }
    if (j.contains("peak")) {
        const nlohmann::json& p = j.at("peak");
        s.peak = RunningPeakRecord{p.at("q_over_p"), p.at("step"), p.at("eps1"), p.at("kept_in")};
    }
    return s;
}

} // namespace grainlab
