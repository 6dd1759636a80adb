// See stability_scan.h.
#include "gui/stability_scan.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

namespace grainlab::ui {
namespace {

namespace fs = std::filesystem;

std::string fileText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw std::runtime_error(fmt::format("{}: cannot be read", path.string()));
    }
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

/// `next` unless it says the same as `previous` (a folder that is not a map).
std::shared_ptr<const StabilityFolder>
sameOr(std::shared_ptr<StabilityFolder> next,
       const std::shared_ptr<const StabilityFolder>& previous) {
    if (previous && previous->kind == next->kind && previous->reason == next->reason) {
        return previous;
    }
    return next;
}

std::shared_ptr<StabilityFolder> refused(std::string reason) {
    auto out = std::make_shared<StabilityFolder>();
    out->kind = StabilityFolder::Kind::Refused;
    out->reason = std::move(reason);
    return out;
}

} // namespace

std::shared_ptr<const StabilityFolder>
scanStabilityFolder(const std::string& folder,
                    const std::shared_ptr<const StabilityFolder>& previous) {
    const fs::path dir(folder);
    std::error_code ec;
    if (!fs::exists(dir, ec)) {
        return sameOr(std::make_shared<StabilityFolder>(), previous);
    }
    if (!fs::is_directory(dir, ec)) {
        return sameOr(refused(fmt::format("{} is not a folder", folder)), previous);
    }
    const fs::path presetPath = dir / "stability.json";
    if (!fs::exists(presetPath, ec)) {
        if (fs::is_empty(dir, ec)) {
            return sameOr(std::make_shared<StabilityFolder>(), previous);
        }
        // The reasons `grainlab stability --out` would refuse it for, and what it holds instead.
        std::string reason = fmt::format(
            "{} is not a stability map folder: it holds no stability.json (the preset that "
            "`grainlab stability --out` copies into its map folder), and it is not empty",
            folder);
        if (fs::exists(dir / "study.json", ec)) {
            reason += "; it holds a study (study.json): open it on the Study tab";
        } else if (fs::exists(dir / "run.h5", ec)) {
            reason += "; it is a run folder (run.h5): open it in the main window";
        }
        return sameOr(refused(std::move(reason)), previous);
    }

    auto next = std::make_shared<StabilityFolder>();
    next->kind = StabilityFolder::Kind::Map;
    next->presetText = fileText(presetPath);
    const bool samePreset = previous && previous->kind == StabilityFolder::Kind::Map &&
                            previous->presetText == next->presetText;
    if (samePreset) {
        next->spec = previous->spec;
        next->cells = previous->cells;
    } else {
        try {
            next->spec = parseStabilityPreset(next->presetText, presetPath.string());
            next->spec.sourcePath = presetPath.string();
            next->cells = stabilityCells(next->spec);
        } catch (const std::exception& e) {
            return sameOr(
                refused(fmt::format("{} is not a stability map folder: {}", folder, e.what())),
                previous);
        }
    }
    next->resultOf.assign(next->cells.size(), -1);
    bool changed = !samePreset;
    for (std::size_t i = 0; i < next->cells.size(); ++i) {
        if (samePreset && previous->resultOf[i] >= 0) {
            next->resultOf[i] = int(next->results.size());
            next->results.push_back(previous->results[std::size_t(previous->resultOf[i])]);
            continue;
        }
        // A cell writes its file in one step (renamed into place): it exists whole or not at all.
        const fs::path file = dir / "cells" / (next->cells[i].id + ".json");
        if (!fs::exists(file, ec)) {
            continue;
        }
        try {
            StabilityCellResult r = parseCellResult(fileText(file), file.string());
            next->resultOf[i] = int(next->results.size());
            next->results.push_back(std::move(r));
            changed = true;
        } catch (const std::exception& e) {
            next->errors.emplace_back(e.what());
        }
    }
    if (!changed && next->errors == previous->errors) {
        return previous;
    }
    return next;
}

} // namespace grainlab::ui
