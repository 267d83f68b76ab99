"""ParaView (pvpython) reads Paddy's XDMF + HDF5 snapshots as Paddy wrote them (docs/reliability.md).

  pvpython check_snapshot.py particles.xmf WORK_DIR       (under xvfb-run when there is no display)
  pvpython check_snapshot.py --walls walls.xmf WORK_DIR MIN_TRIANGLES
  pvpython check_snapshot.py --png-not-blank FILE.png [MIN_FRACTION]

For the first and the last snapshot of the series: the number of points and of cells (one vertex
cell per particle) equal the particle count, and id, radius and velocity equal the HDF5 datasets
(read with h5dump at full precision) value for value. Then the last snapshot is shown with
ParaView's defaults (Show + Render: the Surface representation): the picture, kept in WORK_DIR,
must differ from the same view with the reader hidden in at least N/2 pixels (without vertex cells
the Surface view of points is empty and the two are identical).
--walls: the mesh walls (walls.xmf): for the first and the last snapshot, as many triangles (at
least MIN_TRIANGLES) and points as Paddy wrote, the points equal /walls/vertices, and the walls
moved no further down than they started (the cone is lifted: its lowest point rises); the default
view of the last snapshot shows them (at least 1000 pixels differ from the view without them).
--png-not-blank: the fraction of pixels that differ from the corner pixel (the background) must be
at least MIN_FRACTION (default 0.01). Exit 1 on any mismatch.
"""
import os
import re
import subprocess
import sys

from paraview import servermanager
from paraview.simple import GetActiveViewOrCreate, Hide, OpenDataFile, Render, ResetCamera, SaveScreenshot, Show
from vtkmodules.vtkIOImage import vtkPNGReader

failures = []


def check(ok, what):
    print(("ok: " if ok else "FAIL: ") + what)
    if not ok:
        failures.append(what)


def h5(file, dataset):
    """The values of a dataset, flattened, at full precision."""
    text = subprocess.run(["h5dump", "-m", "%.17g", "-d", dataset, "-w", "0", "-y", file], check=True,
                          capture_output=True, text=True).stdout
    body = text[text.index("DATA {") + 6:text.rindex("}")]
    return [float(v) for v in re.findall(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?|nan|inf", body)]


def snapshots(xmf):
    """(time, h5 file, particle count) of every grid of the XDMF collection."""
    text = open(xmf).read()
    out = []
    for grid in re.findall(r'<Grid Name="[^"]+" GridType="Uniform">(.*?)</Grid>', text, re.S):
        t = float(re.search(r'<Time Value="([^"]+)"', grid).group(1))
        n = int(re.search(r'NumberOfElements="(\d+)"', grid).group(1))
        f = re.search(r">([^<>:]+\.h5):/particles/position<", grid).group(1)
        out.append((t, os.path.join(os.path.dirname(xmf), f), n))
    return out


def fetch(reader, t):
    reader.UpdatePipeline(t)
    data = servermanager.Fetch(reader)
    if data.IsA("vtkMultiBlockDataSet") or data.IsA("vtkCompositeDataSet"):
        it = data.NewIterator()
        it.InitTraversal()
        data = it.GetCurrentDataObject()
    return data


def array_values(data, name):
    arr = data.GetPointData().GetArray(name)
    if arr is None:
        return None
    return [arr.GetComponent(i, c) for i in range(arr.GetNumberOfTuples()) for c in range(arr.GetNumberOfComponents())]


def pixels(png):
    """The RGB values of a PNG as an (n, 3) integer array, and its size."""
    r = vtkPNGReader()
    r.SetFileName(png)
    r.Update()
    img = r.GetOutput()
    w, h, _ = img.GetDimensions()
    from vtkmodules.util.numpy_support import vtk_to_numpy
    return vtk_to_numpy(img.GetPointData().GetScalars()).reshape(w * h, -1)[:, :3].astype(int), w, h


def differing_pixels(a, b):
    pa, pb = pixels(a)[0], pixels(b)[0]
    return int((abs(pa - pb).max(axis=1) > 8).sum()) if pa.shape == pb.shape else pa.shape[0]


def shown_pixels(reader, t, work, stem):
    """ParaView's default view of reader at time t: Show + Render, nothing changed. Returns the
    representation and how many pixels differ from the same view with the reader hidden (what
    shows of it); both screenshots are kept in work as <stem>.png and <stem>_hidden.png."""
    view = GetActiveViewOrCreate("RenderView")
    view.ViewTime = t
    rep = Show(reader, view)
    ResetCamera(view)
    Render(view)
    shown = os.path.join(work, stem + ".png")
    SaveScreenshot(shown, view, ImageResolution=[800, 600])
    Hide(reader, view)
    Render(view)
    empty = os.path.join(work, stem + "_hidden.png")
    SaveScreenshot(empty, view, ImageResolution=[800, 600])
    return rep, differing_pixels(shown, empty)


def not_blank(png, min_fraction=0.01):
    rgb, w, h = pixels(png)
    bg = tuple(int(v) for v in rgb[0])
    differ = int((abs(rgb - rgb[0]).max(axis=1) > 24).sum())
    fraction = differ / float(w * h)
    check(fraction >= min_fraction, "%s: %.2f %% of %dx%d pixels differ from the background %s (at least %.2f %%)"
          % (png, 100 * fraction, w, h, bg, 100 * min_fraction))


def wall_snapshots(xmf):
    """(time, h5 file, triangles, vertices) of every grid of walls.xmf."""
    text = open(xmf).read()
    out = []
    for grid in re.findall(r'<Grid Name="[^"]+" GridType="Uniform">(.*?)</Grid>', text, re.S):
        t = float(re.search(r'<Time Value="([^"]+)"', grid).group(1))
        n = int(re.search(r'NumberOfElements="(\d+)"', grid).group(1))
        v = int(re.search(r'<DataItem Dimensions="(\d+) 3"[^>]*>[^<]*:/walls/vertices<', grid).group(1))
        f = re.search(r">([^<>:]+\.h5):/walls/vertices<", grid).group(1)
        out.append((t, os.path.join(os.path.dirname(xmf), f), n, v))
    return out


def check_walls(xmf, work, min_triangles):
    series = wall_snapshots(xmf)
    check(len(series) >= 2, "%d snapshots with walls in %s" % (len(series), xmf))
    reader = OpenDataFile(xmf)
    check(reader is not None, "ParaView opens %s" % xmf)
    lowest = []
    for t, file, n, v in (series[0], series[-1]):
        data = fetch(reader, t)
        where = "walls at t = %.6g s (%s)" % (t, os.path.basename(file))
        check(data.GetNumberOfCells() == n and n >= min_triangles,
              "%s: %d triangles, Paddy wrote %d (at least %d)" % (where, data.GetNumberOfCells(), n, min_triangles))
        check(data.GetNumberOfPoints() == v, "%s: %d points, Paddy wrote %d" % (where, data.GetNumberOfPoints(), v))
        pos = data.GetPoints()
        got = [pos.GetPoint(i)[c] for i in range(pos.GetNumberOfPoints()) for c in range(3)]
        check(got == h5(file, "/walls/vertices"), "%s: vertices equal /walls/vertices" % where)
        bounds = data.GetBounds()
        print("%s: bounds x %.4g..%.4g y %.4g..%.4g z %.4g..%.4g" % ((where,) + tuple(bounds)))
        lowest.append(bounds[4])
    check(lowest[1] >= lowest[0], "the walls' lowest point went from z = %.6g to %.6g m (not down)" % tuple(lowest))
    _, differ = shown_pixels(reader, series[-1][0], work, "paraview_walls_view")
    check(differ >= 1000, "default view of the walls: %d pixels show them" % differ)
    print("%d failures" % len(failures))
    return 1 if failures else 0


def main(argv):
    if argv and argv[0] == "--walls":
        return check_walls(os.path.abspath(argv[1]), os.path.abspath(argv[2]), int(argv[3]))
    if argv and argv[0] == "--png-not-blank":
        not_blank(argv[1], float(argv[2]) if len(argv) > 2 else 0.01)
        return 1 if failures else 0
    xmf, work = os.path.abspath(argv[0]), os.path.abspath(argv[1])
    series = snapshots(xmf)
    check(len(series) >= 2, "%d snapshots in %s" % (len(series), xmf))
    reader = OpenDataFile(xmf)
    check(reader is not None, "ParaView opens %s (%s)" % (xmf, reader.GetXMLName() if reader else "no reader"))
    times = reader.TimestepValues
    times = list(times) if hasattr(times, "__len__") else [times]
    check(len(times) == len(series), "ParaView sees %d time steps, the XDMF lists %d" % (len(times), len(series)))
    for t, file, n in (series[0], series[-1]):
        data = fetch(reader, t)
        where = "t = %.6g s (%s)" % (t, os.path.basename(file))
        check(data.GetNumberOfPoints() == n, "%s: %d points, Paddy wrote %d" % (where, data.GetNumberOfPoints(), n))
        check(data.GetNumberOfCells() == n, "%s: %d cells (vertex), %d particles" % (where, data.GetNumberOfCells(), n))
        for name in ("id", "radius", "velocity"):
            got, wrote = array_values(data, name), h5(file, "/particles/" + name)
            check(got is not None and got == wrote,
                  "%s: %s read back equal to the HDF5 dataset (%d values)" % (where, name, len(wrote)))
        pos = data.GetPoints()
        got = [pos.GetPoint(i)[c] for i in range(pos.GetNumberOfPoints()) for c in range(3)]
        check(got == h5(file, "/particles/position"), "%s: positions equal" % where)
    # ParaView's default view of the last snapshot: Show + Render, nothing changed. The particles
    # are visible when the picture differs from the same view with the reader hidden (without
    # cells the two are identical) in at least as many pixels as half the particle count.
    rep, differ = shown_pixels(reader, series[-1][0], work, "paraview_default_view")
    check(differ >= series[-1][2] / 2, "default view (%s representation): %d pixels show particles (%d particles)"
          % (rep.Representation, differ, series[-1][2]))
    print("%d failures" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    code = main(sys.argv[1:])
    # Leave without ParaView's teardown: under Xvfb (Mesa) it sometimes ends in "X Error ...
    # GLXBadContext" and a non-zero exit after every check has passed.
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(code)
