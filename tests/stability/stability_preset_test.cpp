// The stability preset reader (docs/stability.md): the shipped presets read, the cells they
// make, and every refusal naming the file, the key and the allowed range.
#include <gtest/gtest.h>

#include "grainlab/stability_map.h"
#include "grainlab/strict_json.h"

namespace grainlab {
namespace {

const std::string kPresets = std::string(GRAINLAB_SOURCE_DIR) + "/resources/stability/";

std::string minimal(const std::string& extra = "", const std::string& axes = "") {
    return R"({)" + extra + R"("axes": {"aspect_ratio": [1, 0.6], "stiffness_ratio": [1],
        "damping": [{"kind": "none"}, {"kind": "local", "coefficient": 0.7}],
        "packing": [{"state": "gas"}, {"state": "shear", "pressure": 15000}])" +
           axes + "}}";
}

/// The message of the refusal of `text`, or "" when it was accepted.
std::string refusal(const std::string& text) {
    try {
        parseStabilityPreset(text, "map.json");
    } catch (const JsonFileError& e) {
        return e.what();
    }
    return "";
}

TEST(StabilityPreset, TheFullPresetIsTheIssuesMap) {
    const StabilityMapSpec spec = readStabilityPreset(kPresets + "full.json");
    EXPECT_EQ(spec.aspectRatios, (std::vector<double>{1.0, 0.8, 0.6, 0.4}));
    EXPECT_EQ(spec.stiffnessRatios, (std::vector<double>{0.25, 0.5, 1.0, 2.0}));
    ASSERT_EQ(spec.dampings.size(), 4u);
    EXPECT_EQ(dampingLabel(spec.dampings[2]), "viscous 0.2");
    EXPECT_EQ(dampingLabel(spec.dampings[3]), "local 0.7");
    ASSERT_EQ(spec.packings.size(), 4u);
    EXPECT_EQ(packingLabel(spec.packings[2]), "dense 100 kPa");
    EXPECT_EQ(stabilityCells(spec).size(), 256u);
}

TEST(StabilityPreset, CellsHaveDistinctFileNameIds) {
    const StabilityMapSpec spec = parseStabilityPreset(minimal(), "map.json");
    const auto cells = stabilityCells(spec);
    ASSERT_EQ(cells.size(), 8u);
    EXPECT_EQ(cells[0].id, "eta1_kt1_none_gas");
    EXPECT_EQ(cells[7].id, "eta0.6_kt1_local0.7_shear15kPa");
    for (std::size_t i = 0; i < cells.size(); ++i) {
        for (std::size_t j = i + 1; j < cells.size(); ++j) {
            EXPECT_NE(cells[i].id, cells[j].id);
        }
    }
    EXPECT_EQ(readStabilityPreset(kPresets + "tiny.json").name, "tiny");
}

TEST(StabilityPreset, RefusesWithFileKeyAndRange) {
    EXPECT_NE(refusal(minimal(R"("probes": {},)")).find("probes"), std::string::npos);
    const std::string wrongType = refusal(minimal(R"("scene": {"grains": "many"},)"));
    EXPECT_NE(wrongType.find("map.json"), std::string::npos) << wrongType;
    EXPECT_NE(wrongType.find("scene.grains"), std::string::npos) << wrongType;
    const std::string range = refusal(minimal(R"("probe": {"precision": 0.9},)"));
    EXPECT_NE(range.find("probe.precision"), std::string::npos) << range;
    EXPECT_NE(range.find("0.5"), std::string::npos) << range;
    const std::string bracket = refusal(minimal(R"("probe": {"bracket": [2, 1]},)"));
    EXPECT_NE(bracket.find("probe.bracket"), std::string::npos) << bracket;
    const std::string eta = refusal(R"({"axes": {"aspect_ratio": [1.5], "stiffness_ratio": [1],
        "damping": [{"kind": "none"}], "packing": [{"state": "gas"}]}})");
    EXPECT_NE(eta.find("axes.aspect_ratio[0]"), std::string::npos) << eta;
    const std::string kind = refusal(R"({"axes": {"aspect_ratio": [1], "stiffness_ratio": [1],
        "damping": [{"kind": "none"}, {"kind": "cundall"}], "packing": [{"state": "gas"}]}})");
    EXPECT_NE(kind.find("axes.damping[1].kind"), std::string::npos) << kind;
    const std::string alpha = refusal(R"({"axes": {"aspect_ratio": [1], "stiffness_ratio": [1],
        "damping": [{"kind": "local", "coefficient": 1.2}], "packing": [{"state": "gas"}]}})");
    EXPECT_NE(alpha.find("axes.damping[0].coefficient"), std::string::npos) << alpha;
    const std::string pressure = refusal(R"({"axes": {"aspect_ratio": [1], "stiffness_ratio": [1],
        "damping": [{"kind": "none"}], "packing": [{"state": "dense"}]}})");
    EXPECT_NE(pressure.find("axes.packing[0].pressure"), std::string::npos) << pressure;
    const std::string gasPressure = refusal(R"({"axes": {"aspect_ratio": [1],
        "stiffness_ratio": [1], "damping": [{"kind": "none"}],
        "packing": [{"state": "gas", "pressure": 1000}]}})");
    EXPECT_NE(gasPressure.find("axes.packing[0].pressure"), std::string::npos) << gasPressure;
    const std::string noAxes = refusal(R"({"name": "x"})");
    EXPECT_NE(noAxes.find("axes"), std::string::npos) << noAxes;
    const std::string empty = refusal(R"({"axes": {"aspect_ratio": [1], "stiffness_ratio": [1],
        "damping": [], "packing": [{"state": "gas"}]}})");
    EXPECT_NE(empty.find("axes.damping"), std::string::npos) << empty;
}

TEST(StabilityPreset, CellResultsRoundTripThroughJson) {
    const StabilityMapSpec spec = parseStabilityPreset(minimal(), "map.json");
    StabilityCellResult r;
    r.cell = stabilityCells(spec)[7];
    r.timeUnit = 3e-6;
    r.limit = {true, 0.81, 0.82, 0.81, BlowUp::UnbalancedFloor, 1000, "jitters", 9};
    r.estimate = 0.5;
    r.estimateTranslational = 0.8;
    r.estimateRotational = 0.5;
    r.accuracy = {{0.5, 0.405, true, 1e-3, 5e-4}};
    r.seconds = 4.5;
    const StabilityCellResult back = parseCellResult(cellResultJson(r), "x.json");
    EXPECT_EQ(back.cell.id, r.cell.id);
    EXPECT_EQ(back.cell.damping.kind, DampingKind::CundallLocal);
    EXPECT_EQ(back.cell.packing.kind, PackingKind::Shear);
    EXPECT_EQ(back.limit.detector, BlowUp::UnbalancedFloor);
    EXPECT_DOUBLE_EQ(back.limit.limit, 0.81);
    ASSERT_EQ(back.accuracy.size(), 1u);
    EXPECT_DOUBLE_EQ(back.accuracy[0].maxResidual, 1e-3);
    const std::string csv = limitsCsv({r, back});
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 3);
    EXPECT_NE(csv.find("limit [sqrt(m_min/k_n)]"), std::string::npos);
    EXPECT_NE(csv.find(",unbalanced_force_floor,"), std::string::npos);
    EXPECT_NE(csv.find(",1.62,"), std::string::npos) << "limit / estimate";
    EXPECT_THROW(parseCellResult("{\"cell\": 1}", "x.json"), std::runtime_error);
}

} // namespace
} // namespace grainlab
