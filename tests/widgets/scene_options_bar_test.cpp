// The scene's options bar sets the view's options choice by choice, in the order of the
// renderer's enums, and keeps what it does not show (the selection, the colours).
#include <QCheckBox>
#include <QComboBox>
#include <QTest>

#include <gtest/gtest.h>

#include "grainlab/ui/scene_options_bar.h"
#include "grainlab/ui/scene_renderer.h"
#include "grainlab/ui/scene_view.h"

namespace grainlab::ui {
namespace {

TEST(SceneOptionsBar, StartsAtTheRendererDefaultsAndChangesNothingUntouched) {
    SceneView view;
    SceneOptionsBar bar(&view);
    const SceneOptions defaults;
    const SceneOptions& o = view.renderer().options();
    EXPECT_EQ(bar.colouringBox()->currentIndex(), static_cast<int>(defaults.colouring));
    EXPECT_EQ(bar.forceChainsBox()->currentIndex(), static_cast<int>(defaults.forceChains));
    EXPECT_EQ(bar.voidCellsBox()->currentIndex(), static_cast<int>(defaults.voidCells));
    EXPECT_EQ(bar.roseBox()->isChecked(), defaults.contactRose);
    EXPECT_EQ(bar.periodicImagesBox()->isChecked(), defaults.periodicImages);
    EXPECT_EQ(o.colouring, defaults.colouring);
    EXPECT_EQ(o.periodicImages, defaults.periodicImages);
}

TEST(SceneOptionsBar, EveryChoiceReachesTheViewAndTheRestIsKept) {
    SceneView view;
    SceneOptionsBar bar(&view);
    view.renderer().options().selectedGrain = 7;
    view.renderer().options().rotationRange = 0.25;
    bar.show();
    const SceneOptions& o = view.renderer().options();
    const GrainColouring colourings[] = {GrainColouring::Size, GrainColouring::Rotation,
                                         GrainColouring::Coordination, GrainColouring::LoadBearing,
                                         GrainColouring::Uniform};
    for (int i = 4; i >= 0; --i) {
        bar.colouringBox()->setCurrentIndex(i);
        EXPECT_EQ(o.colouring, colourings[i]) << i;
    }
    const ForceChains chains[] = {ForceChains::Off, ForceChains::Strong, ForceChains::All};
    for (int i = 2; i >= 0; --i) {
        bar.forceChainsBox()->setCurrentIndex(i);
        EXPECT_EQ(o.forceChains, chains[i]) << i;
    }
    const VoidCellShading shadings[] = {VoidCellShading::Off, VoidCellShading::Valence,
                                        VoidCellShading::Area};
    for (int i = 2; i >= 0; --i) {
        bar.voidCellsBox()->setCurrentIndex(i);
        EXPECT_EQ(o.voidCells, shadings[i]) << i;
    }
    QTest::mouseClick(bar.roseBox(), Qt::LeftButton);
    EXPECT_TRUE(o.contactRose);
    QTest::mouseClick(bar.periodicImagesBox(), Qt::LeftButton);
    EXPECT_TRUE(o.periodicImages);
    EXPECT_EQ(o.selectedGrain, 7);
    EXPECT_DOUBLE_EQ(o.rotationRange, 0.25);
}

} // namespace
} // namespace grainlab::ui
