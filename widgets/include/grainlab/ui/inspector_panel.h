#pragma once
// The inspector: what a click on the paused scene selected — a void cell (its grains, valence,
// area, elongation, orientation) or a grain (size, contacts, forces, sliding contacts) — as a
// table of quantity / value rows read from the snapshot. GUI thread only.

#include <QString>
#include <QWidget>

#include "grainlab/snapshot.h"

class QLabel;
class QTableWidget;

namespace grainlab::ui {

class InspectorPanel : public QWidget {
    Q_OBJECT
public:
    explicit InspectorPanel(QWidget* parent = nullptr);

    void showGrain(const SnapshotPtr& snapshot, int grain);
    void showVoidCell(const SnapshotPtr& snapshot, int voidCell);
    void clear();

    /// The title line, e.g. "Void cell 12".
    QString title() const;
    /// The value shown for a quantity (first column text), or an empty string.
    QString value(const QString& quantity) const;
    /// Number of rows shown.
    int rowCount() const;

private:
    void addRow(const QString& quantity, const QString& value);

    QLabel* title_;
    QTableWidget* table_;
};

} // namespace grainlab::ui
