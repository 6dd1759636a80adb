#include "gui/folder_command.h"

#include <algorithm>

#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>

#include "gui/duration_text.h"

namespace grainlab::ui {

CommandRow::CommandRow(const QString& startTip, const QString& stopTip, const QString& unit)
    : layout(new QHBoxLayout), start(new QPushButton(QObject::tr("Start"))),
      stop(new QPushButton(QObject::tr("Stop"))), bar(new QProgressBar), text(new QLabel),
      unit_(unit) {
    start->setToolTip(startTip);
    stop->setToolTip(stopTip);
    bar->setFormat(QObject::tr("%v / %m %1").arg(unit));
    bar->setRange(0, 1);
    bar->setValue(0);
    layout->addWidget(start);
    layout->addWidget(stop);
    layout->addWidget(bar, 1);
    layout->addWidget(text);
}

void CommandRow::started(int finishedNow) {
    finishedAtStart_ = finishedNow;
    sinceStart_.start();
}

void CommandRow::show(int done, int total, bool running, const QString& extra) {
    bar->setRange(0, std::max(1, total));
    bar->setValue(done);
    QString line = QObject::tr("%1 of %2 %3 finished").arg(done).arg(total).arg(unit_);
    if (running) {
        const double elapsed = double(sinceStart_.elapsed()) / 1000.0;
        const int doneHere = done - finishedAtStart_;
        const double eta = doneHere > 0 ? elapsed / doneHere * (total - done) : -1.0;
        line +=
            QObject::tr(" · running %1 · ETA %2").arg(formatDuration(elapsed), formatDuration(eta));
        if (!extra.isEmpty()) {
            line += QStringLiteral(" · ") + extra;
        }
    }
    text->setText(line);
}

QString commandEndedText(int exitStatus, bool stopping, const QString& current,
                         const QString& finished, const QString& stopped, const QString& failed) {
    if (exitStatus == 0) {
        return finished;
    }
    if (exitStatus == 130 || stopping) {
        return stopped;
    }
    if (current.startsWith(QObject::tr("Could not start"))) {
        return current; // said already
    }
    return failed.contains(QStringLiteral("%1")) ? failed.arg(exitStatus) : failed;
}

bool refuseStart(QString* error, const QString& message) {
    if (error) {
        *error = message;
    }
    return false;
}

FolderScanner::FolderScanner() : context_(new QObject) {
    context_->moveToThread(&worker_);
    worker_.start();
}

FolderScanner::~FolderScanner() {
    worker_.quit();
    worker_.wait();
    delete context_;
}

} // namespace grainlab::ui
