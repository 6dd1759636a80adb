// The Parameters tab must never change the experiment behind the user: an experiment that
// compacts at several pressures and shears only some of the samples keeps its compaction stages
// whatever is typed into the shear list, and the list is refused by the experiment file's own
// rule (each shear pressure one of the compaction pressures, listed once). Typed with QTest.
#include <vector>

#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QTest>

#include <gtest/gtest.h>

#include "grainlab/experiment_file.h"
#include "grainlab/ui/parameters_panel.h"

namespace grainlab::ui {
namespace {

/// The quick experiment, compacted at 15, 25, 50 and 100 kPa, sheared at 100 kPa only.
ExperimentConfig compactFourShearOne() {
    ExperimentConfig c =
        readExperimentFile(GRAINLAB_SOURCE_DIR "/resources/experiments/quick.json");
    c.compaction.pressures = {15e3, 25e3, 50e3, 100e3};
    c.shear.pressures = {100e3};
    return c;
}

void type(QLineEdit* edit, const char* text) {
    edit->selectAll();
    QTest::keyClick(edit, Qt::Key_Backspace);
    QTest::keyClicks(edit, QString::fromLatin1(text));
}

TEST(ParametersPanel, UntouchedPanelGivesBackTheExperiment) {
    ParametersPanel panel;
    const ExperimentConfig c = compactFourShearOne();
    panel.setExperiment(c);
    ASSERT_TRUE(panel.valid()) << panel.problem().toStdString();
    const ExperimentConfig a = panel.applied();
    EXPECT_EQ(a.compaction.pressures, c.compaction.pressures);
    EXPECT_EQ(a.shear.pressures, c.shear.pressures);
}

TEST(ParametersPanel, TheTestIsChosenAndAListOrACyclicTestIsKeptAsTheFileHasIt) {
    ParametersPanel panel;
    for (const char* preset : {"quick-cyclic.json", "quick-critical-state.json"}) {
        const ExperimentConfig c =
            readExperimentFile(std::string(GRAINLAB_SOURCE_DIR "/resources/experiments/") + preset);
        panel.setExperiment(c);
        EXPECT_TRUE(
            panel.testKindEdit()->currentText().startsWith(QStringLiteral("as in the file")))
            << preset << ": " << panel.testKindEdit()->currentText().toStdString();
        const ExperimentConfig kept = panel.applied();
        ASSERT_EQ(kept.tests.size(), c.tests.size()) << preset;
        EXPECT_EQ(kept.tests.front().kind, c.tests.front().kind) << preset;
        EXPECT_EQ(kept.tests.front().amplitude, c.tests.front().amplitude) << preset;
        // Another test chosen replaces the file's.
        panel.testKindEdit()->setCurrentIndex(
            panel.testKindEdit()->findData(QStringLiteral("constant_p")));
        ASSERT_EQ(panel.applied().tests.size(), 1u);
        EXPECT_EQ(panel.applied().tests[0].kind, LoadingPath::Kind::ConstantP);
    }
    // A file of one editable test shows it.
    panel.setExperiment(compactFourShearOne());
    EXPECT_EQ(panel.testKindEdit()->currentData().toString(), QStringLiteral("drained"));
}

TEST(ParametersPanel, EditingTheShearListKeepsTheCompactionStages) {
    ParametersPanel panel;
    const ExperimentConfig c = compactFourShearOne();
    panel.setExperiment(c);
    panel.show();
    QLineEdit* shear = panel.shearPressuresEdit();
    type(shear, "50, 100");
    ASSERT_TRUE(panel.valid()) << panel.problem().toStdString();
    const ExperimentConfig a = panel.applied();
    EXPECT_EQ(a.compaction.pressures, c.compaction.pressures);
    EXPECT_EQ(a.shear.pressures, (std::vector<double>{50e3, 100e3}));
}

TEST(ParametersPanel, ShearListFollowsTheExperimentFileRule) {
    ParametersPanel panel;
    panel.setExperiment(compactFourShearOne());
    panel.show();
    QLineEdit* shear = panel.shearPressuresEdit();
    // Not a compaction pressure: refused, as the experiment file would refuse it, not added as a
    // compaction stage.
    type(shear, "30");
    EXPECT_FALSE(panel.valid());
    EXPECT_TRUE(panel.problem().contains(QStringLiteral("compaction pressures")))
        << panel.problem().toStdString();
    type(shear, "100, 100");
    EXPECT_FALSE(panel.valid());
    EXPECT_TRUE(panel.problem().contains(QStringLiteral("listed once")))
        << panel.problem().toStdString();
    // The file does not ask shear tests to be in ascending order.
    type(shear, "100, 15");
    EXPECT_TRUE(panel.valid()) << panel.problem().toStdString();
    type(shear, "15, abc");
    EXPECT_FALSE(panel.valid());
    EXPECT_TRUE(panel.problem().contains(QStringLiteral("abc")));
    type(shear, "");
    EXPECT_FALSE(panel.valid());
}

TEST(ParametersPanel, PressureTypedAsShownIsTheCompactionPressure) {
    // 12.345 * 1e3 != 12345 in doubles: the panel reads "12.345" kPa as 12345 Pa exactly.
    ExperimentConfig c = compactFourShearOne();
    c.compaction.pressures = {12345.0, 100e3};
    c.shear.pressures = {12345.0};
    ParametersPanel panel;
    panel.setExperiment(c);
    EXPECT_EQ(panel.shearPressuresEdit()->text(), QStringLiteral("12.345"));
    EXPECT_EQ(panel.compactionPressuresLabel()->text(), QStringLiteral("12.345, 100"));
    panel.show();
    type(panel.shearPressuresEdit(), "100, 12.345");
    ASSERT_TRUE(panel.valid()) << panel.problem().toStdString();
    EXPECT_EQ(panel.applied().shear.pressures, (std::vector<double>{100e3, 12345.0}));
}

} // namespace
} // namespace grainlab::ui
