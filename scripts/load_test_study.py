#!/usr/bin/env python3
"""Case 3 of issue 14 (seed 000 D): the rapid load test (RLT) read by the unloading-point
method (UPM) against the static load test (SLT) of the same model, and what the pore water
does to it:

    load_test_study.py --out DIR [--permeabilities 2e-5,2e-4,2e-3] [--refine F]
                       [--pilempm build/pilempm] [--threads N] [--check]

Every run is derived from cases/load-tests/rapid-load-test.yaml (the seed's sand, a 0.3 m
closed-ended pile 3 m deep, a 250 kN half-sine over 200 ms): the SLT (the head pushed at
0.1 m/s to 0.4 D, drained, local damping 0.7: quasi-static), the RLT with the pore water
coupled at each permeability (m/s; the seed's is 2e-5), and the RLT drained (the pore water
held at hydrostatic: the limit of a permeable sand). --refine F: cells and pile elements
F times finer (a graded grid's zones each). Each run goes to DIR/<name> (pilempm run); a
complete run of the same case there, newer than pilempm and the template, is read, not
repeated.

DIR/load_tests.csv   per RLT: the permeability, F_u (the UPM's static resistance at the
                     unloading point), C, the largest settlement s_max, the SLT's load at
                     s_max and F_u over it.
DIR/load_tests.png   load against settlement: the SLT; each RLT's load and its derived
                     static curve F - m a - C v, F_u marked.

--check exits 1 unless the trends hold: the drained RLT's F_u lies within 25 % of the SLT at
its s_max (the UPM's premise: a rate-independent soil, inertia and damping taken out), and
the coupled RLTs overstate the SLT the more the less permeable the sand (the pore water's
rate effect, the reason the UPM is corrected in fine sands and silts).

Exit status: 0 success (and trends held with --check), 1 a run failed or a trend did not
hold, 2 bad input, 3 matplotlib not available.
"""
import argparse
import copy
import csv
import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from plot_common import InputError, read_columns, require_matplotlib, save_figure  # noqa: E402

plt = require_matplotlib(__file__)
import yaml  # noqa: E402  (after the re-run under the system python, which has python3-yaml)
import study_runs  # noqa: E402

ROOT = os.path.dirname(HERE)
TEMPLATE = os.path.join(ROOT, "cases", "load-tests", "rapid-load-test.yaml")
D = 0.3                     # m, the template's pile
SLT_VELOCITY = 0.1          # m/s
SLT_DEPTH = 0.4 * D         # m: past the drained RLT's settlement
SLT_RISE = 0.02             # s


def refined(case, factor):
    """The case on cells `factor` times finer (each zone's), the pile's elements with them."""
    c = copy.deepcopy(case)
    if factor != 1.0:
        for axis in ("x", "y"):
            for zone in c["grid"]["zones"][axis]:
                zone["cell"] = zone["cell"] / factor
        c["pile"]["element_size"] = c["pile"]["element_size"] / factor
        c["pile"]["radial_divisions"] = int(round(c["pile"]["radial_divisions"] * factor))
    return c


def slt_case(template):
    c = copy.deepcopy(template)
    c["title"] = "Static load test (twin of the rapid load test, seed 000 D)"
    c.pop("hammer")
    c["stages"][1] = {"name": "slt", "type": "dynamic", "duration": round(SLT_DEPTH / SLT_VELOCITY, 9),
                      "drainage": "drained", "local_damping": 0.7,
                      "pile": {"velocity": SLT_VELOCITY, "rise_time": SLT_RISE, "load_test": "static"}}
    return c


def rlt_case(template, permeability):
    """permeability None: the RLT drained."""
    c = copy.deepcopy(template)
    if permeability is None:
        c["title"] = "Rapid load test, drained (seed 000 D)"
        c["stages"][1]["drainage"] = "drained"
    else:
        c["title"] = f"Rapid load test, k = {permeability:g} m/s (seed 000 D)"
        for m in c["materials"]:
            m["hydraulic_conductivity"] = permeability
    return c


def interpolate(xs, ys, x):
    for i in range(1, len(xs)):
        if xs[i] >= x:
            w = (x - xs[i - 1]) / (xs[i] - xs[i - 1]) if xs[i] > xs[i - 1] else 1.0
            return ys[i - 1] + w * (ys[i] - ys[i - 1])
    raise InputError(f"the SLT reaches {xs[-1]:.4g} m, not the RLT's {x:.4g} m: push it further")


def load_test(out_dir):
    with open(os.path.join(out_dir, "summary.json")) as f:
        tests = json.load(f).get("load_tests", [])
    if not tests:
        raise InputError(f"{out_dir}/summary.json: no load_tests")
    if "note" in tests[0]:
        raise InputError(f"{out_dir}: {tests[0]['note']}")
    return tests[0]


def study(args):
    with open(TEMPLATE) as f:
        template = refined(yaml.safe_load(f), args.refine)
    suffix = "" if args.refine == 1.0 else f"-refine-{args.refine:g}"
    run = lambda case, name: study_runs.run_case(case, os.path.join(args.out, name + suffix), args.pilempm,
                                                 args.threads, TEMPLATE)
    slt_dir = run(slt_case(template), "slt")
    slt = read_columns(os.path.join(slt_dir, "load_test_slt.csv"), ["settlement_m", "load_N"])
    results = []
    for k in args.permeabilities + [None]:
        name = "rlt-drained" if k is None else f"rlt-k{k:g}"
        out_dir = run(rlt_case(template, k), name)
        t = load_test(out_dir)
        static = interpolate(slt["settlement_m"], slt["load_N"], t["max_settlement_m"])
        curve = read_columns(os.path.join(out_dir, "load_test_rlt.csv"), ["settlement_m", "load_N", "static_force_N"])
        results.append({"name": name, "permeability": k, "test": t, "slt_at_s_max": static, "curve": curve})
    write_table(args.out, results, suffix)
    plot(args.out, slt, results, suffix)
    return check(results) if args.check else 0


def write_table(out_dir, results, suffix):
    path = os.path.join(out_dir, f"load_tests{suffix}.csv")
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["run", "permeability_m_s", "F_u_N", "C_N_s_m", "s_max_m", "unloading_time_s", "peak_load_N",
                    "slt_load_at_s_max_N", "F_u_over_slt"])
        for r in results:
            t = r["test"]
            w.writerow([r["name"], "drained" if r["permeability"] is None else r["permeability"],
                        f"{t['static_resistance_N']:.6g}", f"{t['damping_N_s_m']:.6g}", f"{t['max_settlement_m']:.6g}",
                        f"{t['unloading_time_s']:.6g}", f"{t['peak_load_N']:.6g}", f"{r['slt_at_s_max']:.6g}",
                        f"{t['static_resistance_N'] / r['slt_at_s_max']:.4f}"])
            print(f"{r['name']:>14}: F_u {t['static_resistance_N'] / 1e3:7.1f} kN at s_max {t['max_settlement_m'] * 1e3:6.2f} mm,"
                  f" SLT there {r['slt_at_s_max'] / 1e3:7.1f} kN, ratio {t['static_resistance_N'] / r['slt_at_s_max']:.3f}")
    print(f"wrote {path}")


def plot(out_dir, slt, results, suffix):
    fig, ax = plt.subplots(figsize=(8, 6))
    mm = lambda xs: [1e3 * x for x in xs]
    kn = lambda xs: [1e-3 * x for x in xs]
    ax.plot(mm(slt["settlement_m"]), kn(slt["load_N"]), "k-", lw=2, label="SLT (drained, quasi-static)")
    for r, colour in zip(results, plt.rcParams["axes.prop_cycle"].by_key()["color"]):
        c, t = r["curve"], r["test"]
        label = "drained" if r["permeability"] is None else f"k = {r['permeability']:g} m/s"
        ax.plot(mm(c["settlement_m"]), kn(c["load_N"]), "--", color=colour, lw=1, label=f"RLT load, {label}")
        ax.plot(mm(c["settlement_m"]), kn(c["static_force_N"]), "-", color=colour, lw=1.5,
                label=f"UPM static, {label}")
        ax.plot([1e3 * t["max_settlement_m"]], [1e-3 * t["static_resistance_N"]], "o", color=colour)
    ax.set_xlabel("head settlement (mm)")
    ax.set_ylabel("load on the head (kN)")
    ax.set_title("Rapid load test by the unloading-point method against the static test (seed 000 D)")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    save_figure(fig, os.path.join(out_dir, f"load_tests{suffix}.png"))


def check(results):
    failed = []
    drained = [r for r in results if r["permeability"] is None][0]
    ratio = drained["test"]["static_resistance_N"] / drained["slt_at_s_max"]
    if abs(ratio - 1.0) > 0.25:
        failed.append(f"the drained RLT's F_u is {ratio:.3f} of the SLT at its s_max (within 25 % expected)")
    coupled = sorted((r for r in results if r["permeability"] is not None), key=lambda r: r["permeability"])
    ratios = [r["test"]["static_resistance_N"] / r["slt_at_s_max"] for r in coupled]
    if any(b >= a for a, b in zip(ratios, ratios[1:])) or (coupled and ratios[-1] <= ratio):
        failed.append("F_u over the SLT does not fall as the permeability grows: "
                      + ", ".join(f"k {r['permeability']:g}: {q:.3f}" for r, q in zip(coupled, ratios))
                      + f", drained: {ratio:.3f}")
    return study_runs.trends_status(failed)


def main():
    ap = argparse.ArgumentParser(description="Case 3 of issue 14: the rapid load test by the unloading-point method")
    ap.add_argument("--out", required=True)
    ap.add_argument("--permeabilities", default="2e-5,2e-4,2e-3")
    ap.add_argument("--refine", type=float, default=1.0)
    ap.add_argument("--pilempm", default=os.path.join(ROOT, "build", "pilempm"))
    ap.add_argument("--threads", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--check", action="store_true")
    args = ap.parse_args()
    args.permeabilities = study_runs.numbers(args.permeabilities, "--permeabilities", "permeabilities in m/s")
    if not args.refine >= 1.0:
        raise InputError(f"--refine: expected a factor of at least 1, got {args.refine}")
    return study(args)


if __name__ == "__main__":
    study_runs.exit_with("load_test_study.py", main, (InputError,))
