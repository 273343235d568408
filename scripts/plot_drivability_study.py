#!/usr/bin/env python3
"""Plots of a drivability study against field records: usage `plot_drivability_study.py OUT_DIR`.

study.png             predicted against measured total blows over the driven range, one
                      marker per location and soil case, log axes, with the 1:1 line and a
                      factor of 1.5 either side; the calibration location ringed.
locations/<LOC>.png   per location, depth pointing down: (a) q_t with the soil type from
                      the CPT (sand-like / clay-like after smoothing), (b) blows per metre,
                      measured (black) and predicted per soil case, the band between the
                      study's lower and upper cases shaded, (c) cumulative blows from the
                      start of driving, (d) the hammer energy used at each depth.

Inputs in OUT_DIR: summary.json, study.csv and locations/<LOC>.csv, <LOC>_cpt.csv.
Exit status: 0 success, 2 missing/malformed input, 3 matplotlib not available.
"""
import csv
import json
import math
import os
import sys

import plot_common
from plot_common import InputError, require_matplotlib

plt = require_matplotlib(__file__)
import numpy as np  # noqa: E402

PROG = "plot_drivability_study.py"
COLORS = ["tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple", "tab:brown"]


def read_rows(path):
    try:
        with open(path, newline="") as f:
            return list(csv.DictReader(f))
    except OSError as e:
        raise InputError(f"{path}: {e.strerror or e}")


def number(x):
    try:
        v = float(x)
    except (TypeError, ValueError):
        return math.nan
    return v


def plot_study(out_dir, summary, rows):
    cases = list(dict.fromkeys(r["soil_case"] for r in rows))
    fig, ax = plt.subplots(figsize=(8, 7.5))
    lo, hi = math.inf, 0.0
    stats = {s["soil_case"]: s for s in summary.get("statistics", [])}
    for k, case in enumerate(cases):
        sel = [r for r in rows if r["soil_case"] == case]
        m = np.array([number(r["measured_total_blows"]) for r in sel])
        p = np.array([number(r["predicted_total_blows"]) for r in sel])
        cal = np.array([number(r["calibration_location"]) > 0 for r in sel])
        ok = (m > 0) & (p > 0)
        st = stats.get(case, {})
        label = (f"{case} ({sel[0]['srd_method']}): median |ln| "
                 f"{st.get('median_abs_ln_predicted_over_measured', math.nan):.2f}, "
                 f"r {st.get('median_profile_correlation', math.nan):.2f}")
        ax.plot(m[ok & ~cal], p[ok & ~cal], "o", ms=5, color=COLORS[k % len(COLORS)], alpha=0.8, label=label)
        if (ok & cal).any():
            ax.plot(m[ok & cal], p[ok & cal], "o", ms=11, mfc="none", mec=COLORS[k % len(COLORS)], mew=1.5)
        if ok.any():
            lo, hi = min(lo, m[ok].min(), p[ok].min()), max(hi, m[ok].max(), p[ok].max())
    if not math.isfinite(lo):
        lo, hi = 1.0, 10.0
    lo, hi = lo / 1.5, hi * 1.5
    x = np.array([lo, hi])
    ax.plot(x, x, "k-", lw=1, label="1:1")
    ax.plot(x, 1.5 * x, "k:", lw=1, label="factor 1.5")
    ax.plot(x, x / 1.5, "k:", lw=1)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlim(lo, hi)
    ax.set_ylim(lo, hi)
    ax.set_xlabel("Measured blows over the driven range")
    ax.set_ylabel("Predicted blows over the driven range")
    ref = summary.get("reference_energy_J", math.nan)
    cal = summary.get("calibration", {})
    sub = f"reference energy {ref / 1e3:.0f} kJ" + (f", fitted on {cal['location']} (ringed)" if cal else "")
    ax.set_title(f"{summary.get('title', 'Drivability study')}\n{sub}", fontsize=11)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8.5, loc="upper left")
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "study.png"), dpi=100)
    plt.close(fig)


def plot_location(out_dir, summary, loc, cases):
    base = os.path.join(out_dir, "locations", loc)
    with open(base + ".csv") as f:
        header = next(csv.reader(f))
    d = {n: np.asarray(v, dtype=float) for n, v in plot_common.read_columns(base + ".csv", header).items()}
    cpt_cols = ["depth_m", "qt_Pa", "soil_type_clay"]
    c = {n: np.asarray(v, dtype=float) for n, v in plot_common.read_columns(base + "_cpt.csv", cpt_cols).items()}
    fig, (ax_q, ax_b, ax_c, ax_e) = plt.subplots(1, 4, figsize=(15, 8), sharey=True,
                                                 gridspec_kw={"width_ratios": [1.1, 1.3, 1.1, 0.7]})
    z = c["depth_m"]
    clay = c["soil_type_clay"] > 0.5
    ax_q.plot(c["qt_Pa"] * 1e-6, z, color="0.2", lw=1.3)
    for zi, is_clay in zip(z, clay):
        if is_clay:
            ax_q.axhspan(zi - 0.25, zi + 0.25, color="tab:brown", alpha=0.25, lw=0)
    ax_q.set_xlabel("q_t (MPa); clay-like shaded")
    ax_q.set_title("(a) CPT", fontsize=11)
    depth = d["depth_m"]
    band = summary.get("band", "").split(" .. ")
    if len(band) == 2 and all(f"predicted_blows_per_m_{b}" in d for b in band):
        a, b = d[f"predicted_blows_per_m_{band[0]}"], d[f"predicted_blows_per_m_{band[1]}"]
        ax_b.fill_betweenx(depth, np.minimum(a, b), np.maximum(a, b), color="0.85", label="band")
    for k, case in enumerate(cases):
        col = COLORS[k % len(COLORS)]
        ax_b.plot(d[f"predicted_blows_per_m_{case}"], depth, color=col, lw=1.4, label=case)
        ax_c.plot(d[f"predicted_cumulative_blows_{case}"], depth, color=col, lw=1.4)
    ax_b.plot(d["measured_blows_per_m"], depth, "k.-", lw=1.2, ms=4, label="measured")
    ax_c.plot(d["measured_cumulative_blows"], depth, "k.-", lw=1.2, ms=4)
    ax_e.plot(d["hammer_energy_J"] * 1e-3, depth, color="0.2", lw=1.4)
    ax_b.set_xlabel("Blows per metre")
    ax_b.set_title("(b) Blow count", fontsize=11)
    ax_b.legend(fontsize=8.5, loc="lower right")
    ax_c.set_xlabel("Cumulative blows")
    ax_c.set_title("(c) Cumulative blows", fontsize=11)
    ax_e.set_xlabel("Hammer energy (kJ)")
    ax_e.set_title("(d) Energy used", fontsize=11)
    bottom = max(np.nanmax(depth), 1.0) * 1.05
    for ax in (ax_q, ax_b, ax_c, ax_e):
        ax.set_ylim(bottom, 0.0)
        ax.grid(True, alpha=0.35)
        ax.set_xlim(left=0)
    ax_q.set_ylabel("Depth below seabed (m)")
    fig.suptitle(f"Location {loc}", fontsize=13, fontweight="bold")
    fig.tight_layout(rect=(0, 0, 1, 0.96))
    fig.savefig(base + ".png", dpi=90)
    plt.close(fig)


def plot_all(out_dir):
    with open(os.path.join(out_dir, "summary.json")) as f:
        summary = json.load(f)
    rows = read_rows(os.path.join(out_dir, "study.csv"))
    if not rows:
        raise InputError("study.csv: no rows")
    plot_study(out_dir, summary, rows)
    cases = list(dict.fromkeys(r["soil_case"] for r in rows))
    for loc in dict.fromkeys(r["location"] for r in rows):
        plot_location(out_dir, summary, loc, cases)


def main(argv):
    return plot_common.run_main(PROG, argv, plot_all)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
