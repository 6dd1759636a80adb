// The LAMMPS data reader of `grainlab bench` (app/bench/lammps_peer.h): the disk benchmark
// assembly must be the one LAMMPS runs: same grains, sizes, masses, box and contacts.
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "bench/lammps_peer.h"
#include "grainlab/simulation.h"

namespace grainlab {
namespace {

const std::string kDense = std::string(GRAINLAB_SOURCE_DIR) + "/resources/bench/lammps/dense.data";

TEST(LammpsData, DenseAssemblyMatchesTheLammpsReadme) {
    const SimulationState s = readLammpsDisks(kDense, SimulationParameters{});
    ASSERT_EQ(s.grains.size(), 8450u);
    ASSERT_EQ(s.shapes.size(), 11u); // diameters 1.0, 1.1, ..., 2.0 mm
    EXPECT_NEAR(s.shapes.front().width, 1e-3, 1e-15);
    EXPECT_NEAR(s.shapes.back().width, 2e-3, 1e-15);
    // Square periodic box, L = 0.136102038 m (README "Dense state").
    EXPECT_NEAR(s.cell[0], 0.136102038, 1e-9);
    EXPECT_NEAR(s.cell[3], 0.136102038, 1e-9);
    double area = 0, mass = 0;
    for (std::size_t i = 0; i < s.grains.size(); ++i) {
        const OvalShape& shape = s.shapes[s.grains.shape[i]];
        EXPECT_TRUE(shape.isDisk);
        area += shape.area;
        mass += 2650 * shape.area;
        ASSERT_GE(s.grains.x1[i], 0.0);
        ASSERT_LE(s.grains.x1[i], s.cell[0]);
        ASSERT_GE(s.grains.x2[i], 0.0);
        ASSERT_LE(s.grains.x2[i], s.cell[3]);
    }
    // Total mass 41.5509 kg and packing fraction 0.84646 (README).
    EXPECT_NEAR(mass, 41.5509, 1e-4);
    EXPECT_NEAR(area / (s.cell[0] * s.cell[3]), 0.84646, 1e-5);
}

TEST(LammpsData, ContactsAndPressureMatchLammps) {
    // LAMMPS (in.coord): Z = 3.997 contacts per particle, P = 100 kPa. The engine's contact
    // detection on the same positions must find the same contact count and a pressure close to
    // LAMMPS's (its Hooke normal force kn * overlap is the engine's; the damping and tangential
    // forces are zero in the frictionless, zero-velocity state).
    SimulationParameters p;
    p.friction = 0.0;
    Simulation sim(readLammpsDisks(kDense, p));
    const double z = 2.0 * double(sim.contactCount()) / double(sim.grainCount());
    EXPECT_NEAR(z, 3.997, 0.0005);
    const Stress s = sim.stress();
    EXPECT_NEAR(0.5 * (s.s11 + s.s22), 1e5, 0.002e5);
    // LAMMPS reports Pxx = 100.6 kPa and Pyy = 99.4 kPa; its y is the engine's x1.
    EXPECT_NEAR(s.s11, 99.4e3, 0.2e3);
    EXPECT_NEAR(s.s22, 100.6e3, 0.2e3);
}

TEST(LammpsData, UnreadableOrWrongFilesAreNamed) {
    EXPECT_THROW(readLammpsDisks("/nonexistent/dense.data", SimulationParameters{}),
                 std::runtime_error);
    const std::string path = testing::TempDir() + "grainlab_bad.data";
    {
        std::ofstream out(path);
        out << "title\n\n2 atoms\n1 atom types\n0 1 xlo xhi\n0 1 ylo yhi\n\nAtoms # sphere\n\n"
               "1 1 0.001 1000 0.5 0.5 0 0 0 0\n"; // announces 2, holds 1; wrong mass too
    }
    try {
        readLammpsDisks(path, SimulationParameters{});
        FAIL() << "expected an error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
    std::remove(path.c_str());
}

} // namespace
} // namespace grainlab
