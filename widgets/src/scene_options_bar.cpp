// See scene_options_bar.h.
#include "grainlab/ui/scene_options_bar.h"

#include <QCheckBox>
#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>

#include "grainlab/ui/scene_renderer.h"
#include "grainlab/ui/scene_view.h"

namespace grainlab::ui {

SceneOptionsBar::SceneOptionsBar(SceneView* scene, QWidget* parent)
    : QWidget(parent), scene_(scene), colouring_(new QComboBox), forceChains_(new QComboBox),
      voidCells_(new QComboBox), rose_(new QCheckBox(tr("normal rose"))),
      images_(new QCheckBox(tr("periodic images"))) {
    auto* row = new QHBoxLayout(this);
    row->setContentsMargins(4, 2, 4, 2);
    colouring_->addItems(
        {tr("size"), tr("rotation"), tr("coordination"), tr("load-bearing"), tr("uniform")});
    forceChains_->addItems({tr("no force chains"), tr("strong force chains"), tr("all forces")});
    voidCells_->addItems(
        {tr("no void cells"), tr("void cells by valence"), tr("void cells by area")});
    auto* fit = new QPushButton(tr("Fit"));
    row->addWidget(new QLabel(tr("Colour:")));
    row->addWidget(colouring_);
    row->addWidget(forceChains_);
    row->addWidget(voidCells_);
    row->addWidget(rose_);
    row->addWidget(images_);
    row->addStretch(1);
    row->addWidget(fit);
    connect(colouring_, &QComboBox::currentIndexChanged, this, &SceneOptionsBar::apply);
    connect(forceChains_, &QComboBox::currentIndexChanged, this, &SceneOptionsBar::apply);
    connect(voidCells_, &QComboBox::currentIndexChanged, this, &SceneOptionsBar::apply);
    connect(rose_, &QCheckBox::toggled, this, &SceneOptionsBar::apply);
    connect(images_, &QCheckBox::toggled, this, [this] {
        apply();
        scene_->fitToCell();
    });
    connect(fit, &QPushButton::clicked, scene_, &SceneView::fitToCell);
}

void SceneOptionsBar::apply() {
    SceneOptions o = scene_->renderer().options();
    o.colouring = static_cast<GrainColouring>(colouring_->currentIndex());
    o.forceChains = static_cast<ForceChains>(forceChains_->currentIndex());
    o.voidCells = static_cast<VoidCellShading>(voidCells_->currentIndex());
    o.contactRose = rose_->isChecked();
    o.periodicImages = images_->isChecked();
    scene_->setOptions(o);
}

} // namespace grainlab::ui
