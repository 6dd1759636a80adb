#pragma once
// One `grainlab report RUN_DIR --out DIR --quiet` process of the window, as File > Report… and
// the figure-set export start it: the window does not wait for it (a report on a large run takes
// seconds) and learns from finished() when it has ended and what went wrong. One report at a
// time per job. GUI thread.

#include <QObject>
#include <QString>

namespace grainlab::ui {

class CommandProcess;

class ReportJob : public QObject {
    Q_OBJECT
public:
    explicit ReportJob(QObject* parent = nullptr);

    /// Starts `grainlab` (the executable) writing the report of run folder `source` into `out`.
    /// False, starting nothing, while a report of this job is being written.
    bool start(const QString& grainlab, const QString& source, const QString& out);
    bool running() const;

signals:
    /// The report into `out` has ended: `error` is "" when it was written, else what went wrong
    /// (the process's own message, or why it could not start).
    void finished(const QString& out, const QString& error);

private:
    CommandProcess* command_;
    QString out_;
};

} // namespace grainlab::ui
