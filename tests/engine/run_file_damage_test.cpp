// Damaged and foreign run files (issue 12): a byte changed anywhere in a run file is either
// refused by the readers with an error naming the file, or changes nothing that they read;
// never a crash, never a silently different result. Files of another format version, and
// files that are not run files, are refused by name.
#include <H5Cpp.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "child_output.h"
#include "grainlab/assembly.h"
#include "grainlab/run_file.h"
#include "grainlab/simulation.h"
#include "grainlab/void_cells.h"
#include "refusal.h"
#include "scenes.h"
#include "scratch_folder.h"

namespace grainlab {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
    return test::scratchFolder("damage", name);
}

std::string slurp(const fs::path& path) {
    return test::slurp(path.string());
}

/// A frictional assembly of 40 grains after some steps: contacts with tangential history.
SimulationState steppedState() {
    return test::squeezedAssembly(40, 5, 600).state();
}

/// Everything the readers give for a run file, flattened to text and bits for comparison.
std::string readEverything(const std::string& path) {
    std::ostringstream out;
    out << readExperimentText(path) << '|' << readSoftwareVersion(path) << '|';
    for (const auto& name : listCheckpoints(path)) {
        const SimulationState s = readState(path, checkpointGroup(name));
        out << name << '|' << readRunnerState(path, checkpointGroup(name)) << '|' << s.step;
        for (const auto* v : {&s.grains.x1, &s.grains.x2, &s.grains.theta, &s.grains.v1,
                              &s.grains.v2, &s.grains.omega, &s.pairs.tangentialForce}) {
            out.write(reinterpret_cast<const char*>(v->data()), std::streamsize(v->size() * 8));
        }
        out << s.pairs.first.size() << s.parameters.friction << s.parameters.timeStep;
    }
    for (double p : listSamples(path)) {
        out << p << readState(path, sampleGroup(p)).grains.x1.size();
    }
    for (const auto& test : listTests(path)) {
        const SeriesTable t = readSeries(path, test);
        out << test;
        for (const auto& c : t.columns) {
            out << c.name << c.unit;
        }
        for (std::size_t r = 0; r < t.rows.size(); ++r) {
            out << t.stages[r];
            out.write(reinterpret_cast<const char*>(t.rows[r].data()),
                      std::streamsize(t.rows[r].size() * 8));
        }
    }
    return out.str();
}

std::string writeRunFile(const fs::path& dir) {
    const std::string path = (dir / "run.h5").string();
    RunFile file(path, "{\"name\": \"damage\", \"seed\": 5}");
    SeriesTable t;
    t.test = "p015kPa";
    t.columns = {{"step", "-"}, {"time", "s"}, {"sigma22", "Pa"}};
    for (int k = 0; k < 30; ++k) {
        t.rows.push_back({1000.0 * k, 1e-3 * k, 15000.0 + k / 7.0});
        t.stages.push_back(k < 10 ? "equilibration 15 kPa" : "shear 15 kPa");
        file.record(t);
    }
    const SimulationState state = steppedState();
    file.sample(15e3, state);
    file.checkpoint("000001-shear-15-kPa-step600", state, "{\"phase\": 2}");
    file.flush();
    return path;
}

TEST(RunFileDamage, EveryChangedByteIsRefusedByNameOrChangesNothing) {
    const fs::path dir = scratch("bytes");
    const std::string path = writeRunFile(dir);
    const std::string reference = readEverything(path);
    const std::string bytes = slurp(path);
    const std::string damaged = (dir / "damaged.h5").string();
    int refused = 0, unchanged = 0;
    // Every byte of the first 1 KiB (superblock and root group), then 1500 spread over the
    // rest. (Every byte of the file, 45,000 files, gave the same verdict: none read differently.)
    std::vector<std::size_t> offsets;
    const std::size_t stride = std::max<std::size_t>(1, bytes.size() / 1500) | 1;
    for (std::size_t o = 0; o < bytes.size(); o += o < 1024 ? 1 : stride) {
        offsets.push_back(o);
    }
    for (std::size_t offset : offsets) {
        std::string copy = bytes;
        copy[offset] = static_cast<char>(copy[offset] ^ 0x5a);
        std::ofstream(damaged, std::ios::binary | std::ios::trunc) << copy;
        try {
            const std::string result = readEverything(damaged);
            ASSERT_TRUE(result == reference)
                << "byte " << offset << " changed what the readers read, without an error";
            ++unchanged;
        } catch (const std::runtime_error& e) {
            ASSERT_NE(std::string(e.what()).find(damaged), std::string::npos)
                << "byte " << offset << ": the error does not name the file: " << e.what();
            ++refused;
        }
    }
    EXPECT_GT(refused, 100);
    std::printf("%zu damaged files: %d refused, %d read unchanged\n", offsets.size(), refused,
                unchanged);
    fs::remove_all(dir);
}

TEST(RunFileDamage, DamagedDataIsRefusedNamingTheDataset) {
    const fs::path dir = scratch("dataset");
    const std::string path = writeRunFile(dir);
    // Find the bytes of /checkpoints/<name>/grains/x1 (its first values) and change one.
    const std::vector<double> x1 = steppedState().grains.x1;
    const std::string needle(reinterpret_cast<const char*>(x1.data()), 4 * sizeof(double));
    const std::size_t found = slurp(path).rfind(needle);
    ASSERT_NE(found, std::string::npos);
    const std::size_t offset = found + 11;
    std::string bytes = slurp(path);
    bytes[offset] = static_cast<char>(bytes[offset] ^ 1);
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
    ASSERT_NO_FATAL_FAILURE(test::expectRefusedNaming(
        [&] { readState(path, checkpointGroup("000001-shear-15-kPa-step600")); },
        {path, "grains/x1", "damaged"}, "a damaged dataset was read"));
    fs::remove_all(dir);
}

TEST(RunFileDamage, OtherVersionsAndOtherFilesAreRefusedByName) {
    const fs::path dir = scratch("version");
    const std::string path = writeRunFile(dir);
    {
        H5::H5File file(path, H5F_ACC_RDWR);
        H5::Group root = file.openGroup("/");
        root.removeAttr("format_version");
        const std::int32_t one = 1;
        root.createAttribute("format_version", H5::PredType::STD_I32LE, H5::DataSpace(H5S_SCALAR))
            .write(H5::PredType::NATIVE_INT32, &one);
    }
    for (const auto& read : {+[](const std::string& p) { listCheckpoints(p); },
                             +[](const std::string& p) { readExperimentText(p); },
                             +[](const std::string& p) { listTests(p); }}) {
        ASSERT_NO_FATAL_FAILURE(test::expectRefusedNaming([&] { read(path); }, {path, "version 1"},
                                                          "a version 1 file was read"));
    }
    EXPECT_THROW(RunFile(path, "{\"name\": \"damage\", \"seed\": 5}", RunFile::Mode::Resume),
                 std::runtime_error);
    // Not an HDF5 file at all, and an HDF5 file that is not a run file.
    const std::string text = (dir / "text.h5").string();
    std::ofstream(text) << "not a run file";
    const std::string other = (dir / "other.h5").string();
    H5::H5File(other, H5F_ACC_TRUNC).close();
    for (const std::string& p : {text, other}) {
        ASSERT_NO_FATAL_FAILURE(test::expectRefusedNaming([&] { listCheckpoints(p); }, {p}, p));
    }
    fs::remove_all(dir);
}

TEST(RunFileDamage, ReadOnlyFileNamesTheCause) {
    const fs::path dir = scratch("readonly");
    const std::string path = writeRunFile(dir);
    fs::permissions(path, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
    fs::permissions(dir, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                             fs::perms::others_read | fs::perms::others_exec);
    // Root may write any file: the attempt runs in a child that gives up root (if it has it).
    const test::ChildOutput r = test::childOutput([&](int out) {
        if (::geteuid() == 0 && (::setgid(65534) != 0 || ::setuid(65534) != 0)) {
            _exit(3);
        }
        std::string message = "opened";
        try {
            RunFile file(path, "{\"name\": \"damage\", \"seed\": 5}", RunFile::Mode::Resume);
        } catch (const std::runtime_error& e) {
            message = e.what();
        }
        (void)!::write(out, message.data(), message.size());
        _exit(0);
    });
    ASSERT_TRUE(WIFEXITED(r.status) && WEXITSTATUS(r.status) == 0) << "could not give up root";
    const std::string& what = r.output;
    EXPECT_NE(what, "opened") << "a read-only file was opened for writing";
    EXPECT_NE(what.find(path), std::string::npos) << what;
    EXPECT_NE(what.find("Permission denied"), std::string::npos) << what;
    EXPECT_EQ(what.find("H5File::H5File"), std::string::npos) << what;
    fs::remove_all(dir);
}

TEST(RunFileDamage, AFileOpenForWritingElsewhereNamesTheCause) {
    const fs::path dir = scratch("locked");
    const std::string path = writeRunFile(dir);
    int ready[2];
    ASSERT_EQ(::pipe(ready), 0);
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        // Another process holds the file open for writing.
        RunFile writer(path, "{\"name\": \"damage\", \"seed\": 5}", RunFile::Mode::Resume);
        const char c = 'r';
        (void)!::write(ready[1], &c, 1);
        ::sleep(30);
        _exit(0);
    }
    char c = 0;
    ASSERT_EQ(::read(ready[0], &c, 1), 1);
    try {
        RunFile second(path, "{\"name\": \"damage\", \"seed\": 5}", RunFile::Mode::Resume);
        ADD_FAILURE() << "a file open for writing was opened again for writing";
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(path), std::string::npos) << what;
        EXPECT_NE(what.find("in use by another program"), std::string::npos) << what;
        EXPECT_EQ(what.find("H5File::H5File"), std::string::npos) << what;
    }
    kill(child, SIGKILL);
    waitpid(child, nullptr, 0);
    fs::remove_all(dir);
}

} // namespace
} // namespace grainlab
