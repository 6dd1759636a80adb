#!/usr/bin/env bash
# `grainlab export vtk` on a real run, read back with VTK's own reader (Debian's python3-vtk9)
# and compared with the run file's checkpoints (h5py): every array of every file (ids, widths,
# orientations, velocities, coordination, rotation and displacement since the test's start,
# contact forces to the bit, strong/sliding flags, void cells), the grains' outlines within the
# sampling tolerance of the exact ovals and closed about their centres, contacts through the
# periodic boundary as two halves, the .pvd listing every file with increasing times, --every and
# --strains, and the refusals (not a run folder, a damaged run file, --out an existing export)
# with exit status 2, a message naming the file, and nothing overwritten.
# Skipped (exit 77) only when no python3 with vtk, h5py and numpy is found.
# Usage: vtk_export_test.sh <grainlab executable> <experiment file>
set -uo pipefail

grainlab="$1"
experiment="$2"

# shellcheck source=find_python.sh
source "$(dirname "${BASH_SOURCE[0]}")/find_python.sh"
find_python vtk h5py numpy

make_work
failed=0
fail() {
  echo "FAILED: $*" >&2
  failed=1
}

must_run "$work/run.log" "grainlab run $experiment" \
  "$grainlab" run "$experiment" --out "$work/run" --quiet
must_run "$work/export.log" "grainlab export vtk" \
  "$grainlab" export vtk "$work/run" --out "$work/vtk"
du -sh "$work/vtk"
"$grainlab" export vtk "$work/run" --out "$work/every2" --every 2 --quiet || fail "--every 2"
"$grainlab" export vtk "$work/run" --out "$work/strains" --strains 0,0.01 --quiet ||
  fail "--strains 0,0.01"

"$python" - "$work/run/run.h5" "$work/vtk" "$work/every2" "$work/strains" << 'CHECK' || failed=1
import os
import sys
import xml.etree.ElementTree as ET

import h5py
import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

run_file, export, every2, strains = sys.argv[1:5]
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)


def same_bits(a, b):
    a, b = np.ascontiguousarray(a), np.ascontiguousarray(b)
    return a.shape == b.shape and a.dtype == b.dtype and a.tobytes() == b.tobytes()


def read(path):
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    check(reader.GetErrorCode() == 0, f"{path}: VTK reports error {reader.GetErrorCode()}")
    return reader.GetOutput()


def cells(data):
    """The cells' point lists (lines or polygons) and the points."""
    points = vtk_to_numpy(data.GetPoints().GetData())
    array = data.GetPolys() if data.GetNumberOfPolys() else data.GetLines()
    offsets = vtk_to_numpy(array.GetOffsetsArray())
    connectivity = vtk_to_numpy(array.GetConnectivityArray())
    return [connectivity[offsets[k]:offsets[k + 1]] for k in range(len(offsets) - 1)], points


def cell_array(data, name):
    a = data.GetCellData().GetArray(name)
    check(a is not None, f"no cell array {name}")
    return vtk_to_numpy(a) if a is not None else np.array([])


def field(data, name):
    return vtk_to_numpy(data.GetFieldData().GetArray(name))[0]


def arcs(shapes, s):
    """Arc centres and radii of shape s (right end, top side, left end, bottom side)."""
    a, b = shapes["half_width"][s], shapes["half_height"][s]
    r, R = shapes["end_radius"][s], shapes["side_radius"][s]
    return [((a - r, 0.0), r), ((0.0, b - R), R), ((r - a, 0.0), r), ((0.0, R - b), R)]


def pvd_entries(path):
    root = ET.parse(path).getroot()
    return [(float(d.get("timestep")), int(d.get("part")), d.get("file"))
            for d in root.iter("DataSet")]


with h5py.File(run_file, "r") as f:
    cps = f["checkpoints"]
    by_index = sorted(cps, key=lambda n: cps[n].attrs["index"])
    tests = []
    for n in by_index:
        t = cps[n].attrs["test"].decode()
        if t not in tests:
            tests.append(t)
    pvds = sorted(p for p in os.listdir(export) if p.endswith(".pvd"))
    check(pvds == sorted(t + ".pvd" for t in tests), f"pvd files {pvds} for tests {tests}")
    periodic_grains = split_contacts = frames = 0
    for test in tests:
        mine = [n for n in by_index if cps[n].attrs["test"].decode() == test]
        start = cps[mine[0]]
        entries = pvd_entries(os.path.join(export, test + ".pvd"))
        listed = {e[2] for e in entries}
        on_disk = {f"{test}/{p}" for p in os.listdir(os.path.join(export, test))}
        check(listed == on_disk, f"{test}.pvd lists {len(listed)} files, {len(on_disk)} on disk")
        for part in range(4):
            times = [e[0] for e in entries if e[1] == part]
            check(all(b > a for a, b in zip(times, times[1:])), f"{test} part {part}: times {times}")
            check(len(times) == len(entries) // 4, f"{test}: part {part} has {len(times)} files")
        for time, part, name in entries:
            if part != 0:
                continue
            frames += 1
            grains = read(os.path.join(export, name))
            step = int(field(grains, "step"))
            eps1 = field(grains, "axial_strain")
            # The checkpoint of that step (the later written, as the export takes it).
            cp = cps[[n for n in mine if cps[n].attrs["step"] == step][-1]]
            where = f"{name} ({cp.name})"
            check(eps1 == cp.attrs["axial_strain"], f"{where}: axial_strain {eps1}")
            check(time in (eps1, float(step)), f"{where}: pvd time {time}, eps1 {eps1}")
            g, sh, c = cp["grains"], cp["shapes"], cp["contacts"]
            shape = g["shape"][:]
            n = len(shape)
            # Grains: every array against the checkpoint.
            check(grains.GetNumberOfCells() == n, f"{where}: {grains.GetNumberOfCells()} grains")
            check(same_bits(cell_array(grains, "id"), np.arange(n, dtype=np.int32)), f"{where}: id")
            centre = np.stack([c["centre1"][:], c["centre2"][:], np.zeros(n)], axis=1)
            check(same_bits(cell_array(grains, "centre"), centre), f"{where}: centre")
            check(same_bits(cell_array(grains, "width"), sh["width"][:][shape]), f"{where}: width")
            check(np.allclose(cell_array(grains, "aspect_ratio"),
                              sh["height"][:][shape] / sh["width"][:][shape], rtol=1e-15, atol=0),
                  f"{where}: aspect_ratio")
            check(same_bits(cell_array(grains, "orientation"), g["theta"][:]), f"{where}: orientation")
            velocity = np.stack([g["v1"][:], g["v2"][:], np.zeros(n)], axis=1)
            check(same_bits(cell_array(grains, "velocity"), velocity), f"{where}: velocity")
            check(same_bits(cell_array(grains, "angular_velocity"), g["omega"][:]),
                  f"{where}: angular_velocity")
            first, second = c["first"][:], c["second"][:]
            coordination = (np.bincount(first, minlength=n) + np.bincount(second, minlength=n))
            check(np.array_equal(cell_array(grains, "coordination"), coordination),
                  f"{where}: coordination")
            s = start["grains"]
            displacement = np.stack([g["x1"][:] - s["x1"][:], g["x2"][:] - s["x2"][:], np.zeros(n)],
                                    axis=1)
            check(same_bits(cell_array(grains, "displacement"), displacement),
                  f"{where}: displacement")
            check(same_bits(cell_array(grains, "rotation"), g["theta"][:] - s["theta"][:]),
                  f"{where}: rotation")
            # The outlines: every vertex on the exact oval (body frame), the polygon missing at
            # most perimeter x 1 % of the width of its area, closed about its wrapped centre.
            polys, points = cells(grains)
            L1, L2 = cp["cell"][0], cp["cell"][3]
            worst = 0.0
            for i, poly in enumerate(polys):
                p = points[poly, :2] - centre[i, :2]
                th = g["theta"][i]
                body = np.stack([np.cos(th) * p[:, 0] + np.sin(th) * p[:, 1],
                                 -np.sin(th) * p[:, 0] + np.cos(th) * p[:, 1]], axis=1)
                k = shape[i]
                w = sh["width"][k]
                off = np.min([np.abs(np.hypot(body[:, 0] - cx, body[:, 1] - cy) - r)
                              for (cx, cy), r in arcs(sh, k)], axis=0)
                worst = max(worst, off.max() / w)
                x, y = body[:, 0], body[:, 1]
                area = 0.5 * np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y)
                if not (sh["area"][k] - np.pi * w * 0.01 * w <= area <= sh["area"][k]):
                    check(False, f"{where}: grain {i} polygon area {area}, oval {sh['area'][k]}")
                if np.hypot(p[:, 0], p[:, 1]).max() > sh["half_width"][k] * (1 + 1e-9):
                    check(False, f"{where}: grain {i} polygon not about its centre")
                xs = points[poly, 0]
                if xs.min() < 0 or xs.max() > L1 or points[poly, 1].min() < 0 or \
                        points[poly, 1].max() > L2:
                    periodic_grains += 1
            check(worst < 1e-9, f"{where}: a vertex {worst} widths off the oval")
            # Contacts: one line, or two halves through the periodic boundary; forces to the bit.
            contacts = read(os.path.join(export, name.replace("grains_", "contacts_")))
            index = cell_array(contacts, "contact")
            segment = cell_array(contacts, "segment")
            across = (c["shift1"][:] != 0) | (c["shift2"][:] != 0)
            expected = np.repeat(np.arange(len(first)), np.where(across, 2, 1))
            check(np.array_equal(index, expected), f"{where}: contact cells {index}")
            for key in ("normal_force", "tangential_force", "overlap"):
                check(same_bits(cell_array(contacts, key), c[key][:][index]), f"{where}: {key}")
            for key in ("first", "second", "strong", "sliding", "load_bearing"):
                check(same_bits(cell_array(contacts, key), c[key][:][index]), f"{where}: {key}")
            check(field(contacts, "strong_threshold") == c.attrs["strong_threshold"],
                  f"{where}: strong_threshold")
            lines, lpoints = cells(contacts)
            h = cp["cell"][:]
            for k, line in enumerate(lines):
                a, b = lpoints[line[0], :2], lpoints[line[1], :2]
                j = index[k]
                A = (c["centre1"][first[j]], c["centre2"][first[j]])
                B = (c["centre1"][second[j]], c["centre2"][second[j]])
                P = np.array([c["point1"][j], c["point2"][j]])
                hk = np.array([h[0] * c["shift1"][j] + h[2] * c["shift2"][j],
                               h[1] * c["shift1"][j] + h[3] * c["shift2"][j]])
                want = {0: (A, B), 1: (A, P), 2: (B, P - hk)}[int(segment[k])]
                if not (np.array_equal(a, want[0]) and np.array_equal(b, want[1])):
                    check(False, f"{where}: contact cell {k} from {a} to {b}, not {want}")
            split_contacts += int(across.sum())
            # Void cells: the stored polygons and their valence, area, elongation.
            voids = read(os.path.join(export, name.replace("grains_", "void_cells_")))
            v = cp["void_cells"]
            for key in ("valence", "area", "elongation", "direction"):
                check(same_bits(cell_array(voids, key), v[key][:]), f"{where}: void {key}")
            vpolys, vpoints = cells(voids)
            offsets = v["vertex_offsets"][:]
            check(len(vpolys) == len(offsets) - 1, f"{where}: {len(vpolys)} void cells")
            stored = np.stack([v["vertices1"][:], v["vertices2"][:]], axis=1)
            got = np.concatenate([vpoints[p, :2] for p in vpolys]) if vpolys else stored[:0]
            check(same_bits(got, stored), f"{where}: void cell polygons")
            # The periodic cell.
            quad = read(os.path.join(export, name.replace("grains_", "cell_")))
            qpolys, qpoints = cells(quad)
            want = np.array([[0, 0], [h[0], h[1]], [h[0] + h[2], h[1] + h[3]], [h[2], h[3]]])
            check(len(qpolys) == 1 and np.array_equal(qpoints[qpolys[0], :2], want),
                  f"{where}: periodic cell")
            for other in (contacts, voids, quad):
                check(field(other, "step") == step, f"{where}: step of a piece")
    print(f"{frames} frames read back; {periodic_grains} grain outlines across the boundary, "
          f"{split_contacts} contacts split")
    check(periodic_grains > 0, "no grain across the periodic boundary: the run tests nothing")
    check(split_contacts > 0, "no contact through the periodic boundary")
    # --every 2 and --strains keep a subset, with the last checkpoint of each test.
    for folder, most in ((every2, None), (strains, 2)):
        for test in tests:
            full = [e for e in pvd_entries(os.path.join(export, test + ".pvd")) if e[1] == 0]
            some = [e for e in pvd_entries(os.path.join(folder, test + ".pvd")) if e[1] == 0]
            if most is None:
                check(len(some) == (len(full) + 1) // 2 + (len(full) % 2 == 0),
                      f"--every 2, {test}: {len(some)} of {len(full)} frames")
                check(some[-1][0] == full[-1][0], f"--every 2, {test}: last frame missing")
            else:
                check(1 <= len(some) <= most, f"--strains, {test}: {len(some)} frames")

for message in failures[:30]:
    print("FAILED:", message, file=sys.stderr)
sys.exit(1 if failures else 0)
CHECK

# Refusals: exit status 2, a message naming the file, nothing overwritten.
refused() { # refused <what> <word in the message> <arguments>...
  local what="$1" word="$2"
  shift 2
  "$grainlab" export vtk "$@" > "$work/out.log" 2>&1
  local status=$?
  if [[ $status -ne 2 ]]; then
    fail "$what: exit status $status, expected 2"
  fi
  if ! grep -qF -- "$word" "$work/out.log"; then
    fail "$what: the message does not name $word: $(cat "$work/out.log")"
  fi
}
listing() { (cd "$work" && find . -path ./run -prune -o ! -name '*.log' -print | sort && md5sum vtk/*.pvd); }
before="$(listing)"
mkdir -p "$work/empty"
refused "not a run folder" "$work/empty/run.h5" "$work/empty" --out "$work/new"
mkdir -p "$work/cut"
head -c 100000 "$work/run/run.h5" > "$work/cut/run.h5"
refused "a damaged run file" "$work/cut/run.h5" "$work/cut" --out "$work/new"
refused "--out an existing export" "$work/vtk" "$work/run" --out "$work/vtk"
[[ -e "$work/new" ]] && fail "a refused export wrote $work/new"
rm -rf "$work/empty" "$work/cut"
[[ "$(listing)" == "$before" ]] || fail "a refused export changed the files"
exit "$failed"
