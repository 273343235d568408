#!/usr/bin/env python3
"""Plots of a drivability study: usage `plot_drivability.py OUT_DIR`.

drivability.png   the drivability sheet: four panels sharing a depth axis pointing down
                  (depth below seabed): (a) SRD total (solid) and shaft part (dashed) in MN,
                  (b) blows per 0.25 m with the hard-driving and refusal counts, (c) cumulative
                  blows with any observed points, (d) max compression (solid) and tension
                  (dashed) stress in MPa. One colour per run (soil case x energy level); a
                  triangle on the left axis and a thin line mark each run's refusal depth.
                  With soil from a CPT (summary cpt_profile_file) a first panel shows q_t
                  with the clay-like stretches shaded; with a driving plan (energy_level
                  varying with depth) a last panel shows the hammer energy used.
bearing_graph.png when the bearing graph CSV exists: ultimate resistance against blows per
                  0.25 m, one line per energy level, and the stresses against resistance.
calibration.png   with a calibration (summary calibration): per coupled run, the head
                  velocity (and force, for a ram-cushion hammer) of the coupled model, the
                  fast path before and after the fit; the sets beside them. The coupled
                  blow counts are also marked on the sheet's blow-count panel.

Inputs in OUT_DIR: summary.json (title, runs[], refusal/hard-driving blow counts, optional
observed points and bearing_graph_file) and the CSV files it names.

Exit status: 0 success, 2 missing/malformed input, 3 matplotlib not available.
"""
import csv
import json
import math
import os
import sys

import plot_common  # noqa: E402
from plot_common import InputError, require_matplotlib  # noqa: E402

plt = require_matplotlib(__file__)
import matplotlib.transforms as mtransforms  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.ticker import MaxNLocator  # noqa: E402
import numpy as np  # noqa: E402

PROG = "plot_drivability.py"

RUN_COLUMNS = ["depth_m", "srd_shaft_N", "srd_toe_N", "srd_total_N", "blows_per_0.25m",
               "cumulative_blows", "max_compression_Pa", "max_tension_Pa", "refusal"]
BEARING_COLUMNS = ["energy_level", "ultimate_resistance_N", "blows_per_0.25m",
                   "max_compression_Pa", "max_tension_Pa"]

# Blow counts far past refusal are capped by the simulator (10x the refusal count); the blow
# axes stop at this multiple of the refusal count and mark what lies beyond.
BLOW_AXIS_FACTOR = 1.2




def read_columns(path, names):
    """The named columns of a CSV file as numpy float arrays (nan/inf are simply not drawn)."""
    return {n: np.asarray(v, dtype=float) for n, v in plot_common.read_columns(path, names).items()}


def number(obj, key, where, default=None, allow_none=False):
    """obj[key] as a finite float; `default` when absent, None when null and allowed."""
    if key not in obj:
        if default is not None:
            return default
        raise InputError(f"{where}: missing \"{key}\"")
    v = obj[key]
    if v is None and allow_none:
        return None
    if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
        raise InputError(f"{where}: \"{key}\" is not a number: {v!r}")
    return float(v)


def read_observed(items, where):
    if items is None:
        return []
    if not isinstance(items, list):
        raise InputError(f"{where}: \"observed\" is not a list")
    points = []
    for i, p in enumerate(items):
        if not isinstance(p, dict):
            raise InputError(f"{where}: observed[{i}] is not an object")
        points.append((number(p, "depth_m", f"{where} observed[{i}]"),
                       number(p, "cumulative_blows", f"{where} observed[{i}]")))
    return points


def read_summary(out_dir):
    path = os.path.join(out_dir, "summary.json")
    try:
        with open(path) as f:
            summary = json.load(f)
    except OSError as e:
        raise InputError(f"{path}: {e.strerror or e}")
    except ValueError as e:
        raise InputError(f"{path}: not valid JSON: {e}")
    if not isinstance(summary, dict):
        raise InputError(f"{path}: not a JSON object")
    runs = summary.get("runs")
    if not isinstance(runs, list) or not runs:
        raise InputError(f"{path}: \"runs\" missing or empty")
    out = {
        "title": str(summary.get("title") or "Drivability"),
        "refusal": number(summary, "refusal_blow_count", path, default=250.0),
        "hard": number(summary, "hard_driving_blow_count", path, default=75.0),
        "observed": read_observed(summary.get("observed"), path),
        "bearing_file": summary.get("bearing_graph_file"),
        "cpt_profile_file": summary.get("cpt_profile_file") if isinstance(summary.get("cpt_profile_file"), str) else None,
        "rated_energy_J": summary.get("rated_energy_J") if isinstance(summary.get("rated_energy_J"), (int, float)) else None,
        "runs": [],
        "coupled": [(number(p, "depth_m", path), number(p, "blows_per_0.25m", path))
                    for p in summary.get("coupled_blow_counts") or []],
        "calibration": summary.get("calibration"),
    }
    if out["bearing_file"] is not None and not isinstance(out["bearing_file"], str):
        raise InputError(f"{path}: \"bearing_graph_file\" is not a string")
    for i, r in enumerate(runs):
        where = f"{path} runs[{i}]"
        if not isinstance(r, dict):
            raise InputError(f"{where}: not an object")
        if not isinstance(r.get("file"), str) or not r["file"]:
            raise InputError(f"{where}: \"file\" missing")
        # Only a file name inside OUT_DIR, never a path elsewhere.
        name = os.path.basename(r["file"])
        out["runs"].append({
            "file": os.path.join(out_dir, name),
            "soil_case": str(r.get("soil_case") or os.path.splitext(name)[0]),
            "energy_level": number(r, "energy_level", where, default=1.0),
            "refusal_depth": number(r, "refusal_depth_m", where, default=-1.0, allow_none=True),
            "total_blows": r.get("total_blows") if isinstance(r.get("total_blows"), (int, float))
            else None,
            "observed": read_observed(r.get("observed"), where),
            "data": None,
        })
        if out["runs"][-1]["refusal_depth"] is not None and out["runs"][-1]["refusal_depth"] < 0:
            out["runs"][-1]["refusal_depth"] = None
    return out


def has_column(path, name):
    with open(path, newline="") as f:
        return name in (next(csv.reader(f), []) or [])


def percent(level):
    return f"E={level * 100:.0f}%"


def run_label(run, several_levels):
    label = run["soil_case"]
    if several_levels:
        label += f", {percent(run['energy_level'])}"
    if run["refusal_depth"] is not None:
        label += f": refusal at {run['refusal_depth']:.1f} m"
    else:
        total = run["total_blows"]
        depth, cum = run["data"]["depth_m"], run["data"]["cumulative_blows"]
        ok = np.isfinite(depth) & np.isfinite(cum)
        if total is None and ok.any():
            total = cum[ok][-1]
        if total is not None and math.isfinite(total) and ok.any():
            label += f": {total:,.0f} blows to {depth[ok][-1]:.1f} m"
    return label


def nice_ceiling(x):
    """A round number at or above x for the end of an axis."""
    if not math.isfinite(x) or x <= 0:
        return 1.0
    magnitude = 10 ** math.floor(math.log10(x))
    for step in (1.0, 0.5, 0.25, 0.2, 0.1):  # the coarsest that fits
        s = step * magnitude
        top = math.ceil(x / s - 1e-9) * s
        if top <= x * 1.12:
            return top
    return math.ceil(x / magnitude) * magnitude


def stress_limits(compression, tension):
    """x-limits of a stress axis (MPa): from 0, or below it when tension is stored negative."""
    smax = finite_max(*compression, *tension, default=1.0)
    smin = min(0.0, -finite_max(*[-t for t in tension], default=0.0))
    return (-nice_ceiling(-smin * 1.1) if smin < 0 else 0.0), nice_ceiling(smax * 1.05)


def finite_max(*arrays, default=0.0):
    vals = [np.nanmax(a[np.isfinite(a)]) for a in arrays if np.isfinite(a).any()]
    return max(vals) if vals else default


def clipped_blows(ax, x, y, cap, color, horizontal=True, every_point=False, **kw):
    """Plots blow counts with values above `cap` drawn along the cap, with a triangle pointing
    off the axis where the curve leaves it (at every such point when `every_point`). x is the
    blow count when horizontal, else y is. Returns whether any were clipped."""
    blows = x if horizontal else y
    over = np.isfinite(blows) & (blows > cap)
    shown = np.where(over, cap, blows)
    xs, ys = (shown, y) if horizontal else (x, shown)
    ax.plot(xs, ys, color=color, **kw)
    if over.any():
        mark = over if every_point else over & ~np.concatenate([[False], over[:-1]])
        ax.plot(xs[mark], ys[mark], ls="none", marker=">" if horizontal else "^", ms=8,
                color=color, mec="white", mew=0.6, clip_on=False, zorder=5)
    return bool(over.any())


def blow_axis_limit(max_blows, refusal, hard):
    """End of a blows-per-0.25 m axis: the data when below refusal, else a little past it;
    easy driving (below half the hard-driving count) gets an axis of its own size."""
    cap = nice_ceiling(BLOW_AXIS_FACTOR * refusal)
    if 0.0 < max_blows <= 0.5 * hard:
        return nice_ceiling(1.25 * max_blows), cap
    top = max(max_blows, refusal, hard) * 1.08
    return min(nice_ceiling(top), cap), cap


def count_lines(ax, hard, refusal, vertical=True):
    """Dotted lines at the hard-driving and refusal blow counts, labelled along the line."""
    for value, name, color in ((hard, "hard driving", "0.35"), (refusal, "refusal", "black")):
        if vertical:
            ax.axvline(value, color=color, ls=":", lw=1.3, zorder=1)
            trans = mtransforms.blended_transform_factory(ax.transData, ax.transAxes)
            ax.text(value, 0.985, f" {name} {value:g}", transform=trans, rotation=90,
                    ha="right", va="top", fontsize=8.5, color=color, clip_on=True,
                    bbox={"boxstyle": "square,pad=0.1", "fc": "white", "ec": "none", "alpha": 0.8})
        else:
            ax.axhline(value, color=color, ls=":", lw=1.3, zorder=1)


def mark_refusal(ax, depth, color):
    """A triangle on the left spine and a thin line across the panel at a refusal depth."""
    ax.axhline(depth, color=color, lw=0.8, ls=(0, (6, 3)), alpha=0.55, zorder=1)
    trans = mtransforms.blended_transform_factory(ax.transAxes, ax.transData)
    ax.plot([0.0], [depth], marker=">", ms=9, color=color, mec="white", mew=0.6,
            transform=trans, clip_on=False, zorder=5)


def run_colors(runs, levels):
    """One colour per run: a hue per soil case, darker for a higher energy level, so the runs
    of one soil case read as a family when there are several energy levels."""
    base = plt.get_cmap("tab10").colors
    cases = []
    for run in runs:
        if run["soil_case"] not in cases:
            cases.append(run["soil_case"])
    colors = []
    for i, run in enumerate(runs):
        if len(cases) == len(runs) or len(cases) > len(base):  # one run per case, or too many
            colors.append(base[i % len(base)])
            continue
        rgb = np.array(base[cases.index(run["soil_case"]) % len(base)])
        rank = levels.index(run["energy_level"]) if run["energy_level"] in levels else 0
        # Highest level: the full colour; lowest: mixed 45 % toward white.
        lighten = 0.45 * (len(levels) - 1 - rank) / max(len(levels) - 1, 1)
        colors.append(tuple(rgb + (1.0 - rgb) * lighten))
    return colors


def legend_layout(runs, entries, levels, several_levels):
    """Handles, labels and column count of the figure legend. With several energy levels each
    soil case gets a column with its levels stacked (the legend fills column by column, so the
    columns are padded with blank entries to the same height); else up to four per row.
    `entries` are (handle, label) per run, in run order, then any extra ones (observed)."""
    blank = Line2D([], [], ls="none")
    cases = []
    for run in runs:
        if run["soil_case"] not in cases:
            cases.append(run["soil_case"])
    extra = entries[len(runs):]
    if not several_levels or len(cases) > 5:
        return [h for h, _ in entries], [l for _, l in entries], min(len(entries), 4)
    height = max(sum(r["soil_case"] == c for r in runs) for c in cases)
    columns = []
    for case in cases:
        members = sorted((i for i, r in enumerate(runs) if r["soil_case"] == case),
                         key=lambda i: runs[i]["energy_level"])
        columns.append([entries[i] for i in members])
    if extra:
        columns.append(list(extra))
    handles, labels = [], []
    for column in columns:
        column = column + [(blank, "")] * (height - len(column))
        handles += [h for h, _ in column]
        labels += [l for _, l in column]
    return handles, labels, len(columns)


def plot_drivability(out_dir, summary):
    runs = summary["runs"]
    for run in runs:
        run["data"] = read_columns(run["file"], RUN_COLUMNS)
    refusal, hard = summary["refusal"], summary["hard"]
    levels = sorted({r["energy_level"] for r in runs})
    several_levels = len(levels) > 1
    colors = run_colors(runs, levels)
    observed = list(summary["observed"])
    for run in runs:
        observed += run["observed"]

    # A driving plan (energy varying with depth) gets a fifth panel: the energy used.
    energies = []
    for run in runs:
        e = plot_common.read_columns(run["file"], ["energy_level"]) if has_column(run["file"], "energy_level") else None
        energies.append(np.asarray(e["energy_level"], dtype=float) if e else None)
    planned = any(e is not None and np.nanmax(e) - np.nanmin(e) > 1e-12 for e in energies)
    # Soil from a CPT gets a first panel: q_t with the clay-like stretches, beside the SRD.
    cpt = None
    if summary.get("cpt_profile_file"):
        cpt = read_columns(os.path.join(out_dir, os.path.basename(summary["cpt_profile_file"])),
                           ["depth_m", "qt_Pa", "soil_type_clay"])
    n = 4 + int(planned) + int(cpt is not None)
    fig, all_axes = plt.subplots(1, n, figsize=(3.8 * n + 0.8, 9), sharey=True)
    axes = list(all_axes[1:] if cpt is not None else all_axes)
    ax_srd, ax_blows, ax_cum, ax_stress = axes[:4]
    if cpt is not None:
        ax_q = all_axes[0]
        ax_q.plot(cpt["qt_Pa"] * 1e-6, cpt["depth_m"], color="0.2", lw=1.3)
        z, clay = cpt["depth_m"], cpt["soil_type_clay"] > 0.5
        for i in np.nonzero(clay)[0]:
            lo = 0.5 * (z[i - 1] + z[i]) if i > 0 else 0.0
            hi = 0.5 * (z[i] + z[i + 1]) if i + 1 < len(z) else z[i]
            ax_q.axhspan(lo, hi, color="tab:brown", alpha=0.25, lw=0)
        ax_q.set_xlim(left=0)
        ax_q.set_xlabel("q_t (MPa); clay-like shaded")
        ax_q.set_title("CPT", fontsize=11)

    # Depth range shared by all panels, 0 (seabed) at the top.
    max_depth = finite_max(*[r["data"]["depth_m"] for r in runs],
                           np.array([d for d, _ in observed] or [np.nan]), default=1.0)
    depth_bottom = nice_ceiling(max_depth * 1.01)

    max_blows = finite_max(*[r["data"]["blows_per_0.25m"] for r in runs])
    blow_xmax, blow_cap = blow_axis_limit(max_blows, refusal, hard)

    # Cumulative blows: scale to what is driven before refusal (past refusal the count runs
    # away); the part beyond refusal is drawn dotted and may leave the axis.
    cum_extent = 0.0
    any_clipped = False
    any_beyond = False
    handles = []
    for i, run in enumerate(runs):
        d = run["data"]
        color = colors[i]
        depth = d["depth_m"]
        mn = 1e-6
        line, = ax_srd.plot(d["srd_total_N"] * mn, depth, color=color, lw=1.8)
        ax_srd.plot(d["srd_shaft_N"] * mn, depth, color=color, lw=1.3, ls="--")
        handles.append((line, run_label(run, several_levels)))

        any_clipped |= clipped_blows(ax_blows, d["blows_per_0.25m"], depth, blow_cap, color,
                                     lw=1.6)

        cum = d["cumulative_blows"]
        before = np.ones_like(depth, dtype=bool)
        if run["refusal_depth"] is not None:
            before = depth <= run["refusal_depth"] + 1e-9
        ax_cum.plot(cum[before], depth[before], color=color, lw=1.8)
        if (~before).any():
            k = max(int(np.argmax(~before)) - 1, 0)  # join the dotted part to the solid one
            ax_cum.plot(cum[k:], depth[k:], color=color, lw=1.2, ls=":")
            any_beyond = True
        cum_extent = max(cum_extent, finite_max(cum[before]))

        ax_stress.plot(d["max_compression_Pa"] * mn, depth, color=color, lw=1.8)
        ax_stress.plot(d["max_tension_Pa"] * mn, depth, color=color, lw=1.3, ls="--")

    if summary["coupled"]:
        cd, cb = zip(*summary["coupled"])
        ax_blows.plot(cb, cd, ls="none", marker="D", ms=7, mfc="gold", mec="black", mew=0.9, zorder=6)
        handles.append((Line2D([], [], ls="none", marker="D", ms=7, mfc="gold", mec="black"),
                        "coupled MPM-FEM (fitted to)"))
    if observed:
        od, ob = zip(*observed)
        ax_cum.plot(ob, od, ls="none", marker="o", ms=6, mfc="black", mec="white", mew=0.8,
                    color="black", zorder=6)
        cum_extent = max(cum_extent, max(ob))
        handles.append((Line2D([], [], ls="none", marker="o", ms=6, mfc="black", mec="white",
                               color="black"), "observed"))

    # (a) SRD
    ax_srd.set_xlim(0, nice_ceiling(finite_max(*[r["data"]["srd_total_N"] * 1e-6 for r in runs])
                                    * 1.05))
    ax_srd.set_xlabel("SRD (MN)")
    ax_srd.set_title("(a) Soil resistance to driving", fontsize=11)
    ax_srd.legend(handles=[Line2D([], [], color="0.3", lw=1.8),
                           Line2D([], [], color="0.3", lw=1.3, ls="--")],
                  labels=["total", "shaft"], loc="best", fontsize=9, framealpha=0.9)

    # (b) blows per 0.25 m
    ax_blows.set_xlim(0, blow_xmax)
    count_lines(ax_blows, hard, refusal)
    ax_blows.set_xlabel("Blows per 0.25 m" +
                        (f"  (▶ off scale, > {blow_cap:g})" if any_clipped else ""))
    ax_blows.set_title("(b) Blow count", fontsize=11)

    # (c) cumulative blows
    ax_cum.set_xlim(0, nice_ceiling(cum_extent * 1.08) if cum_extent > 0 else 1.0)
    ax_cum.set_xlabel("Cumulative blows")
    ax_cum.set_title("(c) Cumulative blows", fontsize=11)
    if any_beyond:
        ax_cum.legend(handles=[Line2D([], [], color="0.3", lw=1.2, ls=":")],
                      labels=["beyond refusal"], loc="upper right", fontsize=9, framealpha=0.9)

    # (d) stresses
    ax_stress.set_xlim(*stress_limits([r["data"]["max_compression_Pa"] * 1e-6 for r in runs],
                                      [r["data"]["max_tension_Pa"] * 1e-6 for r in runs]))
    ax_stress.set_xlabel("Max stress in the pile (MPa)")
    ax_stress.set_title("(d) Driving stresses", fontsize=11)
    ax_stress.legend(handles=[Line2D([], [], color="0.3", lw=1.8),
                              Line2D([], [], color="0.3", lw=1.3, ls="--")],
                     labels=["compression", "tension"], loc="best", fontsize=9,
                     framealpha=0.9)

    if planned:
        ax_e = axes[4]
        rated = summary.get("rated_energy_J")
        for i, e in enumerate(energies):
            if e is not None:
                x = e * rated * 1e-3 if rated else e * 100
                ax_e.plot(x, runs[i]["data"]["depth_m"], color=colors[i], lw=1.6)
        ax_e.set_xlim(left=0)
        ax_e.set_xlabel("Hammer energy (kJ)" if rated else "Hammer energy (% of rated)")
        ax_e.set_title("(e) Energy used", fontsize=11)

    if cpt is not None:
        axes = [all_axes[0]] + axes
    for ax in axes:
        ax.set_ylim(depth_bottom, 0.0)  # depth axis points down
        ax.grid(True, alpha=0.35)
        ax.tick_params(labelsize=9.5)
        ax.xaxis.set_major_locator(MaxNLocator(nbins=6, steps=[1, 2, 2.5, 5, 10]))
    for i, run in enumerate(runs):
        if run["refusal_depth"] is not None:
            for ax in axes:
                mark_refusal(ax, run["refusal_depth"], colors[i])
    axes[0].set_ylabel("Depth below seabed (m)")

    fig.suptitle(summary["title"], fontsize=14, fontweight="bold")
    handles, labels, ncol = legend_layout(runs, handles, levels, several_levels)
    fig.legend(handles, labels, loc="lower center", ncol=ncol, fontsize=10, frameon=False,
               bbox_to_anchor=(0.5, 0.0))
    rows = math.ceil(len(handles) / ncol)
    fig.tight_layout(rect=(0, 0.035 * rows + 0.01, 1, 0.96), w_pad=2.0)
    fig.savefig(os.path.join(out_dir, "drivability.png"), dpi=100)
    plt.close(fig)


def plot_bearing_graph(out_dir, summary):
    name = summary["bearing_file"]
    path = os.path.join(out_dir, os.path.basename(name or "bearing_graph.csv"))
    if not os.path.exists(path):
        if name:  # named in summary.json but not there
            raise InputError(f"{path}: not found (named as bearing_graph_file in summary.json)")
        return
    g = read_columns(path, BEARING_COLUMNS)
    refusal, hard = summary["refusal"], summary["hard"]
    levels = sorted(set(g["energy_level"].tolist()))
    colors = plt.get_cmap("tab10").colors
    mn = 1e-6

    fig, (ax_b, ax_s) = plt.subplots(1, 2, figsize=(14, 7), sharey=True,
                                     gridspec_kw={"width_ratios": [3, 2]})
    max_blows = finite_max(g["blows_per_0.25m"])
    blow_xmax, blow_cap = blow_axis_limit(max_blows, refusal, hard)
    any_clipped = False
    level_handles = []
    for i, level in enumerate(levels):
        sel = g["energy_level"] == level
        order = np.argsort(g["ultimate_resistance_N"][sel])
        r_u = g["ultimate_resistance_N"][sel][order] * mn
        blows = g["blows_per_0.25m"][sel][order]
        color = colors[i % len(colors)]
        any_clipped |= clipped_blows(ax_b, blows, r_u, blow_cap, color, every_point=True,
                                     lw=1.8, marker="o", ms=5)
        ax_s.plot(g["max_compression_Pa"][sel][order] * mn, r_u, color=color, lw=1.8,
                  marker="o", ms=4.5)
        ax_s.plot(g["max_tension_Pa"][sel][order] * mn, r_u, color=color, lw=1.3, ls="--",
                  marker="s", ms=4, mfc="white")
        level_handles.append(Line2D([], [], color=color, lw=1.8, marker="o", ms=5))

    labels = [percent(level) + (" hammer energy" if len(levels) == 1 else "") for level in levels]
    ax_b.set_xlim(0, blow_xmax)
    count_lines(ax_b, hard, refusal)
    ax_b.set_xlabel("Blows per 0.25 m" +
                    (f"  (▶ off scale, > {blow_cap:g})" if any_clipped else ""))
    ax_b.set_ylabel("Ultimate resistance to driving (MN)")
    ax_b.set_title("Bearing graph", fontsize=11)
    ax_b.legend(level_handles, labels, loc="lower right", fontsize=10, framealpha=0.9)
    rmax = finite_max(g["ultimate_resistance_N"] * mn, default=1.0)
    ax_b.set_ylim(0, nice_ceiling(rmax * 1.05))
    ax_s.set_xlim(*stress_limits([g["max_compression_Pa"] * mn], [g["max_tension_Pa"] * mn]))
    ax_s.set_xlabel("Max stress in the pile (MPa)")
    ax_s.set_title("Driving stresses", fontsize=11)
    ax_s.legend(level_handles + [Line2D([], [], color="0.3", lw=1.8, marker="o", ms=4.5),
                                 Line2D([], [], color="0.3", lw=1.3, ls="--", marker="s", ms=4,
                                        mfc="white")],
                labels + ["compression", "tension"], loc="lower right", fontsize=9.5,
                framealpha=0.9)
    for ax in (ax_b, ax_s):
        ax.grid(True, alpha=0.35)
        ax.tick_params(labelsize=9.5)

    fig.suptitle(summary["title"], fontsize=14, fontweight="bold")
    fig.tight_layout(rect=(0, 0, 1, 0.95))
    fig.savefig(os.path.join(out_dir, "bearing_graph.png"), dpi=110)
    plt.close(fig)


CALIBRATION_COLUMNS = ["depth_m", "time_s", "coupled_force_N", "coupled_velocity_m_s", "fast_before_force_N",
                       "fast_before_velocity_m_s", "fast_after_force_N", "fast_after_velocity_m_s"]


def plot_calibration(out_dir, summary):
    cal = summary["calibration"]
    if not cal:
        return
    if not isinstance(cal, dict) or not isinstance(cal.get("points"), list):
        raise InputError(f"{out_dir}/summary.json: \"calibration\" without its points")
    r = read_columns(os.path.join(out_dir, os.path.basename(cal.get("records_file", "calibration_records.csv"))),
                     CALIBRATION_COLUMNS)
    depths = sorted(set(r["depth_m"].tolist()))
    force = bool(cal.get("compares_force"))
    rows = 2 if force else 1
    fig, axes = plt.subplots(rows, len(depths) + 1, figsize=(4.2 * (len(depths) + 1), 4.0 * rows + 0.8),
                             squeeze=False)
    styles = [("coupled", "k", "-", 2.0, "coupled MPM-FEM"), ("fast_before", "tab:blue", "--", 1.4, "fast path, before"),
              ("fast_after", "tab:red", "-", 1.4, "fast path, fitted")]
    for j, d in enumerate(depths):
        sel = r["depth_m"] == d
        t = r["time_s"][sel] * 1e3
        for key, color, ls, lw, label in styles:
            axes[0][j].plot(t, r[key + "_velocity_m_s"][sel], color=color, ls=ls, lw=lw, label=label)
            if force:
                axes[1][j].plot(t, r[key + "_force_N"][sel] * 1e-6, color=color, ls=ls, lw=lw)
        axes[0][j].set_title(f"{d:.2f} m", fontsize=11)
        axes[0][j].set_ylabel("head velocity, down (m/s)")
        axes[-1][j].set_xlabel("time from impact (ms)")
        if force:
            axes[1][j].set_ylabel("head force (MN)")
        for a in (axes[0][j], axes[-1][j]):
            a.grid(True, alpha=0.35)
    axes[0][0].legend(fontsize=9)
    ax = axes[0][-1]
    pts = cal["points"]
    x = np.arange(len(pts))
    w = 0.27
    for k, (key, color, label) in enumerate([("coupled_set_m", "k", "coupled"),
                                             ("fast_set_before_m", "tab:blue", "fast, before"),
                                             ("fast_set_after_m", "tab:red", "fast, fitted")]):
        ax.bar(x + (k - 1) * w, [1e3 * number(p, key, "calibration.points") for p in pts], w, color=color, label=label)
    ax.set_xticks(x, [f"{number(p, 'depth_m', 'calibration.points'):.2f} m" for p in pts])
    ax.set_ylabel("set per blow (mm)")
    ax.set_ylim(0, 1.45 * max(1e3 * number(p, k, "calibration.points") for p in pts
                              for k in ("coupled_set_m", "fast_set_before_m", "fast_set_after_m")))
    ax.set_title("Sets", fontsize=11)
    ax.legend(fontsize=8, loc="upper right")
    ax.grid(True, axis="y", alpha=0.35)
    for a in axes[1:, -1] if force else []:
        a.axis("off")
    fig.suptitle(f"{summary['title']}\nthe fast path fitted to the coupled model: objective "
                 f"{cal.get('objective_before', float('nan')):.3g} before, {cal.get('objective_after', float('nan')):.3g} after",
                 fontsize=12, fontweight="bold")
    fig.tight_layout(rect=(0, 0, 1, 0.9))
    fig.savefig(os.path.join(out_dir, "calibration.png"), dpi=100)
    plt.close(fig)


def main(argv):
    if len(argv) != 2:
        print(f"usage: {PROG} OUT_DIR", file=sys.stderr)
        return 2
    out_dir = argv[1]
    try:
        summary = read_summary(out_dir)
    except InputError as e:
        print(f"{PROG}: {e}", file=sys.stderr)
        return 2
    status = 0
    for plot in (plot_drivability, plot_bearing_graph, plot_calibration):
        try:
            plot(out_dir, summary)
        except (OSError, InputError) as e:
            print(f"{PROG}: {e}", file=sys.stderr)
            status = 2
    return status


if __name__ == "__main__":
    sys.exit(main(sys.argv))
