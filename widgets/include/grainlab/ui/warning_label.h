#pragma once
// The run's warnings in the window's status bar (run_warning.h): the newest one in amber, every
// one in its tooltip, hidden while there is none. Fed by the main window from the live snapshot
// or from an open run file; GUI thread only. The line is elided to the space the status bar
// gives it.

#include <vector>

#include <QLabel>

#include "grainlab/run_warning.h"

namespace grainlab::ui {

class WarningLabel : public QLabel {
    Q_OBJECT
public:
    explicit WarningLabel(QWidget* parent = nullptr);
    /// Shows `warnings` (does nothing when they are the ones shown already).
    void setWarnings(const std::vector<RunWarning>& warnings);
    const std::vector<RunWarning>& warnings() const { return warnings_; }

    /// The whole line shown (elided to the label's width on screen).
    const QString& line() const { return line_; }

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void elide();
    std::vector<RunWarning> warnings_;
    QString line_;
};

} // namespace grainlab::ui
