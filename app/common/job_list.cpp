#include "common/job_list.h"

#include <algorithm>
#include <filesystem>

#include <fmt/format.h>

namespace grainlab {

namespace fs = std::filesystem;

std::string StudyLayout::experimentFile(const std::string& run) const {
    return (fs::path(folder) / "experiments" / (run + ".json")).string();
}
std::string StudyLayout::runFolder(const std::string& run) const {
    return (fs::path(folder) / "runs" / run).string();
}
std::string StudyLayout::logFile(const std::string& run) const {
    return (fs::path(folder) / "logs" / (run + ".log")).string();
}

std::vector<std::string> runArguments(const StudyLayout& layout, const std::string& run,
                                      bool resume) {
    if (resume) {
        return {layout.grainlab, "run", "--resume", layout.runFolder(run), "--quiet"};
    }
    return {layout.grainlab,       "run",    layout.experimentFile(run), "--out",
            layout.runFolder(run), "--quiet"};
}

std::string shellQuote(const std::string& s) {
    std::string out = "'";
    for (char c : s) {
        if (c == '\'') {
            out += "'\\''";
        } else {
            out += c;
        }
    }
    return out + "'";
}

namespace {

std::string joined(const std::vector<std::string>& argv) {
    std::string out;
    for (const std::string& a : argv) {
        if (!out.empty()) {
            out += ' ';
        }
        out += shellQuote(a);
    }
    return out;
}

} // namespace

std::string runShellLine(const StudyLayout& layout, const std::string& run) {
    const std::string runFile = (fs::path(layout.runFolder(run)) / "run.h5").string();
    return fmt::format("if [ -e {} ]; then {}; else {}; fi", shellQuote(runFile),
                       joined(runArguments(layout, run, true)),
                       joined(runArguments(layout, run, false)));
}

std::string slurmScript(const StudyLayout& layout, const std::string& studyName,
                        const std::vector<std::string>& runs, int threads) {
    std::string s = "#!/bin/bash\n";
    s += fmt::format("# The runs of study {} as a Slurm job array: one task per run.\n", studyName);
    s += "# Submit with: sbatch study.slurm    Summarise when all are done with:\n";
    s += fmt::format("#   {} study collect {}\n", shellQuote(layout.grainlab),
                     shellQuote(layout.folder));
    s +=
        "# A task that is cancelled or times out continues from its checkpoint when resubmitted.\n";
    s += fmt::format("#SBATCH --job-name={}\n", studyName);
    s += fmt::format("#SBATCH --array=0-{}\n", runs.empty() ? 0 : runs.size() - 1);
    s += "#SBATCH --ntasks=1\n";
    s += fmt::format("#SBATCH --cpus-per-task={}\n", threads < 1 ? 1 : threads);
    s += fmt::format("#SBATCH --output={}\n",
                     (fs::path(layout.folder) / "logs" / "slurm-%A_%a.log").string());
    s += "set -euo pipefail\n";
    s += "runs=(\n";
    for (const std::string& r : runs) {
        s += "  " + shellQuote(r) + "\n";
    }
    s += ")\n";
    s += "run=\"${runs[$SLURM_ARRAY_TASK_ID]}\"\n";
    const std::string runs_ = shellQuote((fs::path(layout.folder) / "runs").string());
    const std::string experiments = shellQuote((fs::path(layout.folder) / "experiments").string());
    s += fmt::format("if [ -e {}/\"$run\"/run.h5 ]; then\n", runs_);
    s += fmt::format("  exec {} run --resume {}/\"$run\" --quiet\n", shellQuote(layout.grainlab),
                     runs_);
    s += "else\n";
    s += fmt::format("  exec {} run {}/\"$run\".json --out {}/\"$run\" --quiet\n",
                     shellQuote(layout.grainlab), experiments, runs_);
    s += "fi\n";
    return s;
}

std::string shellLine(const std::vector<std::string>& argv) {
    return joined(argv);
}

std::string slurmArrayScript(const std::string& jobName, const std::string& comment,
                             const std::string& logFolder,
                             const std::vector<std::vector<std::string>>& commands, int threads) {
    std::string s = "#!/bin/bash\n";
    std::size_t from = 0;
    while (from < comment.size()) {
        const std::size_t end = std::min(comment.find('\n', from), comment.size());
        s += "# " + comment.substr(from, end - from) + "\n";
        from = end + 1;
    }
    s += fmt::format("#SBATCH --job-name={}\n", jobName);
    s += fmt::format("#SBATCH --array=0-{}\n", commands.empty() ? 0 : commands.size() - 1);
    s += "#SBATCH --ntasks=1\n";
    s += fmt::format("#SBATCH --cpus-per-task={}\n", threads < 1 ? 1 : threads);
    s += fmt::format("#SBATCH --output={}\n", (fs::path(logFolder) / "slurm-%A_%a.log").string());
    s += "set -euo pipefail\n";
    s += "tasks=(\n";
    for (const auto& argv : commands) {
        s += "  " + shellQuote(joined(argv)) + "\n";
    }
    s += ")\n";
    s += "eval \"exec ${tasks[$SLURM_ARRAY_TASK_ID]}\"\n";
    return s;
}

std::string commandJobList(const std::vector<std::vector<std::string>>& commands) {
    std::string s;
    for (const auto& argv : commands) {
        s += joined(argv) + "\n";
    }
    return s;
}

std::string parallelJobList(const StudyLayout& layout, const std::vector<std::string>& runs) {
    std::string s;
    for (const std::string& r : runs) {
        s += runShellLine(layout, r) + "\n";
    }
    return s;
}

} // namespace grainlab
