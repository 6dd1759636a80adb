// See parameters_panel.h.
#include "grainlab/ui/parameters_panel.h"

#include <cmath>

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QSpinBox>

namespace grainlab::ui {

ParametersPanel::ParametersPanel(QWidget* parent)
    : QWidget(parent), pressures_(new QLineEdit(this)), grains_(new QSpinBox(this)),
      friction_(new QDoubleSpinBox(this)), strain_(new QDoubleSpinBox(this)),
      message_(new QLabel(this)) {
    auto* form = new QFormLayout(this);
    form->setContentsMargins(4, 4, 4, 4);
    pressures_->setToolTip(tr("Confining pressures in kPa, ascending, separated by commas. Each "
                              "is a compaction stage and a shear test."));
    grains_->setRange(4, 1000000);
    grains_->setToolTip(tr("Number of grains (the reference study uses 8450)."));
    friction_->setRange(0.0, 2.0);
    friction_->setDecimals(3);
    friction_->setSingleStep(0.05);
    friction_->setToolTip(tr("Inter-particle friction coefficient μ during shear."));
    strain_->setRange(0.01, 50.0);
    strain_->setDecimals(2);
    strain_->setSuffix(QStringLiteral(" %"));
    strain_->setToolTip(tr("Axial strain ε1 at which each shear test ends."));
    message_->setWordWrap(true);
    message_->setStyleSheet(QStringLiteral("color: #b00020"));
    form->addRow(tr("Confining pressures [kPa]"), pressures_);
    form->addRow(tr("Grains"), grains_);
    form->addRow(tr("Friction μ (shear)"), friction_);
    form->addRow(tr("Axial strain target ε1"), strain_);
    form->addRow(message_);
    connect(pressures_, &QLineEdit::textChanged, this, &ParametersPanel::check);
    connect(grains_, &QSpinBox::valueChanged, this, &ParametersPanel::check);
    connect(friction_, &QDoubleSpinBox::valueChanged, this, &ParametersPanel::check);
    connect(strain_, &QDoubleSpinBox::valueChanged, this, &ParametersPanel::check);
}

void ParametersPanel::setExperiment(const ExperimentConfig& config) {
    base_ = config;
    QStringList kilopascals;
    for (double p :
         config.shear.pressures.empty() ? config.compaction.pressures : config.shear.pressures) {
        kilopascals << QString::number(p / 1e3, 'g', 6);
    }
    pressures_->setText(kilopascals.join(QStringLiteral(", ")));
    grains_->setValue(config.assembly.grainCount);
    friction_->setValue(config.shear.friction);
    strain_->setValue(100.0 * config.shear.targetAxialStrain);
    check();
}

std::vector<double> ParametersPanel::parsePressures(QString* why) const {
    std::vector<double> out;
    const QStringList items = pressures_->text().split(QLatin1Char(','), Qt::SkipEmptyParts);
    for (const QString& item : items) {
        bool ok = false;
        const double kPa = item.trimmed().toDouble(&ok);
        if (!ok || !std::isfinite(kPa) || kPa <= 0.0) {
            *why = tr("confining pressure '%1': must be a number > 0 [kPa]").arg(item.trimmed());
            return {};
        }
        if (!out.empty() && !(kPa * 1e3 > out.back())) {
            *why = tr("confining pressures must be strictly ascending (%1 after %2 kPa)")
                       .arg(kPa)
                       .arg(out.back() / 1e3);
            return {};
        }
        out.push_back(kPa * 1e3);
    }
    if (out.empty()) {
        *why = tr("give at least one confining pressure [kPa]");
    }
    return out;
}

QString ParametersPanel::problem() const {
    QString why;
    parsePressures(&why);
    return why;
}

ExperimentConfig ParametersPanel::applied() const {
    ExperimentConfig c = base_;
    QString why;
    const std::vector<double> pressures = parsePressures(&why);
    if (!pressures.empty()) {
        c.compaction.pressures = pressures;
        c.shear.pressures = pressures;
    }
    c.assembly.grainCount = grains_->value();
    c.shear.friction = friction_->value();
    c.shear.targetAxialStrain = strain_->value() / 100.0;
    return c;
}

void ParametersPanel::check() {
    const QString why = problem();
    message_->setText(why);
    message_->setVisible(!why.isEmpty());
    pressures_->setStyleSheet(why.isEmpty() ? QString()
                                            : QStringLiteral("border: 1px solid #b00020"));
    emit edited(why.isEmpty());
}

} // namespace grainlab::ui
