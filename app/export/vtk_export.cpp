// See vtk_export.h.
#include "export/vtk_export.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>
#include <set>

#include <fmt/format.h>

#include "grainlab/experiment_runner.h"

namespace grainlab {
namespace {

namespace fs = std::filesystem;

/// The arcs' normal ranges [rad], in the order of OvalShape::arcs(): right end, top side, left
/// end, bottom side.
std::array<std::array<double, 2>, 4> arcRanges(const OvalShape& s) {
    const double phi = s.junctionAngle;
    const double pi = std::numbers::pi;
    return {{{-phi, phi}, {phi, pi - phi}, {pi - phi, pi + phi}, {pi + phi, 2.0 * pi - phi}}};
}

/// The field data every file of a frame carries.
std::vector<VtkArray> frameFieldData(const SimulationState& state, double axialStrain) {
    return {int64Array("step", {state.step}), float64Array("axial_strain", {axialStrain}),
            float64Array("simulated_time", {state.time})};
}

/// A test name as a file name: '/' and other separators would make folders.
std::string fileName(const std::string& test) {
    std::string out = test;
    for (char& c : out) {
        if (c == '/' || c == '\\' || c == ':') {
            c = '_';
        }
    }
    return out;
}

/// Reads with the run file's readers; their errors (a damaged dataset, a missing group) become
/// refusals naming the file.
template <class F>
auto readRun(const std::string& path, F&& read) {
    try {
        return read();
    } catch (const VtkExportRefused&) {
        throw;
    } catch (const std::exception& e) {
        throw VtkExportRefused(fmt::format(
            "{}: the run file cannot be read ({}); only an undamaged GrainLab run file can be "
            "exported",
            path, e.what()));
    }
}

} // namespace

std::vector<std::array<double, 2>> outlinePolygon(const OvalShape& shape, double tolerance) {
    std::vector<std::array<double, 2>> out;
    const auto arcs = shape.arcs();
    const auto ranges = arcRanges(shape);
    for (int k = 0; k < 4; ++k) {
        const double span = ranges[k][1] - ranges[k][0];
        if (span <= 0.0) {
            continue; // a disk's side arcs, or an end arc of zero angle
        }
        // The chord of angle d stands r (1 - cos(d / 2)) off its arc.
        const double r = arcs[k].radius;
        const double maxAngle =
            tolerance >= r ? std::numbers::pi : 2.0 * std::acos(1.0 - tolerance / r);
        const int chords = std::max(1, static_cast<int>(std::ceil(span / maxAngle)));
        for (int j = 0; j < chords; ++j) {
            // Each arc's points start at its first junction; the next arc's first point closes
            // it. The point is that arc's own (boundaryPoint picks the first arc admitting the
            // direction, the same point at a junction).
            const double angle = ranges[k][0] + span * double(j) / double(chords);
            const double c = std::cos(angle), s = std::sin(angle);
            out.push_back(
                j == 0 ? shape.boundaryPoint(angle)
                       : std::array<double, 2>{arcs[k].centreX + r * c, arcs[k].centreY + r * s});
        }
    }
    return out;
}

std::vector<VtkTestFrames> chooseFrames(const std::vector<CheckpointInfo>& checkpoints, int every,
                                        const std::vector<double>& strains) {
    every = std::max(every, 1);
    std::vector<VtkTestFrames> tests;
    std::map<std::string, std::vector<std::size_t>> byTest; // indices into checkpoints
    for (std::size_t k = 0; k < checkpoints.size(); ++k) {
        const CheckpointInfo& info = checkpoints[k];
        if (info.test.empty()) {
            continue;
        }
        if (!byTest.contains(info.test)) {
            tests.push_back({info.test, info.name, false, {}});
        }
        byTest[info.test].push_back(k);
    }
    for (VtkTestFrames& t : tests) {
        std::vector<std::size_t> order = byTest[t.test];
        std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
            return checkpoints[a].step < checkpoints[b].step;
        });
        std::vector<VtkFrame> all;
        for (std::size_t k : order) {
            const CheckpointInfo& info = checkpoints[k];
            VtkFrame f{info.name, info.step, info.axialStrain, 0.0};
            if (!all.empty() && all.back().step == f.step) {
                all.back() = f; // the later written of one step
            } else {
                all.push_back(f);
            }
        }
        for (std::size_t k = 1; k < all.size(); ++k) {
            t.timeIsStep = t.timeIsStep || all[k].axialStrain < all[k - 1].axialStrain;
        }
        std::vector<VtkFrame> timed;
        for (VtkFrame& f : all) {
            f.time = t.timeIsStep ? double(f.step) : f.axialStrain;
            if (!timed.empty() && timed.back().time == f.time) {
                timed.back() = f;
            } else {
                timed.push_back(f);
            }
        }
        std::set<std::size_t> chosen;
        if (!strains.empty()) {
            for (double strain : strains) {
                std::size_t best = 0;
                for (std::size_t k = 1; k < timed.size(); ++k) {
                    if (std::fabs(timed[k].axialStrain - strain) <
                        std::fabs(timed[best].axialStrain - strain)) {
                        best = k;
                    }
                }
                if (!timed.empty()) {
                    chosen.insert(best);
                }
            }
        } else {
            for (std::size_t k = 0; k < timed.size(); k += std::size_t(every)) {
                chosen.insert(k);
            }
            if (!timed.empty()) {
                chosen.insert(timed.size() - 1);
            }
        }
        for (std::size_t k : chosen) {
            t.frames.push_back(timed[k]);
        }
    }
    return tests;
}

VtkPolyData grainCells(const SimulationState& state, const StoredContacts& contacts,
                       const SimulationState& start) {
    const std::size_t n = state.grains.size();
    VtkPolyData out;
    out.cells = VtkPolyData::Cells::Polygons;
    std::vector<std::vector<std::array<double, 2>>> outlines;
    for (const OvalShape& shape : state.shapes) {
        outlines.push_back(outlinePolygon(shape, kOutlineTolerance * shape.width));
    }
    std::vector<std::int32_t> id(n), coordination(n, 0);
    std::vector<double> width(n), aspect(n), orientation(n), velocity, omega(n), rotation(n);
    std::vector<double> displacement;
    std::vector<double> centre;
    for (std::size_t c = 0; c < contacts.first.size(); ++c) {
        ++coordination[std::size_t(contacts.first[c])];
        ++coordination[std::size_t(contacts.second[c])];
    }
    std::vector<double> x1, x2;
    for (std::size_t i = 0; i < n; ++i) {
        const OvalShape& shape = state.shapes[std::size_t(state.grains.shape[i])];
        const double theta = state.grains.theta[i];
        const double c = std::cos(theta), s = std::sin(theta);
        const double cx = contacts.centre1[i], cy = contacts.centre2[i];
        x1.clear();
        x2.clear();
        for (const auto& p : outlines[std::size_t(state.grains.shape[i])]) {
            x1.push_back(cx + c * p[0] - s * p[1]);
            x2.push_back(cy + s * p[0] + c * p[1]);
        }
        out.addCell(x1, x2);
        id[i] = static_cast<std::int32_t>(i);
        width[i] = shape.width;
        aspect[i] = shape.height / shape.width;
        orientation[i] = theta;
        velocity.insert(velocity.end(), {state.grains.v1[i], state.grains.v2[i], 0.0});
        omega[i] = state.grains.omega[i];
        rotation[i] = theta - start.grains.theta[i];
        displacement.insert(displacement.end(), {state.grains.x1[i] - start.grains.x1[i],
                                                 state.grains.x2[i] - start.grains.x2[i], 0.0});
        centre.insert(centre.end(), {cx, cy, 0.0});
    }
    out.cellData.push_back(int32Array("id", std::move(id)));
    out.cellData.push_back(float64Array("centre", std::move(centre), 3));
    out.cellData.push_back(float64Array("width", std::move(width)));
    out.cellData.push_back(float64Array("aspect_ratio", std::move(aspect)));
    out.cellData.push_back(float64Array("orientation", std::move(orientation)));
    out.cellData.push_back(float64Array("velocity", std::move(velocity), 3));
    out.cellData.push_back(float64Array("angular_velocity", std::move(omega)));
    out.cellData.push_back(float64Array("rotation", std::move(rotation)));
    out.cellData.push_back(int32Array("coordination", std::move(coordination)));
    out.cellData.push_back(float64Array("displacement", std::move(displacement), 3));
    return out;
}

VtkPolyData contactCells(const StoredContacts& contacts, const std::array<double, 4>& cell) {
    VtkPolyData out;
    out.cells = VtkPolyData::Cells::Lines;
    std::vector<std::int64_t> index;
    std::vector<std::int32_t> first, second;
    std::vector<std::uint8_t> segment, strong, sliding, loadBearing;
    std::vector<double> fn, ft, force, normal, overlap;
    for (std::size_t c = 0; c < contacts.first.size(); ++c) {
        const auto a = std::size_t(contacts.first[c]), b = std::size_t(contacts.second[c]);
        const double ax = contacts.centre1[a], ay = contacts.centre2[a];
        const double bx = contacts.centre1[b], by = contacts.centre2[b];
        const int k1 = contacts.shift1[c], k2 = contacts.shift2[c];
        // One line between the centres, or through the periodic boundary two halves: A to the
        // contact point, and B to the contact point's image beside B (the point minus h k).
        std::vector<std::array<double, 4>> lines;
        if (k1 == 0 && k2 == 0) {
            lines.push_back({ax, ay, bx, by});
        } else {
            const double hk1 = cell[0] * k1 + cell[2] * k2, hk2 = cell[1] * k1 + cell[3] * k2;
            const double px = contacts.point1[c], py = contacts.point2[c];
            lines.push_back({ax, ay, px, py});
            lines.push_back({bx, by, px - hk1, py - hk2});
        }
        for (std::size_t part = 0; part < lines.size(); ++part) {
            const auto& l = lines[part];
            out.addCell({l[0], l[2]}, {l[1], l[3]});
            index.push_back(static_cast<std::int64_t>(c));
            first.push_back(contacts.first[c]);
            second.push_back(contacts.second[c]);
            segment.push_back(lines.size() == 1 ? 0 : std::uint8_t(part + 1));
            fn.push_back(contacts.normalForce[c]);
            ft.push_back(contacts.tangentialForce[c]);
            const double n1 = contacts.normal1[c], n2 = contacts.normal2[c];
            // The force on B, f = f_n n + f_t t with t = (-n2, n1) (run_file.h).
            force.insert(force.end(),
                         {contacts.normalForce[c] * n1 - contacts.tangentialForce[c] * n2,
                          contacts.normalForce[c] * n2 + contacts.tangentialForce[c] * n1, 0.0});
            normal.insert(normal.end(), {n1, n2, 0.0});
            overlap.push_back(contacts.overlap[c]);
            strong.push_back(contacts.strong[c]);
            sliding.push_back(contacts.sliding[c]);
            loadBearing.push_back(contacts.loadBearing[c]);
        }
    }
    out.cellData.push_back(int64Array("contact", std::move(index)));
    out.cellData.push_back(int32Array("first", std::move(first)));
    out.cellData.push_back(int32Array("second", std::move(second)));
    out.cellData.push_back(uint8Array("segment", std::move(segment)));
    out.cellData.push_back(float64Array("normal_force", std::move(fn)));
    out.cellData.push_back(float64Array("tangential_force", std::move(ft)));
    out.cellData.push_back(float64Array("force", std::move(force), 3));
    out.cellData.push_back(float64Array("normal", std::move(normal), 3));
    out.cellData.push_back(float64Array("overlap", std::move(overlap)));
    out.cellData.push_back(uint8Array("strong", std::move(strong)));
    out.cellData.push_back(uint8Array("sliding", std::move(sliding)));
    out.cellData.push_back(uint8Array("load_bearing", std::move(loadBearing)));
    out.fieldData.push_back(float64Array("strong_threshold", {contacts.strongThreshold}));
    return out;
}

VtkPolyData voidCellPolygons(const StoredVoidCells& cells) {
    VtkPolyData out;
    out.cells = VtkPolyData::Cells::Polygons;
    std::vector<std::int64_t> index;
    std::vector<double> x1, x2;
    for (std::size_t k = 0; k < cells.valence.size(); ++k) {
        const auto from = std::size_t(cells.vertexOffsets[k]),
                   to = std::size_t(cells.vertexOffsets[k + 1]);
        x1.assign(cells.vertices1.begin() + std::ptrdiff_t(from),
                  cells.vertices1.begin() + std::ptrdiff_t(to));
        x2.assign(cells.vertices2.begin() + std::ptrdiff_t(from),
                  cells.vertices2.begin() + std::ptrdiff_t(to));
        out.addCell(x1, x2);
        index.push_back(static_cast<std::int64_t>(k));
    }
    out.cellData.push_back(int64Array("void_cell", std::move(index)));
    out.cellData.push_back(int32Array("valence", cells.valence));
    out.cellData.push_back(float64Array("area", cells.area));
    out.cellData.push_back(float64Array("elongation", cells.elongation));
    out.cellData.push_back(float64Array("direction", cells.direction));
    return out;
}

VtkPolyData periodicCellQuad(const std::array<double, 4>& cell) {
    VtkPolyData out;
    out.cells = VtkPolyData::Cells::Polygons;
    out.addCell({0.0, cell[0], cell[0] + cell[2], cell[2]},
                {0.0, cell[1], cell[1] + cell[3], cell[3]});
    out.cellData.push_back(float64Array("area", {cell[0] * cell[3] - cell[1] * cell[2]}));
    return out;
}

std::string runFileOf(const std::string& run) {
    const fs::path p(run);
    std::error_code error;
    if (fs::is_regular_file(p, error)) {
        return p.string();
    }
    if (!fs::is_directory(p, error)) {
        throw VtkExportRefused(
            fmt::format("{}: no such run folder; give the folder `grainlab run --out` wrote "
                        "(it holds run.h5), or its run.h5",
                        run));
    }
    const fs::path file = p / "run.h5";
    if (!fs::is_regular_file(file, error)) {
        throw VtkExportRefused(fmt::format(
            "{}: not a run folder (no {}); give the folder `grainlab run --out` wrote, or its "
            "run.h5",
            run, file.string()));
    }
    return file.string();
}

VtkExportSummary exportVtk(const VtkExportOptions& options,
                           const std::function<void(double, const std::string&)>& progress) {
    if (options.out.empty()) {
        throw VtkExportRefused("no export folder: give --out DIR, a folder that does not exist");
    }
    const std::string path = runFileOf(options.run);
    const std::vector<CheckpointInfo> infos =
        readRun(path, [&] { return listCheckpointInfo(path); });
    std::string last;
    for (const CheckpointInfo& info : infos) {
        if (!info.peak) {
            last = info.name;
        }
    }
    if (last.empty()) {
        throw VtkExportRefused(fmt::format(
            "{}: the run file holds no checkpoint yet; only a run with checkpoints can be "
            "exported",
            path));
    }
    const std::string runnerState =
        readRun(path, [&] { return readRunnerState(path, checkpointGroup(last)); });
    const bool finished = readRun(path, [&] { return ExperimentRunner::finishedAt(runnerState); });
    if (!finished && !options.unfinished) {
        throw VtkExportRefused(fmt::format(
            "{}: the run has not finished (its last checkpoint is {}); finish it with `grainlab "
            "run --resume {}`, or export the checkpoints it has with --unfinished",
            path, last, fs::absolute(path).parent_path().string()));
    }
    const std::vector<VtkTestFrames> tests = chooseFrames(infos, options.every, options.strains);

    fs::path out = fs::absolute(options.out).lexically_normal();
    if (out.filename().empty()) {
        out = out.parent_path(); // "DIR/"
    }
    std::error_code error;
    if (fs::exists(out, error) && !(fs::is_directory(out, error) && fs::is_empty(out, error))) {
        throw VtkExportRefused(fmt::format(
            "{}: exists already; give --out a folder that does not exist (or is empty): an "
            "export never writes into another one",
            options.out));
    }
    const fs::path writing =
        out.parent_path() / fmt::format(".{}.writing-{}", out.filename().string(), getpid());

    VtkExportSummary summary;
    summary.out = out.string();
    int total = 0;
    for (const VtkTestFrames& t : tests) {
        total += static_cast<int>(t.frames.size());
    }
    try {
        fs::create_directories(writing);
        for (const VtkTestFrames& t : tests) {
            const std::string folder = fileName(t.test);
            fs::create_directories(writing / folder);
            const SimulationState start =
                readRun(path, [&] { return readState(path, checkpointGroup(t.firstCheckpoint)); });
            std::vector<PvdEntry> entries;
            int index = 0;
            for (const VtkFrame& f : t.frames) {
                const std::string group = checkpointGroup(f.checkpoint);
                const SimulationState state = readRun(path, [&] { return readState(path, group); });
                const StoredContacts contacts =
                    readRun(path, [&] { return readContacts(path, f.checkpoint); });
                const StoredVoidCells voids =
                    readRun(path, [&] { return readVoidCells(path, f.checkpoint); });
                if (contacts.centre1.size() != state.grains.size() ||
                    start.grains.size() != state.grains.size() ||
                    voids.vertexOffsets.size() != voids.valence.size() + 1) {
                    throw VtkExportRefused(fmt::format(
                        "{}: checkpoint {} holds no contacts or void-cell polygons (a run file of "
                        "format {} has them; this one was written by an older GrainLab)",
                        path, f.checkpoint, kRunFileFormatVersion));
                }
                std::vector<std::pair<std::string, VtkPolyData>> pieces{
                    {"grains", grainCells(state, contacts, start)},
                    {"contacts", contactCells(contacts, state.cell)},
                    {"void_cells", voidCellPolygons(voids)},
                    {"cell", periodicCellQuad(state.cell)}};
                for (std::size_t part = 0; part < pieces.size(); ++part) {
                    VtkPolyData& data = pieces[part].second;
                    const std::vector<VtkArray> field = frameFieldData(state, f.axialStrain);
                    data.fieldData.insert(data.fieldData.begin(), field.begin(), field.end());
                    const std::string file =
                        fmt::format("{}/{}_{:04d}.vtp", folder, pieces[part].first, index);
                    writeVtp((writing / file).string(), data);
                    entries.push_back({f.time, static_cast<int>(part), pieces[part].first, file});
                    ++summary.files;
                }
                ++index;
                ++summary.frames;
                if (progress) {
                    progress(total > 0 ? double(summary.frames) / double(total) : 1.0,
                             fmt::format("{} eps1 = {:.4f}", t.test, f.axialStrain));
                }
            }
            writePvd((writing / (folder + ".pvd")).string(), entries,
                     fmt::format("GrainLab: test {} of {}; time = {}", t.test, path,
                                 t.timeIsStep ? "the step (eps1 of this test is not monotone)"
                                              : "eps1 of the test"));
            ++summary.files;
            ++summary.tests;
        }
        for (const auto& entry : fs::recursive_directory_iterator(writing)) {
            if (entry.is_regular_file()) {
                summary.bytes += entry.file_size();
            }
        }
        if (fs::exists(out, error)) {
            fs::remove(out); // empty (checked above)
        }
        fs::rename(writing, out);
    } catch (...) {
        fs::remove_all(writing, error);
        throw;
    }
    return summary;
}

} // namespace grainlab
