#!/usr/bin/env python3
"""Validation 3 of issue 13: the shaft capacity of a jacked pile against the same pile
wished in place, Q_s^f / Q_s^0, for the models of seed 002's Table 2 (Jardine et al. 2013's
sand, D = 0.8 m, closed-ended):

    shaft_capacity_study.py --out DIR [--size full|reduced] [--cells-per-diameter N[,N...]]
                            [--models 1,2,...] [--jack-velocity V] [--slip-friction-angle A]
                            [--peak-friction-offset P]
                            [--pilempm build/pilempm] [--threads N] [--check]

Every model is derived from cases/jacking/shaft-capacity.yaml (model 2, jacked): the same
sand, pile and stages with the model's L/D, phi' and OCR, and its wished-in-place twin
(toe at L, the soil in the steel removed, a nil step, the same D/30 push); the toe's slip
line takes the model's phi'. Each run goes to DIR/<code>-D<N>-jacked and
DIR/<code>-D<N>-wished (pilempm run; N the cells per diameter); a complete run of the same
case there, newer than pilempm and the template, is read, not repeated. --size reduced uses
cells of D/3 instead of the paper's D/4; --cells-per-diameter runs each model on each of
the grids given (a grid sequence). --jack-velocity jacks at V m/s instead of 1 (the push
stays at 1 m/s; runs go to DIR/<code>-D<N>-jack<V>-jacked), to see what the rate does.
--slip-friction-angle sets the toe slip line's friction angle to A degrees in every model
instead of the model's phi' (runs go to DIR/<code>-D<N>-slip<A>-...), to see what the
slip line, a numerical device, does to the phi' trend. --peak-friction-offset bounds each
model's sand by the Matsuoka-Nakai cone P degrees above its phi' (peak_friction_angle of
subloading Cam clay; runs go to DIR/<code>-D<N>-peak+<P>-...); without it the case file's
own offset holds (none: the model as published, whose dry side reaches tension).

DIR/shaft_capacity.csv   per model and grid: Q_s^f, Q_s^0, their ratio, each over
                         mu K0 sigma'_v0 A (sigma'_v0 at mid-embedment, A the shaft's area),
                         and the mean normal traction on the shaft after the push, jacked
                         over wished.
DIR/shaft_capacity.png   the ratios per model on the finest grid (the paper's Figure 22), or
                         against the grid for a sequence, and the shaft's normal traction
                         against depth on the finest grid, jacked and wished.

The seed's text gives trends, not Figure 22's numbers: the gain is larger for phi' = 40
than 20 deg and for L/D 5 than 25, OCR hardly matters, and the jacked shaft's radial
stress averages some 5 times the initial for phi' 40 and 1.5 for phi' 20. --check exits 1
unless, on the finest grid, the phi' trend holds at each L/D run (and the L/D trend where
both were run) and every ratio is above 1, and, for a sequence, each model's ratio on the
two finest grids differs by less than 10 % of the finest's (converged).

Exit status: 0 success (and trends held with --check), 1 a run failed or a trend did
not hold, 2 bad input, 3 matplotlib not available.
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
TEMPLATE = os.path.join(ROOT, "cases", "jacking", "shaft-capacity.yaml")
D = 0.8                     # m, the pile's diameter (Table 2)
WIDTH = 15.0 * D            # the domain: r / R = 30
BELOW_TOE = 10.0 * D        # sand below the toe's final depth
ABOVE = 2.0 * D             # empty grid above the surface (heave)
HEAD_ABOVE = 1.5 * D        # pile above the surface at the end
VELOCITY = 1.0              # m/s, the push, and jacking unless --jack-velocity says otherwise
RISE = 0.02                 # s
PUSH = D / 30.0             # m, the push that mobilises the shaft
CELLS_PER_D = {"full": 4, "reduced": 3}   # the paper's D/4; D/3 in CI
# Table 2 of seed 002: model -> (L/D, phi' in degrees, OCR).
MODELS = {1: (5, 20.0, 1.0), 2: (5, 40.0, 1.0), 3: (25, 20.0, 1.0), 4: (25, 40.0, 1.0),
          5: (5, 40.0, 8.0), 6: (25, 40.0, 8.0)}


def code(model):
    ld, phi, ocr = MODELS[model]
    return f"{ld}-{phi:g}-{ocr:g}"


def peak_offset_of(template, peak_offset=None):
    """Degrees from phi' to the cone that bounds the sand's stress: `peak_offset`, else the
    template's own (its peak_friction_angle less its friction_angle); None: no bound."""
    if peak_offset is not None:
        return peak_offset
    sand = template["materials"][0]
    peak = sand.get("peak_friction_angle", 0.0)
    return peak - sand["friction_angle"] if peak > 0.0 else None


def variant(template, model, jacked, cell, jack_velocity=VELOCITY, slip_angle=None, peak_offset=None):
    """The case of `model` (jacked at `jack_velocity` m/s, or wished in place) on cells of `cell`
    metres, its toe's slip line at `slip_angle` degrees (None: the model's phi'), its sand's
    stress bounded `peak_offset` degrees above phi' (None: as the template)."""
    ld, phi, ocr = MODELS[model]
    offset = peak_offset_of(template, peak_offset)
    c = copy.deepcopy(template)
    length = ld * D
    depth = length + BELOW_TOE
    nx, ny_soil, ny_above = round(WIDTH / cell), round(depth / cell), round(ABOVE / cell)
    surface = round(ny_soil * cell, 9)
    c["title"] = (f"Validation 3, model {model} ({code(model)}): L/D {ld}, phi' {phi:g} deg, OCR {ocr:g}, "
                  + ("jacked" if jacked else "wished in place"))
    c["grid"] = {"origin": [0.0, 0.0], "size": [round(nx * cell, 9), round((ny_soil + ny_above) * cell, 9)],
                 "cells": [nx, ny_soil + ny_above]}
    sand = c["materials"][0]
    sand["friction_angle"], sand["ocr"] = phi, ocr
    if offset is not None:
        sand["peak_friction_angle"] = phi + offset
    if "toe_slip_line" in c["pile"]:
        # The sand's own phi' unless a study sets it.
        c["pile"]["toe_slip_line"]["friction_angle"] = phi if slip_angle is None else slip_angle
    c["regions"][0]["box"] = {"min": [0.0, 0.0], "max": [round(nx * cell, 9), surface]}
    c["initial_stress"]["surface"] = surface
    pile = c["pile"]
    pile["segments"][0]["length"] = length + HEAD_ABOVE
    pile["element_size"] = cell
    by_name = {s["name"]: s for s in c["stages"]}
    push = dict(by_name["push"], duration=PUSH / VELOCITY + RISE / 2.0)
    push["pile"] = {"velocity": VELOCITY, "rise_time": RISE}
    if jacked:
        pile["toe_elevation"] = surface
        jack = dict(by_name["jack"], duration=length / jack_velocity + RISE / 2.0)
        jack["pile"] = {"velocity": jack_velocity, "rise_time": RISE}
        c["stages"] = [by_name["geostatic"], jack, by_name["hold"], push]
        c["output"]["snapshot_interval"] = length / jack_velocity / 16.0
    else:
        pile["toe_elevation"] = surface - length
        pile["wished_in_place"] = True
        nil = dict(by_name["geostatic"], name="nil")
        c["stages"] = [nil, push]
        c["output"]["snapshot_interval"] = push["duration"] / 4.0
    return c


def run_case(case, out_dir, pilempm, threads):
    return study_runs.run_case(case, out_dir, pilempm, threads, TEMPLATE)


def shaft_capacity(out_dir):
    """Q_s: the outer shaft's mean resistance over the second half of the push (the last
    stage), when the whole shaft slips; a mean, as the toe's chatter rides on it. N."""
    h = read_columns(os.path.join(out_dir, "history.csv"), ["stage", "outer_shaft_resistance_N"])
    last = max(h["stage"])
    push = [q for s, q in zip(h["stage"], h["outer_shaft_resistance_N"]) if s == last]
    half = push[len(push) // 2:]
    if not half:
        raise InputError(f"{out_dir}/history.csv: no rows in the push stage")
    return sum(half) / len(half)


def shaft_tractions(out_dir):
    column = "stage_mean_normal_traction_compression_Pa"  # over the push, not its last step
    t = read_columns(os.path.join(out_dir, "pile_tractions_outer.csv"), ["elevation_m", "length_m", column])
    return list(zip(t["elevation_m"], t["length_m"], t[column]))


def mean_traction(rows, top):
    """Length-weighted mean normal traction over the embedded shaft (below `top`)."""
    inside = [(l, s) for z, l, s in rows if z < top]
    total = sum(l for l, _ in inside)
    return sum(l * s for l, s in inside) / total if total > 0 else float("nan")


def surface_of(out_dir):
    with open(out_dir + ".yaml") as f:
        return yaml.safe_load(f)["initial_stress"]["surface"]


def reference_capacity(c, model):
    """mu K0 sigma'_v0 A: the shaft's capacity at the soil's initial stress, sigma'_v0 at
    mid-embedment (the case `c`'s unit weight, K0 and mu). N."""
    sand, length = c["materials"][0], MODELS[model][0] * D
    gamma = sand["density"] * c["gravity"]
    return c["pile"]["friction"] * sand["k0"] * gamma * length / 2.0 * math.pi * D * length


def study(args):
    with open(TEMPLATE) as f:
        template = yaml.safe_load(f)
    results = []
    slip = "" if args.slip_friction_angle is None else f"-slip{args.slip_friction_angle:g}"
    if args.peak_friction_offset is not None:
        slip += f"-peak+{args.peak_friction_offset:g}"
    offset = peak_offset_of(template, args.peak_friction_offset)
    for m in args.models:
        slip_angle = MODELS[m][1] if args.slip_friction_angle is None else args.slip_friction_angle
        for n in args.cells_per_diameter:
            runs = {}
            for jacked in (True, False):
                rate = f"-jack{args.jack_velocity:g}" if jacked and args.jack_velocity != VELOCITY else ""
                name = f"{code(m)}-D{n}{slip}{rate}-{'jacked' if jacked else 'wished'}"
                runs[jacked] = run_case(variant(template, m, jacked, D / n, args.jack_velocity, args.slip_friction_angle,
                                                args.peak_friction_offset),
                                        os.path.join(args.out, name),
                                        args.pilempm, args.threads)
            qf, q0 = shaft_capacity(runs[True]), shaft_capacity(runs[False])
            top = surface_of(runs[True])
            tf, t0 = shaft_tractions(runs[True]), shaft_tractions(runs[False])
            results.append({"model": m, "code": code(m), "ld": MODELS[m][0], "phi": MODELS[m][1],
                            "ocr": MODELS[m][2], "cells": n, "jack_velocity": args.jack_velocity,
                            "slip_angle": slip_angle,
                            "peak_angle": "" if offset is None else MODELS[m][1] + offset, "qf": qf, "q0": q0, "ratio": qf / q0,
                            "qref": reference_capacity(template, m),
                            "sigma_ratio": mean_traction(tf, top) / mean_traction(t0, top), "tf": tf, "t0": t0,
                            "top": top})
    write_table(args.out, results)
    plot(args.out, results)
    for r in results:
        print(f"model {r['model']} ({r['code']}), D/{r['cells']}: Q_s^f = {r['qf'] / 1e3:.1f} kN, "
              f"Q_s^0 = {r['q0'] / 1e3:.1f} kN, ratio {r['ratio']:.2f}; over mu K0 sigma'_v0 A "
              f"{r['qf'] / r['qref']:.2f} and {r['q0'] / r['qref']:.2f}; shaft normal traction jacked / wished "
              f"{r['sigma_ratio']:.2f}")
    return check(results) if args.check else 0


def write_table(out_dir, results):
    with open(os.path.join(out_dir, "shaft_capacity.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["model", "code", "L_over_D", "phi_deg", "OCR", "cells_per_D", "jack_velocity_m_s",
                    "slip_line_friction_angle_deg", "peak_friction_angle_deg", "Qs_jacked_kN", "Qs_wished_kN",
                    "Qs_ratio", "Qs_jacked_over_mu_K0_sv0_A", "Qs_wished_over_mu_K0_sv0_A",
                    "shaft_normal_traction_ratio"])
        for r in results:
            w.writerow([r["model"], r["code"], r["ld"], r["phi"], r["ocr"], r["cells"], r["jack_velocity"], r["slip_angle"], r["peak_angle"],
                        f"{r['qf'] / 1e3:.3f}", f"{r['q0'] / 1e3:.3f}", f"{r['ratio']:.4f}", f"{r['qf'] / r['qref']:.4f}",
                        f"{r['q0'] / r['qref']:.4f}", f"{r['sigma_ratio']:.4f}"])


def finest(results):
    """Each model's result on its finest grid, in the order the models were run."""
    best = {}
    for r in results:
        if r["model"] not in best or r["cells"] > best[r["model"]]["cells"]:
            best[r["model"]] = r
    return list(best.values())


def plot(out_dir, results):
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(12, 5.5))
    top = finest(results)
    if len({r["cells"] for r in results}) > 1:
        for m in dict.fromkeys(r["model"] for r in results):
            seq = sorted((r["cells"], r["ratio"]) for r in results if r["model"] == m)
            ax1.plot([c for c, _ in seq], [q for _, q in seq], "o-", label=f"model {m} ({code(m)})")
        ax1.set_xlabel("cells per diameter")
        ax1.set_title("Shaft capacity, jacked over wished in place, on a grid sequence")
        ax1.legend(fontsize=8)
    else:
        ax1.bar([str(r["model"]) for r in top], [r["ratio"] for r in top], color="tab:blue")
        for i, r in enumerate(top):
            ax1.text(i, r["ratio"], f"{r['ratio']:.2f}", ha="center", va="bottom", fontsize=9)
        ax1.set_xlabel("model (Table 2: " + ", ".join(f"{r['model']} = {r['code']}" for r in top) + ")", fontsize=8)
        ax1.set_title(f"Shaft capacity, jacked over wished in place (cells of D/{top[0]['cells']})")
    ax1.axhline(1.0, color="k", lw=0.8)
    ax1.set_ylabel("Q_s^f / Q_s^0")
    for r in top:
        for rows, style, label in ((r["tf"], "-", "jacked"), (r["t0"], "--", "wished")):
            pts = sorted((r["top"] - z, s / 1e3) for z, _, s in rows if z < r["top"])
            ax2.plot([s for _, s in pts], [d for d, _ in pts], style, label=f"{r['code']} D/{r['cells']} {label}")
    ax2.invert_yaxis()
    ax2.set_xlabel("normal traction on the shaft after the push (kPa)")
    ax2.set_ylabel("depth (m)")
    save_figure(fig, os.path.join(out_dir, "shaft_capacity.png"), (ax2,))
    plt.close(fig)


def check(results):
    """The seed's trends on the finest grid: phi' 40 gains more than 20 at each L/D; L/D 5
    more than 25; jacking raises every shaft's capacity. A sequence must have converged."""
    top = finest(results)
    by = {(r["ld"], r["phi"], r["ocr"]): r["ratio"] for r in top}
    failed = []
    for ld in (5, 25):
        if (ld, 20.0, 1.0) in by and (ld, 40.0, 1.0) in by and not by[(ld, 40.0, 1.0)] > by[(ld, 20.0, 1.0)]:
            failed.append(f"L/D {ld}: phi' 40 ratio {by[(ld, 40.0, 1.0)]:.2f} not above phi' 20's {by[(ld, 20.0, 1.0)]:.2f}")
    for phi in (20.0, 40.0):
        if (5, phi, 1.0) in by and (25, phi, 1.0) in by and not by[(5, phi, 1.0)] > by[(25, phi, 1.0)]:
            failed.append(f"phi' {phi:g}: L/D 5 ratio {by[(5, phi, 1.0)]:.2f} not above L/D 25's {by[(25, phi, 1.0)]:.2f}")
    for r in top:
        if not r["ratio"] > 1.0:
            failed.append(f"model {r['model']}: jacking lowered the shaft capacity (ratio {r['ratio']:.2f})")
        seq = sorted((q["cells"], q["ratio"]) for q in results if q["model"] == r["model"])
        if len(seq) > 1 and not abs(seq[-1][1] - seq[-2][1]) < 0.1 * abs(seq[-1][1]):
            failed.append(f"model {r['model']}: not converged, ratio {seq[-2][1]:.2f} on D/{seq[-2][0]} and "
                          f"{seq[-1][1]:.2f} on D/{seq[-1][0]}")
    return study_runs.trends_status(failed)


def main():
    ap = argparse.ArgumentParser(description="Validation 3: Q_s^f / Q_s^0 of seed 002's Table 2")
    ap.add_argument("--out", required=True)
    ap.add_argument("--size", choices=("full", "reduced"), default="full")
    ap.add_argument("--cells-per-diameter", help="grids, e.g. 3,4,6 (default: --size's)")
    ap.add_argument("--models", default="1,2,3,4,5,6")
    ap.add_argument("--pilempm", default=os.path.join(ROOT, "build", "pilempm"))
    ap.add_argument("--threads", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--jack-velocity", type=float, default=VELOCITY,
                    help="m/s, the jacking rate (default 1; the push stays at 1 m/s)")
    ap.add_argument("--slip-friction-angle", type=float,
                    help="degrees, the toe slip line's friction angle in every model (default: the model's phi')")
    ap.add_argument("--peak-friction-offset", type=float,
                    help="degrees above each model's phi' of the cone that bounds the sand's stress "
                         "(default: as the case file; its peak_friction_angle less its friction_angle)")
    ap.add_argument("--check", action="store_true")
    args = ap.parse_args()
    if not args.jack_velocity > 0.0:
        raise InputError(f"--jack-velocity: expected a rate above 0 m/s, got {args.jack_velocity}")
    if args.slip_friction_angle is not None and not 0.0 <= args.slip_friction_angle < 90.0:
        raise InputError(f"--slip-friction-angle: expected degrees in [0, 90), got {args.slip_friction_angle}")
    if args.peak_friction_offset is not None and not 0.0 <= args.peak_friction_offset < 40.0:
        raise InputError(f"--peak-friction-offset: expected degrees in [0, 40), got {args.peak_friction_offset}")
    try:
        args.models = [int(m) for m in args.models.split(",")]
    except ValueError:
        raise InputError(f"--models: expected model numbers 1-6 separated by commas, got '{args.models}'")
    bad = [m for m in args.models if m not in MODELS]
    if bad:
        raise InputError(f"--models: no model {bad[0]} in Table 2 (1-6)")
    cells = args.cells_per_diameter or str(CELLS_PER_D[args.size])
    try:
        args.cells_per_diameter = sorted({int(n) for n in cells.split(",")})
    except ValueError:
        args.cells_per_diameter = [0]
    if min(args.cells_per_diameter) < 1:
        raise InputError(f"--cells-per-diameter: expected whole numbers of at least 1 separated by commas, got '{cells}'")
    return study(args)


if __name__ == "__main__":
    study_runs.exit_with("shaft_capacity_study.py", main, (InputError,))
