#pragma once
// What the Study window and the Stability view share around a grainlab subcommand that works in
// a folder (`grainlab study`, `grainlab stability`): the row that starts and stops it and shows
// its progress with the ETA (CommandRow), the scans of its folder on a worker thread, one at a
// time, a stale one dropped (FolderScanner), and the whole of it with the command's process, the
// folder's polling and the status line (FolderCommand). GUI thread only, but for the scans
// themselves.

#include <cstdint>
#include <functional>
#include <initializer_list>
#include <memory>
#include <optional>
#include <utility>

#include <QElapsedTimer>
#include <QMetaObject>
#include <QObject>
#include <QString>
#include <QStringList>
#include <QThread>
#include <QTimer>
#include <QWidget>

class QGridLayout;
class QHBoxLayout;
class QLabel;
class QProgressBar;
class QPushButton;

namespace grainlab::ui {

/// Start, Stop, the progress bar of finished items ("runs", "cells") and the progress text.
class CommandRow {
public:
    /// Makes the row's widgets (parented once `layout` is added to a window's layout).
    CommandRow(const QString& startTip, const QString& stopTip, const QString& unit);

    QHBoxLayout* layout;
    QPushButton* start;
    QPushButton* stop;
    QProgressBar* bar;
    QLabel* text;

    /// The command started with `finishedNow` items finished: the ETA counts from here.
    void started(int finishedNow);
    /// `done` of `total` finished; while `running`, the time since the start, the ETA from the
    /// items finished since, and `extra` (the command's own progress) after them.
    void show(int done, int total, bool running, const QString& extra = {});

private:
    QString unit_;
    QElapsedTimer sinceStart_;
    int finishedAtStart_ = 0;
};

/// What the status line says once the command ended with `exitStatus`: `finished` (0), `stopped`
/// (130, the command stopped its own work; or any status after Stop, which may come before it
/// started any), `current` when it already says the command could not start, else `failed`
/// (which may hold %1 for the status).
QString commandEndedText(int exitStatus, bool stopping, const QString& current,
                         const QString& finished, const QString& stopped, const QString& failed);

/// For a start() that cannot start: `message` into `error` (when given); false.
bool refuseStart(QString* error, const QString& message);

/// Scans of a folder on a worker thread of its own.
class FolderScanner {
public:
    FolderScanner();
    /// Waits for a scan under way; its result is dropped.
    ~FolderScanner();
    FolderScanner(const FolderScanner&) = delete;
    FolderScanner& operator=(const FolderScanner&) = delete;

    /// The folder or what is read from it changed: the scans posted so far are dropped.
    void forget() { ++generation_; }

    /// Runs `scan` on the worker thread (it must copy in all it reads), then `done(result,
    /// error)` on `receiver`'s thread, unless forget() came in between; `result` is null when
    /// `scan` threw, `error` its message. One scan at a time: a request during a scan calls
    /// `again` once that scan is done (which asks anew with the state of then).
    template <class Result>
    void request(QObject* receiver, std::function<std::shared_ptr<const Result>()> scan,
                 std::function<void(std::shared_ptr<const Result>, const QString&)> done,
                 std::function<void()> again) {
        if (scanning_) {
            again_ = std::move(again);
            return;
        }
        scanning_ = true;
        QMetaObject::invokeMethod(
            context_,
            [this, receiver, generation = generation_, scan = std::move(scan),
             done = std::move(done)] {
                std::shared_ptr<const Result> next;
                QString error;
                try {
                    next = scan();
                } catch (const std::exception& e) {
                    error = QString::fromStdString(e.what());
                }
                QMetaObject::invokeMethod(
                    receiver,
                    [this, generation, next, error, done] {
                        scanning_ = false;
                        if (generation == generation_) {
                            done(next, error);
                        }
                        if (again_) {
                            const std::function<void()> again = std::move(again_);
                            again_ = nullptr;
                            again();
                        }
                    },
                    Qt::QueuedConnection);
            },
            Qt::QueuedConnection);
    }

private:
    QThread worker_;
    QObject* context_; ///< lives on worker_: the context of the scans posted there
    std::uint64_t generation_ = 0;
    bool scanning_ = false;
    std::function<void()> again_; ///< asked for during a scan
};

class CommandProcess;

/// What a FolderCommand says: the row's tool tips and unit ("runs", "cells"), and the status
/// line's texts once Stop is asked and once the command ended (`finished` holds %1 for what the
/// command said, `failed` %1 for the exit status and is followed by what it said).
struct FolderCommandTexts {
    QString startTip, stopTip, unit;
    QString stopping, finished, stopped, failed;
};

/// What a FolderCommand asks of its view.
struct FolderCommandHooks {
    std::function<bool(QString*)> start;  ///< Start clicked: false with the reason when refused
    std::function<void()> rescan;         ///< read the folder (on a FolderScanner)
    std::function<void()> updateControls; ///< enable the buttons as the state says
    std::function<void()> updateProgress; ///< the row's progress (CommandRow::show)
    std::function<QString()> said;        ///< what the ended command said (its log read)
    std::function<void(int)> ended;       ///< the command ended with this exit status
    std::function<void()> redraw;         ///< draw what the view holds of its folder
};

/// One folder command of a view: its process (output into a log file, so it goes on when the
/// window closes), the row, the status line, the scans and the timer that reads the folder while
/// the command runs (and, with `pollWhileShown`, while the view is shown).
class FolderCommand {
public:
    FolderCommand(QWidget* view, const QString& grainlab, FolderCommandTexts texts,
                  bool pollWhileShown);
    /// Lets go of the command, which goes on.
    ~FolderCommand();
    FolderCommand(const FolderCommand&) = delete;
    FolderCommand& operator=(const FolderCommand&) = delete;
    /// The hooks; the buttons and the timer call them from now on.
    void setHooks(FolderCommandHooks hooks);
    /// The view has a new folder (and has dropped what it held of the old one): the scans and
    /// the exit status of the old folder are dropped, then the view redraws, shows its progress
    /// and controls, and reads the new folder.
    void newFolder();

    QString grainlab; ///< the executable started (tests give the built grainlab)
    CommandRow row;
    FolderScanner scans; ///< forgotten when the folder changes
    QTimer poll;
    QLabel* status; ///< the status line, for the view's layout
    std::optional<int> lastExit;

    bool running() const;
    bool stopping() const;
    QString logPath() const;
    /// Starts `grainlab arguments`, its output into grainlab-<logName>-<pid>.log in the temporary
    /// folder; `finishedNow` items are finished already (the ETA counts from here).
    void launch(const QStringList& arguments, const QString& logName, int finishedNow);
    /// Asks the running command to stop (SIGINT).
    void stop();
    /// Puts `text` in the status line.
    void say(const QString& text);
    /// Reads the folder (the view's rescan()).
    void rescanNow() { hooks_.rescan(); }
    /// The view was shown / hidden.
    void shown();
    void hidden();

private:
    void ended(int exitStatus);

    QWidget* view_;
    FolderCommandTexts texts_;
    bool pollWhileShown_;
    CommandProcess* command_;
    FolderCommandHooks hooks_;
};

/// A view of a folder that a grainlab subcommand writes (the Study window, the Stability view):
/// its FolderCommand and what the window and the tests ask of it.
class FolderCommandView : public QWidget {
public:
    FolderCommandView(QWidget* parent, Qt::WindowFlags flags, const QString& grainlab,
                      FolderCommandTexts texts, bool pollWhileShown)
        : QWidget(parent, flags), run_(this, grainlab, std::move(texts), pollWhileShown) {}

    /// Asks the running command to stop (SIGINT): its runs or cells keep what they finished.
    void stop() { run_.stop(); }
    bool running() const { return run_.running(); }
    /// The exit status of the last command (nothing while none has ended).
    std::optional<int> lastExitStatus() const { return run_.lastExit; }
    /// How often the folder is read while the command runs [ms].
    void setPollInterval(int ms) { run_.poll.setInterval(ms); }

    QProgressBar* progressBar() const { return run_.row.bar; }
    QLabel* progressLabel() const { return run_.row.text; }
    QPushButton* startButton() const { return run_.row.start; }
    QPushButton* stopButton() const { return run_.row.stop; }
    QLabel* statusLabel() const { return run_.status; }
    /// The folder followed ("" until one is chosen).
    QString folderPath() const { return folder_; }
    /// The details panel beside the plot.
    QLabel* details() const { return details_; }

protected:
    /// What the folder's rows say: the row's name, its button, the title of the folder dialog
    /// the button opens, and the grey hint below.
    struct FolderRowTexts {
        QString name, button, dialogTitle, hint;
    };
    /// Makes the folder's label ("–" until one is chosen), its button (which hands the folder
    /// chosen in the dialog to `chosen`) and the hint, and adds them to `grid` as rows 1 (the
    /// name, the label spanning `span` columns, the button) and 2 (the hint under the label and
    /// the button); column `span` of `grid` takes the room.
    void addFolderRows(QGridLayout* grid, const FolderRowTexts& texts, int span,
                       std::function<void(const QString&)> chosen);
    /// `folder` (absolute and clean) becomes folder_, shown in the folder's label.
    void showFolder(const QString& folder);
    /// The row of the view's plot (taking the room) and, beside it, its details panel, made here
    /// into details_: wrapped, selectable text, `width` px wide, showing `text` to start with.
    QHBoxLayout* plotWithDetails(QWidget* plot, const QString& text, int width);
    /// The row of the plot's choices: each box after its label ("Test:"), then the room.
    static QHBoxLayout* choicesRow(std::initializer_list<std::pair<QString, QWidget*>> choices);

    FolderCommand run_;
    QString folder_;
    QLabel* folderLabel_ = nullptr;
    QPushButton* folderButton_ = nullptr;
    QLabel* details_ = nullptr;
};

/// A FolderCommandView whose folder reads (on the worker thread) as a `Result`.
template <class Result>
class FolderScanView : public FolderCommandView {
public:
    using FolderCommandView::FolderCommandView;

    /// What the latest scan read in the folder (null until the folder is read).
    std::shared_ptr<const Result> folderState() const { return state_; }

protected:
    /// Reads the folder with `scan` on the worker thread, then hands the result to `scanned`;
    /// a scan that threw puts its message in the status line.
    void scanFolder(std::function<std::shared_ptr<const Result>()> scan,
                    std::function<void(std::shared_ptr<const Result>)> scanned) {
        run_.scans.request<Result>(
            this, std::move(scan),
            [this, scanned = std::move(scanned)](std::shared_ptr<const Result> next,
                                                 const QString& error) {
                if (next) {
                    scanned(std::move(next));
                } else {
                    run_.say(error);
                }
            },
            [this] { run_.rescanNow(); });
    }

    std::shared_ptr<const Result> state_;
};

} // namespace grainlab::ui
