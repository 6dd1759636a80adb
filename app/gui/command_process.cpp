// See command_process.h.
#include "gui/command_process.h"

#include <csignal>

#include <QIODevice>
#include <QProcess>

namespace grainlab::ui {

CommandProcess::CommandProcess(QObject* parent) : QObject(parent) {}

CommandProcess::~CommandProcess() {
    if (process_ && !logPath_.isEmpty() && process_->state() != QProcess::NotRunning) {
        // Let go, so that the process object's destructor does not kill the command.
        disconnect(process_, nullptr, this, nullptr);
        process_->setParent(nullptr);
        process_ = nullptr;
    }
}

bool CommandProcess::start(const QString& grainlab, const QStringList& arguments,
                           const QString& logPath) {
    if (running()) {
        return false;
    }
    logPath_ = logPath;
    stopping_ = false;
    process_ = new QProcess(this);
    process_->setStandardInputFile(QProcess::nullDevice());
    process_->setProcessChannelMode(QProcess::MergedChannels);
    if (!logPath_.isEmpty()) {
        process_->setStandardOutputFile(logPath_, QIODevice::Truncate);
    }
    connect(process_, &QProcess::finished, this, [this](int code, QProcess::ExitStatus status) {
        finish(status == QProcess::NormalExit ? code : -1, QString());
    });
    // A process that cannot start emits no finished().
    connect(process_, &QProcess::errorOccurred, this, [this](QProcess::ProcessError e) {
        if (e == QProcess::FailedToStart) {
            finish(-1, process_->errorString());
        }
    });
    process_->start(grainlab, arguments);
    return true;
}

bool CommandProcess::stop() {
    if (!process_ || process_->processId() <= 0) {
        return false;
    }
    ::kill(pid_t(process_->processId()), SIGINT);
    stopping_ = true;
    return true;
}

void CommandProcess::finish(int exitStatus, const QString& startError) {
    if (!process_) {
        return;
    }
    const QString output =
        logPath_.isEmpty() ? QString::fromLocal8Bit(process_->readAll()).trimmed() : QString();
    process_->deleteLater();
    process_ = nullptr;
    emit ended(exitStatus, output, startError);
}

} // namespace grainlab::ui
