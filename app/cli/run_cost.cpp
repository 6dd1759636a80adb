#include "cli/run_cost.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/atomic_file.h"

namespace grainlab {

std::string runCostPath(const std::string& runFolder) {
    return (std::filesystem::path(runFolder) / "cost.json").string();
}

RunCostRecord readRunCost(const std::string& runFolder) {
    const std::string path = runCostPath(runFolder);
    RunCostRecord c;
    std::ifstream in(path);
    if (!in) {
        return c;
    }
    std::ostringstream text;
    text << in.rdbuf();
    try {
        const auto j = nlohmann::json::parse(text.str());
        c.finished = j.at("finished").get<bool>();
        c.wallSeconds = j.at("wall_seconds").get<double>();
        c.cpuSeconds = j.at("cpu_seconds").get<double>();
        c.steps = j.at("steps").get<std::int64_t>();
        c.grainSteps = j.at("grain_steps").get<std::int64_t>();
        c.threads = j.at("threads").get<int>();
        c.processes = j.at("processes").get<int>();
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error(fmt::format("{}: not a cost record: {}", path, e.what()));
    }
    return c;
}

void writeRunCost(const std::string& runFolder, const RunCostRecord& c) {
    nlohmann::ordered_json j;
    j["finished"] = c.finished;
    j["wall_seconds"] = c.wallSeconds;
    j["cpu_seconds"] = c.cpuSeconds;
    j["steps"] = c.steps;
    j["grain_steps"] = c.grainSteps;
    j["threads"] = c.threads;
    j["processes"] = c.processes;
    writeFileAtomically(runCostPath(runFolder), j.dump(2) + "\n");
}

} // namespace grainlab
