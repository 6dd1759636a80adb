#include "common/run_cost.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <sys/resource.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "common/atomic_file.h"

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
        if (j.contains("seconds")) {
            const auto& t = j.at("seconds");
            c.times = {t.at("stepping").get<double>(), t.at("records").get<double>(),
                       t.at("checkpoints").get<double>(), t.at("events").get<double>()};
        }
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
    nlohmann::ordered_json t;
    t["stepping"] = c.times.stepping;
    t["records"] = c.times.records;
    t["checkpoints"] = c.times.checkpoints;
    t["events"] = c.times.events;
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
    c.times.stepping += work.times.stepping;
    c.times.records += work.times.records;
    c.times.checkpoints += work.times.checkpoints;
    c.times.events += work.times.events;
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
