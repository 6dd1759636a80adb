// See gui_run.h: the ExperimentRunner adapter.
#include "gui_run.h"

namespace grainlab::ui {
namespace {

class ExperimentRun final : public SteppedRun {
public:
    explicit ExperimentRun(const ExperimentConfig& config) : runner_(config) {}
    bool advance(std::int64_t maxSteps) override { return runner_.advance(maxSteps); }
    SnapshotPtr snapshot() const override { return runner_.snapshot(); }
    RunProgress progress() const override { return runner_.progress(); }

private:
    ExperimentRunner runner_;
};

} // namespace

std::unique_ptr<SteppedRun> makeExperimentRun(const ExperimentConfig& config) {
    return std::make_unique<ExperimentRun>(config);
}

} // namespace grainlab::ui
