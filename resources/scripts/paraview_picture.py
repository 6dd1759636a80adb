"""A ParaView picture of one frame of a `grainlab export vtk` folder: the grains coloured by their
rotation since the test's start, the strong force chains as tubes whose radius follows the normal
force, and the periodic cell, oriented as GrainLab's window draws it (x1 up, x2 to the right). Run it with ParaView's Python (Debian: pvpython from
python3-paraview, or pvbatch from paraview), under Xvfb on a machine without a display:

    xvfb-run -a pvpython resources/scripts/paraview_picture.py EXPORT/p015kPa --frame 12 \\
        --out picture.png

EXPORT/p015kPa is a test's folder of the export (grains_NNNN.vtp, contacts_NNNN.vtp,
cell_NNNN.vtp); --frame picks NNNN (default: the last). Options: --size (pixels, square),
--rotation-range (rad: the colour scale runs from minus to plus this), --all-chains (every
contact, not only the strong ones).
"""

import argparse
import glob
import os
import sys

from paraview.simple import (  # noqa: E402  (ParaView's Python)
    CellDatatoPointData, ColorBy, ExtractSurface, GetActiveViewOrCreate,
    GetColorTransferFunction, GetScalarBar, Hide, Render, SaveScreenshot, Show, Threshold, Tube,
    XMLPolyDataReader)


def frame_files(folder, frame):
    """The grains, contacts and cell files of one frame (the last when frame is None)."""
    grains = sorted(glob.glob(os.path.join(folder, "grains_*.vtp")))
    if not grains:
        sys.exit(f"{folder}: no grains_NNNN.vtp: not a test folder of `grainlab export vtk`")
    if frame is None:
        tag = os.path.basename(grains[-1])[len("grains_"):-len(".vtp")]
    else:
        tag = f"{frame:04d}"
    files = {part: os.path.join(folder, f"{part}_{tag}.vtp")
             for part in ("grains", "contacts", "cell")}
    for part, path in files.items():
        if not os.path.exists(path):
            sys.exit(f"{path}: no such file (frames: {len(grains)})")
    return files


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("folder", help="a test's folder of an export, e.g. EXPORT/p015kPa")
    parser.add_argument("--frame", type=int, default=None, help="frame number (default: last)")
    parser.add_argument("--out", required=True, help="the picture (.png)")
    parser.add_argument("--size", type=int, default=1600, help="pixels (square)")
    parser.add_argument("--rotation-range", type=float, default=0.2,
                        help="|rotation| [rad] at the ends of the colour scale")
    parser.add_argument("--all-chains", action="store_true", help="every contact, not only strong")
    args = parser.parse_args()
    files = frame_files(args.folder, args.frame)

    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [args.size, args.size]
    view.UseColorPaletteForBackground = 0
    view.Background = [1.0, 1.0, 1.0]
    view.OrientationAxesVisibility = 0
    view.CameraParallelProjection = 1

    # The grains: their outlines filled by rotation since the test's start.
    grains = XMLPolyDataReader(FileName=[files["grains"]])
    shown = Show(grains, view)
    ColorBy(shown, ("CELLS", "rotation"))
    lut = GetColorTransferFunction("rotation")
    lut.ApplyPreset("Cool to Warm", True)
    lut.RescaleTransferFunction(-args.rotation_range, args.rotation_range)
    lut.AutomaticRescaleRangeMode = "Never"
    shown.Ambient, shown.Diffuse = 1.0, 0.0  # the colour map's own colours, unlit
    shown.SetScalarBarVisibility(view, True)
    bar = GetScalarBar(lut, view)
    bar.Title = "rotation since the test's start [rad]"
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0.0, 0.0, 0.0]

    # The chains: the strong contacts (normal force above the mean), as tubes scaled by force.
    contacts = XMLPolyDataReader(FileName=[files["contacts"]])
    chains = contacts
    if not args.all_chains:
        chains = Threshold(Input=contacts)
        chains.Scalars = ["CELLS", "strong"]
        chains.LowerThreshold = 1
        chains.UpperThreshold = 1
        chains = ExtractSurface(Input=chains)  # the Tube filter takes lines as polygonal data
    points = CellDatatoPointData(Input=chains)
    tubes = Tube(Input=points)
    tubes.Scalars = ["POINTS", "normal_force"]
    tubes.VaryRadius = "By Scalar"
    tubes.NumberofSides = 12
    tubes.Capping = 1
    # The radius: 4 % of the smallest grain width at the weakest chain, 5 times that at the
    # strongest.
    widths = grains.CellData["width"].GetRange()
    tubes.Radius = 0.04 * widths[0]
    tubes.RadiusFactor = 5.0
    tube_shown = Show(tubes, view)
    tube_shown.ColorArrayName = [None, ""]
    tube_shown.AmbientColor = tube_shown.DiffuseColor = [0.1, 0.1, 0.1]
    Hide(points, view)

    # The periodic cell's outline.
    cell = XMLPolyDataReader(FileName=[files["cell"]])
    cell_shown = Show(cell, view)
    cell_shown.SetRepresentationType("Wireframe")
    cell_shown.ColorArrayName = [None, ""]
    cell_shown.AmbientColor = cell_shown.DiffuseColor = [0.0, 0.0, 0.0]
    cell_shown.LineWidth = 2.0

    # As GrainLab's window draws a sample: x1 (the axis compressed) up, x2 to the right, which
    # is the plane seen from below (from -x3).
    view.ResetCamera()
    view.CameraPosition = [view.CameraFocalPoint[0], view.CameraFocalPoint[1], -1.0]
    view.CameraViewUp = [1.0, 0.0, 0.0]
    view.ResetCamera()
    Render(view)
    SaveScreenshot(args.out, view, ImageResolution=[args.size, args.size])
    print(f"{args.out}: {files['grains']} and its chains, {args.size} x {args.size} pixels")


if __name__ == "__main__":
    main()
