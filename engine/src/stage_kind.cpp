#include "grainlab/stage_kind.h"

#include <array>
#include <utility>

#include <fmt/format.h>

namespace grainlab {
namespace {

constexpr std::array<std::pair<StageKind, const char*>, 9> kNames{{
    {StageKind::Compaction, "compaction"},
    {StageKind::Equilibration, "equilibration"},
    {StageKind::Shear, "shear"},
    {StageKind::Done, "done"},
    {StageKind::ConstantVolume, "constant_volume"},
    {StageKind::ConstantP, "constant_p"},
    {StageKind::StressPath, "stress_path"},
    {StageKind::Cyclic, "cyclic"},
    {StageKind::Probes, "probes"},
}};

} // namespace

bool isTestStage(StageKind kind) {
    return kind == StageKind::Shear || kind == StageKind::ConstantVolume ||
           kind == StageKind::ConstantP || kind == StageKind::StressPath ||
           kind == StageKind::Cyclic || kind == StageKind::Probes;
}

std::string stageKindName(StageKind kind) {
    for (const auto& [k, name] : kNames) {
        if (k == kind) {
            return name;
        }
    }
    return "done";
}

std::optional<StageKind> stageKindFromName(const std::string& name) {
    for (const auto& [k, text] : kNames) {
        if (name == text) {
            return k;
        }
    }
    return std::nullopt;
}

std::string stageTitle(const std::string& kindName, double pressure) {
    return fmt::format("{} {:g} kPa", kindName, pressure / 1000.0);
}

} // namespace grainlab
