// See stability_view.h.
#include "gui/stability_view.h"

#include <algorithm>
#include <cmath>

#include <QComboBox>
#include <QCoreApplication>
#include <QCursor>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QToolTip>
#include <QVBoxLayout>

#include "common/resources.h"
#include "grainlab/ui/heat_map_view.h"
#include "gui/duration_text.h"
#include "gui/stability_map_text.h"
#include "gui/ui_text.h"
#include "gui/window_run_folder.h"

namespace grainlab::ui {
namespace {

const QString kPresetFileItem = QStringLiteral("\x01file"); ///< the box's "Preset file…" item
const QPoint kNoSquare(-1, -1);

QString presetsFolder() {
    return QString::fromStdString(resourcePath("stability"));
}

std::size_t valuesOn(const StabilityMapSpec& spec, StabilityAxis axis) {
    switch (axis) {
    case StabilityAxis::AspectRatio:
        return spec.aspectRatios.size();
    case StabilityAxis::StiffnessRatio:
        return spec.stiffnessRatios.size();
    case StabilityAxis::Damping:
        return spec.dampings.size();
    case StabilityAxis::Packing:
        return spec.packings.size();
    }
    return 0;
}

/// The value a square of the heat map draws for `r` (stability_figures.cpp), NaN for none.
double shownValue(const StabilityCellResult& r, StabilityValue value) {
    if (!(r.estimate > 0)) {
        return NAN;
    }
    return value == StabilityValue::Limit ? r.limit.limit : r.limit.limit / r.estimate;
}

} // namespace

StabilityView::StabilityView(QWidget* parent, QString grainlab)
    : FolderScanView(
          parent, {}, grainlab,
          {tr("Run the map (grainlab stability … --out FOLDER); a stopped map continues where "
              "it stopped"),
           tr("Stop the map: the cells done are kept; Start continues"), tr("cells"),
           tr("Stopping: the running cells end; the cells done are kept…"),
           tr("The map finished. %1"),
           tr("Stopped: the cells done are kept; Start continues the map."),
           tr("The map failed (exit status %1):\n")},
          true) {
    run_.setHooks({[this](QString* error) { return start(error); }, [this] { rescan(); },
                   [this] { updateControls(); }, [this] { updateProgressText(); },
                   [this] { return stabilityLogSummary(run_.logPath()); },
                   [this](int exitStatus) { emit mapEnded(exitStatus); }, [this] { redraw(); }});

    preset_ = new QComboBox;
    preset_->setToolTip(tr("The map Start runs into the folder"));
    preset_->addItem(tr("the folder's map (its stability.json)"), QString());
    for (const QString& name : shippedPresets()) {
        preset_->addItem(name, name);
    }
    preset_->addItem(tr("Preset file…"), kPresetFileItem);
    connect(preset_, &QComboBox::activated, this, &StabilityView::presetChosenInBox);
    presetLabel_ = new QLabel;
    presetLabel_->setWordWrap(true);
    presetLabel_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto* files = new QGridLayout;
    files->addWidget(new QLabel(tr("Map:")), 0, 0);
    files->addWidget(preset_, 0, 1);
    files->addWidget(presetLabel_, 0, 2, 1, 2);
    addFolderRows(
        files,
        {tr("Map folder:"), tr("Open folder…"),
         tr("Map folder (a map to show, or a new or empty folder)"),
         tr("By default a new map goes to stability-<name> in the runs folder. A folder that "
            "holds a map shows it at once, and Start continues it: finished cells are not "
            "redone.")},
        2, [this](const QString& folder) { setMapFolder(folder); });
    folderButton_->setToolTip(tr("A map folder to show and continue, or a new or empty folder "
                                 "for the map to start"));

    xAxis_ = new QComboBox;
    yAxis_ = new QComboBox;
    for (StabilityAxis a : kStabilityAxes) {
        xAxis_->addItem(stabilityAxisTitle(a, true), int(a));
        yAxis_->addItem(stabilityAxisTitle(a, true), int(a));
    }
    xAxis_->setCurrentIndex(lastX_);
    yAxis_->setCurrentIndex(lastY_);
    xAxis_->setToolTip(tr("The axis across the heat map"));
    yAxis_->setToolTip(tr("The axis up the heat map; each square shows the smallest value over "
                          "the other two axes"));
    connect(xAxis_, &QComboBox::currentIndexChanged, this,
            [this] { axisChosen(xAxis_, yAxis_, lastX_); });
    connect(yAxis_, &QComboBox::currentIndexChanged, this,
            [this] { axisChosen(yAxis_, xAxis_, lastY_); });
    value_ = new QComboBox;
    value_->addItem(tr("measured limit (the estimate below)"), int(StabilityValue::Limit));
    value_->addItem(tr("limit / estimate"), int(StabilityValue::LimitOverEstimate));
    connect(value_, &QComboBox::currentIndexChanged, this, &StabilityView::redraw);
    auto* mapRow =
        choicesRow({{tr("Across:"), xAxis_}, {tr("Up:"), yAxis_}, {tr("Show:"), value_}});

    heatMap_ = new HeatMapView;
    heatMap_->setToolTip(tr("Hover or click a square for its cells' numbers"));
    connect(heatMap_, &HeatMapView::cellHovered, this, [this](QPoint square) {
        showSquare(square == kNoSquare ? selected_ : square);
        if (square != kNoSquare && heatMap_->underMouse()) {
            QToolTip::showText(QCursor::pos(), details_->text(), heatMap_);
        }
    });
    connect(heatMap_, &HeatMapView::cellClicked, this, [this](QPoint square) {
        selected_ = square;
        heatMap_->setSelectedCell(square);
        showSquare(square);
    });
    auto* centre = plotWithDetails(heatMap_, {}, 320);

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(files);
    layout->addLayout(run_.row.layout);
    layout->addLayout(mapRow);
    layout->addLayout(centre, 1);
    layout->addWidget(run_.status);

    const QStringList shipped = shippedPresets();
    if (shipped.contains(QStringLiteral("tiny"))) {
        setChoice(QStringLiteral("tiny"), nullptr, true);
    }
    redraw();
    updateControls();
}

StabilityView::~StabilityView() = default; // a running map goes on (its output goes to a file)

QStringList StabilityView::shippedPresets() {
    QStringList names;
    for (const QFileInfo& f :
         QDir(presetsFolder()).entryInfoList({QStringLiteral("*.json")}, QDir::Files, QDir::Name)) {
        names << f.completeBaseName();
    }
    return names;
}

QString StabilityView::defaultMapFolder(const StabilityMapSpec& spec) {
    return QDir::cleanPath(QDir(defaultRunsFolder()).filePath("stability-" + q(spec.name)));
}

QString StabilityView::preset() const {
    return choice_;
}

bool StabilityView::choosePreset(const QString& nameOrFile, QString* error) {
    return setChoice(nameOrFile, error, true);
}

bool StabilityView::setChoice(const QString& nameOrFile, QString* error, bool moveDefaultFolder) {
    if (running()) {
        if (error) {
            *error = tr("A map is running: stop it before choosing another.");
        }
        return false;
    }
    if (nameOrFile.isEmpty()) {
        choice_.clear();
        choiceSpec_ = {};
        preset_->setCurrentIndex(0);
        presetLabel_->setText(tr("Start continues the map the folder holds."));
        updateControls();
        return true;
    }
    const bool shipped = shippedPresets().contains(nameOrFile);
    const QString path = shipped ? QDir(presetsFolder()).filePath(nameOrFile + ".json")
                                 : QFileInfo(nameOrFile).absoluteFilePath();
    StabilityMapSpec spec;
    try {
        spec = readStabilityPreset(path.toStdString());
    } catch (const std::exception& e) {
        if (error) {
            *error = q(e.what());
        }
        return false;
    }
    choice_ = shipped ? nameOrFile : path;
    choiceSpec_ = std::move(spec);
    int item = preset_->findData(choice_);
    if (item < 0) {
        item = preset_->count() - 1; // before "Preset file…"
        preset_->insertItem(item, QFileInfo(path).fileName(), choice_);
    }
    preset_->setCurrentIndex(item);
    presetLabel_->setText(tr("%1: %2 cells (%3 × %4 × %5 × %6)%7")
                              .arg(q(choiceSpec_.name))
                              .arg(stabilityCells(choiceSpec_).size())
                              .arg(choiceSpec_.aspectRatios.size())
                              .arg(choiceSpec_.stiffnessRatios.size())
                              .arg(choiceSpec_.dampings.size())
                              .arg(choiceSpec_.packings.size())
                              .arg(shipped ? QString() : QStringLiteral(", ") + path));
    if (moveDefaultFolder && (folder_.isEmpty() || folderIsDefault_)) {
        followFolder(defaultMapFolder(choiceSpec_), false);
        folderIsDefault_ = true;
    }
    updateControls();
    updateProgressText();
    return true;
}

void StabilityView::presetChosenInBox(int index) {
    const QString data = preset_->itemData(index).toString();
    QString error;
    if (data == kPresetFileItem) {
        const QString path = QFileDialog::getOpenFileName(
            this, tr("Stability preset"), presetsFolder(), tr("Stability presets (*.json)"));
        if (path.isEmpty() || !choosePreset(path, &error)) {
            preset_->setCurrentIndex(std::max(0, preset_->findData(choice_)));
        }
    } else if (!choosePreset(data, &error)) {
        preset_->setCurrentIndex(std::max(0, preset_->findData(choice_)));
    }
    if (!error.isEmpty()) {
        run_.status->setText(error);
    }
}

void StabilityView::setMapFolder(const QString& folder) {
    if (running()) {
        return;
    }
    folderIsDefault_ = false;
    followFolder(folder, true);
}

void StabilityView::followFolder(const QString& folder, bool adoptItsMap) {
    showFolder(folder);
    state_.reset();
    adoptFolderMap_ = adoptItsMap;
    selected_ = kNoSquare;
    heatMap_->setSelectedCell(kNoSquare);
    run_.status->clear();
    run_.newFolder();
}

bool StabilityView::start(QString* error) {
    const auto fail = [error](const QString& message) { return refuseStart(error, message); };
    if (running()) {
        return fail(tr("The map is already running."));
    }
    if (folder_.isEmpty()) {
        return fail(tr("Choose a map folder first."));
    }
    if (state_ && state_->kind == StabilityFolder::Kind::Refused) {
        return fail(q(state_->reason));
    }
    const bool folderMap = state_ && state_->kind == StabilityFolder::Kind::Map;
    if (choice_.isEmpty() && !folderMap) {
        return fail(tr("The folder holds no map yet: choose a preset to start one."));
    }
    QStringList arguments{QStringLiteral("stability")};
    if (choice_.isEmpty()) {
        arguments << QDir(folder_).filePath(QStringLiteral("stability.json"));
    } else if (shippedPresets().contains(choice_)) {
        arguments << QStringLiteral("--preset") << choice_;
    } else {
        arguments << choice_;
    }
    arguments << QStringLiteral("--out") << folder_;
    const std::string name = choice_.isEmpty() ? state_->spec.name : choiceSpec_.name;
    run_.launch(arguments, QStringLiteral("stability-%1").arg(q(name)),
                state_ ? state_->finishedCount() : 0);
    return true;
}

void StabilityView::rescan() {
    if (folder_.isEmpty()) {
        return;
    }
    // Everything the scan needs is copied in: the worker never touches the view.
    scanFolder([folder = folder_.toStdString(),
                previous = state_] { return scanStabilityFolder(folder, previous); },
               [this](std::shared_ptr<const StabilityFolder> next) { scanned(std::move(next)); });
}

void StabilityView::scanned(std::shared_ptr<const StabilityFolder> state) {
    const bool changed = state != state_;
    const bool newMap = state->kind == StabilityFolder::Kind::Map &&
                        (!state_ || state_->kind != StabilityFolder::Kind::Map ||
                         state_->presetText != state->presetText);
    state_ = std::move(state);
    if (changed) {
        switch (state_->kind) {
        case StabilityFolder::Kind::Refused:
            run_.status->setText(q(state_->reason));
            break;
        case StabilityFolder::Kind::Map:
            if (adoptFolderMap_) {
                setChoice(QString(), nullptr, false);
            }
            if (!state_->errors.empty()) {
                run_.status->setText(q(state_->errors.front()));
            }
            break;
        case StabilityFolder::Kind::New:
            if (choice_.isEmpty() && shippedPresets().contains(QStringLiteral("tiny"))) {
                setChoice(QStringLiteral("tiny"), nullptr, false);
            }
            break;
        }
        adoptFolderMap_ = false;
    }
    if (newMap) {
        // The first two axes with more than one value, then the others in order.
        std::vector<StabilityAxis> order;
        for (StabilityAxis a : kStabilityAxes) {
            if (valuesOn(state_->spec, a) > 1) {
                order.push_back(a);
            }
        }
        for (StabilityAxis a : kStabilityAxes) {
            if (valuesOn(state_->spec, a) <= 1) {
                order.push_back(a);
            }
        }
        setAxes(order[0], order[1]);
    }
    if (changed) {
        redraw();
    }
    updateProgressText();
    updateControls();
    emit progressChanged();
}

StabilityAxis StabilityView::xAxis() const {
    return StabilityAxis(xAxis_->currentData().toInt());
}

StabilityAxis StabilityView::yAxis() const {
    return StabilityAxis(yAxis_->currentData().toInt());
}

void StabilityView::setAxes(StabilityAxis x, StabilityAxis y) {
    if (x == y) {
        return;
    }
    {
        const QSignalBlocker blockX(xAxis_);
        const QSignalBlocker blockY(yAxis_);
        xAxis_->setCurrentIndex(xAxis_->findData(int(x)));
        yAxis_->setCurrentIndex(yAxis_->findData(int(y)));
    }
    lastX_ = xAxis_->currentIndex();
    lastY_ = yAxis_->currentIndex();
    redraw();
}

void StabilityView::axisChosen(QComboBox* changed, QComboBox* other, int previous) {
    // The same axis both ways would be a diagonal: the other box takes the axis just left.
    if (changed->currentIndex() == other->currentIndex()) {
        const QSignalBlocker block(other);
        other->setCurrentIndex(previous);
    }
    lastX_ = xAxis_->currentIndex();
    lastY_ = yAxis_->currentIndex();
    redraw();
}

void StabilityView::setValue(StabilityValue value) {
    value_->setCurrentIndex(value_->findData(int(value)));
}

std::vector<int> StabilityView::resultsInSquare(QPoint square) const {
    std::vector<int> out;
    if (!state_ || state_->kind != StabilityFolder::Kind::Map) {
        return out;
    }
    const StabilityAxis x = xAxis(), y = yAxis();
    for (std::size_t i = 0; i < state_->results.size(); ++i) {
        const StabilityCell& c = state_->results[i].cell;
        if (stabilityAxisIndex(state_->spec, x, c) == square.x() &&
            stabilityAxisIndex(state_->spec, y, c) == square.y()) {
            out.push_back(int(i));
        }
    }
    const auto value = StabilityValue(value_->currentData().toInt());
    std::stable_sort(out.begin(), out.end(), [&](int a, int b) {
        const double va = shownValue(state_->results[std::size_t(a)], value);
        const double vb = shownValue(state_->results[std::size_t(b)], value);
        return std::isnan(vb) ? !std::isnan(va) : va < vb; // no value: last
    });
    return out;
}

void StabilityView::redraw() {
    HeatMapPainter map;
    if (!state_) {
        map.title = folder_.isEmpty() ? tr("open a map folder or choose a preset")
                                      : tr("reading the folder…");
    } else if (state_->kind == StabilityFolder::Kind::Map) {
        map = stabilityHeatMap(state_->spec, state_->results, xAxis(), yAxis(),
                               StabilityValue(value_->currentData().toInt()));
    } else if (state_->kind == StabilityFolder::Kind::New) {
        map.title = tr("no map in this folder yet: Start runs the chosen preset into it");
    } else {
        map.title = tr("not a stability map folder (the reason is below)");
    }
    heatMap_->setMap(std::move(map));
    heatMap_->setSelectedCell(selected_);
    selected_ = heatMap_->selectedCell(); // none when the grid no longer has it
    const QPoint hovered = heatMap_->hoveredCell();
    showSquare(hovered != kNoSquare ? hovered : selected_);
}

void StabilityView::updateControls() {
    const bool isRunning = running();
    const bool refused = state_ && state_->kind == StabilityFolder::Kind::Refused;
    const bool folderMap = state_ && state_->kind == StabilityFolder::Kind::Map;
    run_.row.start->setEnabled(!isRunning && !folder_.isEmpty() && state_ && !refused &&
                               (!choice_.isEmpty() || folderMap));
    run_.row.stop->setEnabled(isRunning && !run_.stopping());
    folderButton_->setEnabled(!isRunning);
    preset_->setEnabled(!isRunning);
}

void StabilityView::updateProgressText() {
    const bool folderMap = state_ && state_->kind == StabilityFolder::Kind::Map;
    const int total = folderMap ? int(state_->cells.size())
                                : (choice_.isEmpty() ? 0 : int(stabilityCells(choiceSpec_).size()));
    const int done = folderMap ? state_->finishedCount() : 0;
    run_.row.show(done, total, running(),
                  running() ? stabilityLogProgress(run_.logPath()) : QString());
}

void StabilityView::showSquare(QPoint square) {
    const HeatMapPainter& map = heatMap_->map();
    if (square.x() < 0 || square.y() < 0 || square.x() >= map.xLabels.size() ||
        square.y() >= map.yLabels.size()) {
        details_->setText(tr("Hover or click a square for its cells' numbers."));
        return;
    }
    const QString where = QStringLiteral("%1 = %2, %3 = %4")
                              .arg(stabilityAxisTitle(xAxis(), true), map.xLabels[square.x()],
                                   stabilityAxisTitle(yAxis(), true), map.yLabels[square.y()])
                              .toHtmlEscaped();
    const std::vector<int> cells = resultsInSquare(square);
    if (cells.empty()) {
        details_->setText(tr("%1: no finished cell yet.").arg(where));
        return;
    }
    QString text =
        where + "<br>" + stabilityCellNumbers(state_->results[std::size_t(cells.front())]);
    if (cells.size() > 1) {
        const auto value = StabilityValue(value_->currentData().toInt());
        text +=
            tr("<br><br>Also in this square (%1 cells, the drawn one first):").arg(cells.size());
        for (std::size_t k = 1; k < cells.size(); ++k) {
            const StabilityCellResult& r = state_->results[std::size_t(cells[k])];
            text += QStringLiteral("<br>%1: %2")
                        .arg(q(r.cell.id).toHtmlEscaped(), number(shownValue(r, value)));
        }
    }
    details_->setText(text);
}

void StabilityView::showEvent(QShowEvent* event) {
    run_.shown();
    QWidget::showEvent(event);
}

void StabilityView::hideEvent(QHideEvent* event) {
    run_.hidden();
    QWidget::hideEvent(event);
}

} // namespace grainlab::ui
