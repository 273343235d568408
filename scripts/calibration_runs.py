#!/usr/bin/env python3
"""The coupled runs a calibrated fast path is fitted to (issue 14, `calibration:` of an
`analysis: drivability` case): a coupled driving case struck a few blows with its pile
wished in place at each of a few depths.

    calibration_runs.py CASE --depths 5,8,11 --out DIR [--blows 4]
                        [--pilempm build/pilempm] [--threads N] [--export DIR2]
    calibration_runs.py --from-drive DRIVE --depths 6,8,10 --blows 5 --export DIR2

CASE is an `analysis: mpm` case with a driving stage and a wished-in-place pile (e.g.
cases/driving/north-sea-monopile.yaml); its mudline is `initial_stress.surface`. For each
depth d (m below the mudline) the case is derived with the pile's toe at surface - d and
the driving stage cut to --blows blows (no target, plots and snapshots off) and run into
DIR/depth-<d>m (pilempm run); a complete run of the same case there, newer than pilempm
and CASE, is read, not repeated. The drivability case then names these folders under
`calibration: runs:`.

--export DIR2: a copy of each run small enough to keep beside a case (DIR2/depth-<d>m):
blows.csv whole, and of history.csv the columns the calibration reads (time, stage, head
force and velocity) for the last blow only (the record it fits).

--from-drive DRIVE: no runs; the targets are cut from an installed drive instead (the
output folder of a finished coupled driving run: its history.csv is written at the end): at each
depth d the --blows blows from the first that began with the toe d or more below the
mudline, exported as above (DIR2/drive-<d>m; blows.csv those blows' rows). The fast path
fitted to them carries what installation did to the soil, which a pile wished in place
does not; the case reads them with `skip_blows: 0`.

Exit status: 0 success, 1 a run failed, 2 bad input.
"""
import argparse
import copy
import csv
import os
import sys

import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import study_runs  # noqa: E402

ROOT = os.path.dirname(HERE)


class InputError(Exception):
    pass


def derived_case(template, case_file, depth, blows):
    c = copy.deepcopy(template)
    try:
        surface = float(c["initial_stress"]["surface"])
        pile = c["pile"]
        stages = c["stages"]
    except (KeyError, TypeError):
        raise InputError(f"{case_file}: expected initial_stress.surface (the mudline), pile and stages")
    if not pile.get("wished_in_place", False):
        raise InputError(f"{case_file}: pile.wished_in_place: expected true (the pile is placed at each depth)")
    drives = [s for s in stages if s.get("type") == "driving"]
    if len(drives) != 1:
        raise InputError(f"{case_file}: stages: expected one driving stage, found {len(drives)}")
    pile["toe_elevation"] = round(surface - depth, 9)
    drive = drives[0]
    drive["blows"] = blows
    for key in ("target_toe_elevation", "refusal"):
        drive.pop(key, None)
    c["title"] = f"{c.get('title', 'coupled drive')}: {blows} blows from {depth:g} m"
    c.setdefault("output", {})["plots"] = False
    c["output"].pop("snapshot_interval", None)
    return c


HISTORY_COLUMNS = ["time_s", "stage", "pile_head_force_N", "pile_head_velocity_m_s"]


def export_runs(run_dir, windows):
    """windows: (to_dir, first_depth, count) each; first_depth None: every blow, else the
    `count` blows from the first that began that deep. history.csv is read once for all."""
    with open(os.path.join(run_dir, "blows.csv")) as f:
        reader = csv.DictReader(f)
        header = reader.fieldnames
        blows = list(reader)
    last_stage = {}  # each window's last blow's stage -> the history files its record goes to
    for to_dir, first_depth, count in windows:
        chosen = blows
        if first_depth is not None:
            start = next((i for i, b in enumerate(blows) if float(b["toe_depth_before_m"]) >= first_depth), None)
            if start is None or start + count > len(blows):
                raise InputError(f"{run_dir}/blows.csv: no {count} blows from {first_depth:g} m (the drive reached "
                                 f"{float(blows[-1]['toe_depth_m']) if blows else 0:.2f} m)")
            chosen = blows[start:start + count]
        if not chosen:
            raise RuntimeError(f"{run_dir}/blows.csv: no blows")
        os.makedirs(to_dir, exist_ok=True)
        with open(os.path.join(to_dir, "blows.csv"), "w", newline="") as g:
            w = csv.DictWriter(g, fieldnames=header, lineterminator="\n")
            w.writeheader()
            w.writerows(chosen)
        last_stage.setdefault(chosen[-1]["stage"], []).append(to_dir)
    files = {d: open(os.path.join(d, "history.csv"), "w", newline="") for dirs in last_stage.values() for d in dirs}
    try:
        writers = {d: csv.writer(g) for d, g in files.items()}
        for w in writers.values():
            w.writerow(HISTORY_COLUMNS)
        with open(os.path.join(run_dir, "history.csv")) as f:
            for row in csv.DictReader(f):
                for d in last_stage.get(row["stage"], ()):
                    writers[d].writerow([row[c] for c in HISTORY_COLUMNS])
    finally:
        for g in files.values():
            g.close()


def main():
    ap = argparse.ArgumentParser(description="Coupled runs at a few depths for a calibrated fast path")
    ap.add_argument("case", nargs="?")
    ap.add_argument("--depths", required=True, help="m below the mudline, separated by commas")
    ap.add_argument("--out")
    ap.add_argument("--from-drive", help="an installed drive's folder to cut the targets from (no runs)")
    ap.add_argument("--blows", type=int, default=4)
    ap.add_argument("--pilempm", default=os.path.join(ROOT, "build", "pilempm"))
    ap.add_argument("--threads", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--export", help="a folder for small copies of the runs (blows, the last blow's head record)")
    args = ap.parse_args()
    depths = study_runs.numbers(args.depths, "--depths", "depths in m below the mudline")
    if args.blows < 1:
        raise InputError(f"--blows: expected at least 1, got {args.blows}")
    if args.from_drive:
        if not args.export:
            raise InputError("--from-drive: expected --export DIR2 (where the targets go)")
        windows = [(os.path.join(args.export, f"drive-{d:g}m"), d, args.blows) for d in depths]
        export_runs(args.from_drive, windows)
        for to, _, _ in windows:
            print(f"  {to}")
        return 0
    if not args.case or not args.out:
        raise InputError("expected CASE and --out DIR (or --from-drive DRIVE)")
    with open(args.case) as f:
        template = yaml.safe_load(f)
    for d in depths:
        out = os.path.join(args.out, f"depth-{d:g}m")
        study_runs.run_case(derived_case(template, args.case, d, args.blows), out, args.pilempm, args.threads,
                            args.case)
        print(f"  {out}")
        if args.export:
            export_runs(out, [(os.path.join(args.export, os.path.basename(out)), None, None)])
            print(f"  exported to {os.path.join(args.export, os.path.basename(out))}")
    return 0


if __name__ == "__main__":
    study_runs.exit_with("calibration_runs.py", main, [InputError])
