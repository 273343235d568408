#!/usr/bin/env python3
"""Validation 2 of issue 13: the centrifuge pile of seed 000 (Huy 2008, Deltares) jacked at
40 g and load-tested, with and without its installation, against NEN 9997-1's base
settlement lines:

    centrifuge_study.py --out DIR [--cells-per-diameter N] [--near-pile M] [--container full|cut]
                        [--sands medium,loose] [--models mohr_coulomb,hypoplastic]
                        [--cfl C] [--pilempm build/pilempm] [--threads N] [--check]

Every run is derived from cases/jacking/centrifuge-huy2008.yaml (medium-dense sand,
Mohr-Coulomb, jacked): the sand (medium dense, D_R 54 %, e0 0.68; loose, D_R 36 %, e0 0.75),
the model (the seed's Mohr-Coulomb; hypoplastic with seed 000 C's Schlabendorfer sand
parameters at the same e0, as the seed names no other), and the installation: `jacked` (the
pile pre-embedded 10 D, jacked 10 D, unloaded, then the static load test, SLT, over 0.12 D)
or `wished` (pre-embedded 20 D, no installation, the SLT over 0.25 D). Each run goes to
DIR/<sand>-<model>-<installation> (pilempm run); a complete run of the same case there,
newer than pilempm and the template, is read, not repeated. --cells-per-diameter: the grid
(default 4, the template's); --container cut: the sand cut to 13 D in radius and 20 D below
the final toe (default full: the container, 26 D and 50 D). CI runs D/2 in the cut one.
--near-pile M: a graded grid, cells of D/M within 3 D of the axis and from 4 D below the
final toe up (the soil the pile passes and its toe bears on), growing over 3 D to the
D/N cells elsewhere (default: N, a uniform grid).

DIR/centrifuge_base.csv    per run: the base capacity at 0.1 D and 0.2 D of base settlement,
                           the settlement at half the capacity, and the mean distance of the
                           normalised curve from NEN 9997-1's lines 1 and 3.
DIR/centrifuge_base.png    base resistance against s_b / D (kN), and normalised against the
                           NEN lines (the seed's "comparison to NEN 9997").
DIR/<run>/slt_base.csv     each SLT's base settlement (m, % of D) and base resistance (N).

The capacity is read as NEN 9997-1 reads it: at s_b = 0.1 D for a driven (here jacked) pile,
0.2 D for a bored one (here wished in place). The seed reports that the hypoplastic SLT after
installation follows line 1 and the wished-in-place pile line 3, and that Mohr-Coulomb does
not capture the SLT after installation. --check exits 1 unless the trends hold: installation
raises the base resistance at 0.1 D; without installation the medium-dense sand carries
more than the loose; and with the hypoplastic model installation also stiffens the base (a
smaller s_b at half the capacity), the medium-dense sand carries more after installation
too, the jacked curve lies nearer line 1 than line 3 and the wished one nearer line 3.
It also holds every run's contact to issue 13's bound: the deepest penetration of a point
into the pile over the whole run (history.csv, max_penetration_over_cell) below 1 % of a cell.

Exit status: 0 success (and trends held with --check), 1 a run failed or a trend did not
hold, 2 bad input, 3 matplotlib not available.
"""
import argparse
import copy
import csv
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from plot_common import InputError, read_columns, require_matplotlib, save_figure  # noqa: E402

plt = require_matplotlib(__file__)
import yaml  # noqa: E402  (after the re-run under the system python, which has python3-yaml)
import study_runs  # noqa: E402  (reads YAML too)

ROOT = os.path.dirname(HERE)
TEMPLATE = os.path.join(ROOT, "cases", "jacking", "centrifuge-huy2008.yaml")
NEN_CURVES = os.path.join(ROOT, "cases", "jacking", "data", "nen9997-1-base-settlement-curves.csv")
D = 0.0113                  # m, the model pile
G_S = 2.65                  # grain density over water's (not given: quartz sand)
VELOCITY = 1.0              # m/s, jacking
SLT_VELOCITY = 0.1          # m/s, the load test
RISE = 0.02                 # s, the jack's rise
SLT_RISE = 0.002            # s
SLT_DEPTH = {"jacked": 0.12 * D, "wished": 0.25 * D}   # past 0.1 D and 0.2 D, the read-offs
PENETRATION_BOUND = 0.01   # of a cell, issue 13's
CAPACITY_AT = {"jacked": 0.10, "wished": 0.20}          # s_b / D where NEN 9997-1 reads it
# The seed's table: D_R, e0, E (Pa); phi 30 deg, psi 0, c 1 kPa, nu 0.3 for both.
SANDS = {"medium": (54, 0.68, 40.0e6), "loose": (36, 0.75, 22.0e6)}
MODELS = ("mohr_coulomb", "hypoplastic")
INSTALLATIONS = ("jacked", "wished")
CONTAINERS = {  # the sand's radius and depth below the final toe (None: the template's)
    "full": (None, None),
    "cut": (13.0 * D, 20.0 * D),
}
# seed 000 C: Schlabendorfer sand (Mahutka 2008), with intergranular strain.
HYPOPLASTIC = {"friction_angle": 33.0, "h_s": 1600.0e6, "n": 0.19, "e_d0": 0.44, "e_c0": 0.85, "e_i0": 1.00,
               "alpha": 0.25, "beta": 1.00, "p_t": 1.0e3, "intergranular_strain": True, "m_T": 2.0, "m_R": 5.0,
               "R_max": 1.0e-4, "beta_r": 0.5, "chi": 6.0}


def name_of(sand, model, installation):
    return f"{sand}-{model.replace('_', '-')}-{installation}"


def dry_density(e0):
    return round(1000.0 * G_S / (1.0 + e0), 1)


def graded_grid(width, surface, top, final_toe, coarse, fine):
    """Zones of cells of `fine` within 3 D of the axis and from 4 D under the final toe up,
    grading over 3 D to `coarse` beyond; the surface on a grid line."""
    near = round(math.ceil(3.0 * D / fine) * fine, 9)
    fine_from = max(0.0, final_toe - 4.0 * D - 3.0 * D)
    y0 = round(math.floor(fine_from / coarse) * coarse, 9)
    x = [{"to": near, "cell": fine}, {"to": round(near + 3.0 * D, 9), "cell": coarse}, {"to": width, "cell": coarse}]
    y = ([{"to": y0, "cell": coarse}] if y0 > 0.0 else []) + [
        {"to": round(y0 + 3.0 * D, 9), "cell": fine}, {"to": surface, "cell": fine}, {"to": top, "cell": fine}]
    return {"origin": [0.0, 0.0], "zones": {"x": x, "y": y}}


def variant(template, sand, model, installation, per_d, container, near_pile=None, cfl=None):
    """The case of one sand, model and installation on cells of D / per_d (D / near_pile by
    the pile, graded, when given and finer); cfl, when given, the share of the stable step
    (the soil's and the contact's) taken."""
    radius, below_toe = CONTAINERS[container]
    cell = D / per_d
    c = copy.deepcopy(template)
    t_size, t_cells = c["grid"]["size"], c["grid"]["cells"]
    t_cell = t_size[0] / t_cells[0]
    surface_t = c["initial_stress"]["surface"]
    above = t_size[1] - surface_t                       # empty grid over the sand (heave)
    pre = surface_t - c["pile"]["toe_elevation"]        # the template's pre-embedment, 10 D
    final_depth = pre + 10.0 * D
    nx = round((radius if radius else t_size[0]) / cell)
    ny_soil = round((final_depth + below_toe) / cell) if below_toe else round(surface_t / cell)
    ny_above = round(above / cell)
    surface = round(ny_soil * cell, 9)
    width = round(nx * cell, 9)
    d_r, e0, youngs = SANDS[sand]
    c["title"] = (f"Validation 2, {sand} sand (D_R {d_r} %), {model.replace('_', '-')}, "
                  + ("jacked 10 D at 40 g" if installation == "jacked" else "wished in place 20 D") + ", then the SLT")
    c["grid"] = {"origin": [0.0, 0.0], "size": [width, round((ny_soil + ny_above) * cell, 9)],
                 "cells": [nx, ny_soil + ny_above]}
    if near_pile and near_pile > per_d:
        c["grid"] = graded_grid(width, surface, round((ny_soil + ny_above) * cell, 9), surface - final_depth, cell,
                                D / near_pile)
        cell = D / near_pile  # the pile's elements follow the fine cells
    sand_material = c["materials"][0]
    if model == "mohr_coulomb":
        sand_material.update(density=dry_density(e0), youngs_modulus=youngs)
    else:
        c["materials"][0] = dict({"name": "sand", "model": "hypoplastic", "density": dry_density(e0)}, **HYPOPLASTIC,
                                 void_ratio=e0)
    c["regions"][0]["box"] = {"min": [0.0, 0.0], "max": [width, surface]}
    c["initial_stress"]["surface"] = surface
    pile = c["pile"]
    pile["element_size"] = round(pile["element_size"] * cell / t_cell, 9)
    by_name = {s["name"]: s for s in c["stages"]}
    slt = dict(by_name["slt"], duration=round(SLT_DEPTH[installation] / SLT_VELOCITY + SLT_RISE / 2.0, 9))
    slt["pile"] = {"velocity": SLT_VELOCITY, "rise_time": SLT_RISE}
    if installation == "jacked":
        pile["toe_elevation"] = round(surface - pre, 9)
        jack = dict(by_name["jack"], duration=round(10.0 * D / VELOCITY + RISE / 2.0, 9))
        jack["pile"] = {"velocity": VELOCITY, "rise_time": RISE}
        c["stages"] = [by_name["geostatic"], jack, by_name["unload"], slt]
    else:
        pile["toe_elevation"] = round(surface - final_depth, 9)
        c["stages"] = [by_name["geostatic"], slt]
    c["output"]["snapshot_interval"] = round(sum(s.get("duration", 0.0) for s in c["stages"]) / 12.0, 9)
    if cfl is not None:
        c["cfl"] = cfl
    return c


def slt_curve(out_dir):
    """The last stage's base settlement (m, from its start) and base resistance (N)."""
    h = read_columns(os.path.join(out_dir, "history.csv"), ["stage", "pile_toe_elevation_m", "base_resistance_N"])
    last = max(h["stage"])
    rows = [(z, f) for s, z, f in zip(h["stage"], h["pile_toe_elevation_m"], h["base_resistance_N"]) if s == last]
    if len(rows) < 2:
        raise InputError(f"{out_dir}/history.csv: no rows in the load test (the last stage)")
    z0 = rows[0][0]
    return [z0 - z for z, _ in rows], [f for _, f in rows]


def at_settlement(settlement, force, s):
    """The base resistance where the settlement first reaches s (linear between rows)."""
    for k in range(1, len(settlement)):
        if settlement[k] >= s:
            a, b = settlement[k - 1], settlement[k]
            w = (s - a) / (b - a) if b > a else 1.0
            return force[k - 1] + w * (force[k] - force[k - 1])
    raise InputError(f"the load test stopped at s_b = {settlement[-1] / D:.3f} D, short of {s / D:.3f} D")


def settlement_at(settlement, force, f):
    """The settlement where the base resistance first reaches f."""
    for k in range(len(force)):
        if force[k] >= f:
            if k == 0:
                return settlement[0]
            a, b = force[k - 1], force[k]
            w = (f - a) / (b - a) if b > a else 1.0
            return settlement[k - 1] + w * (settlement[k] - settlement[k - 1])
    return float("nan")


def read_nen():
    rows = []
    with open(NEN_CURVES) as f:
        for line in f:
            if not line.startswith("#"):
                rows.append(line.strip())
    reader = csv.DictReader(rows)
    table = {"fraction": [], 1: [], 2: [], 3: []}
    for r in reader:
        table["fraction"].append(float(r["mobilised_fraction"]))
        for k in (1, 2, 3):
            table[k].append(float(r[f"line{k}_sb_over_D_percent"]))
    return table


def distance_from_line(settlement, force, capacity, nen, line):
    """Mean |s_b / D - line's s_b / D| in % of D over the mobilised levels 0.1 to 0.9."""
    gaps = []
    for frac, s_line in zip(nen["fraction"], nen[line]):
        if 0.1 <= frac <= 0.9:
            s = settlement_at(settlement, force, frac * capacity)
            if not math.isnan(s):
                gaps.append(abs(100.0 * s / D - s_line))
    return sum(gaps) / len(gaps) if gaps else float("nan")


def write_curve(out_dir, settlement, force):
    with open(os.path.join(out_dir, "slt_base.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["base_settlement_m", "base_settlement_over_D_percent", "base_resistance_N"])
        for s, q in zip(settlement, force):
            w.writerow([f"{s:.6e}", f"{100.0 * s / D:.4f}", f"{q:.4f}"])


def study(args):
    with open(TEMPLATE) as f:
        template = yaml.safe_load(f)
    nen = read_nen()
    results = []
    for sand in args.sands:
        for model in args.models:
            for installation in INSTALLATIONS:
                name = name_of(sand, model, installation)
                case = variant(template, sand, model, installation, args.cells_per_diameter, args.container,
                               args.near_pile, args.cfl)
                out = study_runs.run_case(case, os.path.join(args.out, name), args.pilempm, args.threads, TEMPLATE)
                s, q = slt_curve(out)
                penetration = max(read_columns(os.path.join(out, "history.csv"), ["max_penetration_over_cell"])
                                  ["max_penetration_over_cell"])
                write_curve(out, s, q)
                capacity = at_settlement(s, q, CAPACITY_AT[installation] * D)
                results.append({
                    "name": name, "sand": sand, "model": model, "installation": installation, "s": s, "q": q,
                    "capacity": capacity, "penetration": penetration, "q_01": at_settlement(s, q, 0.1 * D),
                    "q_02": at_settlement(s, q, 0.2 * D) if installation == "wished" else float("nan"),
                    "s50": settlement_at(s, q, 0.5 * capacity) / D,
                    "to_line1": distance_from_line(s, q, capacity, nen, 1),
                    "to_line3": distance_from_line(s, q, capacity, nen, 3)})
    write_table(args.out, results)
    plot(args.out, results, nen, args.cells_per_diameter)
    for r in results:
        print(f"{r['name']}: base capacity {r['capacity']:.0f} N at {CAPACITY_AT[r['installation']]:g} D "
              f"(q_b {r['capacity'] / (math.pi * D * D / 4.0) / 1e6:.2f} MPa), at 0.1 D {r['q_01']:.0f} N; "
              f"s_b at half of it {100.0 * r['s50']:.2f} % D (line 1: 1.18, line 3: 4.40); "
              f"mean distance from line 1 {r['to_line1']:.2f} % D, line 3 {r['to_line3']:.2f} % D; "
              f"deepest penetration {100.0 * r['penetration']:.2f} % of a cell")
    return check(results) if args.check else 0


def write_table(out_dir, results):
    with open(os.path.join(out_dir, "centrifuge_base.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["run", "sand", "model", "installation", "base_capacity_N", "capacity_read_at_sb_over_D",
                    "base_resistance_at_0.1D_N", "base_resistance_at_0.2D_N", "sb_at_half_capacity_over_D_percent",
                    "mean_distance_from_NEN_line1_percent_D", "mean_distance_from_NEN_line3_percent_D"])
        for r in results:
            w.writerow([r["name"], r["sand"], r["model"], r["installation"], f"{r['capacity']:.3f}",
                        CAPACITY_AT[r["installation"]], f"{r['q_01']:.3f}", f"{r['q_02']:.3f}",
                        f"{100.0 * r['s50']:.4f}", f"{r['to_line1']:.4f}", f"{r['to_line3']:.4f}"])


def plot(out_dir, results, nen, per_d):
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(13, 5.5))
    colours = {("medium", "mohr_coulomb"): "tab:blue", ("loose", "mohr_coulomb"): "tab:cyan",
               ("medium", "hypoplastic"): "tab:red", ("loose", "hypoplastic"): "tab:orange"}
    for r in results:
        style = "-" if r["installation"] == "jacked" else "--"
        colour = colours[(r["sand"], r["model"])]
        sd = [100.0 * x / D for x in r["s"]]
        ax1.plot(sd, [x / 1e3 for x in r["q"]], style, color=colour, label=r["name"])
        if r["capacity"] > 0.0:  # a toe that floated after unloading never reached the soil again
            ax2.plot([x / r["capacity"] for x in r["q"]], sd, style, color=colour, label=r["name"])
    ax1.set_xlabel("base settlement s_b / D (%)")
    ax1.set_ylabel("base resistance (kN)")
    ax1.set_title(f"Static load tests at 40 g (cells of D/{per_d})")
    ax1.grid(True, alpha=0.4)
    ax1.legend(fontsize=7)
    for line, style in ((1, "k-"), (2, "k:"), (3, "k-.")):
        ax2.plot(nen["fraction"], nen[line], style, lw=1.5, label=f"NEN 9997-1 line {line}")
    ax2.invert_yaxis()
    ax2.set_xlim(0.0, 1.05)
    ax2.set_ylim(20.0, 0.0)
    ax2.set_xlabel("R_b / R_b;max (capacity at 0.1 D jacked, 0.2 D wished in place)")
    ax2.set_ylabel("s_b / D (%)")
    ax2.set_title("Against NEN 9997-1 (line 1 driven, 3 bored)")
    save_figure(fig, os.path.join(out_dir, "centrifuge_base.png"), (ax2,))
    plt.close(fig)


def check(results):
    """The seed's trends (module docstring). Mohr-Coulomb's constant stiffness reloads the
    jacked pile's base elastically from the installation's unloading, far from its capacity
    at 0.1 D; the seed shows Mohr-Coulomb missing the SLT after installation (it needs the
    hypoplastic model), so for it only the base gain from installation and, without
    installation, the sands' order are checked."""
    by = {(r["sand"], r["model"], r["installation"]): r for r in results}
    failed = [f"{r['name']}: the contact's penetration reached {100.0 * r['penetration']:.2f} % of a cell (bound 1 %)"
              for r in results if r["penetration"] > PENETRATION_BOUND]
    for (sand, model, inst), r in by.items():
        if inst != "jacked" or (sand, model, "wished") not in by:
            continue
        w = by[(sand, model, "wished")]
        if not r["q_01"] > w["q_01"]:
            failed.append(f"{sand} {model}: jacked base at 0.1 D {r['q_01']:.0f} N not above wished {w['q_01']:.0f} N")
        if model == "hypoplastic" and not r["s50"] < w["s50"]:
            failed.append(f"{sand} {model}: jacked s_b at half capacity {100 * r['s50']:.2f} % D not below wished "
                          f"{100 * w['s50']:.2f} % D")
    for (sand, model, inst), r in by.items():
        if sand == "medium" and ("loose", model, inst) in by and (model == "hypoplastic" or inst == "wished"):
            lo = by[("loose", model, inst)]
            if not r["capacity"] > lo["capacity"]:
                failed.append(f"{model} {inst}: medium-dense capacity {r['capacity']:.0f} N not above loose "
                              f"{lo['capacity']:.0f} N")
        if model == "hypoplastic":
            nearer, other = (1, 3) if inst == "jacked" else (3, 1)
            if not r[f"to_line{nearer}"] < r[f"to_line{other}"]:
                failed.append(f"{r['name']}: nearer NEN line {other} ({r[f'to_line{other}']:.2f} % D) than "
                              f"line {nearer} ({r[f'to_line{nearer}']:.2f} % D)")
    return study_runs.trends_status(failed)


def main():
    ap = argparse.ArgumentParser(description="Validation 2: the centrifuge pile of seed 000 against NEN 9997-1")
    ap.add_argument("--out", required=True)
    ap.add_argument("--cells-per-diameter", type=int, default=4)
    ap.add_argument("--near-pile", type=int, default=None)
    ap.add_argument("--container", choices=tuple(CONTAINERS), default="full")
    ap.add_argument("--sands", default="medium,loose")
    ap.add_argument("--models", default="mohr_coulomb,hypoplastic")
    ap.add_argument("--pilempm", default=os.path.join(ROOT, "build", "pilempm"))
    ap.add_argument("--threads", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--cfl", type=float, default=None,
                    help="share of the stable step taken (default the case's 0.5): halve it to check the step")
    ap.add_argument("--check", action="store_true")
    args = ap.parse_args()
    args.sands, args.models = args.sands.split(","), args.models.split(",")
    if args.cells_per_diameter < 1:
        raise InputError(f"--cells-per-diameter: expected a whole number of at least 1, got {args.cells_per_diameter}")
    if args.cfl is not None and not 0.0 < args.cfl < 1.0:
        raise InputError(f"--cfl: expected a number between 0 and 1, got {args.cfl}")
    if args.near_pile is not None and args.near_pile < args.cells_per_diameter:
        raise InputError(f"--near-pile: expected at least --cells-per-diameter ({args.cells_per_diameter}), "
                         f"got {args.near_pile}")
    for given, known, key in ((args.sands, SANDS, "--sands"), (args.models, MODELS, "--models")):
        bad = [x for x in given if x not in known]
        if bad:
            raise InputError(f"{key}: expected some of {', '.join(known)} separated by commas, got '{bad[0]}'")
    return study(args)


if __name__ == "__main__":
    study_runs.exit_with("centrifuge_study.py", main, (InputError,))
