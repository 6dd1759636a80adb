#pragma once
// The Study window: opens a study file, chooses its study folder, starts the study as a
// `grainlab study FILE --out DIR` process of this very executable (so it runs exactly as
// headless, and goes on if the window closes), stops it with SIGINT (its runs write checkpoints
// and continue on the next Start), and follows the folder: a timer asks the worker thread to
// read the runs finished since the last look (study_scan.h), and the error-against-cost chart of
// the chosen test and metric fills in as they come. Hovering a point shows its setting and
// numbers; clicking it asks the main window to open that setting's first finished run. The
// figures can be exported, and recommended.json opened in the main window with one click.
// Its second tab is the Stability view (stability_view.h), which does the same for stability maps.
// A top-level window owned by the main window. GUI thread only (its worker thread runs only
// scanStudyFolder()).

#include <memory>
#include <optional>

#include <QTimer>
#include <QWidget>

#include "grainlab/study_plan.h"
#include "gui/folder_command.h"
#include "gui/study_scan.h"

class QComboBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QTabWidget;

namespace grainlab::ui {

class PlotView;
class StabilityView;

class StudyWindow : public FolderScanView<StudyProgress> {
    Q_OBJECT
public:
    /// `grainlab`: the executable that runs `grainlab study` (default: this application's).
    explicit StudyWindow(QWidget* parent = nullptr, QString grainlab = {});
    ~StudyWindow() override;

    /// The executable that runs `grainlab study` and `grainlab stability` (tests give the built
    /// grainlab).
    void setExecutable(const QString& grainlab);

    /// Reads and plans a study file; the study folder becomes defaultStudyFolder(). Returns false
    /// and sets `error` when the file is invalid (the window keeps its previous study).
    bool openStudy(const QString& path, QString* error = nullptr);
    /// Follows `folder` (an existing study folder shows its finished runs at once).
    void setStudyFolder(const QString& folder);
    /// The default study folder: a folder named after the study beside the study file.
    static QString defaultStudyFolder(const QString& studyFile, const StudySpec& spec);

    /// Starts (or continues) the study in its folder. Returns false and sets `error` when there
    /// is no study or it is already running.
    bool start(QString* error = nullptr);

    /// Reads the study folder now (what the timer does while the study runs).
    void rescan();
    /// Writes the study's figures into `folder`; returns the files written.
    QStringList exportFigures(const QString& folder, QString* error = nullptr);
    /// The folder of the first finished run of `setting`, or "" when none has finished.
    QString firstFinishedRunFolder(int setting) const;
    /// The index in plan().settings of the chart's point `point`, or -1.
    int settingOfPoint(int point) const;

    const StudySpec& spec() const { return spec_; }
    const StudyPlan& plan() const { return plan_; }
    QString studyFile() const { return studyFile_; }
    PlotView* chart() const { return chart_; }
    QComboBox* testBox() const { return test_; }
    QComboBox* metricBox() const { return metric_; }
    QPushButton* recommendedButton() const { return recommended_; }
    /// The Stability tab.
    StabilityView* stabilityView() const { return stability_; }
    QTabWidget* tabs() const { return tabs_; }
    /// Brings the Stability tab to the front.
    void showStabilityTab();

signals:
    /// The user asked to see this run folder (runs/<run>/) in the main window.
    void openRunFolderRequested(const QString& folder);
    /// The user asked to load this experiment file (recommended.json) in the main window.
    void openExperimentRequested(const QString& path);
    /// The study folder was read and the chart redrawn.
    void progressChanged();
    /// The study process ended with `exitStatus`.
    void studyEnded(int exitStatus);

private:
    void openStudyDialog();
    void exportFiguresDialog();
    void openRecommended();
    void scanned(std::shared_ptr<const StudyProgress> progress);
    void redraw();
    void fillChoices();
    void updateControls();
    void updateProgressText();
    void showPoint(int point);
    void clickPoint(int point);
    QString logTail() const;

    QString studyFile_;
    StudySpec spec_;
    StudyPlan plan_;
    bool haveStudy_ = false;

    QLabel* fileLabel_;
    QComboBox* test_;
    QComboBox* metric_;
    PlotView* chart_;
    QPushButton* export_;
    QPushButton* recommended_;
    QTabWidget* tabs_;
    StabilityView* stability_;
};

} // namespace grainlab::ui
