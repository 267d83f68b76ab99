"""Shows a Paddy snapshot series in ParaView: the spheres at their radius, coloured by speed, with the
cone (and any other mesh wall) where it was at that time, on the plate.

  pvpython experiments/paraview/show_slump.py OUT/snapshots/particles.xmf [--time T] [--png FILE] [--no-walls]
  xvfb-run -a pvpython experiments/paraview/show_slump.py ... --png slump.png   (no display)
  paraview --script=experiments/paraview/show_slump.py   (GUI; the file from PADDY_XMF)

OUT is the --out directory of `paddy run experiments/slump.lua --set snapshot_interval=...` (or of
any experiment that writes snapshots: the script only needs particles.xmf beside its snap_*.h5).
Spheres: the Point Gaussian representation with the Sphere shader, each scaled by its `radius`
array (metres, true size). Colour: speed = |velocity| in m/s. The mesh walls (the cone, lifted
during the test) come from walls.xmf beside particles.xmf: each snapshot holds their triangles at
their position at that time; they are drawn as a half-transparent steel-grey surface (--no-walls
leaves them out; snapshots written before walls were saved have no walls.xmf and show none). The
plate (z = 0, an infinite plane in the simulation) is drawn as a grey disc under the pile. --time
picks the snapshot nearest T (default: the last); --png saves a 1280x800 picture instead of (or,
in the GUI, besides) showing it.
"""
import argparse
import os
import sys

from paraview.simple import (Calculator, ColorBy, Disk, GetActiveViewOrCreate, GetColorTransferFunction,
                             GetScalarBar,
                             OpenDataFile, Render, ResetCamera, SaveScreenshot, Show, UpdatePipeline)


def parse(argv):
    ap = argparse.ArgumentParser(description="Paddy snapshots in ParaView: spheres by radius, coloured by speed")
    ap.add_argument("xmf", nargs="?", default=os.environ.get("PADDY_XMF"),
                    help="particles.xmf of a snapshot series (default: $PADDY_XMF)")
    ap.add_argument("--time", type=float, default=None, help="simulation time to show (nearest snapshot; default: last)")
    ap.add_argument("--png", default=None, help="save a picture to this file")
    ap.add_argument("--size", default="1280x800", help="picture size WxH (default 1280x800)")
    ap.add_argument("--no-walls", action="store_true", help="do not draw the mesh walls (walls.xmf)")
    a, _ = ap.parse_known_args(argv)  # the GUI (paraview --script) may pass its own arguments
    if not a.xmf:
        ap.error("give particles.xmf (or set PADDY_XMF)")
    return a


def walls_at(xmf, t):
    """The reader of walls.xmf beside xmf updated to time t, or None when there is none."""
    path = os.path.join(os.path.dirname(os.path.abspath(xmf)), "walls.xmf")
    if not os.path.exists(path):
        return None
    walls = OpenDataFile(path)
    if walls is None:
        raise SystemExit("show_slump: ParaView cannot open " + path)
    walls.UpdatePipeline(t)
    return walls


def show(xmf, time=None, png=None, size=(1280, 800), draw_walls=True):
    """Builds the pipeline in the active view; returns (view, shown time, number of particles,
    number of wall triangles drawn)."""
    reader = OpenDataFile(os.path.abspath(xmf))
    if reader is None:
        raise SystemExit("show_slump: ParaView cannot open " + xmf)
    times = list(reader.TimestepValues) if hasattr(reader.TimestepValues, "__len__") else [reader.TimestepValues]
    t = times[-1] if time is None else min(times, key=lambda x: abs(x - time))
    speed = Calculator(Input=reader, ResultArrayName="speed", Function="mag(velocity)")
    speed.UpdatePipeline(t)
    data = speed.GetDataInformation()
    (x0, x1, y0, y1, z0, z1) = data.GetBounds()
    walls = walls_at(xmf, t) if draw_walls else None
    triangles = walls.GetDataInformation().GetNumberOfCells() if walls is not None else 0

    view = GetActiveViewOrCreate("RenderView")
    view.ViewTime = t
    view.ViewSize = list(size)
    view.OrientationAxesVisibility = 1
    try:
        view.UseColorPaletteForBackground = 0  # ParaView >= 5.10
    except AttributeError:
        pass
    view.Background = [1.0, 1.0, 1.0]

    # The plate: a disc under the pile, a little wider than the spread.
    extent = max(abs(x0), abs(x1), abs(y0), abs(y1), 0.05)
    if triangles:
        extent = max([extent] + [abs(v) for v in walls.GetDataInformation().GetBounds()[:4]])
    plate = Disk(InnerRadius=0.0, OuterRadius=1.15 * extent, CircumferentialResolution=96)
    plate_rep = Show(plate, view)
    plate_rep.DiffuseColor = [0.75, 0.75, 0.75]
    plate_rep.AmbientColor = [0.75, 0.75, 0.75]

    # The mesh walls (the cone) at this time: steel grey, half transparent so the pile inside shows.
    if walls is not None:
        walls_rep = Show(walls, view)
        walls_rep.SetRepresentationType("Surface")
        ColorBy(walls_rep, None)
        walls_rep.DiffuseColor = [0.55, 0.58, 0.62]
        walls_rep.AmbientColor = [0.55, 0.58, 0.62]
        walls_rep.Opacity = 0.45

    rep = Show(speed, view)
    rep.SetRepresentationType("Point Gaussian")
    rep.ShaderPreset = "Sphere"
    rep.ScaleByArray = 1
    rep.SetScaleArray = ["POINTS", "radius"]
    rep.UseScaleFunction = 0  # the radius array is the sphere's radius itself
    rep.GaussianRadius = 1.0
    ColorBy(rep, ("POINTS", "speed"))
    lut = GetColorTransferFunction("speed")
    lo, hi = data.GetPointDataInformation().GetArrayInformation("speed").GetComponentRange(0)
    lut.RescaleTransferFunction(lo, max(hi, lo + 1e-6))
    rep.SetScalarBarVisibility(view, True)
    bar = GetScalarBar(lut, view)
    bar.Title = "speed"
    bar.ComponentTitle = "[m/s]"
    bar.TitleColor = [0.1, 0.1, 0.1]
    bar.LabelColor = [0.1, 0.1, 0.1]

    # Oblique view from the side and above.
    cx, cy, cz = (x0 + x1) / 2, (y0 + y1) / 2, (z0 + z1) / 2
    view.CameraFocalPoint = [cx, cy, cz]
    view.CameraPosition = [cx + 1.6 * extent, cy - 2.4 * extent, cz + 1.4 * extent]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    ResetCamera(view)
    Render(view)
    if png:
        SaveScreenshot(png, view, ImageResolution=list(size))
    return view, t, data.GetNumberOfPoints(), triangles


def main(argv):
    a = parse(argv)
    size = tuple(int(v) for v in a.size.lower().split("x"))
    _, t, n, triangles = show(a.xmf, a.time, a.png, size, not a.no_walls)
    print("show_slump: %d particles and %d wall triangles at t = %.6g s%s"
          % (n, triangles, t, (", picture " + a.png) if a.png else ""))
    if a.png and "--png" in argv:
        # pvpython with a picture saved: leave without ParaView's teardown, which under Xvfb (Mesa)
        # sometimes ends in "X Error ... GLXBadContext" and a non-zero exit code.
        sys.stdout.flush()
        sys.stderr.flush()
        os._exit(0)


if __name__ == "__main__":
    main(sys.argv[1:])
