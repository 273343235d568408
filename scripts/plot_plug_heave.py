#!/usr/bin/env python3
"""The soil surface inside an open pile over a drive, from the runs' VTK series: usage
`plot_plug_heave.py OUT.png --inner-radius R --outer-radius R LABEL=RUN_DIR ...` (the path after
the last =).

RUN_DIR is a coupled drive's output (or its .incomplete / .partial folder): vtk/particles_*.vtu
(their TimeValue) and blows.csv. A snapshot at a blow's start (t = k x interval) is read
as the state after blow k. The surface is the highest point in each radial band of
0.5 m inside the wall and, outside, within 1 m of it; the heave is its rise
since the first snapshot. Left: the heave at the axis (r < 0.5 m) and next to the inner
wall against the toe's advance, one line per run; right: the profile at the deepest
advance every run reached. Also prints the table (CSV) on stdout.

Exit status: 0 success, 2 missing/malformed input, 3 matplotlib or vtk not available.
"""
import argparse
import glob
import math
import os
import sys

from plot_common import InputError, read_columns, require_matplotlib  # noqa: E402

plt = require_matplotlib(__file__)
try:
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
except ImportError:
    print("plot_plug_heave.py: vtk (python3-vtk9) not available, no plots written", file=sys.stderr)
    sys.exit(3)
import numpy as np  # noqa: E402

BAND = 0.5  # m


def snapshots(run_dir):
    """(time, points as an N x 3 array) of every particle snapshot, in time order."""
    out = []
    for path in sorted(glob.glob(os.path.join(run_dir, "vtk", "particles_*.vtu"))):
        reader = vtk.vtkXMLUnstructuredGridReader()
        reader.SetFileName(path)
        reader.Update()
        grid = reader.GetOutput()
        time = grid.GetFieldData().GetArray("TimeValue")
        if time is None or grid.GetPoints() is None:
            raise InputError(f"{path}: no TimeValue or no points")
        out.append((time.GetValue(0), vtk_to_numpy(grid.GetPoints().GetData())))
    if not out:
        raise InputError(f"{run_dir}/vtk: no particles_*.vtu")
    return sorted(out, key=lambda s: s[0])


def surface(points, edges, outside):
    """The highest point in each band inside (edges) and in the band outside."""
    r, y = points[:, 0], points[:, 1]
    tops = []
    for a, b in list(zip(edges[:-1], edges[1:])) + [outside]:
        sel = (r >= a) & (r < b)
        tops.append(y[sel].max() if sel.any() else math.nan)
    return np.array(tops)


def run_heave(run_dir, inner, outer, interval):
    blows = read_columns(os.path.join(run_dir, "blows.csv"), ["blow", "toe_depth_before_m", "toe_depth_m"])
    toe = {0: blows["toe_depth_before_m"][0]}
    toe.update({int(b): d for b, d in zip(blows["blow"], blows["toe_depth_m"])})
    edges = np.append(np.arange(0.0, inner - 1e-9, BAND), inner)
    outside = (outer, outer + 1.0)
    rows, base = [], None
    for time, points in snapshots(run_dir):
        k = round(time / interval)
        if abs(time - k * interval) > 1e-6 or k not in toe or (rows and rows[-1][0] == k):
            continue
        top = surface(points, edges, outside)
        base = top if base is None else base
        rows.append((k, toe[k] - toe[0], top - base))
    if len(rows) < 2:
        raise InputError(f"{run_dir}: fewer than two snapshots at blow starts (snapshot_interval a multiple of the interval?)")
    return edges, rows


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("out")
    ap.add_argument("runs", nargs="+", help="LABEL=RUN_DIR")
    ap.add_argument("--inner-radius", type=float, required=True, help="m, the pile's inner radius")
    ap.add_argument("--outer-radius", type=float, required=True, help="m, the pile's outer radius")
    ap.add_argument("--interval", type=float, default=1.25, help="s between blows")
    args = ap.parse_args()
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(12, 4.8))
    results = []
    print("run,blow,toe_advance_m," + ",".join(f"heave_r{a:.1f}_m" for a in np.arange(0.0, args.inner_radius, BAND)) +
          ",heave_outside_m")
    for spec in args.runs:
        label, _, run_dir = spec.rpartition("=")
        edges, rows = run_heave(run_dir, args.inner_radius, args.outer_radius, args.interval)
        results.append((label or run_dir, edges, rows))
        for k, advance, h in rows:
            print(f"{label},{k},{advance:.4f}," + ",".join(f"{v:.4f}" for v in h))
        adv = [r[1] for r in rows]
        line, = ax.plot(adv, [r[2][0] for r in rows], "-", label=f"{label}: axis (r < {BAND} m)")
        ax.plot(adv, [r[2][-2] for r in rows], "--", color=line.get_color(), label=f"{label}: by the inner wall")
    ax.axhline(0.0, color="0.6", lw=0.8)
    ax.set_xlabel("toe advance since the first snapshot (m)")
    ax.set_ylabel("rise of the soil surface inside the pile (m)")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    common = min(r[2][-1][1] for r in results)
    for label, edges, rows in results:
        k, advance, h = min(rows, key=lambda r: abs(r[1] - common))
        bx.step(np.append(edges[:-1], edges[-1]), np.append(h[:-1], h[-2]), where="post",
                label=f"{label}: blow {k}, advance {advance:.2f} m")
        bx.plot([args.outer_radius + 0.5], [h[-1]], "o", color=bx.lines[-1].get_color())
    bx.axvspan(args.inner_radius, args.outer_radius, color="k")
    bx.axhline(0.0, color="0.6", lw=0.8)
    bx.set_xlabel("r (m); the dot: outside, within 1 m of the wall")
    bx.set_ylabel("rise of the surface (m)")
    bx.set_title(f"profile at an advance of about {common:.2f} m")
    bx.legend(fontsize=8)
    bx.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(args.out, dpi=120)


if __name__ == "__main__":
    try:
        main()
    except InputError as e:
        print(f"plot_plug_heave.py: {e}", file=sys.stderr)
        sys.exit(2)
