// The ParaView export (app/export): the sampled outlines against the exact oval, the frames
// chosen per test, the pieces of a run file with grains and contacts across the periodic
// boundary (closed polygons, split chains, the stored forces to the bit), and the refusals of
// bad input, which leave nothing behind. The files themselves are read back with VTK's own
// readers by tests/scripts/vtk_export_test.sh.

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "export/vtk_export.h"
#include "grainlab/run_file.h"
#include "grainlab/simulation.h"
#include "grainlab/void_cells.h"
#include "scenes.h"

namespace grainlab {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
    const fs::path p =
        fs::temp_directory_path() / fmt::format("grainlab-test-export-{}-{}", name, getpid());
    fs::remove_all(p);
    fs::create_directories(p);
    return p;
}

/// Distance from point p to the segment a-b.
double segmentDistance(std::array<double, 2> p, std::array<double, 2> a, std::array<double, 2> b) {
    const double dx = b[0] - a[0], dy = b[1] - a[1];
    const double t =
        std::clamp(((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
    return std::hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy);
}

double signedArea(const std::vector<std::array<double, 2>>& polygon) {
    double twice = 0.0;
    for (std::size_t k = 0; k < polygon.size(); ++k) {
        const auto& p = polygon[k];
        const auto& q = polygon[(k + 1) % polygon.size()];
        twice += p[0] * q[1] - q[0] * p[1];
    }
    return 0.5 * twice;
}

TEST(OutlinePolygon, LiesWithinOnePercentOfTheWidthOfTheExactOval) {
    const std::vector<OvalShape> shapes{makeOval(1e-3, 0.3), makeOval(1e-3, 0.6),
                                        makeOval(2e-3, 0.9), makeOval(1.5e-3, 1.0),
                                        makeOval(2e-3, 0.5, OvalClosure::EndRadiusRatio, 0.1)};
    for (const OvalShape& s : shapes) {
        SCOPED_TRACE(fmt::format("W = {} m, H/W = {}", s.width, s.height / s.width));
        const double tolerance = kOutlineTolerance * s.width;
        const auto polygon = outlinePolygon(s, tolerance);
        ASSERT_GE(polygon.size(), 8u);
        // Every vertex lies on one of the four arcs, in that arc's range of normals.
        const auto arcs = s.arcs();
        for (const auto& p : polygon) {
            bool onArc = false;
            for (int k = 0; k < 4; ++k) {
                const double dx = p[0] - arcs[k].centreX, dy = p[1] - arcs[k].centreY;
                const double d = std::hypot(dx, dy);
                onArc = onArc || (std::fabs(d - arcs[k].radius) <= 1e-12 * s.width &&
                                  arcAdmits(s, k, dx / d, dy / d));
            }
            EXPECT_TRUE(onArc) << "vertex (" << p[0] << ", " << p[1] << ") not on the outline";
        }
        // The exact outline, densely sampled, stays within the tolerance of the polygon.
        double worst = 0.0;
        for (int j = 0; j < 20000; ++j) {
            const auto q = s.boundaryPoint(2.0 * std::numbers::pi * j / 20000.0);
            double nearest = std::numeric_limits<double>::infinity();
            for (std::size_t k = 0; k < polygon.size(); ++k) {
                nearest = std::min(
                    nearest, segmentDistance(q, polygon[k], polygon[(k + 1) % polygon.size()]));
            }
            worst = std::max(worst, nearest);
        }
        EXPECT_LE(worst, tolerance * (1.0 + 1e-9));
        // Counter-clockwise, inside the convex oval, and missing at most perimeter x tolerance
        // of its area (the perimeter is at most pi W).
        const double area = signedArea(polygon);
        EXPECT_GT(area, 0.0);
        EXPECT_LE(area, s.area);
        EXPECT_GE(area, s.area - std::numbers::pi * s.width * tolerance);
    }
}

TEST(OutlinePolygon, TheChordsAreNotNeedlesslyFine) {
    // Halving the tolerance needs more points; the quick experiment's ovals need a few dozen.
    const OvalShape s = makeOval(1e-3, 0.6);
    const auto coarse = outlinePolygon(s, 0.01 * s.width);
    const auto fine = outlinePolygon(s, 0.0025 * s.width);
    EXPECT_GT(fine.size(), coarse.size());
    EXPECT_LE(coarse.size(), 40u);
}

CheckpointInfo info(const std::string& name, const std::string& test, std::int64_t step,
                    double eps1, bool peak = false) {
    CheckpointInfo c;
    c.name = name;
    c.test = test;
    c.step = step;
    c.axialStrain = eps1;
    c.peak = peak;
    c.stageKind = test == "compaction" ? "compaction" : "shear";
    return c;
}

std::vector<std::string> names(const VtkTestFrames& t) {
    std::vector<std::string> out;
    for (const VtkFrame& f : t.frames) {
        out.push_back(f.checkpoint);
    }
    return out;
}

TEST(ChooseFrames, OnePerTimeInIncreasingTimePerTest) {
    // As a run writes them: the compaction (whose eps1 rebounds), the equilibration and the
    // start of the test at eps1 = 0, and a peak written at the end of its test.
    const std::vector<CheckpointInfo> file{info("c0", "compaction", 0, 0.0),
                                           info("c1", "compaction", 500, 0.49),
                                           info("c2", "compaction", 800, 0.48),
                                           info("e", "p015kPa", 800, 0.0),
                                           info("s0", "p015kPa", 900, 0.0),
                                           info("s1", "p015kPa", 1900, 0.01),
                                           info("peak", "p015kPa", 2400, 0.015, true),
                                           info("s2", "p015kPa", 2900, 0.02),
                                           info("s3", "p015kPa", 3900, 0.03),
                                           info("x", "", 3900, 0.0)};
    const auto all = chooseFrames(file, 1, {});
    ASSERT_EQ(all.size(), 2u);
    EXPECT_EQ(all[0].test, "compaction");
    EXPECT_TRUE(all[0].timeIsStep);
    EXPECT_EQ(names(all[0]), (std::vector<std::string>{"c0", "c1", "c2"}));
    EXPECT_EQ(all[0].frames[2].time, 800.0);
    EXPECT_EQ(all[1].test, "p015kPa");
    EXPECT_EQ(all[1].firstCheckpoint, "e");
    EXPECT_FALSE(all[1].timeIsStep);
    EXPECT_EQ(names(all[1]), (std::vector<std::string>{"s0", "s1", "peak", "s2", "s3"}));
    for (const VtkTestFrames& t : all) {
        for (std::size_t k = 1; k < t.frames.size(); ++k) {
            EXPECT_GT(t.frames[k].time, t.frames[k - 1].time) << t.test;
        }
    }
    EXPECT_EQ(all[1].frames[1].time, 0.01);

    const auto every2 = chooseFrames(file, 2, {});
    EXPECT_EQ(names(every2[1]), (std::vector<std::string>{"s0", "peak", "s3"}));
    const auto every3 = chooseFrames(file, 3, {});
    EXPECT_EQ(names(every3[1]), (std::vector<std::string>{"s0", "s2", "s3"})); // last kept

    const auto strains = chooseFrames(file, 1, {0.0, 0.011, 0.012, 0.1});
    EXPECT_EQ(names(strains[1]), (std::vector<std::string>{"s0", "s1", "s3"}));
    EXPECT_EQ(names(strains[0]), (std::vector<std::string>{"c0"})); // nearest to all four
}

/// Six 2 mm ovals (H/W = 0.6) in a 10 mm square cell: grain 0 across the left boundary touches
/// grain 1's image through it, grain 4 across the top touches grain 5's image, grains 2 and 3
/// touch inside the cell. Every overlap is 20 um.
Simulation acrossTheBoundary() {
    const double w = 2e-3, mm = 1e-3, h = std::numbers::pi / 2;
    return Simulation(test::makeScene({{0.3 * mm, 5 * mm, 0, 0.01, -0.02, 0.5, w, 0.6},
                                       {8.32 * mm, 5 * mm, 0, 0, 0, 0, w, 0.6},
                                       {4 * mm, 5 * mm, 0, 0, 0, 0, w, 0.6},
                                       {5.98 * mm, 5 * mm, 0, 0, 0, 0, w, 0.6},
                                       {5 * mm, 9.8 * mm, h, 0, 0, 0, w, 0.6},
                                       {5 * mm, 1.78 * mm, h, 0, 0, 0, w, 0.6}},
                                      10 * mm, 10 * mm, test::bareParameters()));
}

/// A run file of one shear test "p015kPa" with a checkpoint of `sim` at each of `strains`,
/// `steps` steps apart; the last one's runner state says the run finished when `finished`.
void writeRun(const fs::path& folder, Simulation& sim, const std::vector<double>& strains,
              bool finished, std::int64_t steps = 2) {
    fs::create_directories(folder);
    RunFile file((folder / "run.h5").string(), "{}");
    const std::vector<double> theta0 = sim.stateRef().grains.theta;
    for (std::size_t k = 0; k < strains.size(); ++k) {
        if (k > 0) {
            sim.advance(steps);
        }
        const SimulationState state = sim.state();
        const ContactNetwork network = sim.contactNetwork();
        const VoidCellSet cells = computeVoidCells(network);
        CheckpointData d;
        d.name = fmt::format("{:06d}-shear-15-kPa-step{}", k + 1, state.step);
        d.state = &state;
        const bool last = k + 1 == strains.size();
        d.runnerState = fmt::format("{{\"phase\": {}}}", last && finished ? 3 : 2);
        d.identity = {"shear", "p015kPa", 15000.0, state.step, strains[k], theta0, false, 0.0};
        d.network = &network;
        d.voidCells = &cells;
        file.checkpoint(d);
    }
    file.close();
}

std::vector<std::string> listing(const fs::path& folder) {
    std::vector<std::string> out;
    for (const auto& e : fs::recursive_directory_iterator(folder)) {
        out.push_back(fs::relative(e.path(), folder).string());
    }
    std::sort(out.begin(), out.end());
    return out;
}

TEST(VtkExport, GrainsAcrossThePeriodicBoundaryAreClosedPolygonsAndTheirChainsSplit) {
    const fs::path dir = scratch("periodic");
    Simulation sim = acrossTheBoundary();
    writeRun(dir / "run", sim, {0.0, 0.01}, true);
    const std::string path = (dir / "run" / "run.h5").string();
    const std::string last = listCheckpoints(path).back();
    const StoredContacts contacts = readContacts(path, last);
    const SimulationState state = readState(path, checkpointGroup(last));
    const SimulationState start = readState(path, checkpointGroup(listCheckpoints(path)[0]));
    ASSERT_EQ(contacts.first.size(), 3u);

    // Grains: one closed polygon each about its wrapped centre, grain 0 sticking out left.
    const VtkPolyData grains = grainCells(state, contacts, start);
    ASSERT_EQ(grains.cellCount(), 6u);
    std::int64_t from = 0;
    for (std::size_t i = 0; i < 6; ++i) {
        const std::int64_t to = grains.offsets[i];
        std::vector<std::array<double, 2>> polygon;
        for (std::int64_t k = from; k < to; ++k) {
            const auto p = std::size_t(grains.connectivity[std::size_t(k)]);
            polygon.push_back({grains.points[3 * p], grains.points[3 * p + 1]});
            EXPECT_EQ(grains.points[3 * p + 2], 0.0);
            const double d = std::hypot(polygon.back()[0] - contacts.centre1[i],
                                        polygon.back()[1] - contacts.centre2[i]);
            EXPECT_LE(d, 1e-3 * (1 + 1e-12)) << "grain " << i;  // a = W / 2
            EXPECT_GE(d, 0.6e-3 * (1 - 0.02)) << "grain " << i; // b, less the tolerance
        }
        EXPECT_NE(polygon.front(), polygon.back()); // VTK closes a polygon itself
        const double area = signedArea(polygon);
        EXPECT_NEAR(area, state.shapes[i].area, 0.03 * state.shapes[i].area) << "grain " << i;
        if (i == 0) {
            double left = 1.0;
            for (const auto& p : polygon) {
                left = std::min(left, p[0]);
            }
            EXPECT_LT(left, -0.6e-3); // across the left boundary, whole
        }
        from = to;
    }
    // The displacement counts from the test's first checkpoint: grain 0 moves.
    const VtkArray& displacement = grains.cellData.back();
    ASSERT_EQ(displacement.name, "displacement");
    EXPECT_EQ(displacement.float64[0], state.grains.x1[0] - start.grains.x1[0]);
    EXPECT_NE(displacement.float64[0], 0.0);

    // Contacts: the two through the boundary as two halves each, the forces as stored.
    const VtkPolyData lines = contactCells(contacts, state.cell);
    ASSERT_EQ(lines.cellCount(), 5u);
    const auto array = [&](const std::string& name) -> const VtkArray& {
        for (const VtkArray& a : lines.cellData) {
            if (a.name == name) {
                return a;
            }
        }
        throw std::runtime_error("no array " + name);
    };
    int halves = 0;
    for (std::size_t cellIndex = 0; cellIndex < lines.cellCount(); ++cellIndex) {
        const auto c = std::size_t(array("contact").int64[cellIndex]);
        EXPECT_EQ(std::bit_cast<std::uint64_t>(array("normal_force").float64[cellIndex]),
                  std::bit_cast<std::uint64_t>(contacts.normalForce[c]));
        EXPECT_EQ(std::bit_cast<std::uint64_t>(array("tangential_force").float64[cellIndex]),
                  std::bit_cast<std::uint64_t>(contacts.tangentialForce[c]));
        EXPECT_EQ(array("strong").uint8[cellIndex], contacts.strong[c]);
        EXPECT_EQ(array("sliding").uint8[cellIndex], contacts.sliding[c]);
        const bool across = contacts.shift1[c] != 0 || contacts.shift2[c] != 0;
        const std::uint8_t segment = array("segment").uint8[cellIndex];
        EXPECT_EQ(segment != 0, across);
        const auto p0 = std::size_t(lines.connectivity[2 * cellIndex]);
        const auto p1 = std::size_t(lines.connectivity[2 * cellIndex + 1]);
        const std::size_t owner =
            std::size_t(segment == 2 ? contacts.second[c] : contacts.first[c]);
        EXPECT_EQ(lines.points[3 * p0], contacts.centre1[owner]);
        EXPECT_EQ(lines.points[3 * p0 + 1], contacts.centre2[owner]);
        if (segment == 1) {
            ++halves;
            EXPECT_EQ(lines.points[3 * p1], contacts.point1[c]);
            EXPECT_EQ(lines.points[3 * p1 + 1], contacts.point2[c]);
            // The two halves add up to the branch vector.
            const auto q0 = std::size_t(lines.connectivity[2 * cellIndex + 2]);
            const auto q1 = std::size_t(lines.connectivity[2 * cellIndex + 3]);
            const double sum1 = lines.points[3 * p1] - lines.points[3 * p0] + lines.points[3 * q0] -
                                lines.points[3 * q1];
            const double sum2 = lines.points[3 * p1 + 1] - lines.points[3 * p0 + 1] +
                                lines.points[3 * q0 + 1] - lines.points[3 * q1 + 1];
            EXPECT_NEAR(sum1, contacts.branch1[c], 1e-15);
            EXPECT_NEAR(sum2, contacts.branch2[c], 1e-15);
            // Each half stays within its grain's reach of its centre (not across the cell).
            EXPECT_LT(std::hypot(lines.points[3 * p1] - lines.points[3 * p0],
                                 lines.points[3 * p1 + 1] - lines.points[3 * p0 + 1]),
                      1.1e-3);
        }
    }
    EXPECT_EQ(halves, 2);

    // The export writes the files and the time index, and leaves nothing else beside them.
    VtkExportOptions options;
    options.run = (dir / "run").string();
    options.out = (dir / "vtk").string();
    const VtkExportSummary summary = exportVtk(options);
    EXPECT_EQ(summary.tests, 1);
    EXPECT_EQ(summary.frames, 2);
    EXPECT_EQ(summary.files, 9);
    EXPECT_EQ(listing(dir / "vtk"),
              (std::vector<std::string>{"p015kPa", "p015kPa.pvd", "p015kPa/cell_0000.vtp",
                                        "p015kPa/cell_0001.vtp", "p015kPa/contacts_0000.vtp",
                                        "p015kPa/contacts_0001.vtp", "p015kPa/grains_0000.vtp",
                                        "p015kPa/grains_0001.vtp", "p015kPa/void_cells_0000.vtp",
                                        "p015kPa/void_cells_0001.vtp"}));
    EXPECT_EQ(listing(dir),
              (std::vector<std::string>{
                  "run", "run/run.h5", "vtk", "vtk/p015kPa", "vtk/p015kPa.pvd",
                  "vtk/p015kPa/cell_0000.vtp", "vtk/p015kPa/cell_0001.vtp",
                  "vtk/p015kPa/contacts_0000.vtp", "vtk/p015kPa/contacts_0001.vtp",
                  "vtk/p015kPa/grains_0000.vtp", "vtk/p015kPa/grains_0001.vtp",
                  "vtk/p015kPa/void_cells_0000.vtp", "vtk/p015kPa/void_cells_0001.vtp"}));
    fs::remove_all(dir);
}

/// The refusal's message, and that nothing was written: the parent folder lists as before.
void expectRefused(const VtkExportOptions& options, const std::vector<std::string>& words) {
    const fs::path parent = fs::path(options.out).parent_path();
    const std::vector<std::string> before = listing(parent);
    try {
        exportVtk(options);
        ADD_FAILURE() << "not refused: " << options.run;
    } catch (const VtkExportRefused& e) {
        for (const std::string& word : words) {
            EXPECT_NE(std::string(e.what()).find(word), std::string::npos)
                << "\"" << word << "\" not in: " << e.what();
        }
    }
    EXPECT_EQ(listing(parent), before);
}

TEST(VtkExport, RefusesBadInputNamingTheFileAndWritesNothing) {
    const fs::path dir = scratch("refusals");
    Simulation sim = acrossTheBoundary();
    writeRun(dir / "finished", sim, {0.0, 0.01}, true);
    Simulation again = acrossTheBoundary();
    writeRun(dir / "unfinished", again, {0.0, 0.01}, false);
    fs::create_directories(dir / "exports");
    VtkExportOptions options;
    options.out = (dir / "exports" / "out").string();

    // Not a run folder.
    fs::create_directories(dir / "empty");
    options.run = (dir / "empty").string();
    expectRefused(options, {(dir / "empty").string(), "run.h5", "not a run folder"});
    options.run = (dir / "nowhere").string();
    expectRefused(options, {(dir / "nowhere").string(), "run folder"});

    // An unfinished run, unless asked for.
    options.run = (dir / "unfinished").string();
    expectRefused(options,
                  {(dir / "unfinished" / "run.h5").string(), "not finished", "--unfinished"});

    // A damaged run file: cut short, or not HDF5 at all.
    fs::create_directories(dir / "cut");
    const std::string whole = test::slurp((dir / "finished" / "run.h5").string());
    std::ofstream((dir / "cut" / "run.h5"), std::ios::binary)
        .write(whole.data(), std::streamsize(whole.size() / 2));
    options.run = (dir / "cut").string();
    expectRefused(options, {(dir / "cut" / "run.h5").string(), "cannot be read"});
    fs::create_directories(dir / "text");
    std::ofstream(dir / "text" / "run.h5") << "not a run file\n";
    options.run = (dir / "text").string();
    expectRefused(options, {(dir / "text" / "run.h5").string(), "cannot be read"});

    // A damaged dataset (a changed byte of the last checkpoint's normal forces): refused
    // naming the file and the dataset, though the earlier checkpoints read well.
    fs::create_directories(dir / "flipped");
    const std::string finished = (dir / "finished" / "run.h5").string();
    const std::vector<double> forces =
        readContacts(finished, listCheckpoints(finished).back()).normalForce;
    const std::string needle(reinterpret_cast<const char*>(forces.data()),
                             forces.size() * sizeof(double));
    std::string flipped = whole;
    const std::size_t at = flipped.rfind(needle);
    ASSERT_NE(at, std::string::npos);
    flipped[at + 5] = static_cast<char>(flipped[at + 5] ^ 0x5a);
    std::ofstream((dir / "flipped" / "run.h5"), std::ios::binary) << flipped;
    options.run = (dir / "flipped").string();
    expectRefused(options, {(dir / "flipped" / "run.h5").string(), "normal_force"});

    // --out an existing export: refused, its files untouched.
    options.run = (dir / "finished").string();
    options.out = (dir / "exports" / "first").string();
    exportVtk(options);
    const std::string pvd = test::slurp((dir / "exports" / "first" / "p015kPa.pvd").string());
    expectRefused(options, {options.out, "exists already", "does not exist"});
    EXPECT_EQ(test::slurp((dir / "exports" / "first" / "p015kPa.pvd").string()), pvd);

    // Allowed: the unfinished run with --unfinished, into an empty folder.
    fs::create_directories(dir / "exports" / "empty");
    options.run = (dir / "unfinished").string();
    options.out = (dir / "exports" / "empty").string();
    options.unfinished = true;
    EXPECT_EQ(exportVtk(options).frames, 2);
    fs::remove_all(dir);
}

} // namespace
} // namespace grainlab
