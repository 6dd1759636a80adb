#include "grainlab/ui/warning_label.h"

#include <QResizeEvent>

namespace grainlab::ui {
namespace {

QString inWords(const RunWarning& w) {
    return QLabel::tr("%1 (%2, step %3): %4")
        .arg(QString::fromStdString(w.kind).replace(QLatin1Char('_'), QLatin1Char(' ')),
             QString::fromStdString(w.test))
        .arg(w.step)
        .arg(QString::fromStdString(w.text));
}

} // namespace

WarningLabel::WarningLabel(QWidget* parent) : QLabel(parent) {
    setStyleSheet(QStringLiteral("color: #8a5a00"));
    // Takes the width it is given, not the width of its text.
    setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    hide();
}

void WarningLabel::setWarnings(const std::vector<RunWarning>& warnings) {
    if (warnings == warnings_) {
        return;
    }
    warnings_ = warnings;
    if (warnings_.empty()) {
        line_.clear();
        clear();
        setToolTip({});
        hide();
        return;
    }
    const QString newest = inWords(warnings_.back());
    line_ = warnings_.size() == 1
                ? tr("⚠ %1").arg(newest)
                : tr("⚠ %1 warnings; newest: %2").arg(warnings_.size()).arg(newest);
    elide();
    QStringList all;
    for (const RunWarning& w : warnings_) {
        all << inWords(w);
    }
    setToolTip(all.join(QStringLiteral("\n\n")));
    show();
}

void WarningLabel::resizeEvent(QResizeEvent* event) {
    QLabel::resizeEvent(event);
    elide();
}

void WarningLabel::elide() {
    setText(fontMetrics().elidedText(line_, Qt::ElideRight, std::max(width(), 80)));
}

} // namespace grainlab::ui
