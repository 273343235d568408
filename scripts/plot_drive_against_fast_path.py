#!/usr/bin/env python3
"""The coupled model's drive beside the fast path's drivability sheet, on the same axes:
usage `plot_drive_against_fast_path.py OUT.png --coupled LABEL=RUN_DIR ... --fast LABEL=CSV ...`
(the path after the last =).

RUN_DIR holds a coupled drive's blows.csv (toe_depth_before_m, toe_depth_m per blow); CSV is a
drivability sheet's drivability_<case>.csv (depth_m, blows_per_0.25m, cumulative_blows).
Left: blows per 0.25 m against toe depth (the coupled drive's counted in 0.25 m steps from
where it began, a part-filled last step scaled up); right: cumulative blows from the coupled
drive's first depth (the fast path's counted from the same depth).

Exit status: 0 success, 2 missing/malformed input, 3 matplotlib not available.
"""
import math
import os
import sys

from plot_common import read_columns, require_matplotlib  # noqa: E402

plt = require_matplotlib(__file__)
STEP = 0.25


def coupled_counts(run_dir):
    b = read_columns(os.path.join(run_dir, "blows.csv"), ["toe_depth_before_m", "toe_depth_m"])
    start = b["toe_depth_before_m"][0]
    bins = {}
    for before, after in zip(b["toe_depth_before_m"], b["toe_depth_m"]):
        k = int(math.floor((after - start) / STEP - 1e-9))
        bins[k] = bins.get(k, 0) + 1
    depths, counts = [], []
    last = max(bins)
    for k in sorted(bins):
        top = start + k * STEP
        reached = min(b["toe_depth_m"][-1] - top, STEP) if k == last else STEP
        if reached < 0.2 * STEP:
            continue  # too little of the step to scale
        depths.append((top, top + STEP))
        counts.append(bins[k] * STEP / reached)
    cumulative = list(range(1, len(b["toe_depth_m"]) + 1))
    return start, depths, counts, b["toe_depth_m"], cumulative


def main(argv):
    if len(argv) < 4 or "--coupled" not in argv:
        print(__doc__, file=sys.stderr)
        return 2
    out = argv[1]
    coupled, fast, mode = [], [], None
    for a in argv[2:]:
        if a in ("--coupled", "--fast"):
            mode = a
            continue
        if "=" not in a or mode is None:
            print(f"expected LABEL=PATH after --coupled or --fast, got {a}", file=sys.stderr)
            return 2
        (coupled if mode == "--coupled" else fast).append(a.rsplit("=", 1))
    fig, (ax_n, ax_c) = plt.subplots(1, 2, figsize=(10, 7), sharey=True)
    start = None
    deepest = 0.0
    for (label, run_dir), colour in zip(coupled, ["b", "c", "navy", "teal"]):
        s, depths, counts, toe, cumulative = coupled_counts(run_dir)
        start = s if start is None else min(start, s)
        deepest = max(deepest, toe[-1])
        for (top, bottom), n in zip(depths, counts):
            ax_n.plot([n, n], [top, bottom], "-", color=colour, lw=2.0, label=label if top == depths[0][0] else None)
        ax_c.plot(cumulative, toe, "-", color=colour, lw=2.0, label=label)
    for (label, csv), style in zip(fast, ["k--", "k:", "k-.", "0.5"]):
        f = read_columns(csv, ["depth_m", "blows_per_0.25m", "cumulative_blows"])
        keep = [i for i, d in enumerate(f["depth_m"]) if start - STEP <= d <= deepest + 1.0]
        if not keep:
            continue
        d = [f["depth_m"][i] for i in keep]
        ax_n.plot([f["blows_per_0.25m"][i] for i in keep], d, style, label=label)
        # The fast path's count from the coupled drive's first depth (interpolated).
        base = None
        for i in range(1, len(f["depth_m"])):
            if f["depth_m"][i] >= start:
                d0, d1 = f["depth_m"][i - 1], f["depth_m"][i]
                c0, c1 = f["cumulative_blows"][i - 1], f["cumulative_blows"][i]
                base = c0 + (c1 - c0) * (start - d0) / (d1 - d0) if d1 > d0 else c1
                break
        if base is not None:
            below = [i for i in keep if f["depth_m"][i] >= start]
            ax_c.plot([base * 0.0] + [f["cumulative_blows"][i] - base for i in below], [start] + [f["depth_m"][i] for i in below],
                      style, label=label)
    ax_n.set_xlabel("Blows per 0.25 m")
    ax_c.set_xlabel("Cumulative blows from %.2f m" % start)
    ax_n.set_ylabel("Toe depth below the seabed (m)")
    ax_n.set_ylim(deepest + 1.0, start - 0.25)
    # One legend for both panels, under them: inside either it hid the deepest bars.
    entries = {}
    for ax in (ax_n, ax_c):
        ax.grid(True, alpha=0.4)
        for handle, label in zip(*ax.get_legend_handles_labels()):
            entries.setdefault(label, handle)
    rows = (len(entries) + 1) // 2
    fig.legend(list(entries.values()), list(entries.keys()), loc="lower center", ncol=2, fontsize=8)
    fig.suptitle("Coupled MPM-FEM drive beside the fast path")
    fig.tight_layout(rect=(0, 0.035 * rows + 0.02, 1, 1))
    fig.savefig(out, dpi=120)
    plt.close(fig)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
