// See stability_map_text.h.
#include "gui/stability_map_text.h"

#include <algorithm>

#include <QFile>
#include <QObject>
#include <QRegularExpression>
#include <QStringList>

#include "gui/ui_text.h"

namespace grainlab::ui {

QString stabilityCellNumbers(const StabilityCellResult& r) {
    const StabilityCell& c = r.cell;
    QStringList lines;
    lines << QStringLiteral("<b>%1</b>").arg(q(c.id).toHtmlEscaped());
    lines << QObject::tr("η = %1 · k_t/k_n = %2 · damping %3 · %4")
                 .arg(number(c.aspectRatio), number(c.stiffnessRatio),
                      q(dampingLabel(c.damping)).toHtmlEscaped(),
                      q(packingLabel(c.packing)).toHtmlEscaped());
    lines << QObject::tr("limit: <b>%1</b> √(m_min/k_n) = %2 s")
                 .arg(number(r.limit.limit), number(r.limit.limit * r.timeUnit));
    lines << QObject::tr("bracket: [%1, %2] · bracketed: %3 · probes: %4")
                 .arg(number(r.limit.low), number(r.limit.high), yesNo(r.limit.bracketed))
                 .arg(r.limit.probes);
    lines << QObject::tr("detector at %1: %2 at step %3")
                 .arg(number(r.limit.high), q(blowUpName(r.limit.detector)))
                 .arg(r.limit.detectorStep);
    if (!r.limit.detail.empty()) {
        lines << QStringLiteral("<i>%1</i>").arg(q(r.limit.detail).toHtmlEscaped());
    }
    lines << QObject::tr("estimate: %1 (translational %2, rotational %3)")
                 .arg(number(r.estimate), number(r.estimateTranslational),
                      number(r.estimateRotational));
    lines << QObject::tr("limit / estimate: <b>%1</b>")
                 .arg(r.estimate > 0 ? number(r.limit.limit / r.estimate) : QStringLiteral("–"));
    if (!r.accuracy.empty()) {
        lines << QObject::tr("energy-balance residual, damping off:");
        for (const AccuracyPoint& a : r.accuracy) {
            lines << QObject::tr("&nbsp;&nbsp;%1 of the limit (Δt %2): max %3, final %4%5")
                         .arg(number(a.fraction), number(a.step), number(a.maxResidual),
                              number(a.finalResidual),
                              a.stable ? QString() : QObject::tr(", unstable"));
        }
    }
    lines << QObject::tr("compaction calm: %1 · cell time: %2 s")
                 .arg(yesNo(r.compactionCalm), number(r.seconds));
    return lines.join(QStringLiteral("<br>"));
}

QString stabilityLogSummary(const QString& logPath) {
    QFile file(logPath);
    if (!file.open(QIODevice::ReadOnly)) {
        return {};
    }
    // What the map itself said (its summary, an error, the failed cells with the last line of
    // each one's log), not its opening line or its progress lines.
    static const QRegularExpression opening(
        QStringLiteral("^grainlab stability \\S+: \\d+ cells, "));
    static const QRegularExpression cellLog(QStringLiteral("; log (.+)\\)$"));
    QStringList said;
    for (const QString& line : QString::fromUtf8(file.readAll()).split('\n', Qt::SkipEmptyParts)) {
        if (line.startsWith(QStringLiteral("grainlab")) && !opening.match(line).hasMatch()) {
            said << line;
        } else if (line.startsWith(QStringLiteral("  "))) {
            said << line; // a failed cell, listed under its heading
            const QRegularExpressionMatch m = cellLog.match(line);
            QFile log(m.hasMatch() ? m.captured(1) : QString());
            if (m.hasMatch() && log.open(QIODevice::ReadOnly)) {
                const QStringList lines =
                    QString::fromUtf8(log.readAll()).split('\n', Qt::SkipEmptyParts);
                if (!lines.isEmpty()) {
                    said << QStringLiteral("    ") + lines.last();
                }
            }
        }
    }
    return said.mid(std::max<qsizetype>(0, said.size() - 8)).join(QStringLiteral("\n"));
}

QString stabilityLogProgress(const QString& logPath) {
    QFile file(logPath);
    if (logPath.isEmpty() || !file.open(QIODevice::ReadOnly)) {
        return {};
    }
    // The map's progress bar, written as a line every 10 % when not on a terminal.
    static const QRegularExpression bar(QStringLiteral(
        "^stability \\S+ \\(\\d+ cells\\)\\s+([0-9.]+) % \\d+ done, (\\d+) running"));
    QString last;
    for (const QString& line : QString::fromUtf8(file.readAll()).split('\n', Qt::SkipEmptyParts)) {
        const QRegularExpressionMatch m = bar.match(line);
        if (m.hasMatch()) {
            last = QObject::tr("the map's last report: %1 %, %2 running")
                       .arg(m.captured(1), m.captured(2));
        }
    }
    return last;
}

} // namespace grainlab::ui
