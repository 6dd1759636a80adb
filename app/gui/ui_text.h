#pragma once
// The small conversions the study and stability panels share: a std::string as a QString, a
// number as people read it in a panel (4 significant digits), a flag as "yes" or "no". Any
// thread.

#include <string>

#include <QObject>
#include <QString>

namespace grainlab::ui {

inline QString q(const std::string& s) {
    return QString::fromStdString(s);
}

/// 4 significant digits, 'g' form.
inline QString number(double v) {
    return QString::number(v, 'g', 4);
}

inline QString yesNo(bool v) {
    return v ? QObject::tr("yes") : QObject::tr("no");
}

} // namespace grainlab::ui
