// The study file reader: a valid file read into its spec (knobs in the knob table's order,
// defaults, the base inlined), and a table of bad files, each refused naming the key.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "grainlab/strict_json.h"
#include "grainlab/study_file.h"

namespace grainlab {
namespace {

const std::string kFolder = GRAINLAB_SOURCE_DIR "/resources/studies";

std::string study(const std::string& body) {
    return R"({"base": "../experiments/quick.json", )" + body + "}";
}

TEST(StudyFile, ReadsKnobsReferenceSeedsAndDefaults) {
    const StudySpec s = parseStudyText(study(R"("name": "t", "knobs": {"damping": [{"kind": "none"},
                 {"kind": "cundall_local", "coefficient": 0.7}], "time_step_fraction": [0.5, 0.25]},
                 "reference": {"time_step_fraction": 0.1}, "seeds": 3,
                 "metrics": {"peak_q_over_p": {"tolerance": 0.01}})"),
                                       "t.json", kFolder);
    EXPECT_EQ(s.name, "t");
    ASSERT_EQ(s.knobs.size(), 2u);
    EXPECT_EQ(s.knobs[0].kind, KnobKind::TimeStepFraction); // the knob table's order
    EXPECT_EQ(s.knobs[1].kind, KnobKind::Damping);
    EXPECT_EQ(s.knobs[1].levels[1].label(), "cundall_local-0.7");
    EXPECT_EQ(s.reference.at(KnobKind::TimeStepFraction).number, 0.1);
    EXPECT_EQ(s.seeds, (std::vector<std::uint64_t>{1, 2, 3}));
    EXPECT_EQ(s.design, StudyDesign::OneAtATime);
    EXPECT_EQ(s.costMeasure, "cpu_seconds");
    EXPECT_EQ(s.tolerances.at("peak_q_over_p").value, 0.01);
    EXPECT_FALSE(s.tolerances.at("peak_q_over_p").relative);
    EXPECT_EQ(s.tolerances.at("rms_epsv").value, 0.002); // a default kept
    EXPECT_EQ(s.deciding, (std::vector<std::string>{"peak_q_over_p", "rms_q_over_p", "rms_epsv"}));
    // The folder keeps the study with its base inline: reading that gives the same study.
    EXPECT_NE(s.sourceText.find("\"grains\""), std::string::npos);
    const StudySpec again = parseStudyText(s.sourceText, "study.json", "/nowhere");
    EXPECT_EQ(again.sourceText, s.sourceText);
    EXPECT_EQ(again.baseExperiment.empty(), false);
}

struct BadStudy {
    const char* body; ///< the study file's keys after "base"
    const char* key;  ///< the key path the refusal must name
};

class StudyFileRefuses : public ::testing::TestWithParam<BadStudy> {};

TEST_P(StudyFileRefuses, NamingTheKey) {
    const BadStudy& bad = GetParam();
    try {
        parseStudyText(study(bad.body), "bad.json", kFolder);
        FAIL() << "accepted: " << bad.body;
    } catch (const JsonFileError& e) {
        EXPECT_EQ(e.keyPath, bad.key) << e.what();
        EXPECT_NE(std::string(e.what()).find("bad.json"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(bad.key), std::string::npos) << e.what();
    }
}

INSTANTIATE_TEST_SUITE_P(
    Table, StudyFileRefuses,
    ::testing::Values(
        BadStudy{R"("knobs": {"time_step": [0.5]})", "knobs.time_step"},
        BadStudy{R"("knobs": {})", "knobs"},
        BadStudy{R"("knobs": {"time_step_fraction": []})", "knobs.time_step_fraction"},
        BadStudy{R"("knobs": {"time_step_fraction": [1.5]})", "knobs.time_step_fraction[0]"},
        BadStudy{R"("knobs": {"time_step_fraction": [0.5, 0.5]})", "knobs.time_step_fraction[1]"},
        BadStudy{R"("knobs": {"time_step_fraction": ["a"]})", "knobs.time_step_fraction[0]"},
        BadStudy{R"("knobs": {"grain_count": [100.5]})", "knobs.grain_count[0]"},
        BadStudy{R"("knobs": {"threads": [0]})", "knobs.threads[0]"},
        BadStudy{R"("knobs": {"damping": [{"kind": "none", "coefficient": 0.1}]})",
                 "knobs.damping[0].coefficient"},
        BadStudy{R"("knobs": {"damping": [{"kind": "sticky"}]})", "knobs.damping[0].kind"},
        BadStudy{R"("knobs": {"damping": [0.05]})", "knobs.damping[0]"},
        BadStudy{R"("knobs": {"shape": [{"aspect_ratio": 1.2}]})", "knobs.shape[0].aspect_ratio"},
        BadStudy{R"("knobs": {"shape": [{"eta": 1}]})", "knobs.shape[0].eta"},
        BadStudy{R"("knobs": {"inertial_number": [0]})", "knobs.inertial_number[0]"},
        BadStudy{R"("knobs": {"threads": [1]}, "design": "random")", "design"},
        BadStudy{R"("knobs": {"threads": [1]}, "reference": {"threads": 0})", "reference.threads"},
        BadStudy{R"("knobs": {"threads": [1]}, "seeds": 0)", "seeds"},
        BadStudy{R"("knobs": {"threads": [1]}, "seeds": [1, 1])", "seeds[1]"},
        BadStudy{R"("knobs": {"threads": [1]}, "seeds": [-1])", "seeds[0]"},
        BadStudy{R"("knobs": {"threads": [1]}, "cost": "money")", "cost"},
        BadStudy{R"("knobs": {"threads": [1]}, "metrics": {"peak": {"tolerance": 1}})",
                 "metrics.peak"},
        BadStudy{R"("knobs": {"threads": [1]}, "metrics": {"peak_q_over_p": {"tolerance": 0}})",
                 "metrics.peak_q_over_p.tolerance"},
        BadStudy{R"("knobs": {"threads": [1]},
                    "metrics": {"rms_epsv": {"tolerance": 0.1, "relative": true}})",
                 "metrics.rms_epsv.relative"},
        BadStudy{R"("knobs": {"threads": [1]},
                    "metrics": {"peak_q_over_p": {"tolerance": 0.1, "relative": 1}})",
                 "metrics.peak_q_over_p.relative"},
        BadStudy{R"("knobs": {"threads": [1]}, "deciding": ["DI_max"])", "deciding[0]"},
        BadStudy{R"("knobs": {"threads": [1]}, "deciding": ["peak"])", "deciding[0]"},
        BadStudy{R"("knobs": {"threads": [1]}, "deciding": [])", "deciding"},
        BadStudy{R"("knobs": {"threads": [1]}, "name": "a b")", "name"},
        BadStudy{R"("knobs": {"threads": [1]}, "seed": 3)", "seed"}));

TEST(StudyFile, RefusesAMissingOrBadBase) {
    EXPECT_THROW(parseStudyText(R"({"knobs": {"threads": [1]}})", "b.json", kFolder),
                 JsonFileError);
    try {
        parseStudyText(R"({"base": "nowhere.json", "knobs": {"threads": [1]}})", "b.json", kFolder);
        FAIL();
    } catch (const JsonFileError& e) {
        EXPECT_NE(std::string(e.what()).find("nowhere.json"), std::string::npos) << e.what();
    }
    try {
        parseStudyText(R"({"base": {"name": "x"}, "knobs": {"threads": [1]}})", "b.json", kFolder);
        FAIL();
    } catch (const JsonFileError& e) {
        EXPECT_EQ(e.keyPath.rfind("base", 0), 0u) << e.what();
    }
}

TEST(StudyFile, EveryPresetReads) {
    int presets = 0;
    for (const auto& entry : std::filesystem::directory_iterator(kFolder)) {
        if (entry.path().extension() == ".json") {
            EXPECT_NO_THROW(readStudyFile(entry.path().string())) << entry.path();
            ++presets;
        }
    }
    EXPECT_GE(presets, 1);
}

} // namespace
} // namespace grainlab
