#pragma once
// The experiment's main parameters, editable before a run: confining pressures, grain count,
// friction during shear and the axial strain target. Values are checked as they are typed; an
// invalid entry is named in red and valid() turns false (the window then refuses to start).
// GUI thread only.

#include <QString>
#include <QWidget>

#include "grainlab/experiment.h"

class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace grainlab::ui {

class ParametersPanel : public QWidget {
    Q_OBJECT
public:
    explicit ParametersPanel(QWidget* parent = nullptr);

    /// Shows the parameters of `config` (kept as the base for applied()).
    void setExperiment(const ExperimentConfig& config);
    /// The base experiment with the edited parameters. Only meaningful when valid().
    ExperimentConfig applied() const;
    bool valid() const { return problem().isEmpty(); }
    /// Why the entries are invalid, or empty.
    QString problem() const;

    QLineEdit* pressuresEdit() const { return pressures_; }
    QSpinBox* grainCountEdit() const { return grains_; }
    QDoubleSpinBox* frictionEdit() const { return friction_; }
    QDoubleSpinBox* strainTargetEdit() const { return strain_; }

signals:
    /// Any entry changed; `valid` tells whether the whole set is usable.
    void edited(bool valid);

private:
    /// Parses "15, 25, 50" [kPa] into ascending pressures [Pa]; empty on error with `why` set.
    std::vector<double> parsePressures(QString* why) const;
    void check();

    ExperimentConfig base_;
    QLineEdit* pressures_;
    QSpinBox* grains_;
    QDoubleSpinBox* friction_;
    QDoubleSpinBox* strain_;
    QLabel* message_;
};

} // namespace grainlab::ui
