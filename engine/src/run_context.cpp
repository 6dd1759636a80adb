#include "run_context.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "grainlab/contact_network.h"
#include "grainlab/void_cells.h"
#include "stage.h"

namespace grainlab {
namespace {

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

} // namespace

/// Small assemblies run on one thread, where the per-step cost of waking a second thread
/// exceeds the work it takes over (and, on a loaded machine, a waiting OpenMP thread can cost a
/// whole time slice per step). Results are the same bits either way.
int threadsFor(const ExperimentConfig& config) {
    constexpr int kGrainsPerThread = 2000;
    return std::clamp(config.assembly.grainCount / kGrainsPerThread, 1,
                      std::max(1, config.parameters.threads));
}

std::string RunContext::currentTest() const {
    return currentSeries >= 0 ? series[currentSeries].test : kCompactionSeries;
}

void RunContext::warn(const std::string& kind, const std::string& text) {
    warnings.push_back({kind, currentTest(), sim->stepCount(), eps1(), text});
    if (output) {
        output->warnings(warnings);
    }
}

int RunContext::seriesIndex(const std::string& name) {
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

void RunContext::setStrainReference() {
    length1At0 = sim->cell()[0];
    length2At0 = sim->cell()[3];
    areaAt0 = sim->cellArea();
    haveLast = false;
    lastRecordStep = -1;
}

std::int64_t strideOf(const ExperimentConfig& config, double strain) {
    return std::max<std::int64_t>(1, std::llround(strain / config.shear.axialStrainPerStep));
}

RecordInputs RunContext::recordInputs(const MeasureSet& measures, bool asLastRecord) const {
    RecordInputs in;
    in.step = sim->stepCount();
    in.time = sim->time();
    in.eps1 = eps1();
    in.eps2 = eps2();
    in.epsv = epsv();
    const bool before = asLastRecord && lastRecordStep == in.step;
    const bool have = before ? haveBeforeLast : haveLast;
    const double e1 = before ? beforeLastEps1 : lastEps1;
    const double ev = before ? beforeLastEpsv : lastEpsv;
    in.dilatancyIndex = have && in.eps1 != e1 ? -(in.epsv - ev) / (in.eps1 - e1) : 0.0;
    in.stress = sim->stress();
    in.initialVoidCount = stage->initialVoidCount(measures);
    const auto& L = sim->stateRef().velocityGradient;
    in.strainRate1 = -L[0];
    in.strainRate2 = -L[3];
    in.density = config.parameters.density;
    in.energies = sim->energies();
    return in;
}

void RunContext::recordNow() {
    const AddWallTime timed(times.records);
    const ContactNetwork network = sim->contactNetwork();
    // A record keeps the void cells' count and valence, not their polygons.
    MeasureOptions options;
    options.voidCellShapes = false;
    const MeasureSet measures = computeMeasures(network, options);
    stage->noteRecord(measures);
    const RecordInputs in = recordInputs(measures);
    SeriesTable& t = series[currentSeries];
    t.rows.push_back(seriesRow(measures, in));
    t.stages.push_back(stageName());
    t.stageKinds.push_back(stageKindName(stage->kind()));
    t.stagePressures.push_back(stage->pressure());
    haveBeforeLast = haveLast;
    beforeLastEps1 = lastEps1;
    beforeLastEpsv = lastEpsv;
    lastRecordStep = in.step;
    lastEps1 = in.eps1;
    lastEpsv = in.epsv;
    haveLast = true;
    if (output) {
        output->record(t);
    }
}

std::string RunContext::stageName() const {
    return done ? std::string("done") : stageTitle(stageKindName(stage->kind()), stage->pressure());
}

StageIdentity RunContext::identity() const {
    StageIdentity id;
    id.kind = stageKindName(done ? StageKind::Done : stage->kind());
    id.test = currentTest();
    id.pressure = stage->pressure();
    id.step = sim->stepCount();
    id.axialStrain = eps1();
    id.thetaAtTestStart =
        !done && stage->kind() == StageKind::Compaction ? *thetaAtRunStart : *thetaAtTestStart;
    return id;
}

std::string RunContext::checkpointLabel() const {
    std::string name = stageName();
    std::replace(name.begin(), name.end(), ' ', '-');
    return fmt::format("{}-step{}", name, sim->stepCount());
}

std::string RunContext::nextCheckpointName(const std::string& label) {
    ++checkpointCounter;
    return fmt::format("{:06d}-{}", checkpointCounter, label);
}

void RunContext::checkpoint(const std::string& label) {
    checkpoint(label, identity());
}

void RunContext::checkpoint(const std::string& label, const StageIdentity& id) {
    if (!output) {
        return;
    }
    const AddWallTime timed(times.checkpoints);
    const std::string name = nextCheckpointName(label);
    const SimulationState state = sim->state();
    const ContactNetwork network = sim->contactNetwork();
    const VoidCellSet cells = computeVoidCells(network);
    CheckpointData data;
    data.name = name;
    data.state = &state;
    data.identity = id;
    data.network = &network;
    data.voidCells = &cells;
    stage->addToCheckpoint(data); // before the runner state, which may name this checkpoint
    if (probeStart && probeStartKeptIn.empty()) {
        data.probeStart = &*probeStart;
        probeStartKeptIn = name;
    }
    data.runnerState = runnerStateText(runnerState());
    output->checkpoint(data);
}

RunnerState RunContext::runnerState() const {
    RunnerState s = carried;
    s.phase = static_cast<int>(done ? StageKind::Done : stage->kind());
    s.index = stage->index();
    s.stageDone = stageDone;
    s.stageStartStep = stageStartStep;
    s.length1At0 = length1At0;
    s.length2At0 = length2At0;
    s.areaAt0 = areaAt0;
    s.haveLast = haveLast;
    s.lastEps1 = lastEps1;
    s.lastEpsv = lastEpsv;
    s.nextRecordStep = nextRecordStep;
    s.nextSnapshotStep = nextSnapshotStep;
    s.checkpointCounter = checkpointCounter;
    s.thetaAtTestStart = *thetaAtTestStart;
    s.thetaAtRunStart =
        !done && stage->kind() == StageKind::Compaction ? *thetaAtRunStart : std::vector<double>{};
    s.currentSeries = currentSeries >= 0 ? series[currentSeries].test : "";
    s.seriesRows.clear();
    for (const auto& t : series) {
        s.seriesRows[t.test] = t.rows.size();
    }
    s.warnings = warnings;
    s.probeStartState.reset();
    if (probeStart) {
        s.probeStartState = ProbeStartRecord{probeStart->step, probeStartKeptIn};
    }
    stage->save(s, *this);
    return s;
}

void RunContext::restore(const RunnerState& s) {
    carried = s;
    stageDone = s.stageDone;
    stageStartStep = s.stageStartStep;
    length1At0 = s.length1At0;
    length2At0 = s.length2At0;
    areaAt0 = s.areaAt0;
    haveLast = s.haveLast;
    lastEps1 = s.lastEps1;
    lastEpsv = s.lastEpsv;
    nextRecordStep = s.nextRecordStep;
    nextSnapshotStep = s.nextSnapshotStep;
    checkpointCounter = s.checkpointCounter;
    thetaAtTestStart = std::make_shared<const std::vector<double>>(s.thetaAtTestStart);
    thetaAtRunStart = std::make_shared<const std::vector<double>>(s.thetaAtRunStart);
    currentSeries = s.currentSeries.empty() ? -1 : seriesIndex(s.currentSeries);
    warnings = s.warnings;
    probeStartKeptIn = s.probeStartState ? s.probeStartState->keptIn : std::string();
}

} // namespace grainlab
