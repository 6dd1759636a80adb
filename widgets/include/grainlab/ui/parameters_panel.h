#pragma once
// The experiment's main parameters, editable before a run: which compacted samples are sheared,
// grain count, friction during shear, the axial strain target and the test each sample gets
// (drained, constant volume, constant p or a linear stress path with its slope; a file that lists
// several tests, or a cyclic test, whose keys are the file's, keeps it unless another test is
// chosen). The compaction stages are
// shown, not edited: the panel never changes the experiment behind the user (one pressure list
// for both would turn "compact at 15, 25, 50, 100 kPa, shear at 100 kPa" into one compaction at
// 100 kPa). Values are checked as they are typed, the shear list by the experiment file's own
// rule (shearPressureRule); an invalid entry is named in red and valid() turns false (the window
// then refuses to start). GUI thread only.

#include <vector>

#include <QString>
#include <QWidget>

#include "grainlab/experiment.h"

class QCheckBox;
class QComboBox;
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

    /// The shear tests' confining pressures [kPa], e.g. "15, 100".
    QLineEdit* shearPressuresEdit() const { return shearPressures_; }
    /// The compaction pressures [kPa], shown read-only.
    QLabel* compactionPressuresLabel() const { return compactionPressures_; }
    QSpinBox* grainCountEdit() const { return grains_; }
    QDoubleSpinBox* frictionEdit() const { return friction_; }
    QDoubleSpinBox* strainTargetEdit() const { return strain_; }
    /// The test's kind: "drained", "constant_volume", "constant_p", "stress_path" (item data),
    /// and first "as in the file" when the file lists several tests or a cyclic one.
    QComboBox* testKindEdit() const { return testKind_; }
    /// The stress path's slope a (enabled for a stress path only).
    QDoubleSpinBox* pathSlopeEdit() const { return slope_; }
    QCheckBox* extensionEdit() const { return extension_; }

signals:
    /// Any entry changed; `valid` tells whether the whole set is usable.
    void edited(bool valid);

private:
    /// Parses the shear list "100, 15" [kPa] into pressures [Pa] and checks it against the
    /// compaction pressures; empty on error with `why` set.
    std::vector<double> parseShearPressures(QString* why) const;
    void check();

    ExperimentConfig base_;
    QLabel* compactionPressures_;
    QLineEdit* shearPressures_;
    QSpinBox* grains_;
    QDoubleSpinBox* friction_;
    QDoubleSpinBox* strain_;
    QComboBox* testKind_;
    QDoubleSpinBox* slope_;
    QCheckBox* extension_;
    QLabel* message_;
};

} // namespace grainlab::ui
