// See parameters_panel.h.
#include "grainlab/ui/parameters_panel.h"

#include <cmath>
#include <string>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QSignalBlocker>
#include <QSpinBox>

#include "grainlab/experiment_file.h"

namespace grainlab::ui {

ParametersPanel::ParametersPanel(QWidget* parent)
    : QWidget(parent), compactionPressures_(new QLabel(this)), shearPressures_(new QLineEdit(this)),
      grains_(new QSpinBox(this)), friction_(new QDoubleSpinBox(this)),
      strain_(new QDoubleSpinBox(this)), testKind_(new QComboBox(this)),
      slope_(new QDoubleSpinBox(this)), extension_(new QCheckBox(tr("extension"), this)),
      message_(new QLabel(this)) {
    auto* form = new QFormLayout(this);
    form->setContentsMargins(4, 4, 4, 4);
    compactionPressures_->setToolTip(tr("The experiment file's compaction stages, in kPa: the "
                                        "sample is compacted at each in turn."));
    compactionPressures_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    shearPressures_->setToolTip(tr("Which compacted samples to shear: confining pressures in kPa, "
                                   "separated by commas, each one of the compaction pressures, "
                                   "listed once. Each is a shear test."));
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
    testKind_->setToolTip(tr("What each sheared sample is tested by: axis 1 is shortened, axis 2 "
                             "holds σ22 (drained), the cell's area (constant volume), p (constant "
                             "p) or σ22 = P + a (σ11 − σ11,0) (stress path)."));
    slope_->setRange(-10.0, 10.0);
    slope_->setDecimals(3);
    slope_->setSingleStep(0.1);
    slope_->setToolTip(tr("The stress path's slope a = dσ22/dσ11 (0: drained, −1: constant p)."));
    extension_->setToolTip(tr("Lengthen axis 1 instead of shortening it (ε1 < 0), at the same "
                              "strain per step: the test in extension."));
    message_->setWordWrap(true);
    message_->setStyleSheet(QStringLiteral("color: #b00020"));
    form->addRow(tr("Compaction pressures [kPa]"), compactionPressures_);
    form->addRow(tr("Shear at pressures [kPa]"), shearPressures_);
    form->addRow(tr("Grains"), grains_);
    form->addRow(tr("Friction μ (shear)"), friction_);
    form->addRow(tr("Axial strain target ε1"), strain_);
    form->addRow(tr("Test"), testKind_);
    form->addRow(tr("Stress path slope a"), slope_);
    form->addRow(tr("Axis 1"), extension_);
    form->addRow(message_);
    connect(shearPressures_, &QLineEdit::textChanged, this, &ParametersPanel::check);
    connect(grains_, &QSpinBox::valueChanged, this, &ParametersPanel::check);
    connect(friction_, &QDoubleSpinBox::valueChanged, this, &ParametersPanel::check);
    connect(strain_, &QDoubleSpinBox::valueChanged, this, &ParametersPanel::check);
    connect(testKind_, &QComboBox::currentIndexChanged, this, &ParametersPanel::check);
    connect(slope_, &QDoubleSpinBox::valueChanged, this, &ParametersPanel::check);
    connect(extension_, &QCheckBox::toggled, this, &ParametersPanel::check);
}

void ParametersPanel::setExperiment(const ExperimentConfig& config) {
    base_ = config;
    const auto kilopascals = [](const std::vector<double>& pressures) {
        QStringList out;
        for (double p : pressures) {
            out << QString::number(p / 1e3, 'g', QLocale::FloatingPointShortest);
        }
        return out.join(QStringLiteral(", "));
    };
    compactionPressures_->setText(kilopascals(config.compaction.pressures));
    shearPressures_->setText(kilopascals(config.shear.pressures));
    grains_->setValue(config.assembly.grainCount);
    friction_->setValue(config.shear.friction);
    strain_->setValue(100.0 * config.shear.targetAxialStrain);
    {
        const QSignalBlocker block(testKind_);
        testKind_->clear();
        // A list of tests, or a kind the panel has no keys for (cyclic): kept as the file has it
        // unless another test is chosen.
        const bool keep = config.tests.size() > 1 ||
                          config.tests.front().kind == LoadingPath::Kind::Cyclic ||
                          config.tests.front().kind == LoadingPath::Kind::Probes;
        if (keep) {
            QStringList kinds;
            for (const LoadingPath& t : config.tests) {
                kinds << QString::fromLatin1(loadingKindName(t.kind));
            }
            testKind_->addItem(tr("as in the file: %1").arg(kinds.join(QStringLiteral(", "))),
                               QString());
        }
        testKind_->addItem(tr("drained"), QStringLiteral("drained"));
        testKind_->addItem(tr("constant volume"), QStringLiteral("constant_volume"));
        testKind_->addItem(tr("constant p"), QStringLiteral("constant_p"));
        testKind_->addItem(tr("stress path"), QStringLiteral("stress_path"));
        if (!keep) {
            testKind_->setCurrentIndex(testKind_->findData(
                QString::fromLatin1(loadingKindName(config.tests.front().kind))));
        }
    }
    slope_->setValue(config.tests.size() == 1 ? config.tests.front().slope : 0.0);
    extension_->setChecked(config.tests.size() == 1 && config.tests.front().extension);
    check();
}

std::vector<double> ParametersPanel::parseShearPressures(QString* why) const {
    std::vector<double> out;
    const QStringList items = shearPressures_->text().split(QLatin1Char(','), Qt::SkipEmptyParts);
    for (const QString& item : items) {
        // kPa as typed -> Pa by shifting the decimal point ("12.345" reads as "12.345e3"), so
        // that a pressure typed as shown is the very number of the compaction pressure it names
        // (12.345 * 1e3 need not be).
        const QString text = item.trimmed();
        bool ok = false;
        const bool exponent = text.contains(QLatin1Char('e'), Qt::CaseInsensitive);
        const double pa =
            exponent ? text.toDouble(&ok) * 1e3 : (text + QStringLiteral("e3")).toDouble(&ok);
        if (!ok || !std::isfinite(pa) || pa <= 0.0) {
            *why = tr("shear pressure '%1': must be a number > 0 [kPa]").arg(text);
            return {};
        }
        out.push_back(pa);
    }
    if (out.empty()) {
        *why = tr("give at least one shear pressure [kPa]");
        return {};
    }
    std::size_t bad = 0;
    const std::string allowed = shearPressureRule(base_.compaction.pressures, out, bad);
    if (!allowed.empty()) {
        *why = tr("shear pressure %1 kPa: must be %2 [Pa]")
                   .arg(QString::number(out[bad] / 1e3, 'g', QLocale::FloatingPointShortest))
                   .arg(QString::fromStdString(allowed));
        return {};
    }
    return out;
}

QString ParametersPanel::problem() const {
    QString why;
    parseShearPressures(&why);
    return why;
}

ExperimentConfig ParametersPanel::applied() const {
    ExperimentConfig c = base_;
    QString why;
    const std::vector<double> shear = parseShearPressures(&why);
    if (!shear.empty()) {
        c.shear.pressures = shear;
    }
    c.assembly.grainCount = grains_->value();
    c.shear.friction = friction_->value();
    c.shear.targetAxialStrain = strain_->value() / 100.0;
    const QString kind = testKind_->currentData().toString();
    if (!kind.isEmpty()) {
        LoadingPath test;
        for (auto k : {LoadingPath::Kind::Drained, LoadingPath::Kind::ConstantVolume,
                       LoadingPath::Kind::ConstantP, LoadingPath::Kind::StressPath}) {
            if (kind == QString::fromLatin1(loadingKindName(k))) {
                test.kind = k;
            }
        }
        test.slope = test.kind == LoadingPath::Kind::StressPath ? slope_->value() : 0.0;
        test.extension = extension_->isChecked();
        c.tests = {test};
    }
    return c;
}

void ParametersPanel::check() {
    slope_->setEnabled(testKind_->currentData().toString() == QStringLiteral("stress_path"));
    extension_->setEnabled(!testKind_->currentData().toString().isEmpty());
    const QString why = problem();
    message_->setText(why);
    message_->setVisible(!why.isEmpty());
    shearPressures_->setStyleSheet(why.isEmpty() ? QString()
                                                 : QStringLiteral("border: 1px solid #b00020"));
    emit edited(why.isEmpty());
}

} // namespace grainlab::ui
