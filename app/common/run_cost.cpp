#include "common/run_cost.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <type_traits>

#include <sys/resource.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "common/atomic_file.h"

namespace grainlab {

namespace {

/// Calls `field(name, member)` for each top-level value of cost.json, in the file's order
/// ("seconds", the RunnerTimes parts, follows them).
template <typename Record, typename Field>
void forEachCostField(Record& c, Field&& field) {
    field("finished", c.finished);
    field("wall_seconds", c.wallSeconds);
    field("cpu_seconds", c.cpuSeconds);
    field("steps", c.steps);
    field("grain_steps", c.grainSteps);
    field("threads", c.threads);
    field("processes", c.processes);
}

} // namespace

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
        forEachCostField(c, [&](const char* name, auto& value) {
            value = j.at(name).template get<std::decay_t<decltype(value)>>();
        });
        if (j.contains("seconds")) {
            const auto& t = j.at("seconds");
            for (const RunnerTimesPart& part : kRunnerTimesParts) {
                c.times.*part.seconds = t.at(part.name).get<double>();
            }
        }
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error(fmt::format("{}: not a cost record: {}", path, e.what()));
    }
    return c;
}

void writeRunCost(const std::string& runFolder, const RunCostRecord& c) {
    nlohmann::ordered_json j;
    forEachCostField(c, [&](const char* name, const auto& value) { j[name] = value; });
    nlohmann::ordered_json t;
    for (const RunnerTimesPart& part : kRunnerTimesParts) {
        t[part.name] = c.times.*part.seconds;
    }
    j["seconds"] = t;
    writeFileAtomically(runCostPath(runFolder), j.dump(2) + "\n");
}

RunCostMeter::RunCostMeter(std::string runFolder, bool continuing)
    : folder_(std::move(runFolder)), start_(std::chrono::steady_clock::now()), lastSave_(start_) {
    if (continuing) {
        before_ = readRunCost(folder_);
    }
}

namespace {

double processorSeconds() {
    rusage usage{};
    ::getrusage(RUSAGE_SELF, &usage);
    const auto seconds = [](const timeval& t) {
        return double(t.tv_sec) + 1e-6 * double(t.tv_usec);
    };
    return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

} // namespace

void RunCostMeter::save(const Work& work, bool finished) {
    const auto now = std::chrono::steady_clock::now();
    RunCostRecord c = before_;
    c.finished = finished;
    c.wallSeconds += std::chrono::duration<double>(now - start_).count();
    c.cpuSeconds += processorSeconds();
    c.steps += work.steps;
    c.grainSteps += work.steps * work.grains;
    c.threads = work.threads;
    c.processes += 1;
    c.times += work.times;
    writeRunCost(folder_, c);
    lastSave_ = now;
}

void RunCostMeter::saveEvery(double interval, const Work& work) {
    const auto now = std::chrono::steady_clock::now();
    if (std::chrono::duration<double>(now - lastSave_).count() >= interval) {
        save(work, false);
    }
}

} // namespace grainlab
