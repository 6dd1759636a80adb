// See inspector_panel.h.
#include "grainlab/ui/inspector_panel.h"

#include <cmath>
#include <numbers>

#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

namespace grainlab::ui {
namespace {

constexpr double kDegrees = 180.0 / std::numbers::pi;

QString number(double value, int digits = 4) {
    return QString::number(value, 'g', digits);
}

} // namespace

InspectorPanel::InspectorPanel(QWidget* parent)
    : QWidget(parent), title_(new QLabel(this)), table_(new QTableWidget(0, 2, this)) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    title_->setTextFormat(Qt::PlainText);
    QFont bold = title_->font();
    bold.setBold(true);
    title_->setFont(bold);
    table_->setHorizontalHeaderLabels({tr("quantity"), tr("value")});
    table_->horizontalHeader()->setStretchLastSection(true);
    table_->verticalHeader()->hide();
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->setSelectionMode(QAbstractItemView::NoSelection);
    layout->addWidget(title_);
    layout->addWidget(table_);
    clear();
}

void InspectorPanel::clear() {
    title_->setText(tr("Pause and click a void cell or a grain to inspect it."));
    table_->setRowCount(0);
}

QString InspectorPanel::title() const {
    return title_->text();
}

int InspectorPanel::rowCount() const {
    return table_->rowCount();
}

QString InspectorPanel::value(const QString& quantity) const {
    for (int r = 0; r < table_->rowCount(); ++r) {
        if (table_->item(r, 0)->text() == quantity) {
            return table_->item(r, 1)->text();
        }
    }
    return {};
}

void InspectorPanel::addRow(const QString& quantity, const QString& value) {
    const int r = table_->rowCount();
    table_->insertRow(r);
    table_->setItem(r, 0, new QTableWidgetItem(quantity));
    table_->setItem(r, 1, new QTableWidgetItem(value));
}

void InspectorPanel::showVoidCell(const SnapshotPtr& snapshot, int index) {
    table_->setRowCount(0);
    if (!snapshot || index < 0 || index >= static_cast<int>(snapshot->voidCells.size())) {
        clear();
        return;
    }
    const VoidCellView& cell = snapshot->voidCells[index];
    title_->setText(tr("Void cell %1").arg(index));
    addRow(tr("valence"), QString::number(cell.valence));
    addRow(tr("area [mm²]"), number(cell.area * 1e6));
    addRow(tr("elongation [-]"), number(cell.elongation));
    addRow(tr("direction from x1 [deg]"), number(cell.direction * kDegrees, 3));
    addRow(tr("centroid x1, x2 [mm]"), QStringLiteral("%1, %2").arg(number(cell.centroid1 * 1e3),
                                                                    number(cell.centroid2 * 1e3)));
    QStringList grains;
    for (auto g : cell.grains) {
        grains << QString::number(g);
    }
    addRow(tr("grains"), grains.join(QStringLiteral(" ")));
}

void InspectorPanel::showGrain(const SnapshotPtr& snapshot, int grain) {
    table_->setRowCount(0);
    if (!snapshot || grain < 0 || grain >= static_cast<int>(snapshot->x1.size())) {
        clear();
        return;
    }
    const Snapshot& s = *snapshot;
    const OvalShape& shape = s.shapes[s.shape[grain]];
    int contacts = 0, sliding = 0;
    double normalSum = 0.0, largest = 0.0;
    QStringList neighbours;
    for (const ContactRecord& c : s.network.contacts) {
        if (c.first != grain && c.second != grain) {
            continue;
        }
        ++contacts;
        sliding += c.sliding ? 1 : 0;
        normalSum += c.normalForce;
        const auto f = c.force();
        largest = std::max(largest, std::hypot(f[0], f[1]));
        neighbours << QString::number(c.first == grain ? c.second : c.first);
    }
    title_->setText(tr("Grain %1").arg(grain));
    addRow(tr("width × height [mm]"),
           QStringLiteral("%1 × %2").arg(number(shape.width * 1e3), number(shape.height * 1e3)));
    addRow(tr("equivalent diameter [mm]"), number(shape.equivalentDiameter() * 1e3));
    addRow(tr("area [mm²]"), number(shape.area * 1e6));
    addRow(tr("centre x1, x2 [mm]"),
           QStringLiteral("%1, %2").arg(number(s.x1[grain] * 1e3), number(s.x2[grain] * 1e3)));
    addRow(tr("orientation from x1 [deg]"), number(s.theta[grain] * kDegrees, 3));
    if (grain < static_cast<int>(s.rotation.size())) {
        addRow(tr("rotation since start [deg]"), number(s.rotation[grain] * kDegrees, 3));
    }
    addRow(tr("contacts"), QString::number(contacts));
    addRow(tr("sliding contacts"), QString::number(sliding));
    addRow(tr("sum of normal forces [N]"), number(normalSum));
    addRow(tr("largest contact force [N]"), number(largest));
    if (grain < static_cast<int>(s.network.netForce1.size())) {
        addRow(tr("net force [N]"),
               number(std::hypot(s.network.netForce1[grain], s.network.netForce2[grain])));
    }
    if (grain < static_cast<int>(s.loadBearing.size())) {
        addRow(tr("load-bearing"), s.loadBearing[grain] ? tr("yes") : tr("no (rattler)"));
    }
    addRow(tr("neighbours"), neighbours.join(QStringLiteral(" ")));
}

} // namespace grainlab::ui
