#pragma once
// The main window: assembles the panels — the live scene with its display options, the charts,
// the inspector, the run controls and the editable parameters — and wires them to the simulation
// controller. It computes nothing itself: a 33 ms timer picks the controller's newest snapshot
// and hands it to the panels (charts at most every 150 ms while running). While a run is
// running, new pictures are spaced by the picture budget (picture_budget.h), so that making and
// drawing them takes at most a share of a core from the engine; the controller publishes no
// more often. Paused, stepped and finished pictures, zooming, panning and changed options are
// shown at once. Hovering a chart shows that moment in the scene: a run file's nearest
// checkpoint, or the live run's nearest kept snapshot (the controller's history) until the
// hover ends. A run started here is recorded: it writes a run folder as `grainlab run` does
// (window_run_folder.h says where), holding the experiment as edited in the Parameters tab
// (edited_experiment.h), which Save experiment as… writes too. GUI thread only; the run folder
// is written on the controller's worker thread.

#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include <QElapsedTimer>
#include <QKeySequence>
#include <QMainWindow>
#include <QTimer>

#include "common/run_file_view.h"
#include "grainlab/experiment.h"
#include "gui/experiment_run.h"
#include "gui/picture_budget.h"
#include "gui/simulation_controller.h"

class QAction;
class QLabel;
class QProgressBar;
class QSpinBox;
class QTabWidget;
class QSlider;

namespace grainlab::ui {

class ChartsPanel;
class CommandProcess;
class InspectorPanel;
class ParametersPanel;
class ReportJob;
class SceneOptionsBar;
class SceneView;
class StudyWindow;
class WarningLabel;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    /// Makes the run for an experiment when Start or Step is pressed with no run.
    using RunMaker = std::function<std::unique_ptr<SteppedRun>(const ExperimentConfig&)>;

    /// Without a maker (the app), each run is the experiment runner writing a new run folder;
    /// a maker's runs (benchmarks, scripted tests) are its own and write nothing.
    explicit MainWindow(RunMaker maker = {}, QWidget* parent = nullptr);
    ~MainWindow() override;

    /// Reads an experiment file and shows its parameters (stops a current run). Returns false
    /// and sets `error` when the file is invalid.
    bool openExperiment(const QString& path, QString* error = nullptr);
    void setExperiment(const ExperimentConfig& config);
    /// Opens a run file: its series join the charts and its checkpoints can be scrubbed with the
    /// slider under the scene (the live run is paused). Returns false and sets `error` on failure.
    bool openRunFile(const QString& path, QString* error = nullptr);
    /// Opens the run file of a run folder (what `grainlab run --out` writes).
    bool openRunFolder(const QString& folder, QString* error = nullptr);
    /// The Study window (made on first use); its points open run folders here and its
    /// recommendation loads here as the experiment.
    StudyWindow* studyWindow();
    /// Shows the Study window (menu File > Study…).
    void showStudyWindow();
    /// Shows checkpoint `index` of the open run file in the scene.
    void showRunFileCheckpoint(int index);
    /// True while the scene shows a kept snapshot of the live run (a chart is hovered).
    bool showsLiveHistory() const { return viewingHistory_; }

    /// The folder under which each run gets a new dated folder (default: defaultRunsFolder()).
    void setRunsFolder(const QString& folder);
    QString runsFolder() const { return runsFolder_; }
    /// The next run writes into `folder` instead (which must be new or empty), once.
    void setNextRunFolder(const QString& folder);
    /// The folder of the current (or last) run, "" before the first recorded run.
    QString runFolder() const;
    /// The experiment as edited in the Parameters tab, as experiment-file text (what Save
    /// experiment as… writes and a run records). Empty, with `error` set, when it cannot be.
    QString editedExperimentText(QString* error = nullptr) const;
    /// Writes editedExperimentText() to `path`. Returns false and sets `error` on failure.
    bool saveExperimentAs(const QString& path, QString* error = nullptr);

    /// Takes the newest snapshot and status from the controller now (what the timer does). While
    /// running, a new snapshot is taken only once the picture budget allows.
    void refresh();

    /// The budget of the current (or last) run's pictures: its share of a core follows the run's
    /// engine threads and this machine's processors (PictureBudget::shareFor).
    const PictureBudget& pictureBudget() const { return budget_; }
    /// Replaces the rule's share of a core by `share`, at once and for the next runs (tests, and
    /// GRAINLAB_PICTURE_SHARE at start); 0 returns to the rule.
    void setPictureShare(double share);
    /// What the last running picture cost the processor outside the engine's steps [ms] (the
    /// engine thread's copy, the snapshot thread's measures, the scene's preparation and
    /// paint), and the spacing of running pictures it gives; 0 before a run.
    double pictureCostMs() const { return pictureCostMs_; }
    double pictureIntervalMs() const { return pictureIntervalMs_; }
    /// When the last running picture was taken (the window's own monotonic clock [ms]) and the
    /// spacing it was taken under: it came no sooner than that spacing after the one before,
    /// less a timer tick's slack of 3 ms.
    double runningPictureAtMs() const { return pictureAtMs_; }
    double runningPictureIntervalMs() const { return pictureTakenIntervalMs_; }

    /// The figure set into `folder` (no dialog), in two parts. At once: scene.<fmt>, every
    /// chart as <name>.<fmt> and each shown test's series as <test>.csv, returned (`error` set on
    /// a failure, which ends the export). Then the report's figures of reportSource() with the
    /// CSV of each, into `folder`/report/ (what Report… writes into the run folder) by a
    /// `grainlab report` process the window does not wait for. figureSetWritten is emitted once
    /// the set is complete; at once when the report's part is left out: no run to report on, or
    /// the live run it would read is still running or paused (its run file is being written).
    QStringList exportFigureSet(const QString& folder, QString* error = nullptr);

    /// The run folder File > Report… reports on: the open run file's folder while the scene
    /// shows it, else the current (or last) run's; "" when there is none.
    QString reportSource() const;
    /// Writes the report of reportSource() into its folder's report/ with a `grainlab report`
    /// process (the window never waits for it), then opens report.html and emits
    /// reportWritten. Refused (with a message) while the live run it would read is still
    /// running or paused.
    void writeReport();
    /// The executable that writes reports (default: this application's).
    void setGrainlabExecutable(const QString& path) { grainlab_ = path; }
    QAction* reportAction() const { return report_; }

    /// Writes the ParaView files (docs/paraview.md) of the run reportSource() names into `out`, a
    /// folder that must not exist, by a `grainlab export vtk` process the window does not wait
    /// for (a stopped run's checkpoints so far: --unfinished). paraviewFilesWritten follows when
    /// it has ended, at once when refused (no run, or the live run is still going).
    void writeParaViewFiles(const QString& out);
    QAction* paraviewAction() const { return paraview_; }

signals:
    /// report.html has been written (and opened).
    void reportWritten(const QString& html);
    /// The figure set into `folder` is complete. `note` is "" when the report's figures are in
    /// it, else says why they are not (left out, or their report failed).
    void figureSetWritten(const QString& folder, const QString& note);
    /// The ParaView export into `out` has ended: `error` is "" when it was written, else what
    /// went wrong (the command's own message: the file and what is allowed).
    void paraviewFilesWritten(const QString& out, const QString& error);

public:
    SimulationController& controller() { return *controller_; }
    SceneView* sceneView() const { return scene_; }
    SceneOptionsBar* sceneOptionsBar() const { return sceneOptions_; }
    ChartsPanel* chartsPanel() const { return charts_; }
    InspectorPanel* inspector() const { return inspector_; }
    ParametersPanel* parametersPanel() const { return parameters_; }
    QAction* startAction() const { return start_; }
    QAction* pauseAction() const { return pause_; }
    QAction* stepAction() const { return step_; }
    QAction* stopAction() const { return stop_; }
    QAction* saveExperimentAction() const { return saveAs_; }
    /// The status bar's note of where runs are written.
    QLabel* runFolderLabel() const { return runFolder_; }
    QSpinBox* stepSizeEdit() const { return stepSize_; }
    QLabel* speedLabel() const { return speed_; }
    /// The status bar's line of the run's warnings (live, or of the open run file).
    WarningLabel* warningLabel() const { return warning_; }
    QProgressBar* progressBar() const { return progress_; }
    QSlider* runFileSlider() const { return scrub_; }
    /// The generated assembly the next Start begins from, shown in the scene while no run is
    /// going (null before an experiment is loaded, or when the parameters cannot make one).
    const SnapshotPtr& startingAssembly() const { return startingAssembly_; }

public slots:
    void startRun();
    void pauseRun();
    void stepRun();
    void stopRun();

private:
    void buildActions();
    /// An action of the window calling `slot`, with `shortcut` and `toolTip` when they are given.
    QAction* makeAction(const QString& text, const QKeySequence& shortcut, const QString& toolTip,
                        void (MainWindow::*slot)());
    void buildMenus();
    void updateControls(RunState state);
    /// Gives the controller the run Start or Step begins; false (and says why) when the edited
    /// parameters cannot make one.
    bool prepareRun();
    /// The picture budget of a run of `config` (its engine threads, this machine's processors).
    void setPictureBudget(const ExperimentConfig& config);
    void saveExperimentDialog();
    void chooseRunsFolderDialog();
    void chooseNextRunFolderDialog();
    void openExperimentDialog();
    void exportSceneDialog();
    void exportChartDialog(int chart);
    void exportCsvDialog();
    void exportFigureSetDialog();
    void exportParaViewDialog();
    /// The `grainlab export vtk` process has ended (CommandProcess::ended).
    void paraviewEnded(int exitStatus, const QString& output, const QString& startError);
    void showError(const QString& message);
    /// Shows `error` (showError), or, when there is none, `done` in the status bar for 10 s.
    void sayEnded(const QString& error, const QString& done);
    /// `action(path, &error)` (openExperiment(), saveExperimentAs(), …), its error shown when it
    /// fails; whether it succeeded.
    bool showingError(bool (MainWindow::*action)(const QString&, QString*), const QString& path);
    /// Opens `path` with `open` for the Study window, then brings this window to the front.
    void openFromStudy(bool (MainWindow::*open)(const QString&, QString*), const QString& path);
    /// Why no report can be written of reportSource() now ("" when one can): there is none, or
    /// it is the live run, still running or paused.
    QString reportRefusal() const;
    /// The executable that writes reports: grainlab_, else this application.
    QString grainlabExecutable() const;
    /// The Report… process has ended: opens report.html, or says what went wrong.
    void reportEnded(const QString& out, const QString& error);
    /// The figure set into `folder` is complete: says so (or `note`) and emits figureSetWritten.
    void figureSetEnded(const QString& folder, const QString& note);
    void openRunFileDialog();
    /// The live run's tables followed by the open run file's.
    void updateCharts(const SnapshotPtr& live);
    /// The scene follows a chart hover at `eps1`; chartHoverEnded() returns it to the live run.
    void chartHovered(double eps1);
    void chartHoverEnded();
    /// Generates the assembly of the experiment as loaded and edited (the grid the run starts
    /// from) and shows it in the scene, unless a run is going or a run file is viewed.
    void showStartingAssembly();

    RunMaker maker_;
    ExperimentConfig experiment_;
    QString runsFolder_;
    QString nextRunFolder_;
    std::unique_ptr<SimulationController> controller_;
    SnapshotPtr shown_;
    std::int64_t chartedAtMs_ = 0;
    std::size_t chartedRows_ = 0;
    RunState shownState_ = RunState::Idle;
    QString chartedPage_; ///< the charts' page of the live stage last shown
    std::optional<RunFileView> runFile_;
    bool viewingFile_ = false;    ///< the scene shows a run file's checkpoint, not the live run
    bool viewingHistory_ = false; ///< the scene shows a kept snapshot of the live run (hover)
    QTimer timer_;
    QTimer startingAssemblyTimer_; ///< spaces regenerations while parameters are typed
    SnapshotPtr startingAssembly_;
    QElapsedTimer clock_;               ///< monotonic, for the picture budget
    PictureBudget budget_;              ///< set by prepareRun() for each run
    int runEngineThreads_ = 1;          ///< the engine threads of the current (or last) run
    double pictureShare_ = 0;           ///< the chosen share of a core, 0: the rule
    double pictureAtMs_ = -1e300;       ///< clock_ when the last running picture was taken
    double pictureCostMs_ = 0;          ///< see pictureCostMs()
    double pictureIntervalMs_ = 0;      ///< see pictureIntervalMs()
    double pictureTakenIntervalMs_ = 0; ///< see runningPictureIntervalMs()

    SceneView* scene_;
    SceneOptionsBar* sceneOptions_;
    ChartsPanel* charts_;
    InspectorPanel* inspector_;
    ParametersPanel* parameters_;
    QTabWidget* tabs_;
    StudyWindow* study_ = nullptr;
    QAction* open_ = nullptr;
    QAction* start_ = nullptr;
    QAction* pause_ = nullptr;
    QAction* step_ = nullptr;
    QAction* stop_ = nullptr;
    QAction* saveAs_ = nullptr;
    QAction* report_ = nullptr;
    ReportJob* reportJob_ = nullptr;    ///< File > Report…
    ReportJob* figureSetJob_ = nullptr; ///< the report's figures of the figure-set export
    QAction* paraview_ = nullptr;
    CommandProcess* paraviewExport_ = nullptr; ///< Export > ParaView files…
    QString paraviewOut_;
    QString grainlab_;
    QSpinBox* stepSize_ = nullptr;
    QLabel* stage_;
    QLabel* speed_;
    QLabel* eta_;
    QLabel* cursor_;
    QLabel* error_;
    WarningLabel* warning_;
    QLabel* runFolder_;
    QProgressBar* progress_;
    QWidget* scrubBar_;
    QSlider* scrub_;
    QLabel* scrubLabel_;
};

} // namespace grainlab::ui
