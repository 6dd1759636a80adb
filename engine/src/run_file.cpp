#include "grainlab/run_file.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <map>
#include <stdexcept>

#include <functional>

#include <fmt/format.h>

#include "run_file_driver.h"
#include "run_file_io.h"
#include "run_file_room.h"

#ifndef GRAINLAB_VERSION
#define GRAINLAB_VERSION "unknown"
#endif

namespace grainlab {

namespace {

constexpr hsize_t kSeriesChunk = 1024; ///< rows per chunk of a series dataset
constexpr const char* kWritingSuffix = ".writing";
constexpr double kRecordFlushSeconds = 2.0;

using namespace hdf5io;

/// Next write-order index among the children of `parent` (attribute `index`).
std::int64_t nextIndex(const H5::Group& parent) {
    std::int64_t next = 0;
    for (hsize_t i = 0; i < parent.getNumObjs(); ++i) {
        const H5::Group child = parent.openGroup(parent.getObjnameByIdx(i));
        if (child.attrExists("index")) {
            next = std::max(next, readAttribute<std::int64_t>(child, "index") + 1);
        }
    }
    return next;
}

/// Children of `parent` sorted by their `index` attribute; incomplete ones are skipped.
std::vector<std::string> childrenInWriteOrder(const H5::Group& parent) {
    std::vector<std::pair<std::int64_t, std::string>> children;
    for (hsize_t i = 0; i < parent.getNumObjs(); ++i) {
        const std::string link = parent.getObjnameByIdx(i);
        if (link.size() > std::string(kWritingSuffix).size() && link.ends_with(kWritingSuffix)) {
            continue;
        }
        const H5::Group child = parent.openGroup(link);
        if (child.attrExists("index")) {
            children.emplace_back(readAttribute<std::int64_t>(child, "index"), link);
        }
    }
    std::sort(children.begin(), children.end());
    std::vector<std::string> links;
    for (auto& c : children) {
        links.push_back(std::move(c.second));
    }
    return links;
}

H5::Group openOrCreateGroup(H5::Group& parent, const std::string& name) {
    return parent.nameExists(name) ? parent.openGroup(name) : parent.createGroup(name);
}

std::string isoTimeNow() {
    const std::time_t now = std::time(nullptr);
    std::tm utc{};
    gmtime_r(&now, &utc);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
    return text;
}

void checkTable(const SeriesTable& t) {
    if (t.stages.size() != t.rows.size()) {
        throw std::invalid_argument(fmt::format("series {}: {} rows but {} stage names", t.test,
                                                t.rows.size(), t.stages.size()));
    }
    for (std::size_t c = 0; c < t.columns.size(); ++c) {
        const std::string& name = t.columns[c].name;
        if (name.empty() || name == "stage" || name.find('/') != std::string::npos ||
            t.column(name) != static_cast<int>(c)) {
            throw std::invalid_argument(fmt::format("series {}: column name \"{}\" is empty, "
                                                    "reserved, contains '/' or repeats",
                                                    t.test, name));
        }
    }
    for (const std::string& kind : t.stageKinds) {
        if (kind.size() >= hdf5io::kStageKindSize) {
            throw std::invalid_argument(
                fmt::format("series {}: stage kind \"{}\" is too long", t.test, kind));
        }
    }
    for (double p : t.stagePressures) {
        if (!std::isfinite(p)) {
            throw std::invalid_argument(
                fmt::format("series {}: a stage pressure is not finite", t.test));
        }
    }
    for (const std::string& stage : t.stages) {
        if (stage.size() >= hdf5io::kStageTextSize) {
            throw std::invalid_argument(fmt::format("series {}: stage name \"{}\" is longer than "
                                                    "{} bytes",
                                                    t.test, stage, hdf5io::kStageTextSize - 1));
        }
    }
    for (std::size_t k = 0; k < t.rows.size(); ++k) {
        if (t.rows[k].size() != t.columns.size()) {
            throw std::invalid_argument(fmt::format("series {}: record {} has {} values for {} "
                                                    "columns",
                                                    t.test, k, t.rows[k].size(), t.columns.size()));
        }
    }
}

/// Refuses a file that is not a GrainLab run file of a version in [oldest, this version].
void checkFormatVersion(const H5::H5File& file, const std::string& path,
                        int oldest = kRunFileOldestReadableVersion) {
    const H5::Group root = file.openGroup("/");
    if (!root.attrExists("format_version") || !root.attrExists("software")) {
        throw std::runtime_error(fmt::format("{}: not a GrainLab run file (no format_version "
                                             "attribute)",
                                             path));
    }
    const H5::Attribute a = root.openAttribute("format_version");
    std::int64_t version = -1;
    if (a.getTypeClass() == H5T_INTEGER && a.getSpace().getSimpleExtentNpoints() == 1) {
        a.read(H5::PredType::NATIVE_INT64, &version);
    }
    if (version < oldest || version > kRunFileFormatVersion) {
        throw std::runtime_error(
            oldest == kRunFileFormatVersion
                ? fmt::format("{}: run file format version {}; this GrainLab continues version "
                              "{} only (it reads versions {} to {}; run the experiment again to "
                              "get a file it can continue)",
                              path, version, kRunFileFormatVersion, kRunFileOldestReadableVersion,
                              kRunFileFormatVersion)
                : fmt::format("{}: run file format version {}; this GrainLab reads versions {} to "
                              "{} (run the experiment again to get a file of this version)",
                              path, version, oldest, kRunFileFormatVersion));
    }
}

/// The 1.8 layouts: superblock 2 and object headers with checksums. (The 1.10 superblock marks
/// a file open for writing, and a killed run would leave a file no reader may open.)
H5::FileAccPropList checksummedAccess() {
    H5::FileAccPropList access;
    access.setLibverBounds(H5F_LIBVER_V18, H5F_LIBVER_V18);
    return access;
}

} // namespace

// ---- writer --------------------------------------------------------------------------------

struct RunFile::Impl {
    /// The open datasets of one test's series.
    struct OpenSeries {
        H5::Group group; ///< /tests/<test>/series
        std::vector<SeriesColumn> columns;
        std::vector<H5::DataSet> values;
        H5::DataSet stage;
        H5::DataSet stageKind, stagePressure; ///< the stage identity of each row
        std::size_t rows = 0;
    };

    std::string path;
    H5::H5File file;
    std::map<std::string, OpenSeries> series;
    std::chrono::steady_clock::time_point lastFlush = std::chrono::steady_clock::now();

    OpenSeries& seriesFor(const SeriesTable& table);
    void createSeries(H5::Group& test, const SeriesTable& table, OpenSeries& out);
    /// Writes the group under a scratch name and renames it when complete; `fill` adds what
    /// else belongs to it before the rename.
    void writeStateGroup(const std::string& parent, const std::string& name,
                         const SimulationState& state, const std::string* runnerState,
                         const std::vector<std::pair<std::string, double>>& extra,
                         const StageIdentity* identity = nullptr,
                         const std::function<void(H5::Group&)>& fill = {});
    bool failed = false; ///< a write failed: nothing more is written, the file is left as is
    /// The last complete checkpoint that a resumed run continues from (not a peak checkpoint),
    /// as of the last flush.
    std::string lastCheckpoint;

    int reserveFd = -1; ///< run.h5 opened once more, to allocate disk blocks before writes

    /// Runs a write: refused once a write has failed, and fences the file if the library fails
    /// in it (values refused before anything was written leave the file usable).
    template <class F>
    void write(std::uint64_t bytes, const std::string& what, F&& f) {
        if (failed) {
            throw std::runtime_error(
                fmt::format("{}: an earlier write failed; not writing {}", path, what));
        }
        // GRAINLAB_TEST_NO_ROOM_CHECK=1 (tests only): let the write fail in HDF5 itself.
        static const bool check = std::getenv("GRAINLAB_TEST_NO_ROOM_CHECK") == nullptr;
        if (check) {
            ensureRoom(path, file.getId(), reserveFd, bytes, what);
        }
        try {
            f();
        } catch (const hdf5io::Hdf5Error& e) {
            fence();
            throw hdf5io::Hdf5Error(fmt::format("{}; {}", e.what(), keptText()));
        }
    }

    /// What the file holds after a failed write, for its message.
    std::string keptText() const {
        return lastCheckpoint.empty()
                   ? std::string("nothing of this write reached the file, which holds no "
                                 "checkpoint yet")
                   : fmt::format("nothing of this write reached the file, which keeps its last "
                                 "complete checkpoint {} (a resumed run continues from it)",
                                 lastCheckpoint);
    }

    /// Marks the file failed; from now on HDF5's writes to it stay in memory (run_file_driver.h).
    void fence() {
        failed = true;
        (void)fenceRunFile(file.getId());
    }

    /// A flush that cannot fail half-way for room (run_file_room.h).
    void flushNow() {
        allocateToEnd(path, file.getId(), reserveFd);
        file.flush(H5F_SCOPE_GLOBAL);
        lastFlush = std::chrono::steady_clock::now();
    }
};

void RunFile::Impl::createSeries(H5::Group& test, const SeriesTable& table, OpenSeries& out) {
    if (test.nameExists("series")) {
        test.unlink("series");
        flushNow(); // before new chunks can take the freed space the file on disk still uses
    }
    out = OpenSeries{};
    out.group = test.createGroup("series");
    out.columns = table.columns;
    std::vector<std::string> names;
    for (const auto& c : table.columns) {
        names.push_back(c.name);
    }
    writeStringListAttribute(out.group, "columns", names);

    const hsize_t zero = 0, unlimited = H5S_UNLIMITED, chunk = kSeriesChunk;
    H5::DataSpace space(1, &zero, &unlimited);
    H5::DSetCreatPropList chunked;
    chunked.setChunk(1, &chunk);
    chunked.setFletcher32();
    for (const auto& c : table.columns) {
        H5::DataSet ds = out.group.createDataSet(c.name, H5Types<double>::file(), space, chunked,
                                                 writeThrough());
        writeAttribute(ds, "unit", c.unit.empty() ? std::string("-") : c.unit);
        writeHash(ds, nullptr, 0);
        out.values.push_back(ds);
    }
    out.stage = out.group.createDataSet("stage", fixedStringType(kStageTextSize), space, chunked,
                                        writeThrough());
    writeHash(out.stage, nullptr, 0);
    out.stageKind = out.group.createDataSet("stage_kind", fixedStringType(kStageKindSize), space,
                                            chunked, writeThrough());
    writeHash(out.stageKind, nullptr, 0);
    out.stagePressure = out.group.createDataSet("stage_pressure", H5Types<double>::file(), space,
                                                chunked, writeThrough());
    writeAttribute(out.stagePressure, "unit", std::string("Pa"));
    writeHash(out.stagePressure, nullptr, 0);
}

RunFile::Impl::OpenSeries& RunFile::Impl::seriesFor(const SeriesTable& table) {
    auto it = series.find(table.test);
    if (it == series.end()) {
        OpenSeries s;
        H5::Group tests = file.openGroup("tests");
        const std::string link = linkName(table.test);
        if (tests.nameExists(link) && tests.openGroup(link).nameExists("series")) {
            // Resumed file: continue the series already there.
            H5::Group test = tests.openGroup(link);
            s.group = test.openGroup("series");
            for (const auto& name : readStringListAttribute(s.group, "columns")) {
                H5::DataSet ds = s.group.openDataSet(name, writeThrough());
                s.columns.push_back({name, readStringAttribute(ds, "unit")});
                s.values.push_back(ds);
            }
            s.stage = s.group.openDataSet("stage", writeThrough());
            s.stageKind = s.group.openDataSet("stage_kind", writeThrough());
            s.stagePressure = s.group.openDataSet("stage_pressure", writeThrough());
            s.rows = static_cast<std::size_t>(s.stage.getSpace().getSimpleExtentNpoints());
        } else {
            H5::Group test = openOrCreateGroup(tests, link);
            writeAttribute(test, "name", table.test);
            writeAttribute(test, "index", nextIndex(tests));
            createSeries(test, table, s);
        }
        it = series.emplace(table.test, std::move(s)).first;
    }
    OpenSeries& s = it->second;
    bool sameColumns = s.columns.size() == table.columns.size();
    for (std::size_t c = 0; sameColumns && c < s.columns.size(); ++c) {
        const std::string unit = table.columns[c].unit.empty() ? "-" : table.columns[c].unit;
        sameColumns = s.columns[c].name == table.columns[c].name && s.columns[c].unit == unit;
    }
    if (!sameColumns) {
        H5::Group test = file.openGroup("tests").openGroup(linkName(table.test));
        createSeries(test, table, s);
    }
    return s;
}

RunFile::RunFile(const std::string& path, const std::string& experimentText, Mode mode)
    : impl_(std::make_unique<Impl>()) {
    impl_->path = path;
    try {
        open(experimentText, mode);
    } catch (const hdf5io::Hdf5Error&) {
        if (H5Iis_valid(impl_->file.getId()) > 0) {
            impl_->fence(); // closing the file as this object goes writes nothing more to it
        }
        if (mode == Mode::Create) {
            // It holds nothing yet; gone, it leaves nothing to refuse or to resume.
            std::error_code ignored;
            std::filesystem::remove(path, ignored);
        }
        throw;
    }
}

void RunFile::open(const std::string& experimentText, Mode mode) {
    const std::string& path = impl_->path;
    guarded(path, mode == Mode::Create ? "creating the run file" : "opening the run file", [&] {
        if (mode == Mode::Create) {
            impl_->file = openFile(path, H5F_ACC_TRUNC, checksummedAccess(), "creating it");
            H5::Group root = impl_->file.openGroup("/");
            writeAttribute(root, "software", std::string("GrainLab"));
            writeAttribute(root, "software_version", std::string(GRAINLAB_VERSION));
            writeAttribute(root, "created", isoTimeNow());
            writeAttribute(root, "format_version", std::int32_t(kRunFileFormatVersion));
            writeStringDataset(root, "experiment", experimentText);
            root.createGroup("tests");
            root.createGroup("checkpoints");
            root.createGroup("samples");
            impl_->flushNow();
        } else {
            // A resumed run reads only what it continues from; it must not finish a file that
            // other readers (h5dump, h5py) cannot open for damage elsewhere. Read-only, so that
            // a refused file is left byte for byte as it was.
            try {
                readWholeFile(openRunFileToRead(path));
            } catch (const Hdf5Error& e) {
                throw Hdf5Error(fmt::format(
                    "{}: the run file is damaged: {}. A resumed run would finish a file that "
                    "other programs (h5dump, h5py) cannot open, so it is not continued, and the "
                    "file is left as it is. The series up to the interruption stay in the "
                    "folder's CSV files; to get a complete run file, run the experiment again "
                    "into a new folder: grainlab run EXPERIMENT.json --out NEW_FOLDER (the "
                    "experiment's text is in the run file's /experiment)",
                    path, e.what()));
            }
            impl_->file =
                openFile(path, H5F_ACC_RDWR, checksummedAccess(), "opening it for writing");
            checkFormatVersion(impl_->file, path, kRunFileFormatVersion);
            H5::Group root = impl_->file.openGroup("/");
            if (readStringDataset(root, "experiment") != experimentText) {
                throw std::runtime_error(
                    fmt::format("{}: the run file was written by a different experiment "
                                "file; refusing to continue it",
                                path));
            }
            for (const char* g : {"tests", "checkpoints", "samples"}) {
                openOrCreateGroup(root, g);
            }
            const H5::Group checkpoints = root.openGroup("checkpoints");
            for (const auto& link : childrenInWriteOrder(checkpoints)) {
                const H5::Group g = checkpoints.openGroup(link);
                if (!g.attrExists("peak") || readAttribute<std::int32_t>(g, "peak") == 0) {
                    impl_->lastCheckpoint = readStringAttribute(g, "name");
                }
            }
            impl_->flushNow();
        }
    });
}

void RunFile::close() {
    if (H5Iis_valid(impl_->file.getId()) <= 0) {
        return; // closed already
    }
    if (!impl_->failed) {
        // Everything on disk before anything is closed: a dataset's close writes its cached
        // chunks, and after the flush it has none.
        impl_->write(0, "the end of the file",
                     [&] { guarded(impl_->path, "closing", [&] { impl_->flushNow(); }); });
    }
    closeHandles();
}

void RunFile::closeHandles() {
    // After a good flush the closes below write nothing new; after a failure the file is fenced
    // and whatever they write goes nowhere.
    try {
        impl_->series.clear();
        impl_->file.close();
    } catch (const H5::Exception&) {
        // Not reachable after a flush or a fence; the file on disk stands as it was left.
    }
    releaseReserve(impl_->reserveFd);
}

RunFile::~RunFile() {
    try {
        close();
    } catch (const std::exception&) {
        // A destructor must not throw: the failed flush fenced the file, which keeps its last
        // complete flush. close() says so to a caller that closes explicitly.
        closeHandles();
    }
}

const std::string& RunFile::path() const {
    return impl_->path;
}

const std::string& RunFile::lastCheckpoint() const {
    return impl_->lastCheckpoint;
}

void RunFile::flush() {
    impl_->write(0, "pending records",
                 [&] { guarded(impl_->path, "flushing", [&] { impl_->flushNow(); }); });
}

void RunFile::warnings(const std::vector<RunWarning>& all) {
    std::uint64_t bytes = 4096;
    for (const RunWarning& w : all) {
        bytes += w.text.size() + 128;
    }
    impl_->write(bytes, "the warnings", [&] {
        guarded(impl_->path, "writing the warnings", [&] {
            H5::Group root = impl_->file.openGroup("/");
            writeWarnings(root, all);
            impl_->flushNow();
        });
    });
}

void RunFile::record(const SeriesTable& table) {
    checkTable(table);
    const std::uint64_t bytes = (table.columns.size() * 8 + hdf5io::kStageTextSize) * kSeriesChunk;
    impl_->write(bytes, "the series of " + table.test, [&] { recordNow(table); });
}

void RunFile::recordNow(const SeriesTable& table) {
    guarded(impl_->path, "writing the series of " + table.test, [&] {
        Impl::OpenSeries& s = impl_->seriesFor(table);
        const std::size_t n = table.rows.size();
        // Rows [from, n) are written; fewer rows than the file means the run was rewound.
        // (rewound: all of them, so that the file mirrors the table, checksums included).
        const std::size_t from = n > s.rows ? s.rows : 0;
        const bool rewound = n < s.rows;
        for (std::size_t k = from; k < n; ++k) {
            for (std::size_t c = 0; c < table.columns.size(); ++c) {
                if (!std::isfinite(table.rows[k][c])) {
                    throw std::runtime_error(fmt::format(
                        "{}: series {}: column {} of record {} is {}; refusing to write a "
                        "non-finite value",
                        impl_->path, table.test, table.columns[c].name, k,
                        std::isnan(table.rows[k][c]) ? "NaN" : "infinite"));
                }
            }
        }
        const hsize_t size = n, start = from, count = n - from;
        for (auto& ds : s.values) {
            ds.extend(&size);
        }
        s.stage.extend(&size);
        s.stageKind.extend(&size);
        s.stagePressure.extend(&size);
        s.rows = n;
        if (count > 0) {
            H5::DataSpace memory(1, &count);
            std::vector<double> column(count);
            for (std::size_t c = 0; c < s.values.size(); ++c) {
                for (std::size_t k = 0; k < count; ++k) {
                    column[k] = table.rows[from + k][c];
                }
                H5::DataSpace filespace = s.values[c].getSpace();
                filespace.selectHyperslab(H5S_SELECT_SET, &count, &start);
                s.values[c].write(column.data(), H5Types<double>::memory(), memory, filespace);
            }
            std::vector<char> stages(count * kStageTextSize, '\0');
            for (std::size_t k = 0; k < count; ++k) {
                const std::string& stage = table.stages[from + k];
                std::copy(stage.begin(), stage.end(), stages.begin() + k * kStageTextSize);
            }
            H5::DataSpace filespace = s.stage.getSpace();
            filespace.selectHyperslab(H5S_SELECT_SET, &count, &start);
            s.stage.write(stages.data(), fixedStringType(kStageTextSize), memory, filespace);
        }
        // The checksums of the whole columns, as they now stand in the file.
        std::vector<double> column(n);
        for (std::size_t c = 0; c < s.values.size(); ++c) {
            for (std::size_t k = 0; k < n; ++k) {
                column[k] = table.rows[k][c];
            }
            writeHash(s.values[c], column.data(), n * sizeof(double));
        }
        std::vector<char> stages(n * kStageTextSize, '\0');
        for (std::size_t k = 0; k < n; ++k) {
            std::copy(table.stages[k].begin(), table.stages[k].end(),
                      stages.begin() + k * kStageTextSize);
        }
        writeHash(s.stage, stages.data(), stages.size());
        // The stage identity of each row ("" and 0 for a table without one).
        const bool identified = table.stageKinds.size() == n && table.stagePressures.size() == n;
        std::vector<char> kinds(n * kStageKindSize, '\0');
        std::vector<double> pressures(n, 0.0);
        for (std::size_t k = 0; identified && k < n; ++k) {
            std::copy(table.stageKinds[k].begin(), table.stageKinds[k].end(),
                      kinds.begin() + k * kStageKindSize);
            pressures[k] = table.stagePressures[k];
        }
        if (n > 0) {
            const hsize_t all = n, zero = 0;
            H5::DataSpace memory(1, &all);
            H5::DataSpace kindSpace = s.stageKind.getSpace();
            kindSpace.selectHyperslab(H5S_SELECT_SET, &all, &zero);
            s.stageKind.write(kinds.data(), fixedStringType(kStageKindSize), memory, kindSpace);
            H5::DataSpace pressureSpace = s.stagePressure.getSpace();
            pressureSpace.selectHyperslab(H5S_SELECT_SET, &all, &zero);
            s.stagePressure.write(pressures.data(), H5Types<double>::memory(), memory,
                                  pressureSpace);
        }
        writeHash(s.stageKind, kinds.data(), kinds.size());
        writeHash(s.stagePressure, pressures.data(), pressures.size() * sizeof(double));
        const std::chrono::duration<double> sinceFlush =
            std::chrono::steady_clock::now() - impl_->lastFlush;
        // A rewound series is flushed at once: its cut freed chunks that the file on disk
        // still used, and the next rows may be written into them.
        if (rewound || sinceFlush.count() >= kRecordFlushSeconds) {
            impl_->flushNow();
        }
    });
}

void RunFile::Impl::writeStateGroup(const std::string& parentName, const std::string& name,
                                    const SimulationState& state, const std::string* runnerState,
                                    const std::vector<std::pair<std::string, double>>& extra,
                                    const StageIdentity* identity,
                                    const std::function<void(H5::Group&)>& fill) {
    H5::Group parent = file.openGroup(parentName);
    const std::string link = linkName(name);
    const std::string scratch = link + kWritingSuffix;
    if (parent.nameExists(scratch)) {
        parent.unlink(scratch); // left over from a run killed while writing
    }
    try {
        H5::Group g = parent.createGroup(scratch);
        writeAttribute(g, "name", name);
        writeState(g, state);
        for (const auto& [key, value] : extra) {
            writeAttribute(g, key, value);
        }
        if (runnerState) {
            writeStringDataset(g, "runner_state", *runnerState);
        }
        if (identity) {
            // The stage as data (the state's own attribute `step` is its step).
            writeAttribute(g, "stage_kind", identity->kind);
            writeAttribute(g, "test", identity->test);
            writeAttribute(g, "pressure", identity->pressure);
            writeAttribute(g, "axial_strain", identity->axialStrain);
            writeAttribute(g, "peak", std::int32_t(identity->peak ? 1 : 0));
            if (identity->peak) {
                writeAttribute(g, "q_over_p", identity->peakStressRatio);
            }
            writeArray(g, "theta_at_test_start", identity->thetaAtTestStart, "rad");
        }
        if (fill) {
            fill(g);
        }
        writeAttribute(g, "index", nextIndex(parent));
    } catch (const H5::Exception&) {
        throw; // the library failed: nothing more is asked of it (the file is fenced)
    } catch (...) {
        parent.unlink(scratch); // a value refused before it was written
        throw;
    }
    // The complete group replaces an older one of the same name only now.
    if (parent.nameExists(link)) {
        parent.unlink(link);
    }
    parent.moveLink(scratch, link);
    flushNow();
    if (parentName == "checkpoints" && !(identity && identity->peak)) {
        lastCheckpoint = name;
    }
}

namespace {

/// Bytes of a state in the run file, roughly (for the room check).
std::uint64_t stateBytes(const SimulationState& s) {
    return s.grains.size() * (7 * 8 + 3 * 8) + s.pairs.size() * (4 * 4 + 8 + 1) +
           s.shapes.size() * (12 * 8 + 2 * 8 * kShapeOutlinePoints) + (std::uint64_t(64) << 10);
}

/// Bytes of the void cells of a checkpoint, roughly (for the room check).
std::uint64_t voidCellBytes(const VoidCellSet& cells) {
    std::uint64_t grains = 0;
    for (const VoidCell& c : cells.cells) {
        grains += c.grains.size();
    }
    return cells.cells.size() * 96 + grains * (4 + 2 * 2 * 8);
}

} // namespace

void RunFile::checkpoint(const std::string& name, const SimulationState& state,
                         const std::string& runnerState) {
    // Room as for a checkpoint with its void cells (about as many cells as grains / 2).
    const std::uint64_t bytes = stateBytes(state) + runnerState.size() + state.grains.size() * 64;
    impl_->write(bytes, "checkpoint " + name, [&] { checkpointNow(name, state, runnerState); });
}

void RunFile::checkpoint(const CheckpointData& data) {
    std::uint64_t bytes = stateBytes(*data.state) + data.runnerState.size();
    if (data.network) {
        bytes += data.network->contacts.size() * 120 + data.network->grainCount * 16;
    }
    if (data.voidCells) {
        bytes += voidCellBytes(*data.voidCells);
    }
    if (data.runningPeak) {
        bytes += stateBytes(*data.runningPeak);
    }
    if (data.probeStart) {
        bytes += stateBytes(*data.probeStart);
    }
    impl_->write(bytes, "checkpoint " + data.name, [&] { checkpointNow(data); });
}

void RunFile::checkpointNow(const CheckpointData& data) {
    const std::string what = "writing checkpoint " + data.name;
    guarded(impl_->path, what, [&] {
        // A peak checkpoint is for reading, not for continuing: no runner state.
        const std::string* runnerState = data.identity.peak ? nullptr : &data.runnerState;
        const auto network = [&](H5::Group& g) {
            if (data.network) {
                writeContacts(g, *data.network);
                writeShapeOutlines(g, data.state->shapes);
            }
            if (data.voidCells) {
                writeVoidCells(g, *data.voidCells);
            }
            if (data.runningPeak) {
                H5::Group peak = g.createGroup("running_peak");
                writeState(peak, *data.runningPeak);
            }
            if (data.probeStart) {
                H5::Group start = g.createGroup("probe_start");
                writeState(start, *data.probeStart);
            }
        };
        impl_->writeStateGroup("checkpoints", data.name, *data.state, runnerState, {},
                               &data.identity, network);
        if (data.identity.peak) {
            // Where the test's peak is, for readers (also the checkpoint's attribute peak).
            H5::Group tests = impl_->file.openGroup("tests");
            const std::string link = linkName(data.identity.test);
            if (tests.nameExists(link)) {
                H5::Group test = tests.openGroup(link);
                writeAttribute(test, "peak_checkpoint", data.name);
                impl_->flushNow();
            }
        }
    });
}

void RunFile::checkpointNow(const std::string& name, const SimulationState& state,
                            const std::string& runnerState) {
    try {
        guarded(impl_->path, "writing checkpoint " + name, [&] {
            impl_->writeStateGroup("checkpoints", name, state, &runnerState, {}, nullptr);
        });
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        if (what.starts_with(impl_->path)) {
            throw;
        }
        throw std::runtime_error(fmt::format("{}: checkpoint {}: {}", impl_->path, name, what));
    }
}

void RunFile::sample(double pressure, const SimulationState& state) {
    impl_->write(stateBytes(state), fmt::format("the sample at {} Pa", pressure),
                 [&] { sampleNow(pressure, state); });
}

void RunFile::sampleNow(double pressure, const SimulationState& state) {
    const std::string name = sampleGroup(pressure).substr(std::string("/samples/").size());
    try {
        guarded(impl_->path, "writing sample " + name, [&] {
            impl_->writeStateGroup("samples", name, state, nullptr, {{"pressure", pressure}});
        });
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        if (what.starts_with(impl_->path)) {
            throw;
        }
        throw std::runtime_error(fmt::format("{}: sample {}: {}", impl_->path, name, what));
    }
}

// ---- readers -------------------------------------------------------------------------------

namespace {

template <class F>
auto withFile(const std::string& path, const std::string& what, F&& f) {
    return guarded(path, what, [&] {
        H5::H5File file = hdf5io::openRunFileToRead(path);
        return f(file);
    });
}

/// One value per child of the group `group` of the file, in write order: read(child).
template <class Read>
auto readChildren(const std::string& path, const std::string& what, const char* group, Read read) {
    return withFile(path, what, [&](H5::H5File& file) {
        const H5::Group parent = file.openGroup(group);
        std::vector<std::invoke_result_t<Read&, const H5::Group&>> out;
        for (const auto& link : childrenInWriteOrder(parent)) {
            out.push_back(read(parent.openGroup(link)));
        }
        return out;
    });
}

} // namespace

H5::H5File hdf5io::openRunFileToRead(const std::string& path) {
    H5::H5File file =
        openFile(path, H5F_ACC_RDONLY, H5::FileAccPropList::DEFAULT, "opening it to read");
    checkFormatVersion(file, path);
    return file;
}

std::string checkpointGroup(const std::string& name) {
    return "/checkpoints/" + linkName(name);
}

std::string sampleGroup(double pressure) {
    return fmt::format("/samples/{}Pa", pressure);
}

std::string runningPeakGroup(const std::string& name) {
    return checkpointGroup(name) + "/running_peak";
}

std::string probeStartGroup(const std::string& name) {
    return checkpointGroup(name) + "/probe_start";
}

SimulationState readState(const std::string& path, const std::string& groupPath) {
    return withFile(path, "reading the state in " + groupPath,
                    [&](H5::H5File& file) { return hdf5io::readState(file.openGroup(groupPath)); });
}

std::string readRunnerState(const std::string& path, const std::string& groupPath) {
    return withFile(path, "reading the runner state in " + groupPath, [&](H5::H5File& file) {
        const H5::Group g = file.openGroup(groupPath);
        return g.nameExists("runner_state") ? readStringDataset(g, "runner_state") : std::string();
    });
}

std::vector<RunWarning> readWarnings(const std::string& path) {
    return withFile(path, "reading the warnings",
                    [&](H5::H5File& file) { return hdf5io::readWarnings(file); });
}

std::vector<std::string> listCheckpoints(const std::string& path) {
    return readChildren(path, "listing checkpoints", "checkpoints",
                        [](const H5::Group& g) { return readStringAttribute(g, "name"); });
}

std::vector<CheckpointInfo> listCheckpointInfo(const std::string& path) {
    return readChildren(path, "listing checkpoints", "checkpoints", [](const H5::Group& g) {
        CheckpointInfo info;
        info.name = readStringAttribute(g, "name");
        info.step = readAttribute<std::int64_t>(g, "step");
        if (g.attrExists("stage_kind")) {
            info.stageKind = readStringAttribute(g, "stage_kind");
            info.test = readStringAttribute(g, "test");
            info.pressure = readAttribute<double>(g, "pressure");
            info.axialStrain = readAttribute<double>(g, "axial_strain");
        }
        if (g.attrExists("peak") && readAttribute<std::int32_t>(g, "peak") != 0) {
            info.peak = true;
            info.peakStressRatio = readAttribute<double>(g, "q_over_p");
        }
        return info;
    });
}

std::vector<double> readThetaAtTestStart(const std::string& path, const std::string& name) {
    return withFile(
        path, "reading the orientations at the test start of " + name, [&](H5::H5File& file) {
            const H5::Group g = file.openGroup(checkpointGroup(name));
            return g.nameExists("theta_at_test_start") ? readArray<double>(g, "theta_at_test_start")
                                                       : std::vector<double>{};
        });
}

std::vector<double> listSamples(const std::string& path) {
    return readChildren(path, "listing samples", "samples",
                        [](const H5::Group& g) { return readAttribute<double>(g, "pressure"); });
}

std::vector<std::string> listTests(const std::string& path) {
    return readChildren(path, "listing tests", "tests",
                        [](const H5::Group& g) { return readStringAttribute(g, "name"); });
}

SeriesTable readSeries(const std::string& path, const std::string& test) {
    return withFile(path, "reading the series of " + test, [&](H5::H5File& file) {
        const H5::Group g = file.openGroup("tests").openGroup(linkName(test)).openGroup("series");
        SeriesTable table;
        table.test = test;
        table.stages =
            readStringArray(g.openDataSet("stage"), "dataset " + objectName(g) + "/stage");
        table.stageKinds = readStringArray(g.openDataSet("stage_kind"),
                                           "dataset " + objectName(g) + "/stage_kind");
        table.stagePressures = readArray<double>(g, "stage_pressure");
        if (table.stageKinds.size() != table.stages.size() ||
            table.stagePressures.size() != table.stages.size()) {
            throw std::runtime_error(fmt::format("series {}: stage identities of another length "
                                                 "than its records",
                                                 test));
        }
        table.rows.assign(table.stages.size(), {});
        for (const auto& name : readStringListAttribute(g, "columns")) {
            const H5::DataSet ds = g.openDataSet(name);
            table.columns.push_back({name, readStringAttribute(ds, "unit")});
            const std::vector<double> values = readArray<double>(g, name);
            if (values.size() != table.rows.size()) {
                throw std::runtime_error(fmt::format("series {}: column {} has {} values for {} "
                                                     "records",
                                                     test, name, values.size(), table.rows.size()));
            }
            for (std::size_t k = 0; k < values.size(); ++k) {
                table.rows[k].push_back(values[k]);
            }
        }
        return table;
    });
}

std::string readExperimentText(const std::string& path) {
    return withFile(path, "reading /experiment", [&](H5::H5File& file) {
        return readStringDataset(file.openGroup("/"), "experiment");
    });
}

std::string readSoftwareVersion(const std::string& path) {
    return withFile(path, "reading the software version", [&](H5::H5File& file) {
        return readStringAttribute(file.openGroup("/"), "software_version");
    });
}

} // namespace grainlab
