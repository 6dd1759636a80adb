// See main_window.h: the window's files: Save experiment as…, Report…, and the exports (the
// scene, a chart, the series as CSV, the figure set with the report's figures, the ParaView
// files).
#include "gui/main_window.h"

#include <QCoreApplication>
#include <QDesktopServices>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QStatusBar>
#include <QUrl>

#include "common/atomic_file.h"
#include "grainlab/csv_series.h"
#include "grainlab/ui/charts_panel.h"
#include "grainlab/ui/figure_export.h"
#include "grainlab/ui/parameters_panel.h"
#include "grainlab/ui/scene_view.h"
#include "gui/command_process.h"
#include "gui/edited_experiment.h"
#include "gui/report_job.h"

namespace grainlab::ui {

QString MainWindow::reportSource() const {
    if (viewingFile_ && runFile_) {
        return QFileInfo(QString::fromStdString(runFile_->path)).absolutePath();
    }
    return runFolder();
}

QString MainWindow::reportRefusal() const {
    if (reportSource().isEmpty()) {
        return tr("there is no run to report on: run an experiment or open a run file first");
    }
    const RunState state = controller_->status().state;
    if (!(viewingFile_ && runFile_) && (state == RunState::Running || state == RunState::Paused)) {
        return tr("the run is still going, and its run file is read once it has stopped or "
                  "finished");
    }
    return {};
}

QString MainWindow::grainlabExecutable() const {
    return grainlab_.isEmpty() ? QCoreApplication::applicationFilePath() : grainlab_;
}

void MainWindow::writeReport() {
    if (const QString why = reportRefusal(); !why.isEmpty()) {
        showError(tr("No report now: %1.").arg(why));
        return;
    }
    const QString source = reportSource();
    const QString out = QDir(source).filePath(QStringLiteral("report"));
    if (!reportJob_->start(grainlabExecutable(), source, out)) {
        showError(tr("A report is being written already."));
        return;
    }
    report_->setEnabled(false);
    statusBar()->showMessage(tr("Writing the report into %1…").arg(out));
}

void MainWindow::reportEnded(const QString& out, const QString& error) {
    report_->setEnabled(true);
    if (!error.isEmpty()) {
        showError(error);
        return;
    }
    const QString html = QDir(out).filePath(QStringLiteral("report.html"));
    statusBar()->showMessage(tr("Report written: %1").arg(html), 10000);
    QDesktopServices::openUrl(QUrl::fromLocalFile(html));
    emit reportWritten(html);
}

QString MainWindow::editedExperimentText(QString* error) const {
    try {
        if (!parameters_->valid()) {
            throw std::runtime_error(parameters_->problem().toStdString());
        }
        const ExperimentConfig edited =
            editedExperiment(experiment_, parameters_->applied(), experiment_.sourcePath);
        return QString::fromStdString(edited.sourceText);
    } catch (const std::exception& e) {
        if (error) {
            *error = QString::fromStdString(e.what());
        }
        return {};
    }
}

bool MainWindow::saveExperimentAs(const QString& path, QString* error) {
    QString why;
    const QString text = editedExperimentText(&why);
    if (text.isEmpty()) {
        if (error) {
            *error = tr("Save experiment: %1").arg(why);
        }
        return false;
    }
    try {
        writeFileAtomically(path.toStdString(), text.toStdString());
    } catch (const std::exception& e) {
        if (error) {
            *error = QString::fromStdString(e.what());
        }
        return false;
    }
    return true;
}

void MainWindow::saveExperimentDialog() {
    const QFileInfo source(QString::fromStdString(experiment_.sourcePath));
    const QString suggested =
        (source.fileName().isEmpty() ? QDir::current() : source.dir())
            .filePath(QString::fromStdString(experiment_.name) + QStringLiteral("-edited.json"));
    const QString path = QFileDialog::getSaveFileName(this, tr("Save experiment as"), suggested,
                                                      tr("Experiment files (*.json)"));
    if (!path.isEmpty() && showingError(&MainWindow::saveExperimentAs, path)) {
        statusBar()->showMessage(tr("Experiment saved to %1").arg(path), 8000);
    }
}

QStringList MainWindow::exportFigureSet(const QString& folder, QString* error) {
    const SnapshotPtr snapshot = scene_->snapshot();
    static const std::vector<SeriesTable> none;
    QString failure;
    error = error ? error : &failure;
    const QStringList files =
        ui::exportFigureSet(folder, scene_, charts_, snapshot ? snapshot->series : none, {}, error);
    if (!error->isEmpty()) {
        return files;
    }
    // The report's figures are drawn from the run file by `grainlab report`, the code of
    // Report…: a run still going has its run file open for writing, so they wait for its end.
    QString why = reportRefusal();
    const QString out = QDir(folder).filePath(QStringLiteral("report"));
    if (why.isEmpty() && !figureSetJob_->start(grainlabExecutable(), reportSource(), out)) {
        why = tr("the report's figures of an earlier figure set are still being written");
    }
    if (!why.isEmpty()) {
        figureSetEnded(folder, tr("%1 files written to %2, without the report's figures: %3.")
                                   .arg(files.size())
                                   .arg(folder, why));
        return files;
    }
    statusBar()->showMessage(tr("%1 files written to %2; writing the report's figures into %3…")
                                 .arg(files.size())
                                 .arg(folder, out));
    return files;
}

void MainWindow::figureSetEnded(const QString& folder, const QString& note) {
    sayEnded(note,
             tr("Figure set written to %1 (the report's figures in report/figures/)").arg(folder));
    emit figureSetWritten(folder, note);
}

void MainWindow::exportSceneDialog() {
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Export the scene"), QStringLiteral("scene.png"),
        tr("PNG image (*.png);;SVG drawing (*.svg);;PDF document (*.pdf)"));
    QString error;
    if (!path.isEmpty() && !exportScene(*scene_, path, scene_->size() * 2, &error)) {
        showError(error);
    }
}

void MainWindow::exportChartDialog(int chart) {
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Export the chart"), charts_->definition(chart).name + QStringLiteral(".png"),
        tr("PNG image (*.png);;SVG drawing (*.svg);;PDF document (*.pdf)"));
    QString error;
    if (!path.isEmpty() && !charts_->exportChart(chart, path, QSize(1200, 800), &error)) {
        showError(error);
    }
}

void MainWindow::exportCsvDialog() {
    const QString folder = QFileDialog::getExistingDirectory(this, tr("Write the series into"));
    if (folder.isEmpty() || !scene_->snapshot()) {
        return;
    }
    for (const SeriesTable& table : scene_->snapshot()->series) {
        try {
            writeSeriesCsv(
                table,
                QDir(folder).filePath(QString::fromStdString(table.test) + ".csv").toStdString());
        } catch (const std::exception& e) {
            showError(QString::fromStdString(e.what()));
            return;
        }
    }
}

void MainWindow::exportFigureSetDialog() {
    const QString folder = QFileDialog::getExistingDirectory(this, tr("Write the figure set into"));
    if (folder.isEmpty()) {
        return;
    }
    QString error;
    exportFigureSet(folder, &error); // the status bar says how far it got
    if (!error.isEmpty()) {
        showError(error);
    }
}

void MainWindow::writeParaViewFiles(const QString& out) {
    QString why = reportRefusal();
    if (why.isEmpty() && paraviewExport_->running()) {
        why = tr("ParaView files are being written already");
    }
    if (!why.isEmpty()) {
        showError(tr("No ParaView files now: %1.").arg(why));
        emit paraviewFilesWritten(out, why);
        return;
    }
    // The same export as `grainlab export vtk`, in a process of its own: the window goes on. A
    // stopped run has not finished, and the user asked for what it has.
    paraviewOut_ = out;
    const QStringList arguments{QStringLiteral("export"),
                                QStringLiteral("vtk"),
                                reportSource(),
                                QStringLiteral("--out"),
                                out,
                                QStringLiteral("--unfinished"),
                                QStringLiteral("--quiet")};
    if (!paraviewExport_->start(grainlabExecutable(), arguments)) {
        showError(tr("ParaView files are being written already."));
        return;
    }
    paraview_->setEnabled(false);
    statusBar()->showMessage(tr("Writing ParaView files into %1…").arg(out));
}

void MainWindow::paraviewEnded(int exitStatus, const QString& output, const QString& startError) {
    paraview_->setEnabled(true);
    QString error;
    if (!startError.isEmpty()) {
        error = tr("The ParaView export could not start: %1").arg(startError);
    } else if (exitStatus != 0) {
        error = tr("No ParaView files written: %1").arg(output.trimmed());
    }
    sayEnded(error,
             tr("ParaView files written: open the .pvd files of %1 in ParaView").arg(paraviewOut_));
    emit paraviewFilesWritten(paraviewOut_, error);
}

void MainWindow::exportParaViewDialog() {
    const QString source = reportSource();
    const QString suggested = source.isEmpty()
                                  ? QDir::current().filePath(QStringLiteral("paraview"))
                                  : source + QStringLiteral("-paraview");
    const QString out = QFileDialog::getSaveFileName(
        this, tr("Write ParaView files into a new folder"), suggested, QString(), nullptr,
        QFileDialog::ShowDirsOnly | QFileDialog::DontConfirmOverwrite);
    if (!out.isEmpty()) {
        writeParaViewFiles(out);
    }
}

} // namespace grainlab::ui
