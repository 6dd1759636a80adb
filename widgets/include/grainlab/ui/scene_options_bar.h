#pragma once
// The row of display options above the scene: grain colouring, force chains, void cells, the
// contact-normal rose, periodic images, and a Fit button. It drives one SceneView: a changed
// choice sets the view's options (the fields the bar does not show, e.g. the selection, are
// kept), periodic images and Fit refit the cell into the view. It starts at the renderer's
// default options and changes nothing until a choice changes. GUI thread only.

#include <QWidget>

class QCheckBox;
class QComboBox;

namespace grainlab::ui {

class SceneView;

class SceneOptionsBar : public QWidget {
    Q_OBJECT
public:
    explicit SceneOptionsBar(SceneView* scene, QWidget* parent = nullptr);

    /// In the order of GrainColouring, ForceChains and VoidCellShading.
    QComboBox* colouringBox() const { return colouring_; }
    QComboBox* forceChainsBox() const { return forceChains_; }
    QComboBox* voidCellsBox() const { return voidCells_; }
    QCheckBox* roseBox() const { return rose_; }
    QCheckBox* periodicImagesBox() const { return images_; }

private:
    void apply();

    SceneView* scene_;
    QComboBox* colouring_;
    QComboBox* forceChains_;
    QComboBox* voidCells_;
    QCheckBox* rose_;
    QCheckBox* images_;
};

} // namespace grainlab::ui
