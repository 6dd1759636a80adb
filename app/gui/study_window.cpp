// See study_window.h.
#include "gui/study_window.h"

#include <cmath>

#include <QComboBox>
#include <QCoreApplication>
#include <QCursor>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QTabWidget>
#include <QToolTip>
#include <QVBoxLayout>

#include "common/resources.h"
#include "grainlab/study_file.h"
#include "grainlab/ui/plot_view.h"
#include "grainlab/ui/study_figures.h"
#include "gui/duration_text.h"
#include "gui/stability_view.h"
#include "gui/ui_text.h"

namespace grainlab::ui {
namespace {

/// Sets the items of `box` to `items`, keeping the current choice when it is still there.
void setItems(QComboBox* box, const QStringList& items) {
    QStringList now;
    for (int k = 0; k < box->count(); ++k) {
        now << box->itemText(k);
    }
    if (now == items) {
        return;
    }
    const QSignalBlocker block(box);
    const QString current = box->currentText();
    box->clear();
    box->addItems(items);
    const int k = box->findText(current);
    box->setCurrentIndex(k >= 0 ? k : 0);
}

} // namespace

StudyWindow::StudyWindow(QWidget* parent, QString grainlab)
    : FolderScanView(
          parent, Qt::Window, grainlab,
          {tr("Run the study (grainlab study FILE --out FOLDER); a stopped study continues "
              "where it stopped"),
           tr("Stop the study: its runs write checkpoints; Start continues"), tr("runs"),
           tr("Stopping: the runs write their checkpoints…"), tr("The study finished. %1"),
           tr("Stopped: the runs wrote checkpoints; Start continues the study."),
           tr("The study failed (exit status %1): ")},
          false) {
    setWindowTitle(tr("GrainLab — Study"));
    run_.setHooks({[this](QString* error) { return start(error); }, [this] { rescan(); },
                   [this] { updateControls(); }, [this] { updateProgressText(); },
                   [this] { return logTail(); },
                   [this](int exitStatus) { emit studyEnded(exitStatus); }, [this] { redraw(); }});

    fileLabel_ = new QLabel(tr("no study open"));
    fileLabel_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto* openButton = new QPushButton(tr("Open study…"));
    connect(openButton, &QPushButton::clicked, this, &StudyWindow::openStudyDialog);
    auto* files = new QGridLayout;
    files->addWidget(new QLabel(tr("Study file:")), 0, 0);
    files->addWidget(fileLabel_, 0, 1);
    files->addWidget(openButton, 0, 2);
    addFolderRows(files,
                  {tr("Study folder:"), tr("Choose…"), tr("Study folder"),
                   tr("By default a folder named after the study beside the study file. A "
                      "folder that already holds this study is continued: finished runs are not "
                      "redone.")},
                  1, [this](const QString& folder) { setStudyFolder(folder); });

    test_ = new QComboBox;
    test_->setToolTip(tr("The shear test (confining pressure) charted"));
    metric_ = new QComboBox;
    metric_->setToolTip(tr("The metric whose error is charted against the cost"));
    connect(test_, &QComboBox::currentIndexChanged, this, &StudyWindow::redraw);
    connect(metric_, &QComboBox::currentIndexChanged, this, &StudyWindow::redraw);
    export_ = new QPushButton(tr("Export figures…"));
    connect(export_, &QPushButton::clicked, this, &StudyWindow::exportFiguresDialog);
    recommended_ = new QPushButton(tr("Open recommended.json"));
    recommended_->setToolTip(tr("Load the recommended setting as the main window's experiment"));
    connect(recommended_, &QPushButton::clicked, this, &StudyWindow::openRecommended);
    auto* chartRow = choicesRow({{tr("Test:"), test_}, {tr("Metric:"), metric_}});
    chartRow->addWidget(export_);
    chartRow->addWidget(recommended_);

    chart_ = new PlotView;
    chart_->setToolTip(tr("Hover a point for its setting; click it to open its first finished "
                          "run in the main window"));
    connect(chart_, &PlotView::pointHovered, this, &StudyWindow::showPoint);
    connect(chart_, &PlotView::pointClicked, this, &StudyWindow::clickPoint);
    auto* centre = plotWithDetails(chart_, tr("Hover a point for its setting and numbers."), 300);

    auto* studyTab = new QWidget;
    auto* layout = new QVBoxLayout(studyTab);
    layout->addLayout(files);
    layout->addLayout(run_.row.layout);
    layout->addLayout(chartRow);
    layout->addLayout(centre, 1);
    layout->addWidget(run_.status);
    stability_ = new StabilityView(nullptr, run_.grainlab);
    tabs_ = new QTabWidget;
    tabs_->addTab(studyTab, tr("Study"));
    tabs_->addTab(stability_, tr("Stability"));
    auto* outer = new QVBoxLayout(this);
    outer->setContentsMargins(4, 4, 4, 4);
    outer->addWidget(tabs_);
    resize(1100, 720);
    redraw();
    updateControls();
}

StudyWindow::~StudyWindow() = default; // a running study goes on (its output goes to a file)

void StudyWindow::setExecutable(const QString& grainlab) {
    run_.grainlab = grainlab;
    stability_->setExecutable(grainlab);
}

void StudyWindow::showStabilityTab() {
    tabs_->setCurrentWidget(stability_);
}

QString StudyWindow::defaultStudyFolder(const QString& studyFile, const StudySpec& spec) {
    return QDir::cleanPath(QFileInfo(studyFile).absoluteDir().filePath(q(spec.name)));
}

bool StudyWindow::openStudy(const QString& path, QString* error) {
    if (running()) {
        if (error) {
            *error = tr("A study is running: stop it before opening another.");
        }
        return false;
    }
    StudySpec spec;
    StudyPlan plan;
    try {
        spec = readStudyFile(path.toStdString());
        plan = planStudy(spec);
    } catch (const std::exception& e) {
        if (error) {
            *error = QString::fromStdString(e.what());
        }
        return false;
    }
    spec_ = std::move(spec);
    plan_ = std::move(plan);
    haveStudy_ = true;
    studyFile_ = QFileInfo(path).absoluteFilePath();
    fileLabel_->setText(tr("%1 — %2: %3 settings × %4 seeds = %5 runs")
                            .arg(studyFile_, q(spec_.name))
                            .arg(plan_.settings.size())
                            .arg(spec_.seeds.size())
                            .arg(plan_.runs.size()));
    setWindowTitle(tr("GrainLab — Study %1").arg(q(spec_.name)));
    // Metrics: the deciding ones first, then the others with a tolerance; more join from the
    // summary once runs have finished.
    QStringList metrics;
    for (const std::string& m : spec_.deciding) {
        metrics << q(m);
    }
    for (const auto& [m, tolerance] : spec_.tolerances) {
        if (!metrics.contains(q(m))) {
            metrics << q(m);
        }
    }
    {
        const QSignalBlocker blockMetric(metric_);
        const QSignalBlocker blockTest(test_);
        metric_->clear();
        metric_->addItems(metrics);
        test_->clear();
    }
    run_.status->clear();
    setStudyFolder(defaultStudyFolder(studyFile_, spec_));
    return true;
}

void StudyWindow::setStudyFolder(const QString& folder) {
    if (running()) {
        return;
    }
    showFolder(folder);
    state_.reset();
    run_.newFolder();
}

bool StudyWindow::start(QString* error) {
    const auto fail = [error](const QString& message) { return refuseStart(error, message); };
    if (!haveStudy_) {
        return fail(tr("Open a study file first."));
    }
    if (running()) {
        return fail(tr("The study is already running."));
    }
    run_.launch({QStringLiteral("study"), studyFile_, QStringLiteral("--out"), folder_},
                QStringLiteral("study-%1").arg(q(spec_.name)),
                state_ ? state_->finishedCount() : 0);
    return true;
}

QString StudyWindow::logTail() const {
    QFile file(run_.logPath());
    if (!file.open(QIODevice::ReadOnly)) {
        return {};
    }
    // What the study itself said (its recommendation, a failed run), not its progress lines.
    QStringList said;
    for (const QString& line : QString::fromUtf8(file.readAll()).split('\n', Qt::SkipEmptyParts)) {
        if (line.startsWith(QStringLiteral("grainlab")) && !line.contains("settings x")) {
            said << line;
        } else if (line.startsWith(QStringLiteral("  "))) {
            said << line; // a failed run, listed under its heading
        }
    }
    return said.mid(std::max<qsizetype>(0, said.size() - 4)).join(QStringLiteral("\n"));
}

void StudyWindow::rescan() {
    if (!haveStudy_ || folder_.isEmpty()) {
        return;
    }
    // Everything the scan needs is copied in: the worker never touches the window.
    scanFolder([folder = folder_.toStdString(), spec = spec_, plan = plan_,
                previous = state_] { return scanStudyFolder(folder, spec, plan, previous); },
               [this](std::shared_ptr<const StudyProgress> next) { scanned(std::move(next)); });
}

void StudyWindow::scanned(std::shared_ptr<const StudyProgress> progress) {
    const bool changed = progress != state_;
    state_ = std::move(progress);
    if (!state_->errors.empty()) {
        run_.status->setText(q(state_->errors.front()));
    }
    if (changed) {
        fillChoices();
        redraw();
    }
    updateProgressText();
    updateControls();
    emit progressChanged();
}

void StudyWindow::fillChoices() {
    if (!state_) {
        return;
    }
    QStringList tests;
    for (const std::string& t : state_->summary.tests) {
        tests << q(t);
    }
    setItems(test_, tests);
    QStringList metrics;
    for (int k = 0; k < metric_->count(); ++k) {
        metrics << metric_->itemText(k);
    }
    for (const SettingSummary& s : state_->summary.settings) {
        for (const MetricSummary& m : s.metrics) {
            if (!metrics.contains(q(m.metric))) {
                metrics << q(m.metric);
            }
        }
    }
    setItems(metric_, metrics);
}

void StudyWindow::redraw() {
    PlotPainter plot;
    if (state_ && !state_->results.empty() && test_->count() > 0 && metric_->count() > 0) {
        plot = errorCostPlot(spec_, plan_, state_->summary, test_->currentText().toStdString(),
                             metric_->currentText().toStdString());
    } else {
        plot.title = haveStudy_ ? tr("no finished runs yet") : tr("open a study file");
    }
    chart_->setPlot(std::move(plot));
    if (chart_->hoveredPoint() >= 0) {
        showPoint(chart_->hoveredPoint());
    }
}

void StudyWindow::updateControls() {
    const bool isRunning = running();
    run_.row.start->setEnabled(haveStudy_ && !isRunning);
    run_.row.stop->setEnabled(isRunning);
    folderButton_->setEnabled(haveStudy_ && !isRunning);
    export_->setEnabled(state_ && !state_->results.empty());
    recommended_->setEnabled(!folder_.isEmpty() &&
                             QFileInfo::exists(QDir(folder_).filePath("recommended.json")));
}

void StudyWindow::updateProgressText() {
    run_.row.show(state_ ? state_->finishedCount() : 0, int(plan_.runs.size()), running());
}

int StudyWindow::settingOfPoint(int point) const {
    const auto& points = chart_->plot().points;
    if (point < 0 || point >= int(points.size())) {
        return -1;
    }
    for (std::size_t k = 0; k < plan_.settings.size(); ++k) {
        if (q(plan_.settings[k].id) == points[std::size_t(point)].label) {
            return int(k);
        }
    }
    return -1;
}

QString StudyWindow::firstFinishedRunFolder(int setting) const {
    if (!state_) {
        return {};
    }
    for (std::size_t i = 0; i < plan_.runs.size(); ++i) {
        if (plan_.runs[i].setting == setting && state_->finished[i]) {
            return QDir(folder_).filePath(QStringLiteral("runs/") + q(plan_.runs[i].id));
        }
    }
    return {};
}

void StudyWindow::showPoint(int point) {
    const int setting = settingOfPoint(point);
    if (setting < 0 || !state_) {
        details_->setText(tr("Hover a point for its setting and numbers."));
        return;
    }
    const StudySetting& st = plan_.settings[std::size_t(setting)];
    const SettingSummary& s = state_->summary.settings[std::size_t(setting)];
    const std::string test = test_->currentText().toStdString();
    const std::string metric = metric_->currentText().toStdString();
    QStringList lines;
    QString head = QStringLiteral("<b>%1</b>").arg(q(st.id).toHtmlEscaped());
    if (st.isReference) {
        head += tr(" (the reference)");
    }
    if (state_->summary.recommended == setting) {
        head += tr(" (recommended)");
    }
    lines << head;
    for (const auto& [kind, level] : st.levels) {
        lines << QStringLiteral("%1 = %2").arg(q(knobName(kind)), q(level.label()).toHtmlEscaped());
    }
    lines << tr("runs finished: %1 of %2").arg(s.runsDone).arg(spec_.seeds.size());
    if (const MetricSummary* m = findMetricSummary(s, test, metric)) {
        lines << tr("%1 at %2: %3 ± %4 %5")
                     .arg(q(metric), q(test), number(m->scatter.mean), number(m->scatter.sd),
                          m->unit == "-" ? QString() : q(m->unit));
        lines << tr("error: %1").arg(m->error ? number(*m->error) : QStringLiteral("–"));
        lines << tr("noise (2σ of the reference): %1 · within: %2")
                     .arg(m->noise ? number(*m->noise) : QStringLiteral("–"),
                          yesNo(m->withinNoise));
        if (m->withinTolerance) {
            lines << tr("within tolerance: %1").arg(yesNo(*m->withinTolerance));
        }
    }
    lines << tr("cost (%1): %2 ± %3")
                 .arg(q(spec_.costMeasure), number(s.cost.mean), number(s.cost.sd));
    lines << tr("wall time per run: %1 s · processor time: %2 s")
                 .arg(number(s.wallSeconds.mean), number(s.cpuSeconds.mean));
    lines << tr("speed-up over the reference: %1")
                 .arg(s.speedUp ? QStringLiteral("%1×").arg(*s.speedUp, 0, 'f', 2)
                                : QStringLiteral("–"));
    lines << tr("valid (within tolerance on every deciding metric): %1").arg(yesNo(s.valid));
    lines << tr("<i>Click to open its first finished run in the main window.</i>");
    const QString text = lines.join(QStringLiteral("<br>"));
    details_->setText(text);
    if (chart_->underMouse()) {
        QToolTip::showText(QCursor::pos(), text, chart_);
    }
}

void StudyWindow::clickPoint(int point) {
    const int setting = settingOfPoint(point);
    if (setting < 0) {
        return;
    }
    const QString folder = firstFinishedRunFolder(setting);
    if (folder.isEmpty()) {
        run_.status->setText(
            tr("%1: no finished run yet").arg(q(plan_.settings[std::size_t(setting)].id)));
        return;
    }
    emit openRunFolderRequested(folder);
}

QStringList StudyWindow::exportFigures(const QString& folder, QString* error) {
    if (!state_ || state_->results.empty()) {
        if (error) {
            *error = tr("No finished runs to draw yet.");
        }
        return {};
    }
    if (!QDir().mkpath(folder)) {
        if (error) {
            *error = tr("%1: cannot create the folder").arg(folder);
        }
        return {};
    }
    return writeStudyFigures(folder, spec_, plan_, state_->results, state_->summary, error);
}

void StudyWindow::openStudyDialog() {
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Open study"), QString::fromStdString(resourcePath("studies")),
        tr("Study files (*.json)"));
    QString error;
    if (!path.isEmpty() && !openStudy(path, &error)) {
        run_.status->setText(error);
    }
}

void StudyWindow::exportFiguresDialog() {
    const QString folder =
        QFileDialog::getExistingDirectory(this, tr("Export the study's figures into"), folder_);
    if (folder.isEmpty()) {
        return;
    }
    QString error;
    const QStringList files = exportFigures(folder, &error);
    run_.status->setText(
        error.isEmpty() ? tr("%1 files written into %2").arg(files.size()).arg(folder) : error);
}

void StudyWindow::openRecommended() {
    const QString path = QDir(folder_).filePath(QStringLiteral("recommended.json"));
    if (QFileInfo::exists(path)) {
        emit openExperimentRequested(path);
    }
}

} // namespace grainlab::ui
