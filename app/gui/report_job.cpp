// See report_job.h.
#include "gui/report_job.h"

#include "gui/command_process.h"

namespace grainlab::ui {

ReportJob::ReportJob(QObject* parent) : QObject(parent), command_(new CommandProcess(this)) {
    connect(command_, &CommandProcess::ended, this,
            [this](int code, const QString& output, const QString& startError) {
                if (!startError.isEmpty()) {
                    emit finished(out_, tr("The report could not start: %1").arg(startError));
                } else if (code < 0) {
                    emit finished(out_, tr("The report stopped abnormally: %1").arg(output));
                } else if (code != 0) {
                    emit finished(out_, tr("The report failed: %1").arg(output));
                } else {
                    emit finished(out_, QString());
                }
            });
}

bool ReportJob::start(const QString& grainlab, const QString& source, const QString& out) {
    if (running()) {
        return false;
    }
    out_ = out;
    return command_->start(grainlab, {QStringLiteral("report"), source, QStringLiteral("--out"),
                                      out, QStringLiteral("--quiet")});
}

bool ReportJob::running() const {
    return command_->running();
}

} // namespace grainlab::ui
