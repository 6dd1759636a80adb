#include "command_line.h"

#include <cstdio>
#include <exception>
#include <filesystem>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "bench/bench.h"
#include "cli/run_command.h"
#include "report/report_command.h"
#include "stability/stability_cell.h"
#include "stability/stability_command.h"
#include "study/study_command.h"

#ifdef GRAINLAB_WITH_GUI
#include "bench/window_bench.h"
#include "gui/app.h"
#include "report/report_figures_writer.h"
#include "stability/stability_figures_writer.h"
#include "study/study_figures_writer.h"
#endif

namespace grainlab {
namespace {

/// This executable's path, for the commands a study runs (/proc/self/exe where there is one).
std::string executablePath(const char* argv0) {
    std::error_code error;
    const auto self = std::filesystem::read_symlink("/proc/self/exe", error);
    return error ? std::filesystem::absolute(argv0).string() : self.string();
}

} // namespace

int runCommandLine(int argc, char** argv) {
    CLI::App app{"GrainLab: 2D discrete element simulations of oval grains"};
    app.set_version_flag("--version", std::string(GRAINLAB_VERSION));

    BenchOptions bench;
    auto* benchCommand = app.add_subcommand(
        "bench", "time the engine on a dense assembly under biaxial compression");
    addBenchOptions(*benchCommand, bench);

    RunOptions run;
    auto* runCommand = app.add_subcommand("run", "run an experiment headless (no display needed)");
    runCommand->add_option("experiment", run.experiment, "experiment file (.json)");
    runCommand->add_option("--out", run.out, "output folder (run.h5 and <test>/series.csv)");
    runCommand->add_option("--resume", run.resume,
                           "continue the run in this output folder from its last checkpoint");
    // The experiment file's range for `threads` (docs/experiment-file.md).
    runCommand
        ->add_option("--threads", run.threads, "threads, 1 to 1024 (default: the experiment's)")
        ->check(CLI::Range(1, 1024).description("")) // out of range or not a whole number: refused
        ->type_name("N");
    runCommand->add_flag("--force", run.force,
                         "replace the run already in the --out folder (its files are removed)");
    runCommand->add_flag("--quiet", run.quiet, "no progress bar");

    StudyOptions study;
    auto* studyCommand = app.add_subcommand(
        "study", "run an experiment at several method settings and seeds; chart error against "
                 "cost and recommend the cheapest valid setting");
    studyCommand->add_option("study", study.studyFile, "study file (.json)");
    studyCommand->add_option("--out", study.out, "study folder (runs, study.csv, summary.csv)");
    studyCommand
        ->add_option("--jobs", study.jobs, "runs at once (default: as the processors allow)")
        ->check(CLI::Range(1, 1024));
    studyCommand
        ->add_option("--emit", study.emit,
                     "write the runs as a Slurm job array (slurm) or a GNU parallel job "
                     "list (parallel) instead of running them")
        ->check(CLI::IsMember({"slurm", "parallel"}));
    studyCommand->add_flag("--quiet", study.quiet, "no progress bar");
    std::string collectFolder;
    auto* collectCommand = studyCommand->add_subcommand(
        "collect", "summarise a study folder whose runs were run elsewhere (Slurm, GNU parallel)");
    collectCommand->add_option("folder", collectFolder, "the study folder")->required();
    collectCommand->add_flag("--quiet", study.quiet, "print nothing but errors");

    ReportCommandOptions report;
    auto* reportCommand = app.add_subcommand(
        "report", "the reference study's figure set and headline numbers from finished runs of "
                  "one experiment (seeds: means with their scatter)");
    reportCommand->add_option("runs", report.runFolders, "run folders (one per seed)")->required();
    reportCommand->add_option("--out", report.out, "report folder (report.html, figures/)")
        ->required();
    reportCommand->add_flag("--quiet", report.quiet, "print nothing but errors");

    ReproduceOptions reproduce;
    reproduce.experiment =
        std::string(GRAINLAB_SOURCE_DIR) + "/resources/experiments/reference.json";
    auto* reproduceCommand = app.add_subcommand(
        "reproduce", "run the reference experiment at several seeds (a study's local pool, "
                     "resumable), then report on its runs");
    reproduceCommand->add_option("--grains", reproduce.grains,
                                 "grains (default: the reference's 8450)")
        ->check(CLI::Range(2, 1000000));
    reproduceCommand->add_option("--seeds", reproduce.seeds, "seeds (default 1)")
        ->check(CLI::Range(1, 1000));
    reproduceCommand->add_option("--jobs", reproduce.jobs,
                                 "runs at once (default: as the processors allow)")
        ->check(CLI::Range(1, 1024));
    reproduceCommand->add_option("--experiment", reproduce.experiment,
                                 "the experiment to reproduce (default: the reference)");
    reproduceCommand->add_option("--out", reproduce.out, "folder (study/, report/)")->required();
    reproduceCommand->add_flag("--quiet", reproduce.quiet, "no progress bar");

    StabilityOptions stability;
    auto* stabilityCommand = app.add_subcommand(
        "stability", "measure where the methods fail: the largest stable time step, the servo's "
                     "stable gain and interval, the contact geometry's valid overlap "
                     "(docs/stability.md)");
    stabilityCommand->add_option("preset_file", stability.presetFile, "stability preset (.json)");
    stabilityCommand->add_option("--preset", stability.preset,
                                 "a preset of resources/stability (tiny, full, servo-tiny, "
                                 "servo-full, geometry-tiny, geometry-full)");
    stabilityCommand->add_option("--out", stability.out, "map folder (cells/, limits.csv)");
    stabilityCommand
        ->add_option("--jobs", stability.jobs, "cells at once (default: the processors)")
        ->check(CLI::Range(1, 1024));
    stabilityCommand
        ->add_option("--emit", stability.emit,
                     "write the cells as a Slurm job array (slurm) or a GNU parallel job list "
                     "(parallel) instead of running them")
        ->check(CLI::IsMember({"slurm", "parallel"}));
    stabilityCommand->add_flag("--quiet", stability.quiet, "no progress bar");
    std::string stabilityFolder, stabilityCell;
    auto* stabilityCellCommand =
        stabilityCommand->add_subcommand("cell", "measure one cell of a map folder");
    stabilityCellCommand->add_option("folder", stabilityFolder, "the map folder")->required();
    stabilityCellCommand->add_option("--cell", stabilityCell, "the cell's id")->required();
    stabilityCellCommand->add_flag("--quiet", stability.quiet, "print nothing but errors");
    auto* stabilityCollectCommand = stabilityCommand->add_subcommand(
        "collect", "write limits.csv (and figures) of a map folder whose cells ran elsewhere");
    stabilityCollectCommand->add_option("folder", stabilityFolder, "the map folder")->required();
    stabilityCollectCommand->add_flag("--quiet", stability.quiet, "print nothing but errors");

    std::string experiment = std::string(GRAINLAB_SOURCE_DIR) + "/resources/experiments/quick.json";
    app.add_option("--experiment", experiment, "experiment to open in the window");

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }
    try {
        if (*benchCommand) {
#ifdef GRAINLAB_WITH_GUI
            return runBench(bench, runGuiBench);
#else
            return runBench(bench, nullptr);
#endif
        }
#ifdef GRAINLAB_WITH_GUI
        study.figures = writeStudyFiguresHeadless;
#endif
#ifdef GRAINLAB_WITH_GUI
        report.figures = writeReportFiguresHeadless;
        reproduce.figures = writeReportFiguresHeadless;
        stability.figures = writeStabilityFiguresHeadless;
        stability.servoFigures = writeServoFiguresHeadless;
        stability.geometryFigures = writeGeometryFiguresHeadless;
#endif
        if (*reportCommand) {
            return runReportCommand(report);
        }
        if (*reproduceCommand) {
            reproduce.grainlab = executablePath(argv[0]);
            return runReproduceCommand(reproduce);
        }
        if (*stabilityCellCommand) {
            return runStabilityMapCell(stabilityFolder, stabilityCell, stability.quiet);
        }
        if (*stabilityCollectCommand) {
            return collectStabilityCommand(stabilityFolder, stability.quiet, stability.figures,
                                           stability.servoFigures);
        }
        if (*stabilityCommand) {
            if (stability.out.empty() || stability.preset.empty() == stability.presetFile.empty()) {
                fmt::print(stderr, "grainlab stability: give --preset NAME or a preset file, and "
                                   "--out DIR\n");
                return 2;
            }
            stability.grainlab = executablePath(argv[0]);
            return runStabilityCommand(stability);
        }
        if (*collectCommand) {
            return collectStudyCommand(collectFolder, study.quiet, study.figures);
        }
        if (*studyCommand) {
            if (study.studyFile.empty() || study.out.empty()) {
                fmt::print(stderr, "grainlab study: give a study file and --out DIR\n");
                return 2;
            }
            study.grainlab = executablePath(argv[0]);
            return runStudyCommand(study);
        }
        if (*runCommand) {
            if (run.resume.empty() == run.experiment.empty()) {
                fmt::print(stderr, "grainlab run: give either an experiment file with --out DIR, "
                                   "or --resume DIR\n");
                return 2;
            }
            if (!run.experiment.empty() && run.out.empty()) {
                fmt::print(stderr, "grainlab run: --out DIR is required with an experiment file\n");
                return 2;
            }
            return runExperimentCommand(run);
        }
#ifdef GRAINLAB_WITH_GUI
        return runGui(argc, argv, experiment);
#else
        fmt::print("{}", app.help());
        return 0;
#endif
    } catch (const std::exception& e) {
        fmt::print(stderr, "grainlab: error: {}\n", e.what());
        return 1;
    }
}

} // namespace grainlab
