#include "gui/folder_command.h"

#include <algorithm>

#include <QCoreApplication>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QWidget>

#include "gui/command_process.h"
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

namespace {
constexpr int kPollMs = 1000; ///< how often the folder is read [ms]
} // namespace

FolderCommand::FolderCommand(QWidget* view, const QString& grainlab, FolderCommandTexts texts,
                             bool pollWhileShown)
    : grainlab(grainlab.isEmpty() ? QCoreApplication::applicationFilePath() : grainlab),
      row(texts.startTip, texts.stopTip, texts.unit), status(new QLabel), view_(view),
      texts_(std::move(texts)), pollWhileShown_(pollWhileShown),
      command_(new CommandProcess(view)) {
    status->setWordWrap(true);
    status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    poll.setInterval(kPollMs);
    QObject::connect(
        command_, &CommandProcess::ended, view,
        [this](int code, const QString&, const QString& startError) {
            if (!startError.isEmpty()) {
                status->setText(
                    QObject::tr("Could not start %1: %2").arg(this->grainlab, startError));
            }
            ended(code);
        });
}

FolderCommand::~FolderCommand() {
    poll.stop();
    QObject::disconnect(command_, nullptr, view_, nullptr);
}

void FolderCommand::newFolder() {
    scans.forget();
    lastExit.reset();
    hooks_.redraw();
    hooks_.updateProgress();
    hooks_.updateControls();
    hooks_.rescan();
}

void FolderCommand::setHooks(FolderCommandHooks hooks) {
    hooks_ = std::move(hooks);
    QObject::connect(&poll, &QTimer::timeout, view_, [this] {
        hooks_.rescan();
        hooks_.updateProgress();
    });
    QObject::connect(row.start, &QPushButton::clicked, view_, [this] {
        QString error;
        if (!hooks_.start(&error)) {
            status->setText(error);
        }
    });
    QObject::connect(row.stop, &QPushButton::clicked, view_, [this] { stop(); });
}

void FolderCommandView::addFolderRows(QGridLayout* grid, const FolderRowTexts& texts, int span,
                                      std::function<void(const QString&)> chosen) {
    folderLabel_ = new QLabel(QObject::tr("–"));
    folderLabel_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    folderButton_ = new QPushButton(texts.button);
    QObject::connect(folderButton_, &QPushButton::clicked, this,
                     [this, title = texts.dialogTitle, chosen = std::move(chosen)] {
                         const QString folder =
                             QFileDialog::getExistingDirectory(this, title, folder_);
                         if (!folder.isEmpty()) {
                             chosen(folder);
                         }
                     });
    auto* hint = new QLabel(texts.hint);
    hint->setWordWrap(true);
    hint->setStyleSheet(QStringLiteral("color: gray"));
    grid->addWidget(new QLabel(texts.name), 1, 0);
    grid->addWidget(folderLabel_, 1, 1, 1, span);
    grid->addWidget(folderButton_, 1, 1 + span);
    grid->addWidget(hint, 2, 1, 1, span + 1);
    grid->setColumnStretch(span, 1);
}

void FolderCommandView::showFolder(const QString& folder) {
    folder_ = QDir::cleanPath(QFileInfo(folder).absoluteFilePath());
    folderLabel_->setText(folder_);
}

QHBoxLayout* FolderCommandView::plotWithDetails(QWidget* plot, const QString& text, int width) {
    details_ = new QLabel(text);
    details_->setWordWrap(true);
    details_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    details_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    details_->setFixedWidth(width);
    auto* row = new QHBoxLayout;
    row->addWidget(plot, 1);
    row->addWidget(details_);
    return row;
}

QHBoxLayout*
FolderCommandView::choicesRow(std::initializer_list<std::pair<QString, QWidget*>> choices) {
    auto* row = new QHBoxLayout;
    for (const auto& [label, box] : choices) {
        row->addWidget(new QLabel(label));
        row->addWidget(box);
    }
    row->addStretch(1);
    return row;
}

void FolderCommand::say(const QString& text) {
    status->setText(text);
}

bool FolderCommand::running() const {
    return command_->running();
}

bool FolderCommand::stopping() const {
    return command_->stopping();
}

QString FolderCommand::logPath() const {
    return command_->logPath();
}

void FolderCommand::launch(const QStringList& arguments, const QString& logName, int finishedNow) {
    const QString log = QDir(QDir::tempPath())
                            .filePath(QStringLiteral("grainlab-%1-%2.log")
                                          .arg(logName)
                                          .arg(QCoreApplication::applicationPid()));
    lastExit.reset();
    row.started(finishedNow);
    status->setText(QObject::tr("Running: %1 %2").arg(grainlab, arguments.join(QLatin1Char(' '))));
    command_->start(grainlab, arguments, log);
    poll.start();
    hooks_.updateControls();
    hooks_.updateProgress();
}

void FolderCommand::stop() {
    if (command_->stop()) {
        status->setText(texts_.stopping);
        row.stop->setEnabled(false);
    }
}

void FolderCommand::ended(int exitStatus) {
    if (!pollWhileShown_ || !view_->isVisible()) {
        poll.stop();
    }
    lastExit = exitStatus;
    const QString said = hooks_.said();
    status->setText(commandEndedText(exitStatus, command_->stopping(), status->text(),
                                     texts_.finished.arg(said), texts_.stopped,
                                     texts_.failed + said));
    hooks_.rescan();
    hooks_.updateControls();
    hooks_.updateProgress();
    hooks_.ended(exitStatus);
}

void FolderCommand::shown() {
    if (pollWhileShown_) {
        poll.start();
    }
    hooks_.rescan();
}

void FolderCommand::hidden() {
    if (!running()) {
        poll.stop();
    }
}

} // namespace grainlab::ui
