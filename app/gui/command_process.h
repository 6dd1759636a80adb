#pragma once
// One `grainlab` command that the window starts as a process of this very executable and does
// not wait for: the Study window's study, the Stability view's map, File > Report…'s report.
// Its output goes to a log file (a study or a map goes on when the window closes, so it must
// not depend on the window's pipes) or, for a short command, is kept and handed to ended().
// stop() sends SIGINT, on which a study's or a map's runs write their checkpoints and end.
// One command at a time per object. GUI thread.

#include <QObject>
#include <QString>
#include <QStringList>

class QProcess;

namespace grainlab::ui {

class CommandProcess : public QObject {
    Q_OBJECT
public:
    explicit CommandProcess(QObject* parent = nullptr);
    /// A command writing into a log file goes on without the window; one whose output is kept
    /// ends with it.
    ~CommandProcess() override;

    /// Starts `grainlab arguments` with its output (stdout and stderr) into `logPath`, truncated,
    /// or kept for ended() when `logPath` is "". False, starting nothing, while a command of this
    /// object runs.
    bool start(const QString& grainlab, const QStringList& arguments, const QString& logPath = {});
    /// Asks the running command to stop (SIGINT); false when none runs or it has no pid yet.
    bool stop();
    bool running() const { return process_ != nullptr; }
    /// stop() was called for the running command (or the last one).
    bool stopping() const { return stopping_; }
    QString logPath() const { return logPath_; }

signals:
    /// The command ended: `exitStatus` is its exit status, or -1 when a signal ended it or it
    /// could not start; then `startError` says why it could not start ("" otherwise). `output`
    /// is what it printed when its output was kept ("" with a log file). running() is false.
    void ended(int exitStatus, const QString& output, const QString& startError);

private:
    void finish(int exitStatus, const QString& startError);

    QProcess* process_ = nullptr;
    QString logPath_;
    bool stopping_ = false;
};

} // namespace grainlab::ui
