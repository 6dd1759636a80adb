#include "grainlab/experiment_runner.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "grainlab/equilibrium.h"
#include "grainlab/loading_rate.h"
#include "grainlab/measures.h"
#include "grainlab/periodic_cell.h"
#include "grainlab/time_step.h"

namespace grainlab {
namespace {

enum class Phase { Compaction = 0, Equilibration = 1, Shear = 2, Done = 3 };

std::string kiloPascal(double pressure) {
    return fmt::format("{:g} kPa", pressure / 1000.0);
}

/// Test names sort by pressure: p015kPa, p100kPa (p12.5kPa for non-integer kPa).
std::string testName(double pressure) {
    const double kpa = pressure / 1000.0;
    if (kpa == std::round(kpa)) {
        return fmt::format("p{:03d}kPa", static_cast<int>(kpa));
    }
    return fmt::format("p{:g}kPa", kpa);
}

constexpr const char* kCompactionSeries = "compaction";

/// Threads actually used: small assemblies run on one thread, where the per-step cost of
/// waking a second thread exceeds the work it takes over (and, on a loaded machine, a waiting
/// OpenMP thread can cost a whole time slice per step). Results are the same bits either way.
int threadsFor(const ExperimentConfig& config) {
    constexpr int kGrainsPerThread = 2000;
    return std::clamp(config.assembly.grainCount / kGrainsPerThread, 1,
                      std::max(1, config.parameters.threads));
}

/// Numeric columns of the series (the `stage` text column is kept beside the rows).
std::vector<SeriesColumn> numericColumns() {
    std::vector<SeriesColumn> out;
    for (const auto& c : seriesColumns()) {
        if (!c.text) {
            out.push_back(c);
        }
    }
    return out;
}

/// The running maximum of q/p of the shear test under way, at its record points. The peak is
/// known only when the test ends: until then the state of the largest q/p so far is kept here,
/// and written as the test's peak checkpoint at its end. A checkpoint written in between keeps
/// the maximum in its runner state (and the state in the checkpoint, see keptIn), so that a
/// resumed run continues it and writes the same peak checkpoint as an unbroken run.
struct RunningPeak {
    bool active = false;
    double stressRatio = 0; ///< q/p [-]
    std::int64_t step = 0;
    double eps1 = 0;       ///< [-]
    SimulationState state; ///< at that record
    /// The checkpoint whose group running_peak holds `state`; "" while none does (a checkpoint
    /// written at the peak's own step needs none: its state is the peak's).
    std::string keptIn;

    nlohmann::json json(const std::string& keptAs) const {
        nlohmann::json j;
        j["q_over_p"] = stressRatio;
        j["step"] = step;
        j["eps1"] = eps1;
        j["kept_in"] = keptAs;
        return j;
    }
    void restore(const nlohmann::json& j) {
        active = true;
        stressRatio = j.at("q_over_p");
        step = j.at("step");
        eps1 = j.at("eps1");
        keptIn = j.at("kept_in");
    }
};

} // namespace

struct ExperimentRunner::Impl {
    ExperimentConfig config;
    RunOutput* output = nullptr;
    std::unique_ptr<Simulation> sim;
    Phase phase = Phase::Compaction;
    int index = 0;               ///< compaction pressure index, or shear pressure index
    int calm = 0;                ///< consecutive passing equilibrium checks
    std::int64_t stepsTaken = 0; ///< steps advanced by this runner object (its cost)
    std::int64_t stageStartStep = 0;
    double length1At0 = 0, length2At0 = 0, areaAt0 = 0; ///< strain references [m], [m^2]
    double voidsAtStart = -1;                           ///< N_vi of the current test
    bool haveLast = false;
    double lastEps1 = 0, lastEpsv = 0;
    std::int64_t nextRecordStep = 0, nextSnapshotStep = 0;
    std::int64_t checkpointCounter = 0;
    bool stageDone = false; ///< the stage has ended; the next one is still to start
    std::vector<double> thetaAtTestStart;
    std::vector<double> thetaAtRunStart; ///< the generated assembly's (compaction identity)
    std::map<double, SimulationState> samples;
    std::vector<SeriesTable> series;
    int currentSeries = -1;
    RunningPeak peak;                 ///< of the shear test under way (inactive outside shear)
    std::vector<RunWarning> warnings; ///< every warning given so far, in order
    CalmHistory calmHistory;          ///< of the current stage's checks: why it did not calm

    void warn(const std::string& kind, const std::string& text) {
        warnings.push_back({kind,
                            currentSeries >= 0 ? series[currentSeries].test : kCompactionSeries,
                            sim->stepCount(), eps1(), text});
        if (output) {
            output->warnings(warnings);
        }
    }

    double pressure() const {
        return phase == Phase::Compaction ? config.compaction.pressures.at(index)
                                          : config.shear.pressures.at(index);
    }
    std::string stageName() const {
        switch (phase) {
        case Phase::Compaction:
            return "compaction " + kiloPascal(pressure());
        case Phase::Equilibration:
            return "equilibration " + kiloPascal(pressure());
        case Phase::Shear:
            return "shear " + kiloPascal(pressure());
        default:
            return "done";
        }
    }
    std::string stageKind() const {
        switch (phase) {
        case Phase::Compaction:
            return "compaction";
        case Phase::Equilibration:
            return "equilibration";
        case Phase::Shear:
            return "shear";
        default:
            return "done";
        }
    }
    /// The identity of the current stage, for its checkpoints.
    StageIdentity identity() const {
        StageIdentity id;
        id.kind = stageKind();
        id.test = currentSeries >= 0 ? series[currentSeries].test : kCompactionSeries;
        id.pressure = pressure();
        id.step = sim->stepCount();
        id.axialStrain = eps1();
        id.thetaAtTestStart = phase == Phase::Compaction ? thetaAtRunStart : thetaAtTestStart;
        return id;
    }
    const EquilibriumCriterion& criterion() const {
        return phase == Phase::Compaction ? config.compaction.criterion
                                          : config.shear.equilibration;
    }

    int seriesIndex(const std::string& name) {
        for (std::size_t k = 0; k < series.size(); ++k) {
            if (series[k].test == name) {
                return static_cast<int>(k);
            }
        }
        SeriesTable t;
        t.test = name;
        t.columns = numericColumns();
        series.push_back(std::move(t));
        return static_cast<int>(series.size()) - 1;
    }

    // ---- stage set-up ----

    void startCompaction(int k) {
        phase = Phase::Compaction;
        index = k;
        calm = 0;
        calmHistory = {};
        stageStartStep = sim->stepCount();
        const AxisControl servo{AxisMode::Stress, 0.0, pressure()};
        sim->setAxisControl(0, servo);
        sim->setAxisControl(1, servo);
        currentSeries = seriesIndex(kCompactionSeries);
        if (k == 0) {
            setStrainReference();
        }
        // The first record at the first equilibrium check: events fall on whole steps counted
        // from the stage's start, never where a caller's advance() happens to end.
        nextRecordStep = stageStartStep + criterion().checkInterval;
        nextSnapshotStep = sim->stepCount() + config.record.snapshotStepInterval;
    }

    void startEquilibration(int k) {
        phase = Phase::Equilibration;
        index = k;
        calm = 0;
        calmHistory = {};
        SimulationState state = samples.at(pressure());
        state.parameters.friction = config.shear.friction;
        state.parameters.servo.maxStrainRate = config.shear.maxStrainRate;
        state.parameters.threads = threadsFor(config);
        sim = std::make_unique<Simulation>(std::move(state));
        stageStartStep = sim->stepCount();
        const AxisControl servo{AxisMode::Stress, 0.0, pressure()};
        sim->setAxisControl(0, servo);
        sim->setAxisControl(1, servo);
        currentSeries = seriesIndex(testName(pressure()));
        setStrainReference();
        thetaAtTestStart = sim->stateRef().grains.theta;
        // The first record at the first equilibrium check: events fall on whole steps counted
        // from the stage's start, never where a caller's advance() happens to end.
        nextRecordStep = stageStartStep + criterion().checkInterval;
        nextSnapshotStep = sim->stepCount() + config.record.snapshotStepInterval;
    }

    void startShear() {
        phase = Phase::Shear;
        stageStartStep = sim->stepCount();
        setStrainReference();
        voidsAtStart = -1;
        peak = RunningPeak{};
        const double dt = config.parameters.timeStep;
        sim->setAxisControl(
            0, {AxisMode::Strain, config.shear.axialStrainPerStep / dt, 0.0, length1At0});
        sim->setAxisControl(1, {AxisMode::Stress, 0.0, pressure()});
        // Shear events fall on whole steps counted from the start of shear (each step adds the
        // same engineering strain), so they do not depend on how advance() is chunked.
        nextRecordStep = stageStartStep;
        nextSnapshotStep = stageStartStep + strideOf(config.record.snapshotStrainInterval);
        if (const auto text = inertialNumberWarning(config, pressure())) {
            warn("inertial_number", *text);
        }
    }

    std::int64_t strideOf(double strain) const {
        return std::max<std::int64_t>(1, std::llround(strain / config.shear.axialStrainPerStep));
    }
    std::int64_t shearEndStep() const {
        return stageStartStep + strideOf(config.shear.targetAxialStrain);
    }

    void setStrainReference() {
        length1At0 = sim->cell()[0];
        length2At0 = sim->cell()[3];
        areaAt0 = sim->cellArea();
        haveLast = false;
    }

    // ---- measures ----

    double eps1() const { return (length1At0 - sim->cell()[0]) / length1At0; }
    double eps2() const { return (length2At0 - sim->cell()[3]) / length2At0; }
    double epsv() const { return (areaAt0 - sim->cellArea()) / areaAt0; }

    void record(const ContactNetwork& network, const MeasureSet& measures) {
        RecordInputs in;
        in.step = sim->stepCount();
        in.time = sim->time();
        in.eps1 = eps1();
        in.eps2 = eps2();
        in.epsv = epsv();
        in.dilatancyIndex =
            haveLast && in.eps1 != lastEps1 ? -(in.epsv - lastEpsv) / (in.eps1 - lastEps1) : 0.0;
        in.stress = sim->stress();
        if (phase == Phase::Shear && voidsAtStart < 0) {
            voidsAtStart = measures.voidCells.voidCount;
        }
        in.initialVoidCount = phase == Phase::Shear ? voidsAtStart : 0.0;
        const auto& L = sim->stateRef().velocityGradient;
        in.strainRate1 = -L[0];
        in.strainRate2 = -L[3];
        in.density = config.parameters.density;
        in.energies = sim->energies();
        (void)network;
        SeriesTable& t = series[currentSeries];
        t.rows.push_back(seriesRow(measures, in));
        t.stages.push_back(stageName());
        t.stageKinds.push_back(stageKind());
        t.stagePressures.push_back(pressure());
        lastEps1 = in.eps1;
        lastEpsv = in.epsv;
        haveLast = true;
        if (output) {
            output->record(t);
        }
    }

    void recordNow() {
        const ContactNetwork network = sim->contactNetwork();
        record(network, computeMeasures(network));
    }

    std::string runnerState() const {
        nlohmann::json j;
        j["phase"] = static_cast<int>(phase);
        j["index"] = index;
        j["calm"] = calm;
        j["stage_start_step"] = stageStartStep;
        j["length1_at0"] = length1At0;
        j["length2_at0"] = length2At0;
        j["area_at0"] = areaAt0;
        j["voids_at_start"] = voidsAtStart;
        j["have_last"] = haveLast;
        j["last_eps1"] = lastEps1;
        j["last_epsv"] = lastEpsv;
        j["next_record_step"] = nextRecordStep;
        j["next_snapshot_step"] = nextSnapshotStep;
        j["checkpoint_counter"] = checkpointCounter;
        j["stage_done"] = stageDone;
        j["theta_at_test_start"] = thetaAtTestStart;
        j["theta_at_run_start"] =
            phase == Phase::Compaction ? thetaAtRunStart : std::vector<double>{};
        j["current_series"] = currentSeries >= 0 ? series[currentSeries].test : "";
        nlohmann::json rows = nlohmann::json::object();
        for (const auto& t : series) {
            rows[t.test] = t.rows.size();
        }
        j["series_rows"] = rows;
        nlohmann::json given = nlohmann::json::array();
        for (const RunWarning& w : warnings) {
            given.push_back({{"kind", w.kind},
                             {"test", w.test},
                             {"step", w.step},
                             {"eps1", w.axialStrain},
                             {"text", w.text}});
        }
        j["warnings"] = given;
        j["unbalanced_low"] = calmHistory.lowest;
        if (peak.active) {
            // kept_in "": the checkpoint's own state is the peak's.
            j["peak"] = peak.json(peak.step == sim->stepCount() ? std::string() : peak.keptIn);
        }
        return j.dump();
    }

    void restore(const std::string& text) {
        const nlohmann::json j = nlohmann::json::parse(text);
        phase = static_cast<Phase>(j.at("phase").get<int>());
        index = j.at("index");
        calm = j.at("calm");
        stageStartStep = j.at("stage_start_step");
        length1At0 = j.at("length1_at0");
        length2At0 = j.at("length2_at0");
        areaAt0 = j.at("area_at0");
        voidsAtStart = j.at("voids_at_start");
        haveLast = j.at("have_last");
        lastEps1 = j.at("last_eps1");
        lastEpsv = j.at("last_epsv");
        nextRecordStep = j.at("next_record_step");
        nextSnapshotStep = j.at("next_snapshot_step");
        checkpointCounter = j.at("checkpoint_counter");
        stageDone = j.at("stage_done");
        thetaAtTestStart = j.at("theta_at_test_start").get<std::vector<double>>();
        thetaAtRunStart = j.at("theta_at_run_start").get<std::vector<double>>();
        const std::string current = j.at("current_series");
        currentSeries = current.empty() ? -1 : seriesIndex(current);
        // Runner states written before warnings existed have neither key.
        if (j.contains("warnings")) {
            for (const auto& w : j.at("warnings")) {
                warnings.push_back(
                    {w.at("kind"), w.at("test"), w.at("step"), w.at("eps1"), w.at("text")});
            }
        }
        if (j.contains("unbalanced_low")) {
            calmHistory.lowest = j.at("unbalanced_low").get<std::array<double, 4>>();
        }
    }

    /// The running peak of a resumed run: from the runner state, with the state kept in the
    /// checkpoint it names (`kept`), or the resumed state itself when the peak was at its step.
    void restorePeak(const std::string& runnerStateText, const SimulationState& resumed,
                     std::optional<SimulationState> kept) {
        const nlohmann::json j = nlohmann::json::parse(runnerStateText);
        if (!j.contains("peak")) {
            return;
        }
        peak.restore(j.at("peak"));
        if (!peak.keptIn.empty()) {
            if (!kept) {
                throw std::runtime_error(fmt::format(
                    "resume: the checkpoint's running maximum of q/p is kept in checkpoint {}, "
                    "which the resume point does not hold",
                    peak.keptIn));
            }
            peak.state = std::move(*kept);
        } else if (peak.step == resumed.step) {
            peak.state = resumed;
        } else {
            throw std::runtime_error(
                fmt::format("resume: the running maximum of q/p (step {}) is kept in no checkpoint",
                            peak.step));
        }
        if (peak.state.step != peak.step) {
            throw std::runtime_error(fmt::format("resume: the running maximum of q/p is at step "
                                                 "{}, its kept state at step {}",
                                                 peak.step, peak.state.step));
        }
        peak.state.parameters.threads = threadsFor(config);
    }

    void checkpoint(const std::string& label) { checkpoint(label, identity()); }

    void checkpoint(const std::string& label, const StageIdentity& id) {
        if (!output) {
            return;
        }
        ++checkpointCounter;
        const SimulationState state = sim->state();
        const ContactNetwork network = sim->contactNetwork();
        const VoidCellSet cells = computeVoidCells(network);
        CheckpointData data;
        data.name = fmt::format("{:06d}-{}", checkpointCounter, label);
        data.state = &state;
        data.identity = id;
        data.network = &network;
        data.voidCells = &cells;
        if (peak.active && peak.step != state.step && peak.keptIn.empty()) {
            // The first checkpoint since the peak's record keeps its state (named in the
            // runner state, so written before it is made).
            data.runningPeak = &peak.state;
            peak.keptIn = data.name;
        }
        data.runnerState = runnerState();
        output->checkpoint(data);
    }

    /// At a shear record, before a checkpoint of the same step: a new maximum of q/p keeps a
    /// copy of the state. The first of equal maxima is the peak.
    void trackPeak() {
        if (!output) {
            return; // only the peak checkpoint needs it
        }
        const SeriesTable& t = series[currentSeries];
        const double ratio = t.rows.back()[t.column("q_over_p")];
        if (peak.active && !(ratio > peak.stressRatio)) {
            return;
        }
        peak.active = true;
        peak.stressRatio = ratio;
        peak.step = sim->stepCount();
        peak.eps1 = eps1();
        peak.state = sim->state();
        peak.keptIn.clear();
    }

    /// The checkpoint at the peak of q/p of the test that is ending, marked as such. It is for
    /// reading and viewing, not for continuing: it has no runner state (a resumed run starts
    /// from the last checkpoint that is not a peak).
    void peakCheckpoint() {
        if (!output || !peak.active) {
            return;
        }
        ++checkpointCounter;
        std::string stage = stageName();
        std::replace(stage.begin(), stage.end(), ' ', '-');
        // The contacts of the peak's state: a simulation made from it has the same forces, bit
        // for bit (as a resumed run has).
        const Simulation atPeak(peak.state);
        const ContactNetwork network = atPeak.contactNetwork();
        const VoidCellSet cells = computeVoidCells(network);
        CheckpointData data;
        data.name = fmt::format("{:06d}-peak-{}-step{}", checkpointCounter, stage, peak.step);
        data.state = &peak.state;
        data.identity = identity();
        data.identity.step = peak.step;
        data.identity.axialStrain = peak.eps1;
        data.identity.peak = true;
        data.identity.peakStressRatio = peak.stressRatio;
        data.network = &network;
        data.voidCells = &cells;
        output->checkpoint(data);
    }

    std::string checkpointLabel() const {
        std::string stage = stageName();
        std::replace(stage.begin(), stage.end(), ' ', '-');
        return fmt::format("{}-step{}", stage, sim->stepCount());
    }

    // ---- stepping ----

    /// Steps until the next thing the runner must look at.
    std::int64_t stepsToNextEvent() const {
        const std::int64_t now = sim->stepCount();
        if (phase == Phase::Shear) {
            return std::max<std::int64_t>(
                1, std::min({nextRecordStep, nextSnapshotStep, shearEndStep()}) - now);
        }
        const std::int64_t check = criterion().checkInterval;
        const std::int64_t nextCheck =
            stageStartStep + ((now - stageStartStep) / check + 1) * check;
        std::int64_t next = std::min(nextCheck, nextSnapshotStep);
        if (nextRecordStep > now) {
            next = std::min(next, nextRecordStep);
        }
        return std::max<std::int64_t>(1, next - now);
    }

    /// Looks at the state after a chunk of steps: records, checkpoints, stage transitions.
    void handleEvents() {
        const std::int64_t now = sim->stepCount();
        if (phase == Phase::Shear) {
            const bool end = now >= shearEndStep();
            if (now >= nextRecordStep || end) {
                recordNow();
                nextRecordStep = now + strideOf(config.record.strainInterval);
                trackPeak();
            }
            if (now >= nextSnapshotStep && !end) {
                checkpoint(checkpointLabel());
                nextSnapshotStep = now + strideOf(config.record.snapshotStrainInterval);
            }
            if (end) {
                finishShear();
            }
            return;
        }
        if (now >= nextRecordStep) {
            recordNow();
            nextRecordStep = now + config.record.stepInterval;
        }
        if (now >= nextSnapshotStep) {
            checkpoint(checkpointLabel());
            nextSnapshotStep = now + config.record.snapshotStepInterval;
        }
        const EquilibriumCriterion& c = criterion();
        if ((now - stageStartStep) % c.checkInterval == 0) {
            const EquilibriumCheck check = checkEquilibrium(*sim, pressure(), c);
            const double error = check.stressError, unbalanced = check.unbalancedForce;
            calm = calmChecksAfter(calm, check);
            if (calm >= c.calmChecks) {
                finishEquilibrium();
                return;
            }
            calmHistory.note(now - stageStartStep, c.maxSteps, unbalanced);
            if (now - stageStartStep >= c.maxSteps) {
                throw std::runtime_error(fmt::format(
                    "stage '{}' did not reach equilibrium within {} steps (stress error {:.3g} % "
                    "against the tolerance {:.3g} %, unbalanced-force index {:.3g} % against "
                    "{:.3g} %); {}",
                    stageName(), c.maxSteps, 100 * error, 100 * c.stressTolerance, unbalanced,
                    c.unbalancedForceMax, whyNotCalm(calmHistory, error, c, sim->stateRef())));
            }
        }
    }

    void finishEquilibrium() {
        recordNow();
        if (phase == Phase::Compaction) {
            sim->clearVelocities();
            SimulationState sample = sim->state();
            samples[pressure()] = sample;
            if (output) {
                output->sample(pressure(), sample);
            }
            const bool last = index + 1 == int(config.compaction.pressures.size()) &&
                              config.shear.pressures.empty();
            stageEndCheckpoint(last);
        } else {
            startShear();
            recordNow(); // eps1 = 0: N_vi
            nextRecordStep = stageStartStep + strideOf(config.record.strainInterval);
            trackPeak();
            checkpoint(checkpointLabel());
        }
    }

    void finishShear() {
        peakCheckpoint();
        peak = RunningPeak{};
        stageEndCheckpoint(index + 1 == int(config.shear.pressures.size()));
    }

    /// The checkpoint at the end of a compaction stage or a shear test, then the next stage.
    /// The checkpoint says that its stage is done (stage_done), so that a run resumed from it
    /// goes on with the next stage (continueAfterStage) instead of running the finished one
    /// again; after the last stage it holds the finished run (phase Done).
    void stageEndCheckpoint(bool last) {
        const std::string label = checkpointLabel();
        const StageIdentity id = identity();
        if (last) {
            phase = Phase::Done;
        }
        stageDone = true;
        checkpoint(label, id);
        continueAfterStage();
    }

    void continueAfterStage() {
        stageDone = false;
        if (phase == Phase::Compaction) {
            if (index + 1 < int(config.compaction.pressures.size())) {
                startCompaction(index + 1);
            } else {
                startEquilibration(0);
                checkpoint(checkpointLabel());
            }
        } else if (phase == Phase::Shear) {
            startEquilibration(index + 1);
            checkpoint(checkpointLabel());
        }
    }

    double fraction() const {
        // Of the experiment's expected steps. A function of the stage and the steps taken in it
        // only (no history), so it never decreases while the run goes on, and a resumed run
        // reports what the uninterrupted one did at the same step. Each stage weighs its
        // expected steps: a shear exactly its stride to the target strain (and moves linearly);
        // an equilibration two calm windows; a compaction stage a settling time (the first,
        // from the loose grid, 0.1 s of simulated time, each further one 0.01 s: the quick
        // run's stages take 0.12 s, then 0.018, 0.006, 0.007 s), approached as 1 - exp(-s / C)
        // so that a longer stage creeps on rather than stalls, and completed when it ends.
        const double dt = config.parameters.timeStep;
        // Whole numbers of steps: the sums of the weights are exact, so the stage boundaries
        // cannot round backwards.
        const auto capped = [](double expected, std::int64_t maxSteps) {
            return std::round(std::clamp(expected, 1.0, std::max(1.0, double(maxSteps))));
        };
        const EquilibriumCriterion& compactionCriterion = config.compaction.criterion;
        const auto compactionWeight = [&](int k) {
            return capped((k == 0 ? 0.1 : 0.01) / dt, compactionCriterion.maxSteps);
        };
        const EquilibriumCriterion& eq = config.shear.equilibration;
        const double equilibrationWeight =
            capped(2.0 * double(eq.calmChecks) * double(eq.checkInterval), eq.maxSteps);
        const double shearWeight = double(strideOf(config.shear.targetAxialStrain));
        const int nc = int(config.compaction.pressures.size());
        const int ns = int(config.shear.pressures.size());
        double compactionTotal = 0;
        for (int k = 0; k < nc; ++k) {
            compactionTotal += compactionWeight(k);
        }
        const double testWeight = equilibrationWeight + shearWeight;
        const double total = compactionTotal + ns * testWeight;
        const double inStage = std::max(0.0, double(sim->stepCount() - stageStartStep));
        const auto settling = [](double steps, double weight) {
            return weight * -std::expm1(-steps / weight); // < weight for every finite step count
        };
        double done = 0;
        switch (phase) {
        case Phase::Compaction:
            for (int k = 0; k < index; ++k) {
                done += compactionWeight(k);
            }
            done += settling(inStage, compactionWeight(index));
            break;
        case Phase::Equilibration:
            done = compactionTotal + index * testWeight + settling(inStage, equilibrationWeight);
            break;
        case Phase::Shear:
            done = compactionTotal + index * testWeight + equilibrationWeight +
                   std::min(inStage, shearWeight);
            break;
        case Phase::Done:
            done = total;
            break;
        }
        return total > 0 ? std::clamp(done / total, 0.0, 1.0) : 1.0;
    }
};

ExperimentRunner::ExperimentRunner(ExperimentConfig config, RunOutput* output)
    : impl_(std::make_unique<Impl>()) {
    impl_->config = std::move(config);
    impl_->output = output;
    const ExperimentConfig& c = impl_->config;
    if (c.compaction.pressures.empty()) {
        throw std::invalid_argument("experiment: compaction.pressures is empty");
    }
    SimulationParameters p = c.parameters;
    p.friction = c.compaction.friction;
    p.servo.maxStrainRate = c.compaction.maxStrainRate;
    p.threads = threadsFor(c);
    impl_->sim = std::make_unique<Simulation>(generateGridAssembly(c.assembly, p));
    impl_->thetaAtRunStart = impl_->sim->stateRef().grains.theta;
    impl_->startCompaction(0);
    if (const std::string text = checkTimeStep(impl_->sim->stateRef().shapes, p); !text.empty()) {
        impl_->warn("time_step", text);
    }
    // A checkpoint of the generated assembly: a run killed before its first periodic
    // checkpoint can still be resumed.
    impl_->checkpoint(impl_->checkpointLabel());
}

ExperimentRunner::ExperimentRunner(ExperimentConfig config, ResumePoint resume, RunOutput* output)
    : impl_(std::make_unique<Impl>()) {
    impl_->config = std::move(config);
    impl_->output = output;
    impl_->samples = std::move(resume.samples);
    const auto rows = seriesRowsAtCheckpoint(resume.runnerState);
    for (SeriesTable& t : resume.series) {
        const auto it = rows.find(t.test);
        const std::size_t keep = it == rows.end() ? 0 : it->second;
        t.rows.resize(std::min(keep, t.rows.size()));
        t.stages.resize(std::min(keep, t.stages.size()));
        t.stageKinds.resize(std::min(keep, t.stageKinds.size()));
        t.stagePressures.resize(std::min(keep, t.stagePressures.size()));
        impl_->series.push_back(std::move(t));
    }
    resume.state.parameters.threads = threadsFor(impl_->config);
    impl_->restorePeak(resume.runnerState, resume.state, std::move(resume.runningPeak));
    impl_->sim = std::make_unique<Simulation>(std::move(resume.state));
    impl_->restore(resume.runnerState);
    if (output) {
        output->warnings(impl_->warnings); // the file holds what its checkpoint held
    }
}

ExperimentRunner::~ExperimentRunner() = default;

bool ExperimentRunner::advance(std::int64_t maxSteps) {
    Impl& m = *impl_;
    if (m.stageDone) {
        m.continueAfterStage(); // resumed from a stage-end checkpoint
    }
    std::int64_t done = 0;
    while (done < maxSteps && m.phase != Phase::Done) {
        const std::int64_t chunk = std::min(m.stepsToNextEvent(), maxSteps - done);
        m.sim->advance(chunk);
        done += chunk;
        m.stepsTaken += chunk;
        m.handleEvents();
    }
    return m.phase != Phase::Done;
}

std::int64_t ExperimentRunner::stepsTaken() const {
    return impl_->stepsTaken;
}

bool ExperimentRunner::finished() const {
    return impl_->phase == Phase::Done;
}

RunProgress ExperimentRunner::progress() const {
    const Impl& m = *impl_;
    RunProgress p;
    p.stage = m.stageName();
    p.test = m.currentSeries >= 0 ? m.series[m.currentSeries].test : "";
    // eps1 of the current test: during its shear, and its final value once the run is done.
    p.axialStrain =
        (m.phase == Phase::Shear || m.phase == Phase::Done) && !m.config.shear.pressures.empty()
            ? m.eps1()
            : 0.0;
    p.fraction = m.fraction();
    p.step = m.sim->stepCount();
    p.finished = m.phase == Phase::Done;
    return p;
}

const ExperimentConfig& ExperimentRunner::config() const {
    return impl_->config;
}
const Simulation& ExperimentRunner::simulation() const {
    return *impl_->sim;
}
const std::vector<SeriesTable>& ExperimentRunner::series() const {
    return impl_->series;
}
const std::vector<RunWarning>& ExperimentRunner::warnings() const {
    return impl_->warnings;
}

void ExperimentRunner::checkpointNow(const std::string& name) {
    impl_->checkpoint(name);
}

bool ExperimentRunner::finishedAt(const std::string& runnerState) {
    return nlohmann::json::parse(runnerState).at("phase").get<int>() == int(Phase::Done);
}

std::string ExperimentRunner::runningPeakCheckpoint(const std::string& runnerState) {
    const nlohmann::json j = nlohmann::json::parse(runnerState);
    return j.contains("peak") ? j.at("peak").at("kept_in").get<std::string>() : std::string();
}

std::map<std::string, std::size_t>
ExperimentRunner::seriesRowsAtCheckpoint(const std::string& runnerState) {
    std::map<std::string, std::size_t> out;
    const nlohmann::json j = nlohmann::json::parse(runnerState);
    for (const auto& [name, count] : j.at("series_rows").items()) {
        out[name] = count.get<std::size_t>();
    }
    return out;
}

std::shared_ptr<Snapshot> ExperimentRunner::snapshot(SnapshotMeasures measures) const {
    const Impl& m = *impl_;
    const Simulation& sim = *m.sim;
    auto snap = std::make_shared<Snapshot>();
    const RunProgress p = progress();
    snap->stage = p.stage;
    snap->test = p.test;
    snap->axialStrain = p.axialStrain;
    snap->progress = p.fraction;
    fillSnapshotScene(*snap, sim, m.thetaAtTestStart, measures);
    snap->series = m.series;
    snap->warnings = m.warnings;
    return snap;
}

int engineThreads(const ExperimentConfig& config) {
    return threadsFor(config);
}

} // namespace grainlab
