// experiment_fuzz: mutates the checked-in experiment files and feeds each mutant to the reader
// and, when it is accepted, to the runner for a few steps, each case in a forked child with a
// time limit and a memory limit. Counts crashes (the child died of a signal), hangs (the time
// limit), memory exhaustion, and the cases refused by the reader, refused by the engine at run
// time, and run. Exits non-zero on any crash, hang or memory exhaustion, listing the case, its
// mutation and the file that reproduces it. A refusal must also say what is wrong in words (no
// empty key name in its message), and some mutations state what the reader must do with them:
// bytes after a NUL are refused naming the NUL; a key "" or a top level that is not an object
// is refused in words; a density too small for a finite mass is blamed on material.density,
// never on a width; a lateral rate cap of exactly twice the axial strain rate (a round number
// such as 1000 /s) is not refused as below that bound. A case that breaks one is a failure.
//
// Usage:
//   build/tests/fuzz/experiment_fuzz --cases 2000 --seed 1
//   options: --cases N (200), --seed S (1), --steps K (100 steps per accepted case),
//            --timeout T (20 s per case), --presets DIR (resources/experiments),
//            --keep DIR (write every failing mutant there), --verbose
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <new>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "grainlab/experiment_file.h"
#include "grainlab/experiment_runner.h"

namespace {

using Json = nlohmann::json;
using grainlab::ExperimentConfig;

/// Exit codes of a child.
enum Outcome : int {
    kRefused = 10,
    kRan = 11,
    kRunError = 12,
    kOutOfMemory = 13,
    kBadRefusal = 14 ///< refused (or accepted) against what the mutation requires
};

/// What the reader must do with a mutant beyond not crashing.
struct Expectation {
    bool mustRefuse = false;
    std::string mention;                 ///< a refusal's message must hold this
    std::vector<std::string> blameOneOf; ///< a refusal must blame one of these keys
    std::string neverBlamed;             ///< a refusal must not blame this key
};

struct Mutant {
    std::string text;
    std::string what; ///< the mutation, for the report
    Expectation expect;
};

/// Accepted files with more grains than this run with grains.count set to kRunGrains instead, so
/// that every case stays small (the rest of the mutation is still exercised).
constexpr std::int64_t kMaxRunGrains = 2000;
constexpr int kRunGrains = 300;
constexpr rlim_t kMemoryLimit = rlim_t(3) << 30; // [B]

struct Options {
    int cases = 200;
    std::uint64_t seed = 1;
    std::int64_t steps = 100;
    int timeout = 20;
    std::string presets = std::string(GRAINLAB_SOURCE_DIR) + "/resources/experiments";
    std::string keep;
    bool verbose = false;
};

class Mutator {
public:
    explicit Mutator(std::uint64_t seed) : random_(seed) {}

    std::size_t below(std::size_t n) {
        return std::uniform_int_distribution<std::size_t>(0, n - 1)(random_);
    }

    /// A mutant of `text`, a description of the mutation and what the reader must do with it.
    Mutant mutate(const std::string& text) {
        const std::size_t kind = below(14);
        if (kind >= 10) {
            return special(kind, text);
        }
        const auto [out, what] = mutateAny(text);
        return {out, what, {}};
    }

private:
    /// Mutations with a required outcome (issue 24, items 6 to 8).
    Mutant special(std::size_t kind, const std::string& text) {
        Json root = Json::parse(text);
        if (kind == 10) { // bytes after a NUL: the parser must not stop at it and accept
            std::string out = root.dump(1);
            const std::size_t at = below(2) == 0 ? out.size() : out.rfind('}');
            out.insert(at, std::string(1, '\0') + "garbage}{");
            Expectation e;
            e.mustRefuse = true;
            e.mention = "NUL";
            return {out, fmt::format("NUL and garbage at byte {}", at), e};
        }
        if (kind == 11) { // a key "" somewhere, or a top level that is not an object
            std::vector<Json::json_pointer> leaves, objects;
            collect(root, Json::json_pointer(), leaves, objects);
            const std::size_t pick = below(objects.size() + 1);
            Expectation e;
            e.mustRefuse = true;
            if (pick == objects.size()) {
                const Json tops[] = {Json::array({1, 2}), Json(3), Json("text"), Json(nullptr)};
                const Json top = tops[below(std::size(tops))];
                e.mention = "top level";
                return {top.dump(), fmt::format("the whole file = {}", top.dump()), e};
            }
            root[objects[pick]][""] = 1;
            e.mention = "empty key name";
            return {root.dump(1), fmt::format("key \"\" added to {}", objects[pick].to_string()),
                    e};
        }
        if (kind == 12) { // a density too small for a finite mass: never a width's fault
            static const double kDensities[] = {5e-324, 1e-320, 1e-310, 1e-300, 1e-200};
            const double d = kDensities[below(std::size(kDensities))];
            root["material"]["density"] = d;
            Expectation e;
            e.blameOneOf = {"material.density", "time_step"};
            return {root.dump(1), fmt::format("/material/density = {}", d), e};
        }
        // kind 13: the lateral rate cap at exactly twice the axial strain rate, written as the
        // round number a user would write: never refused as below that bound.
        static const double kPerStep[] = {5e-4, 2.5e-4, 1e-4, 3e-5, 7e-6, 1.1e-6, 3e-7};
        const double perStep = kPerStep[below(std::size(kPerStep))];
        const double dt = root["time_step"].get<double>();
        const double bound = std::stod(fmt::format("{:.12g}", 2.0 * perStep / dt));
        root["shear"]["axial_strain_per_step"] = perStep;
        root["shear"]["max_strain_rate"] = bound;
        Expectation e;
        e.neverBlamed = "shear.max_strain_rate";
        return {root.dump(1),
                fmt::format("/shear/axial_strain_per_step = {}, /shear/max_strain_rate = {}",
                            perStep, bound),
                e};
    }

    std::pair<std::string, std::string> mutateAny(const std::string& text) {
        const std::size_t kind = below(10);
        if (kind == 0) { // truncation
            const std::size_t at = below(text.size());
            return {text.substr(0, at), fmt::format("truncated at byte {}", at)};
        }
        if (kind == 1) { // random bytes
            std::string out = text;
            const std::size_t n = 1 + below(8);
            for (std::size_t k = 0; k < n; ++k) {
                out[below(out.size())] = static_cast<char>(below(256));
            }
            return {out, fmt::format("{} random bytes", n)};
        }
        Json root = Json::parse(text);
        std::vector<Json::json_pointer> leaves, objects;
        collect(root, Json::json_pointer(), leaves, objects);
        const Json::json_pointer leaf = leaves[below(leaves.size())];
        if (kind == 2) { // deep nesting in place of a value
            const std::size_t depth = 1 + below(200000);
            std::string mark = "\"__deep__\"";
            root[leaf] = "__deep__";
            std::string out = root.dump(1);
            out.replace(out.find(mark), mark.size(),
                        std::string(depth, '[') + std::string(depth, ']'));
            return {out, fmt::format("{} nested to depth {}", leaf.to_string(), depth)};
        }
        if (kind == 3) { // delete a key
            Json& parent = root[leaf.parent_pointer()];
            if (parent.is_array()) {
                parent.erase(std::stoul(leaf.back()));
            } else {
                parent.erase(leaf.back());
            }
            return {root.dump(1), fmt::format("{} deleted", leaf.to_string())};
        }
        if (kind == 4) { // duplicate a key (text level: nlohmann cannot hold one)
            const Json::json_pointer object = objects[below(objects.size())];
            const Json& o = root[object];
            if (!o.is_object() || o.empty()) {
                return {root.dump(1), "unchanged"};
            }
            auto it = o.begin();
            std::advance(it, below(o.size()));
            std::string out = root.dump(1);
            const std::string key = "\"" + it.key() + "\":";
            const std::size_t at = out.find(key);
            out.insert(at, key + it.value().dump() + ",");
            return {out, fmt::format("key {} duplicated", it.key())};
        }
        if (kind == 5) { // a literal no JSON double holds, written as text
            static const char* kLiterals[] = {"NaN",   "nan",    "Infinity", "-Infinity",
                                              "1e309", "-1e309", "1e-400",   "0x10",
                                              "1.",    ".5",     "+1"};
            const char* literal = kLiterals[below(std::size(kLiterals))];
            root[leaf] = "__literal__";
            std::string out = root.dump(1);
            const std::string mark = "\"__literal__\"";
            out.replace(out.find(mark), mark.size(), literal);
            return {out, fmt::format("{} = {}", leaf.to_string(), literal)};
        }
        if (kind == 6) { // a wrong type
            static const Json kTypes[] = {Json("text"),  Json::array({1, 2}), Json::object(),
                                          Json(nullptr), Json(true),          Json::array()};
            root[leaf] = kTypes[below(std::size(kTypes))];
            return {root.dump(1), fmt::format("{} = {}", leaf.to_string(), root[leaf].dump())};
        }
        // kind 7..9: a number: huge, tiny, negative, zero, integral extremes, scaled
        static const double kValues[] = {1e308,  1e300, 1e100, 1e30,   1e9,          1e8,   1e6,
                                         1e4,    1e-4,  1e-12, 1e-300, 4.9e-324,     0.0,   -1.0,
                                         -1e308, 2.5,   0.5,   1.0,    2147483648.0, 9.3e18};
        double v = kValues[below(std::size(kValues))];
        if (root[leaf].is_number() && below(2) == 0) {
            const double scale[] = {-1.0, 10.0, 0.1, 1e3, 1e-3, 0.0, 2.0};
            v = root[leaf].get<double>() * scale[below(std::size(scale))];
        }
        root[leaf] = v;
        return {root.dump(1), fmt::format("{} = {}", leaf.to_string(), v)};
    }

    static void collect(const Json& j, const Json::json_pointer& at,
                        std::vector<Json::json_pointer>& leaves,
                        std::vector<Json::json_pointer>& objects) {
        if (j.is_object()) {
            objects.push_back(at);
            for (const auto& item : j.items()) {
                collect(item.value(), at / item.key(), leaves, objects);
            }
        } else if (j.is_array() && !j.empty()) {
            for (std::size_t i = 0; i < j.size(); ++i) {
                collect(j[i], at / i, leaves, objects);
            }
        } else if (!at.empty()) {
            leaves.push_back(at);
        }
    }

    std::mt19937_64 random_;
};

/// Why a refusal breaks the expectation or does not say in words what is wrong ("" if fine).
std::string badRefusal(const grainlab::ExperimentFileError& e, const Expectation& expect) {
    const std::string what = e.what();
    // An empty key path printed as if it were a name: "FILE:  = ...", "unknown key ;".
    for (const char* empty : {":  =", "key ;", "key  ", "key (did"}) {
        if (what.find(empty) != std::string::npos) {
            return fmt::format("a message with an empty name (\"{}\")", empty);
        }
    }
    if (!expect.mention.empty() && what.find(expect.mention) == std::string::npos) {
        return fmt::format("the message does not say \"{}\"", expect.mention);
    }
    if (!expect.blameOneOf.empty() && std::find(expect.blameOneOf.begin(), expect.blameOneOf.end(),
                                                e.keyPath) == expect.blameOneOf.end()) {
        return fmt::format("blamed on {}", e.keyPath.empty() ? "no key" : e.keyPath);
    }
    if (!expect.neverBlamed.empty() && e.keyPath == expect.neverBlamed) {
        return fmt::format("blamed on {}", e.keyPath);
    }
    return {};
}

/// The child: read, and if accepted run a few steps. Never returns.
[[noreturn]] void runCase(const std::string& text, const Expectation& expect, const Options& o) {
    const rlimit memory{kMemoryLimit, kMemoryLimit};
    setrlimit(RLIMIT_AS, &memory);
    alarm(static_cast<unsigned>(o.timeout));
    try {
        ExperimentConfig config;
        try {
            config = grainlab::parseExperimentText(text, "mutant.json");
        } catch (const grainlab::ExperimentFileError& e) {
            if (const std::string bad = badRefusal(e, expect); !bad.empty()) {
                std::fprintf(stderr, "  bad refusal (%s): %s\n", bad.c_str(), e.what());
                std::_Exit(kBadRefusal);
            }
            if (o.verbose) {
                std::fprintf(stderr, "  refused: %s\n", e.what());
            }
            std::_Exit(kRefused);
        }
        if (expect.mustRefuse) {
            std::fprintf(stderr, "  accepted, but the mutation must be refused\n");
            std::_Exit(kBadRefusal);
        }
        if (config.assembly.grainCount > kMaxRunGrains) {
            Json j = Json::parse(text);
            j["grains"]["count"] = kRunGrains;
            config = grainlab::parseExperimentText(j.dump(), "mutant.json");
        }
        try {
            grainlab::ExperimentRunner runner(config);
            runner.advance(o.steps);
        } catch (const std::bad_alloc&) {
            throw;
        } catch (const std::exception& e) {
            if (o.verbose) {
                std::fprintf(stderr, "  run error: %s\n", e.what());
            }
            std::_Exit(kRunError);
        }
        std::_Exit(kRan);
    } catch (const std::bad_alloc&) {
        std::_Exit(kOutOfMemory);
    } catch (const std::exception& e) {
        // A refusal of the re-sized file cannot happen; anything else escaping is a defect.
        std::fprintf(stderr, "  unexpected: %s\n", e.what());
        std::abort();
    }
}

Options parseOptions(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const auto value = [&]() -> std::string {
            if (i + 1 >= argc) {
                throw std::invalid_argument(a + " needs a value");
            }
            return argv[++i];
        };
        if (a == "--cases") {
            o.cases = std::stoi(value());
        } else if (a == "--seed") {
            o.seed = std::stoull(value());
        } else if (a == "--steps") {
            o.steps = std::stoll(value());
        } else if (a == "--timeout") {
            o.timeout = std::stoi(value());
        } else if (a == "--presets") {
            o.presets = value();
        } else if (a == "--keep") {
            o.keep = value();
        } else if (a == "--verbose") {
            o.verbose = true;
        } else {
            throw std::invalid_argument("unknown option " + a +
                                        " (--cases, --seed, --steps, --timeout, --presets, "
                                        "--keep, --verbose)");
        }
    }
    if (o.cases < 1 || o.steps < 1 || o.timeout < 1) {
        throw std::invalid_argument("--cases, --steps and --timeout must be >= 1");
    }
    return o;
}

} // namespace

int main(int argc, char** argv) {
    Options o;
    try {
        o = parseOptions(argc, argv);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "experiment_fuzz: %s\n", e.what());
        return 2;
    }
    std::vector<std::pair<std::string, std::string>> presets;
    for (const auto& entry : std::filesystem::directory_iterator(o.presets)) {
        if (entry.path().extension() == ".json") {
            std::ifstream in(entry.path());
            std::ostringstream text;
            text << in.rdbuf();
            presets.emplace_back(entry.path().filename().string(), text.str());
        }
    }
    std::sort(presets.begin(), presets.end());
    if (presets.empty()) {
        std::fprintf(stderr, "experiment_fuzz: no .json files in %s\n", o.presets.c_str());
        return 2;
    }
    Mutator mutator(o.seed);
    int refused = 0, ran = 0, runErrors = 0, crashes = 0, hangs = 0, outOfMemory = 0,
        badRefusals = 0;
    for (int c = 0; c < o.cases; ++c) {
        const auto& [name, text] = presets[mutator.below(presets.size())];
        const Mutant m = mutator.mutate(text);
        const std::string& mutant = m.text;
        const std::string& what = m.what;
        std::fflush(stdout);
        const pid_t child = fork();
        if (child < 0) {
            std::perror("fork");
            return 2;
        }
        if (child == 0) {
            runCase(mutant, m.expect, o);
        }
        int status = 0;
        waitpid(child, &status, 0);
        std::string failure;
        if (WIFSIGNALED(status)) {
            if (WTERMSIG(status) == SIGALRM) {
                ++hangs;
                failure = fmt::format("hang (over {} s)", o.timeout);
            } else {
                ++crashes;
                failure = fmt::format("crash (signal {}: {})", WTERMSIG(status),
                                      strsignal(WTERMSIG(status)));
            }
        } else {
            switch (WEXITSTATUS(status)) {
            case kRefused:
                ++refused;
                break;
            case kRan:
                ++ran;
                break;
            case kRunError:
                ++runErrors;
                break;
            case kBadRefusal:
                ++badRefusals;
                failure = "refusal against the mutation's requirement";
                break;
            case kOutOfMemory:
                ++outOfMemory;
                failure = "out of memory";
                break;
            default:
                ++crashes;
                failure = fmt::format("exit status {}", WEXITSTATUS(status));
            }
        }
        if (!failure.empty()) {
            std::string kept;
            if (!o.keep.empty()) {
                std::filesystem::create_directories(o.keep);
                kept = fmt::format("{}/case{:05d}.json", o.keep, c);
                std::ofstream(kept, std::ios::binary) << mutant;
            }
            fmt::print("case {}: {}: {} ({}){}\n", c, failure, what, name,
                       kept.empty() ? "" : "; kept as " + kept);
        } else if (o.verbose) {
            fmt::print("case {}: ok: {} ({})\n", c, what, name);
        }
    }
    fmt::print("experiment_fuzz: {} cases, seed {}: {} refused by the reader, {} ran {} steps, {} "
               "stopped by the engine with an error; {} crashes, {} hangs, {} out of memory, "
               "{} bad refusals\n",
               o.cases, o.seed, refused, ran, o.steps, runErrors, crashes, hangs, outOfMemory,
               badRefusals);
    return crashes + hangs + outOfMemory + badRefusals > 0 ? 1 : 0;
}
