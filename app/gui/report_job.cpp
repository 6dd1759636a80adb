// See report_job.h.
#include "gui/report_job.h"

#include <QProcess>

namespace grainlab::ui {

ReportJob::ReportJob(QObject* parent) : QObject(parent), process_(new QProcess(this)) {
    process_->setStandardInputFile(QProcess::nullDevice());
    process_->setProcessChannelMode(QProcess::MergedChannels);
    connect(process_, &QProcess::finished, this, [this](int code, QProcess::ExitStatus status) {
        const QString output = QString::fromLocal8Bit(process_->readAll()).trimmed();
        if (status != QProcess::NormalExit) {
            emit finished(out_, tr("The report stopped abnormally: %1").arg(output));
        } else if (code != 0) {
            emit finished(out_, tr("The report failed: %1").arg(output));
        } else {
            emit finished(out_, QString());
        }
    });
    // A process that cannot start emits no finished().
    connect(process_, &QProcess::errorOccurred, this, [this](QProcess::ProcessError e) {
        if (e == QProcess::FailedToStart) {
            emit finished(out_, tr("The report could not start: %1").arg(process_->errorString()));
        }
    });
}

bool ReportJob::start(const QString& grainlab, const QString& source, const QString& out) {
    if (running()) {
        return false;
    }
    out_ = out;
    process_->start(grainlab, {QStringLiteral("report"), source, QStringLiteral("--out"), out,
                               QStringLiteral("--quiet")});
    return true;
}

bool ReportJob::running() const {
    return process_->state() != QProcess::NotRunning;
}

} // namespace grainlab::ui
