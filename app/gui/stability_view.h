#pragma once
// The Stability view, a tab of the Study window: follows a stability map folder (what
// `grainlab stability --out DIR` writes, docs/stability.md) and draws its heat maps as the cells
// finish; starts a map from a preset (a shipped one or a file) as a `grainlab stability ...
// --out DIR` process of this very executable (so it runs exactly as headless, and goes on if the
// window closes), stops it with SIGINT (the cells done are kept; Start continues the map). A
// timer asks the worker thread to read the cells finished since the last look
// (stability_scan.h); the heat map of the measured limit (or of limit / estimate) over the two
// axes chosen fills in, each square the smallest over the other two axes, as in the written
// figures (stability_figures.h). Hovering or clicking a square shows its cells' numbers. GUI
// thread only (its worker thread runs only scanStabilityFolder()).

#include <memory>
#include <optional>
#include <vector>

#include <QPoint>
#include <QTimer>
#include <QWidget>

#include "grainlab/ui/stability_figures.h"
#include "gui/folder_command.h"
#include "gui/stability_scan.h"

class QComboBox;
class QLabel;
class QProgressBar;
class QPushButton;

namespace grainlab::ui {

class HeatMapView;

class StabilityView : public FolderScanView<StabilityFolder> {
    Q_OBJECT
public:
    /// `grainlab`: the executable that runs `grainlab stability` (default: this application's).
    explicit StabilityView(QWidget* parent = nullptr, QString grainlab = {});
    ~StabilityView() override;

    /// The executable that runs `grainlab stability` (tests give the built grainlab).
    void setExecutable(const QString& grainlab) { run_.grainlab = grainlab; }

    /// The names of the shipped presets (resources/stability/*.json), e.g. "full", "tiny".
    static QStringList shippedPresets();
    /// The folder a new map of `spec` goes to unless another is chosen: "stability-<name>" in
    /// the window's runs folder.
    static QString defaultMapFolder(const StabilityMapSpec& spec);

    /// Chooses the map Start runs: a shipped preset's name, a preset file, or "" for the map the
    /// folder holds (its own stability.json). A preset is read and checked at once; returns
    /// false and sets `error` when it is invalid (the previous choice stays). While the folder
    /// is a default one, it follows the preset (defaultMapFolder()).
    bool choosePreset(const QString& nameOrFile, QString* error = nullptr);
    /// The current choice: a shipped preset's name, a file, or "" (the folder's map).
    QString preset() const;
    /// Follows `folder`: a map in it shows at once, and becomes what Start continues; a folder
    /// holding something else is refused, the reason in statusLabel().
    void setMapFolder(const QString& folder);

    /// Starts (or continues) the map in the folder. Returns false and sets `error` when there is
    /// nothing to start, the folder is refused, or a map is running.
    bool start(QString* error = nullptr);

    /// Reads the folder now (what the timer does while the view is shown or a map runs).
    void rescan();

    /// The axes of the heat map (across, up); equal axes are refused (nothing changes).
    void setAxes(StabilityAxis x, StabilityAxis y);
    StabilityAxis xAxis() const;
    StabilityAxis yAxis() const;
    /// What the heat map shows.
    void setValue(StabilityValue value);
    /// The finished cells drawn in square `cell` (column, row) of the heat map, as indices into
    /// folderState()->results, the one whose value is drawn (the smallest) first.
    std::vector<int> resultsInSquare(QPoint cell) const;

    HeatMapView* heatMap() const { return heatMap_; }
    QComboBox* presetBox() const { return preset_; }
    QComboBox* xAxisBox() const { return xAxis_; }
    QComboBox* yAxisBox() const { return yAxis_; }
    QComboBox* valueBox() const { return value_; }

signals:
    /// The folder was read and the heat map redrawn.
    void progressChanged();
    /// The map process ended with `exitStatus`.
    void mapEnded(int exitStatus);

protected:
    void showEvent(QShowEvent* event) override;
    void hideEvent(QHideEvent* event) override;

private:
    void followFolder(const QString& folder, bool adoptItsMap);
    bool setChoice(const QString& nameOrFile, QString* error, bool moveDefaultFolder);
    void presetChosenInBox(int index);
    void scanned(std::shared_ptr<const StabilityFolder> state);
    void redraw();
    void updateControls();
    void updateProgressText();
    void showSquare(QPoint cell);
    void axisChosen(QComboBox* changed, QComboBox* other, int previous);

    QString choice_;               ///< what Start runs: a shipped name, a file, "" (the folder's)
    StabilityMapSpec choiceSpec_;  ///< the preset chosen (unset for "")
    bool folderIsDefault_ = false; ///< the folder follows the preset chosen
    bool adoptFolderMap_ = false;  ///< the next scan that finds a map makes it the choice
    QPoint selected_{-1, -1};      ///< the square clicked last
    int lastX_ = 0, lastY_ = 3;    ///< the axes' combo indices before the latest change

    QComboBox* preset_;
    QLabel* presetLabel_;
    QComboBox* xAxis_;
    QComboBox* yAxis_;
    QComboBox* value_;
    HeatMapView* heatMap_;
};

} // namespace grainlab::ui
