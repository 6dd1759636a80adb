#include "command_line.h"

#include <cstdio>
#include <exception>
#include <filesystem>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "bench/bench.h"
#include "cli/run_command.h"
#include "common/resources.h"
#include "common/version.h"
#include "export/export_command.h"
#include "report/checkpoint_picture.h"
#include "report/report_command.h"
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

/// `run`: its subcommand and options.
CLI::App* addRunCommand(CLI::App& app, RunOptions& run) {
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
    return runCommand;
}

/// The process pool's options of `study` and `stability`: how many processes at once (--jobs),
/// or the job list to write instead (--emit).
void addPoolOptions(CLI::App& command, int& jobs, const std::string& jobsHelp, std::string& emit,
                    const std::string& emitHelp) {
    command.add_option("--jobs", jobs, jobsHelp)->check(CLI::Range(1, 1024));
    command.add_option("--emit", emit, emitHelp)->check(CLI::IsMember({"slurm", "parallel"}));
}

/// `study` and `study collect`.
struct StudyCommands {
    CLI::App* study;
    CLI::App* collect;
    std::string collectFolder;
};
void addStudyCommands(CLI::App& app, StudyOptions& study, StudyCommands& c) {
    c.study = app.add_subcommand(
        "study", "run an experiment at several method settings and seeds; chart error against "
                 "cost and recommend the cheapest valid setting");
    c.study->add_option("study", study.studyFile, "study file (.json)");
    c.study->add_option("--out", study.out, "study folder (runs, study.csv, summary.csv)");
    addPoolOptions(*c.study, study.jobs, "runs at once (default: as the processors allow)",
                   study.emit,
                   "write the runs as a Slurm job array (slurm) or a GNU parallel job "
                   "list (parallel) instead of running them");
    c.study->add_flag("--quiet", study.quiet, "no progress bar");
    c.collect = c.study->add_subcommand(
        "collect", "summarise a study folder whose runs were run elsewhere (Slurm, GNU parallel)");
    c.collect->add_option("folder", c.collectFolder, "the study folder")->required();
    c.collect->add_flag("--quiet", study.quiet, "print nothing but errors");
}

/// `report`.
CLI::App* addReportCommand(CLI::App& app, ReportCommandOptions& report) {
    auto* reportCommand = app.add_subcommand(
        "report", "the reference study's figure set and headline numbers from finished runs of "
                  "one experiment (seeds: means with their scatter)");
    reportCommand->add_option("runs", report.runFolders, "run folders (one per seed)")->required();
    reportCommand->add_option("--out", report.out, "report folder (report.html, figures/)")
        ->required();
    reportCommand->add_flag("--quiet", report.quiet, "print nothing but errors");
    return reportCommand;
}

/// `reproduce` (its default experiment is set by the caller).
CLI::App* addReproduceCommand(CLI::App& app, ReproduceOptions& reproduce) {
    auto* reproduceCommand = app.add_subcommand(
        "reproduce", "run the reference experiment at several seeds (a study's local pool, "
                     "resumable), then report on its runs");
    reproduceCommand
        ->add_option("--grains", reproduce.grains, "grains (default: the reference's 8450)")
        ->check(CLI::Range(2, 1000000));
    reproduceCommand->add_option("--seeds", reproduce.seeds, "seeds (default 1)")
        ->check(CLI::Range(1, 1000));
    reproduceCommand
        ->add_option("--jobs", reproduce.jobs, "runs at once (default: as the processors allow)")
        ->check(CLI::Range(1, 1024));
    reproduceCommand->add_option("--experiment", reproduce.experiment,
                                 "the experiment to reproduce (default: the reference)");
    reproduceCommand->add_option("--out", reproduce.out, "folder (study/, report/)")->required();
    reproduceCommand->add_flag("--quiet", reproduce.quiet, "no progress bar");
    return reproduceCommand;
}

/// `stability`, `stability cell` (one map point) and `stability collect`.
struct StabilityCommands {
    CLI::App* map;
    CLI::App* point;
    CLI::App* collect;
    std::string folder, pointId;
};
void addStabilityCommands(CLI::App& app, StabilityOptions& stability, StabilityCommands& c) {
    c.map = app.add_subcommand(
        "stability", "measure where the methods fail: the largest stable time step, the servo's "
                     "stable gain and interval, the contact geometry's valid overlap "
                     "(docs/stability.md)");
    c.map->add_option("preset_file", stability.presetFile, "stability preset (.json)");
    c.map->add_option("--preset", stability.preset,
                      "a preset of resources/stability (tiny, full, servo-tiny, "
                      "servo-full, geometry-tiny, geometry-full)");
    c.map->add_option("--out", stability.out, "map folder (cells/, limits.csv)");
    addPoolOptions(*c.map, stability.jobs, "map points at once (default: the processors)",
                   stability.emit,
                   "write the map points as a Slurm job array (slurm) or a GNU parallel job list "
                   "(parallel) instead of running them");
    c.map->add_flag("--quiet", stability.quiet, "no progress bar");
    c.point = c.map->add_subcommand("cell", "measure one map point of a map folder");
    c.point->add_option("folder", c.folder, "the map folder")->required();
    c.point->add_option("--cell", c.pointId, "the map point's id")->required();
    c.point->add_flag("--quiet", stability.quiet, "print nothing but errors");
    c.collect = c.map->add_subcommand(
        "collect", "write limits.csv (and figures) of a map folder whose map points ran elsewhere");
    c.collect->add_option("folder", c.folder, "the map folder")->required();
    c.collect->add_flag("--quiet", stability.quiet, "print nothing but errors");
}

/// `export`, `export vtk` and `export picture`.
struct ExportCommands {
    CLI::App* exports;
    CLI::App* vtk;
    CLI::App* picture;
    bool quiet = false;
};
void addExportCommands(CLI::App& app, VtkExportOptions& vtk, CheckpointPictureOptions& picture,
                       ExportCommands& c) {
    c.exports = app.add_subcommand("export", "write a run's checkpoints in other formats");
    c.exports->require_subcommand(1);
    c.vtk = c.exports->add_subcommand(
        "vtk", "each test's checkpoints as VTK XML files and a .pvd time index, for ParaView "
               "(docs/paraview.md)");
    c.vtk->add_option("run", vtk.run, "run folder (or its run.h5)")->required();
    c.vtk->add_option("--out", vtk.out, "export folder, which must not exist")->required();
    auto* every = c.vtk
                      ->add_option("--every", vtk.every,
                                   "every N-th checkpoint of each test, and its last (default 1)")
                      ->check(CLI::Range(1, 1000000))
                      ->type_name("N");
    auto* strains = c.vtk
                        ->add_option("--strains", vtk.strains,
                                     "per test, the checkpoint nearest each of these eps1, "
                                     "e.g. 0,0.01,0.05")
                        ->delimiter(',')
                        ->type_name("EPS1,...");
    every->excludes(strains);
    c.vtk->add_flag("--unfinished", vtk.unfinished,
                    "export a run that has not finished (its checkpoints so far)");
    c.vtk->add_flag("--quiet", c.quiet, "print nothing but errors");

    c.picture = c.exports->add_subcommand(
        "picture", "one checkpoint drawn as the window draws it, as a PNG, SVG or PDF file "
                   "(docs/paraview.md)");
    c.picture->add_option("run", picture.run, "run folder (or its run.h5)")->required();
    c.picture->add_option("--test", picture.test, "the test, e.g. p015kPa")->required();
    c.picture->add_option("--strain", picture.strain,
                          "eps1 of the checkpoint to draw: the test's nearest (default 0)");
    c.picture->add_option("--out", picture.out, "picture file (.png, .svg, .pdf), must not exist")
        ->required();
    c.picture->add_option("--colouring", picture.colouring, "grain colours")
        ->check(CLI::IsMember({"rotation", "size", "coordination", "load-bearing", "uniform"}))
        ->capture_default_str();
    c.picture->add_option("--chains", picture.chains, "force chains")
        ->check(CLI::IsMember({"off", "strong", "all"}))
        ->capture_default_str();
    c.picture->add_option("--void-cells", picture.voidCells, "void-cell shading")
        ->check(CLI::IsMember({"off", "valence", "area"}))
        ->capture_default_str();
    c.picture->add_option("--size", picture.size, "pixels of the square picture")
        ->check(CLI::Range(64, 8192))
        ->capture_default_str();
    c.picture
        ->add_option("--rotation-range", picture.rotationRange,
                     "|rotation| [rad] at the ends of the colour scale")
        ->check(CLI::Range(1e-6, 10.0))
        ->capture_default_str();
}

} // namespace

int runCommandLine(int argc, char** argv) {
    CLI::App app{"GrainLab: 2D discrete element simulations of oval grains"};
    app.set_version_flag("--version", versionText());

    BenchOptions bench;
    auto* benchCommand = app.add_subcommand(
        "bench", "time the engine on a dense assembly under biaxial compression");
    addBenchOptions(*benchCommand, bench);

    RunOptions run;
    CLI::App* runCommand = addRunCommand(app, run);

    StudyOptions study;
    StudyCommands studyCommands;
    addStudyCommands(app, study, studyCommands);

    ReportCommandOptions report;
    CLI::App* reportCommand = addReportCommand(app, report);

    ReproduceOptions reproduce;
    reproduce.experiment = resourcePath("experiments/reference.json");
    CLI::App* reproduceCommand = addReproduceCommand(app, reproduce);

    StabilityOptions stability;
    StabilityCommands stabilityCommands;
    addStabilityCommands(app, stability, stabilityCommands);

    VtkExportOptions exportVtk;
    CheckpointPictureOptions exportPicture;
    ExportCommands exportCommands;
    addExportCommands(app, exportVtk, exportPicture, exportCommands);

    std::string experiment = resourcePath("experiments/quick.json");
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
        if (*exportCommands.vtk) {
            return runExportVtkCommand(exportVtk, exportCommands.quiet);
        }
        if (*exportCommands.picture) {
#ifdef GRAINLAB_WITH_GUI
            return runCheckpointPictureCommand(exportPicture);
#else
            fmt::print(stderr, "grainlab export picture: this grainlab was built without Qt\n");
            return 2;
#endif
        }
        if (*reportCommand) {
            return runReportCommand(report);
        }
        if (*reproduceCommand) {
            reproduce.grainlab = executablePath(argv[0]);
            return runReproduceCommand(reproduce);
        }
        if (*stabilityCommands.point) {
            return runStabilityMapCell(stabilityCommands.folder, stabilityCommands.pointId,
                                       stability.quiet);
        }
        if (*stabilityCommands.collect) {
            return collectStabilityCommand(stabilityCommands.folder, stability.quiet,
                                           stability.figures, stability.servoFigures);
        }
        if (*stabilityCommands.map) {
            if (stability.out.empty() || stability.preset.empty() == stability.presetFile.empty()) {
                fmt::print(stderr, "grainlab stability: give --preset NAME or a preset file, and "
                                   "--out DIR\n");
                return 2;
            }
            stability.grainlab = executablePath(argv[0]);
            return runStabilityCommand(stability);
        }
        if (*studyCommands.collect) {
            return collectStudyCommand(studyCommands.collectFolder, study.quiet, study.figures);
        }
        if (*studyCommands.study) {
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
