// See main_window.h.
#include "gui/main_window.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <QAction>
#include <QDateTime>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QMenuBar>
#include <QProgressBar>
#include <QSlider>
#include <QSpinBox>
#include <QSplitter>
#include <QStatusBar>
#include <QTabWidget>
#include <QThread>
#include <QToolBar>
#include <QVBoxLayout>

#include "common/resources.h"
#include "grainlab/experiment_file.h"
#include "grainlab/experiment_runner.h"
#include "grainlab/ui/charts_panel.h"
#include "grainlab/ui/inspector_panel.h"
#include "grainlab/ui/parameters_panel.h"
#include "grainlab/ui/scene_options_bar.h"
#include "grainlab/ui/scene_view.h"
#include "grainlab/ui/warning_label.h"
#include "gui/command_process.h"
#include "gui/duration_text.h"
#include "gui/edited_experiment.h"
#include "gui/report_job.h"
#include "gui/study_window.h"
#include "gui/window_run_folder.h"

namespace grainlab::ui {
namespace {

/// GUI refresh period: 30 frames per second. Each new scene costs the worker a copy, the snapshot
/// thread its measures and the GUI thread a redraw, all taken from the processor the engine
/// shares, so no faster than needed.
constexpr int kFrameMs = 33;
constexpr int kChartPeriodMs = 150; ///< charts are replotted at most this often while running
/// A coarse QTimer may tick up to 5 % (1.7 ms) early: a picture due within this much of a tick
/// is taken at that tick, not one frame later (which would halve the rate at the 33 ms floor).
constexpr double kTickSlackMs = 3.0;

QString stateName(RunState state) {
    switch (state) {
    case RunState::Idle:
        return QObject::tr("ready");
    case RunState::Running:
        return QObject::tr("running");
    case RunState::Paused:
        return QObject::tr("paused");
    case RunState::Finished:
        return QObject::tr("finished");
    case RunState::Failed:
        return QObject::tr("failed");
    }
    return {};
}

} // namespace

MainWindow::MainWindow(RunMaker maker, QWidget* parent)
    : QMainWindow(parent), maker_(std::move(maker)), runsFolder_(defaultRunsFolder()),
      controller_(std::make_unique<SimulationController>()), scene_(new SceneView),
      sceneOptions_(new SceneOptionsBar(scene_)), charts_(new ChartsPanel),
      inspector_(new InspectorPanel), parameters_(new ParametersPanel), stage_(new QLabel),
      speed_(new QLabel), eta_(new QLabel), cursor_(new QLabel), error_(new QLabel),
      warning_(new WarningLabel), runFolder_(new QLabel), progress_(new QProgressBar),
      scrubBar_(new QWidget), scrub_(new QSlider(Qt::Horizontal)), scrubLabel_(new QLabel) {
    setWindowTitle(QStringLiteral("GrainLab"));
    // OpenGL draws the grains where the platform has a graphics card; the offscreen platform
    // (tests, CI) and GRAINLAB_NO_OPENGL=1 keep the QPainter view, which draws the same picture.
    // So does OpenGL drawn by the processor (Mesa's llvmpipe, e.g. under Xvfb): it takes more
    // processor time from the engine than QPainter and shows fewer pictures (measured with
    // `grainlab bench --gui`); GRAINLAB_OPENGL=1 uses it anyway.
    if (qEnvironmentVariableIsEmpty("GRAINLAB_NO_OPENGL") &&
        (!SceneView::openGLIsSoftware() || !qEnvironmentVariableIsEmpty("GRAINLAB_OPENGL"))) {
        scene_->setUseOpenGL(true);
    }
    // GRAINLAB_PICTURE_SHARE: the share of one core a running run's pictures may take, in
    // place of the rule (PictureBudget::shareFor): lower for fewer pictures and a faster
    // engine, higher for more pictures.
    if (const QByteArray share = qgetenv("GRAINLAB_PICTURE_SHARE"); !share.isEmpty()) {
        bool ok = false;
        const double value = share.toDouble(&ok);
        if (ok && value > 0.0 && value <= 1.0) {
            setPictureShare(value);
        } else {
            std::fprintf(stderr,
                         "grainlab: GRAINLAB_PICTURE_SHARE=%s: allowed values are numbers in "
                         "(0, 1] (a share of one core); using the rule instead\n",
                         share.constData());
        }
    }
    buildActions();
    buildMenus();
    reportJob_ = new ReportJob(this);
    connect(reportJob_, &ReportJob::finished, this, &MainWindow::reportEnded);
    paraviewExport_ = new CommandProcess(this);
    connect(paraviewExport_, &CommandProcess::ended, this, &MainWindow::paraviewEnded);
    figureSetJob_ = new ReportJob(this);
    connect(figureSetJob_, &ReportJob::finished, this,
            [this](const QString& out, const QString& e) {
                const QString folder = QFileInfo(out).path();
                figureSetEnded(
                    folder,
                    e.isEmpty()
                        ? e
                        : tr("The figure set in %1 lacks the report's figures. %2").arg(folder, e));
            });

    // Scene (with its display options) | charts over inspector and parameters.
    auto* sceneSide = new QWidget;
    auto* sceneLayout = new QVBoxLayout(sceneSide);
    sceneLayout->setContentsMargins(0, 0, 0, 0);
    sceneLayout->addWidget(sceneOptions_);
    sceneLayout->addWidget(scene_, 1);
    auto* scrubRow = new QHBoxLayout(scrubBar_);
    scrubRow->setContentsMargins(4, 2, 4, 2);
    scrubRow->addWidget(new QLabel(tr("Run file:")));
    scrubRow->addWidget(scrub_, 1);
    scrubRow->addWidget(scrubLabel_);
    scrubBar_->hide();
    sceneLayout->addWidget(scrubBar_);
    connect(scrub_, &QSlider::valueChanged, this, &MainWindow::showRunFileCheckpoint);
    tabs_ = new QTabWidget;
    tabs_->addTab(inspector_, tr("Inspector"));
    tabs_->addTab(parameters_, tr("Parameters"));
    tabs_->setCurrentWidget(parameters_);
    auto* right = new QSplitter(Qt::Vertical);
    right->addWidget(charts_);
    right->addWidget(tabs_);
    right->setStretchFactor(0, 3);
    right->setStretchFactor(1, 1);
    auto* split = new QSplitter(Qt::Horizontal);
    split->addWidget(sceneSide);
    split->addWidget(right);
    split->setStretchFactor(0, 1);
    split->setStretchFactor(1, 1);
    setCentralWidget(split);

    progress_->setRange(0, 1000);
    progress_->setMaximumWidth(220);
    progress_->setFormat(QStringLiteral("%p %"));
    error_->setStyleSheet(QStringLiteral("color: #b00020"));
    statusBar()->addWidget(stage_);
    statusBar()->addWidget(runFolder_);
    statusBar()->addWidget(error_, 1);
    statusBar()->addWidget(warning_, 2);
    statusBar()->addPermanentWidget(cursor_);
    statusBar()->addPermanentWidget(speed_);
    statusBar()->addPermanentWidget(progress_);
    statusBar()->addPermanentWidget(eta_);

    connect(scene_, &SceneView::voidCellClicked, this, [this](int cell) {
        inspector_->showVoidCell(scene_->snapshot(), cell);
        tabs_->setCurrentWidget(inspector_);
    });
    connect(scene_, &SceneView::grainClicked, this, [this](int grain) {
        inspector_->showGrain(scene_->snapshot(), grain);
        if (grain >= 0) {
            tabs_->setCurrentWidget(inspector_);
        }
    });
    connect(scene_, &SceneView::cursorMoved, this, [this](double x1, double x2) {
        cursor_->setText(
            tr("x1 %1 mm, x2 %2 mm").arg(x1 * 1e3, 0, 'f', 2).arg(x2 * 1e3, 0, 'f', 2));
    });
    connect(charts_, &ChartsPanel::hoveredAxialStrain, this, &MainWindow::chartHovered);
    connect(charts_, &ChartsPanel::hoverEnded, this, &MainWindow::chartHoverEnded);
    connect(parameters_, &ParametersPanel::edited, this, [this](bool) {
        updateControls(controller_->status().state);
        startingAssemblyTimer_.start();
    });
    startingAssemblyTimer_.setSingleShot(true);
    startingAssemblyTimer_.setInterval(300);
    connect(&startingAssemblyTimer_, &QTimer::timeout, this, &MainWindow::showStartingAssembly);
    connect(controller_.get(), &SimulationController::stateChanged, this,
            [this](RunState) { refresh(); });
    controller_->setPublishInterval(kFrameMs / 1000.0);
    clock_.start();
    connect(&timer_, &QTimer::timeout, this, &MainWindow::refresh);
    timer_.start(kFrameMs);
    updateControls(RunState::Idle);
}

MainWindow::~MainWindow() {
    timer_.stop();
    controller_.reset(); // joins the worker before the panels go
}

QAction* MainWindow::makeAction(const QString& text, const QKeySequence& shortcut,
                                const QString& toolTip, void (MainWindow::*slot)()) {
    auto* action = new QAction(text, this);
    if (!shortcut.isEmpty()) {
        action->setShortcut(shortcut);
    }
    if (!toolTip.isEmpty()) {
        action->setToolTip(toolTip);
    }
    connect(action, &QAction::triggered, this, slot);
    return action;
}

void MainWindow::buildActions() {
    open_ = makeAction(tr("&Open experiment…"), QKeySequence::Open, {},
                       &MainWindow::openExperimentDialog);
    saveAs_ = makeAction(tr("&Save experiment as…"), QKeySequence::SaveAs,
                         tr("Write the experiment as edited in the Parameters tab to a file that "
                            "`grainlab run` reads"),
                         &MainWindow::saveExperimentDialog);
    report_ = makeAction(tr("&Report…"), {},
                         tr("Write the reference study's figure set and headline numbers of this "
                            "run (or of the open run file) into its folder's report/ and open "
                            "report.html (grainlab report)"),
                         &MainWindow::writeReport);
    paraview_ = makeAction(tr("&ParaView files…"), {},
                           tr("Write every checkpoint of this run (or of the open run file) as "
                              "VTK files with a .pvd time index per test, for ParaView (grainlab "
                              "export vtk)"),
                           &MainWindow::exportParaViewDialog);
    start_ = makeAction(tr("Start"), Qt::Key_F5, tr("Start or resume the run (F5)"),
                        &MainWindow::startRun);
    pause_ = makeAction(tr("Pause"), Qt::Key_F6, {}, &MainWindow::pauseRun);
    step_ = makeAction(tr("Step"), Qt::Key_F7,
                       tr("Advance by the given number of steps, then pause (F7)"),
                       &MainWindow::stepRun);
    stop_ = makeAction(tr("Stop"), {}, tr("End the run; Start then begins a new one"),
                       &MainWindow::stopRun);

    stepSize_ = new QSpinBox;
    stepSize_->setRange(1, 10000000);
    stepSize_->setValue(100);
    stepSize_->setSuffix(tr(" steps"));
    stepSize_->setToolTip(tr("Steps per click on Step"));

    auto* bar = addToolBar(tr("Run"));
    bar->setObjectName(QStringLiteral("runToolBar"));
    bar->addAction(open_);
    bar->addSeparator();
    bar->addAction(start_);
    bar->addAction(pause_);
    bar->addAction(step_);
    bar->addWidget(stepSize_);
    bar->addAction(stop_);
}

void MainWindow::buildMenus() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(open_);
    file->addAction(saveAs_);
    file->addAction(tr("Open &run file…"), this, &MainWindow::openRunFileDialog);
    file->addAction(tr("&Study…"), this, &MainWindow::showStudyWindow);
    file->addAction(tr("S&tability maps…"), this, [this] {
        showStudyWindow();
        study_->showStabilityTab();
    });
    file->addAction(report_);
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);
    QMenu* run = menuBar()->addMenu(tr("&Run"));
    run->addActions({start_, pause_, step_, stop_});
    if (!maker_) {
        run->addSeparator();
        run->addAction(tr("Write the &next run into…"), this,
                       &MainWindow::chooseNextRunFolderDialog);
        run->addAction(tr("&Runs folder…"), this, &MainWindow::chooseRunsFolderDialog);
    }
    QMenu* view = menuBar()->addMenu(tr("&View"));
    view->addAction(tr("&Fit the cell (0 or Home in the scene)"), scene_, &SceneView::fitToCell);
    QMenu* exports = menuBar()->addMenu(tr("&Export"));
    exports->addAction(tr("&Scene as PNG, SVG or PDF…"), this, &MainWindow::exportSceneDialog);
    QMenu* chartMenu = exports->addMenu(tr("&Chart"));
    for (int k = 0; k < charts_->chartCount(); ++k) {
        chartMenu->addAction(charts_->definition(k).title + QStringLiteral("…"), this,
                             [this, k] { exportChartDialog(k); });
    }
    exports->addAction(tr("Series as &CSV…"), this, &MainWindow::exportCsvDialog);
    exports->addSeparator();
    exports->addAction(tr("&Figure set into a folder…"), this, &MainWindow::exportFigureSetDialog);
    exports->addAction(paraview_);
}

bool MainWindow::openExperiment(const QString& path, QString* error) {
    try {
        setExperiment(readExperimentFile(path.toStdString()));
        return true;
    } catch (const std::exception& e) {
        if (error) {
            *error = QString::fromStdString(e.what());
        }
        return false;
    }
}

void MainWindow::setExperiment(const ExperimentConfig& config) {
    controller_->stop();
    experiment_ = config;
    parameters_->setExperiment(config);
    const QString source =
        config.sourcePath.empty()
            ? QString()
            : QStringLiteral(" — %1").arg(QString::fromStdString(config.sourcePath));
    setWindowTitle(
        QStringLiteral("GrainLab — %1%2").arg(QString::fromStdString(config.name), source));
    viewingFile_ = false;
    startingAssemblyTimer_.stop();
    showStartingAssembly();
}

void MainWindow::showStartingAssembly() {
    const RunState state = controller_->status().state;
    if (state == RunState::Running || state == RunState::Paused || viewingFile_) {
        return;
    }
    startingAssembly_.reset();
    if (parameters_->valid()) {
        try {
            // No output: nothing is written; the runner's first stage is the generated grid.
            const ExperimentRunner runner(parameters_->applied());
            auto snapshot = runner.snapshot();
            snapshot->stage = tr("generated assembly, before Start").toStdString();
            startingAssembly_ = std::move(snapshot);
        } catch (const std::exception&) {
            // Parameters that cannot make an assembly: Start says why (prepareRun).
        }
    }
    scene_->selectGrain(-1);
    scene_->selectVoidCell(-1);
    scene_->setSnapshot(startingAssembly_);
    inspector_->clear();
}

bool MainWindow::prepareRun() {
    if (!parameters_->valid()) {
        showError(parameters_->problem());
        return false;
    }
    if (maker_) {
        const ExperimentConfig config = parameters_->applied();
        RunMaker maker = maker_;
        controller_->setRunFactory([maker, config] { return maker(config); });
        setPictureBudget(config);
        return true;
    }
    // The run is what the edited text says, read back by the experiment-file reader: the run
    // file stores that text, and `grainlab run` on it (or --resume) runs the same experiment.
    ExperimentConfig config;
    try {
        config = editedExperiment(experiment_, parameters_->applied(), experiment_.sourcePath);
    } catch (const std::exception& e) {
        showError(tr("Cannot start: %1").arg(QString::fromStdString(e.what())));
        return false;
    }
    const bool picked = !nextRunFolder_.isEmpty();
    const QString folder = picked ? nextRunFolder_
                                  : datedRunFolder(runsFolder_, QString::fromStdString(config.name),
                                                   QDateTime::currentDateTime());
    nextRunFolder_.clear();
    const std::string path = QDir::cleanPath(folder).toStdString();
    // Called on the worker thread: the folder is claimed and the run file created there.
    controller_->setRunFactory([config, path, picked] {
        return makeRecordedExperimentRun(config, claimRunFolder(path, !picked));
    });
    setPictureBudget(config);
    return true;
}

void MainWindow::setPictureBudget(const ExperimentConfig& config) {
    runEngineThreads_ = engineThreads(config);
    setPictureShare(pictureShare_);
    pictureAtMs_ = -1e300; // the new run's first picture at once
    controller_->setPublishInterval(kFrameMs / 1000.0);
}

void MainWindow::setPictureShare(double share) {
    pictureShare_ = share;
    budget_ = PictureBudget(
        share > 0 ? share : PictureBudget::shareFor(runEngineThreads_, QThread::idealThreadCount()),
        kFrameMs);
}

void MainWindow::startRun() {
    const RunState state = controller_->status().state;
    if (state == RunState::Idle || state == RunState::Failed || state == RunState::Finished) {
        if (state == RunState::Finished) {
            controller_->stop();
        }
        if (!prepareRun()) {
            return;
        }
    }
    error_->clear();
    viewingFile_ = false;
    controller_->start();
    updateControls(RunState::Running);
}

void MainWindow::pauseRun() {
    controller_->pause();
}

void MainWindow::stepRun() {
    const RunState state = controller_->status().state;
    if (state == RunState::Idle || state == RunState::Failed) {
        if (!prepareRun()) {
            return;
        }
    }
    viewingFile_ = false;
    controller_->step(stepSize_->value());
}

void MainWindow::stopRun() {
    controller_->stop();
}

void MainWindow::setRunsFolder(const QString& folder) {
    runsFolder_ = QDir::cleanPath(folder);
    refresh();
}

void MainWindow::setNextRunFolder(const QString& folder) {
    nextRunFolder_ = QDir::cleanPath(folder);
    refresh();
}

QString MainWindow::runFolder() const {
    return QString::fromStdString(controller_->status().runFolder);
}

void MainWindow::chooseRunsFolderDialog() {
    const QString folder = QFileDialog::getExistingDirectory(
        this, tr("Each run gets a new dated folder inside"), runsFolder_);
    if (!folder.isEmpty()) {
        setRunsFolder(folder);
    }
}

void MainWindow::chooseNextRunFolderDialog() {
    const QString folder = QFileDialog::getExistingDirectory(
        this, tr("Write the next run into (a new or empty folder)"), runsFolder_);
    if (!folder.isEmpty()) {
        setNextRunFolder(folder);
    }
}

void MainWindow::showError(const QString& message) {
    error_->setText(message);
    statusBar()->showMessage(message, 10000);
}

void MainWindow::sayEnded(const QString& error, const QString& done) {
    if (error.isEmpty()) {
        statusBar()->showMessage(done, 10000);
    } else {
        showError(error);
    }
}

bool MainWindow::showingError(bool (MainWindow::*action)(const QString&, QString*),
                              const QString& path) {
    QString error;
    if ((this->*action)(path, &error)) {
        return true;
    }
    showError(error);
    return false;
}

void MainWindow::openFromStudy(bool (MainWindow::*open)(const QString&, QString*),
                               const QString& path) {
    showingError(open, path);
    raise();
    activateWindow();
}

void MainWindow::updateControls(RunState state) {
    const bool valid = parameters_->valid();
    const bool hasRun = state == RunState::Running || state == RunState::Paused;
    start_->setEnabled(state != RunState::Running && (hasRun || valid));
    start_->setText(state == RunState::Paused ? tr("Resume") : tr("Start"));
    pause_->setEnabled(state == RunState::Running);
    step_->setEnabled(state != RunState::Running && (hasRun || valid));
    stop_->setEnabled(state != RunState::Idle);
    parameters_->setEnabled(!hasRun);
    open_->setEnabled(state != RunState::Running);
}

void MainWindow::refresh() {
    const RunStatus status = controller_->status();
    const SnapshotPtr latest = controller_->latestSnapshot();
    const auto nowMs = QDateTime::currentMSecsSinceEpoch();
    const bool running = status.state == RunState::Running;
    bool due = true;
    if (running) {
        // The last picture has been painted by now (its paint was queued when it was taken):
        // its whole cost spaces the next. The controller publishes no more often either, so
        // that no picture is copied and measured to be dropped.
        pictureCostMs_ =
            scene_->pictureMs() + 1e3 * (status.snapshotSeconds + status.measureSeconds);
        pictureIntervalMs_ = budget_.intervalMs(pictureCostMs_);
        controller_->setPublishInterval(pictureIntervalMs_ / 1000.0);
        due = double(clock_.elapsed()) + kTickSlackMs >= pictureAtMs_ + pictureIntervalMs_;
    }
    if (latest && latest != shown_ && !viewingFile_ && due) {
        if (running) {
            pictureAtMs_ = double(clock_.elapsed());
            pictureTakenIntervalMs_ = pictureIntervalMs_;
        }
        if (!viewingHistory_) {
            if (shown_ && shown_->step != latest->step) {
                // Indices of grains and void cells refer to the snapshot they were picked in.
                scene_->selectGrain(-1);
                scene_->selectVoidCell(-1);
            }
            scene_->setSnapshot(latest);
        }
        shown_ = latest;
        warning_->setWarnings(latest->warnings);
        std::size_t rows = 0;
        for (const auto& table : latest->series) {
            rows += table.rows.size();
        }
        if (rows != chartedRows_ &&
            (status.state != RunState::Running || nowMs - chartedAtMs_ >= kChartPeriodMs)) {
            updateCharts(latest);
            chartedRows_ = rows;
            chartedAtMs_ = nowMs;
        }
    }
    // The charts follow the live run to the page of its stage (compaction, then the shear
    // tests) when the stage changes page, also when the run ended between two refreshes; the
    // user may pick the other page in between.
    if (!viewingFile_ && (status.state == RunState::Running || status.state == RunState::Paused ||
                          status.state == RunState::Finished)) {
        // A finished run ("done") ends on its results: the first page, the shear tests.
        const QString page = status.state == RunState::Finished
                                 ? charts_->pages().value(0)
                                 : charts_->pageOfStage(status.progress.kind);
        if (!page.isEmpty() && page != chartedPage_) {
            chartedPage_ = page;
            charts_->showPage(page);
        }
    }
    if (status.state != shownState_) {
        shownState_ = status.state;
        updateControls(status.state);
        if (status.state == RunState::Failed) {
            showError(tr("The run failed: %1").arg(QString::fromStdString(status.error)));
        }
    }
    stage_->setText(
        QStringLiteral("%1 · %2 · step %3 · ε1 = %4 %")
            .arg(stateName(status.state),
                 QString::fromStdString(status.progress.stage.empty() ? std::string("–")
                                                                      : status.progress.stage))
            .arg(status.progress.step)
            .arg(100.0 * status.progress.axialStrain, 0, 'f', 3));
    speed_->setText(tr("%1 steps/s · ε1 %2 %/s")
                        .arg(status.stepsPerSecond, 0, 'f', 0)
                        .arg(100.0 * status.strainPerSecond, 0, 'g', 3));
    progress_->setValue(static_cast<int>(1000.0 * std::clamp(status.progress.fraction, 0.0, 1.0)));
    if (!status.runFolder.empty()) {
        const QString folder = QString::fromStdString(status.runFolder);
        runFolder_->setText(tr("run folder: %1").arg(QDir::toNativeSeparators(folder)));
        runFolder_->setToolTip(
            tr("This run writes run.h5 and one series.csv per test here; reopen run.h5 with File "
               "› Open run file, or continue it with: grainlab run --resume \"%1\"")
                .arg(folder));
    } else if (!maker_) {
        const QString next =
            nextRunFolder_.isEmpty()
                ? tr("runs are written under %1").arg(QDir::toNativeSeparators(runsFolder_))
                : tr("the next run is written into %1")
                      .arg(QDir::toNativeSeparators(nextRunFolder_));
        runFolder_->setText(next);
        runFolder_->setToolTip(tr("Change with Run › Runs folder… or Run › Write the next run "
                                  "into…"));
    }
    eta_->setText(tr("ETA %1").arg(status.state == RunState::Running
                                       ? formatDuration(status.etaSeconds)
                                       : QStringLiteral("–")));
}

void MainWindow::updateCharts(const SnapshotPtr& live) {
    std::vector<SeriesTable> tables;
    if (live) {
        tables = live->series;
    }
    if (runFile_) {
        tables.insert(tables.end(), runFile_->series.begin(), runFile_->series.end());
    }
    charts_->setSeries(tables);
}

void MainWindow::chartHovered(double eps1) {
    cursor_->setText(tr("chart: ε1 = %1 %").arg(100.0 * eps1, 0, 'f', 3));
    if (runFile_ && viewingFile_) {
        // With a run file shown, the slider follows the chart cursor to the nearest checkpoint
        // of the test on screen (and stays there).
        if (scene_->snapshot()) {
            const int k = nearestCheckpoint(*runFile_, scene_->snapshot()->test, eps1);
            if (k >= 0) {
                scrub_->setValue(k);
            }
        }
        return;
    }
    // The live run: its kept snapshot of the test on screen nearest the hovered eps1.
    const SnapshotPtr kept =
        controller_->history().nearest(shown_ ? shown_->test : std::string(), eps1);
    if (!kept) {
        return;
    }
    if (kept != scene_->snapshot()) {
        viewingHistory_ = true;
        scene_->selectGrain(-1);
        scene_->selectVoidCell(-1);
        scene_->setSnapshot(kept);
    }
    cursor_->setText(tr("chart: ε1 = %1 % · scene: step %2, ε1 = %3 % (kept snapshot)")
                         .arg(100.0 * eps1, 0, 'f', 3)
                         .arg(kept->step)
                         .arg(100.0 * kept->axialStrain, 0, 'f', 3));
}

void MainWindow::chartHoverEnded() {
    if (!viewingHistory_) {
        return;
    }
    viewingHistory_ = false;
    scene_->selectGrain(-1);
    scene_->selectVoidCell(-1);
    scene_->setSnapshot(shown_);
    cursor_->clear();
}

bool MainWindow::openRunFile(const QString& path, QString* error) {
    try {
        runFile_ = ui::openRunFile(path.toStdString());
    } catch (const std::exception& e) {
        if (error) {
            *error = QString::fromStdString(e.what());
        }
        return false;
    }
    controller_->pause();
    warning_->setWarnings(runFile_->warnings);
    const int count = static_cast<int>(runFile_->checkpoints.size());
    scrubBar_->setVisible(count > 0);
    {
        const QSignalBlocker block(scrub_);
        scrub_->setRange(0, std::max(0, count - 1));
        scrub_->setValue(std::max(0, count - 1));
    }
    updateCharts(controller_->latestSnapshot());
    if (count > 0) {
        showRunFileCheckpoint(count - 1);
    }
    return true;
}

bool MainWindow::openRunFolder(const QString& folder, QString* error) {
    return openRunFile(QDir(folder).filePath(QStringLiteral("run.h5")), error);
}

StudyWindow* MainWindow::studyWindow() {
    if (!study_) {
        study_ = new StudyWindow(this);
        connect(study_, &StudyWindow::openRunFolderRequested, this, [this](const QString& folder) {
            openFromStudy(&MainWindow::openRunFolder, folder);
        });
        connect(study_, &StudyWindow::openExperimentRequested, this,
                [this](const QString& path) { openFromStudy(&MainWindow::openExperiment, path); });
    }
    return study_;
}

void MainWindow::showStudyWindow() {
    studyWindow()->show();
    study_->raise();
    study_->activateWindow();
}

void MainWindow::showRunFileCheckpoint(int index) {
    if (!runFile_ || index < 0 || index >= static_cast<int>(runFile_->checkpoints.size())) {
        return;
    }
    try {
        const SnapshotPtr snapshot = runFileSnapshot(*runFile_, static_cast<std::size_t>(index));
        viewingFile_ = true;
        viewingHistory_ = false;
        scene_->selectGrain(-1);
        scene_->selectVoidCell(-1);
        scene_->setSnapshot(snapshot);
        scrubLabel_->setText(tr("%1 / %2 · %3 · step %4 · ε1 = %5 %")
                                 .arg(index + 1)
                                 .arg(runFile_->checkpoints.size())
                                 .arg(QString::fromStdString(snapshot->stage))
                                 .arg(snapshot->step)
                                 .arg(100.0 * snapshot->axialStrain, 0, 'f', 3));
    } catch (const std::exception& e) {
        showError(QString::fromStdString(e.what()));
    }
}

void MainWindow::openRunFileDialog() {
    const QString path = QFileDialog::getOpenFileName(this, tr("Open run file"), runsFolder_,
                                                      tr("Run files (*.h5)"));
    if (!path.isEmpty()) {
        showingError(&MainWindow::openRunFile, path);
    }
}

void MainWindow::openExperimentDialog() {
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Open experiment"), QString::fromStdString(resourcePath("experiments")),
        tr("Experiment files (*.json)"));
    if (!path.isEmpty()) {
        showingError(&MainWindow::openExperiment, path);
    }
}

} // namespace grainlab::ui
