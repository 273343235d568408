#!/usr/bin/env python3
"""shaft_capacity_study.py's own logic, no pilempm run: the cases it derives from the
template (grid, pile, stages, slip line, rate), the reference capacity mu K0 sigma'_v0 A
against a hand calculation, Q_s as the push's late mean, the length-weighted traction, the
trend check on synthetic ratios, and bad options (exit 2 before anything runs)."""
import math
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPTS = os.path.join(os.path.dirname(os.path.dirname(HERE)), "scripts")
sys.path.insert(0, SCRIPTS)
import shaft_capacity_study as study  # noqa: E402
import yaml  # noqa: E402


def close(a, b, tol=1e-9):
    return abs(a - b) <= tol * max(1.0, abs(b))


def test_variants(template):
    # Model 4: L/D 25 (20 m), phi' 40, OCR 1, on cells of 0.2 m (D/4).
    jacked = study.variant(template, 4, True, 0.2, jack_velocity=0.5, slip_angle=30.0)
    assert jacked["grid"]["cells"] == [60, 148], jacked["grid"]  # 12 m wide; 20 + 8 m of sand and 1.6 m above
    surface = jacked["initial_stress"]["surface"]
    assert close(surface, 28.0), surface
    assert close(jacked["pile"]["toe_elevation"], 28.0)
    assert close(jacked["pile"]["segments"][0]["length"], 21.2)  # 1.2 m above the surface at the end
    assert jacked["materials"][0]["friction_angle"] == 40.0 and jacked["materials"][0]["ocr"] == 1.0
    assert jacked["pile"]["toe_slip_line"]["friction_angle"] == 30.0
    names = [s["name"] for s in jacked["stages"]]
    assert names == ["geostatic", "jack", "hold", "push"], names
    jack, push = jacked["stages"][1], jacked["stages"][3]
    assert close(jack["duration"], 20.0 / 0.5 + 0.01) and jack["pile"]["velocity"] == 0.5
    assert close(push["duration"], 0.8 / 30.0 + 0.01) and push["pile"]["velocity"] == 1.0  # the push at 1 m/s
    wished = study.variant(template, 4, False, 0.2)
    assert close(wished["pile"]["toe_elevation"], 8.0) and wished["pile"]["wished_in_place"] is True
    assert [s["name"] for s in wished["stages"]] == ["nil", "push"]
    assert wished["pile"]["toe_slip_line"]["friction_angle"] == 40.0  # the model's phi' by default
    assert study.variant(template, 1, True, 0.2)["materials"][0]["friction_angle"] == 20.0
    # The bounding cone keeps its offset above each model's phi': given, or the template's.
    assert study.variant(template, 1, True, 0.2, peak_offset=5.0)["materials"][0]["peak_friction_angle"] == 25.0
    bounded = yaml.safe_load(yaml.safe_dump(template))
    bounded["materials"][0]["peak_friction_angle"] = bounded["materials"][0]["friction_angle"] + 3.0
    assert study.variant(bounded, 1, False, 0.2)["materials"][0]["peak_friction_angle"] == 23.0
    unbounded = yaml.safe_load(yaml.safe_dump(template))
    unbounded["materials"][0].pop("peak_friction_angle", None)
    assert "peak_friction_angle" not in study.variant(unbounded, 1, True, 0.2)["materials"][0]


def test_reference_capacity():
    # mu K0 gamma (L / 2) pi D L for model 1 (L = 4 m): 0.4 * 0.5 * 20 kN/m3 * 2 m = 8 kPa
    # over pi * 0.8 * 4 = 10.053 m2.
    c = {"materials": [{"density": 2000.0, "k0": 0.5}], "gravity": 10.0, "pile": {"friction": 0.4}}
    assert close(study.reference_capacity(c, 1), 8000.0 * math.pi * 0.8 * 4.0), study.reference_capacity(c, 1)


def test_capacity_and_traction(tmp):
    with open(os.path.join(tmp, "history.csv"), "w") as f:
        f.write("time_s,stage,outer_shaft_resistance_N\n")
        for k, (stage, q) in enumerate([(1, 9.0), (1, 9.0), (2, 1.0), (2, 2.0), (2, 4.0), (2, 6.0)]):
            f.write(f"{k},{stage},{q}\n")
    assert close(study.shaft_capacity(tmp), 5.0)  # the last stage's second half: (4 + 6) / 2
    rows = [(1.0, 0.5, 10.0), (2.0, 1.5, 30.0), (5.0, 1.0, 999.0)]  # (elevation, length, traction)
    assert close(study.mean_traction(rows, 3.0), (0.5 * 10.0 + 1.5 * 30.0) / 2.0)  # above the surface left out


def result(model, cells, ratio):
    ld, phi, ocr = study.MODELS[model]
    return {"model": model, "ld": ld, "phi": phi, "ocr": ocr, "cells": cells, "ratio": ratio}


def test_check():
    held = [result(1, 4, 1.5), result(2, 4, 2.5), result(1, 6, 1.55), result(2, 6, 2.45)]
    assert study.check(held) == 0
    reversed_phi = [result(1, 6, 2.3), result(2, 6, 1.8)]
    assert study.check(reversed_phi) == 1
    unconverged = [result(1, 4, 1.2), result(1, 6, 1.5), result(2, 4, 2.5), result(2, 6, 2.5)]
    assert study.check(unconverged) == 1  # model 1 moved 20 %
    assert study.check([result(2, 4, 0.9)]) == 1  # jacking lowered the capacity


def test_bad_options(tmp):
    script = os.path.join(SCRIPTS, "shaft_capacity_study.py")
    for bad in (["--slip-friction-angle", "95"], ["--jack-velocity", "-1"], ["--models", "7"],
                ["--cells-per-diameter", "0"], ["--peak-friction-offset", "-1"]):
        run = subprocess.run([sys.executable, script, "--out", tmp, "--pilempm", "/nonexistent"] + bad,
                             capture_output=True, text=True)
        assert run.returncode == 2, (bad, run.returncode, run.stderr)
        assert bad[0] in run.stderr, run.stderr
    assert os.listdir(tmp) == [], os.listdir(tmp)  # nothing run, nothing written


def main():
    with open(study.TEMPLATE) as f:
        template = yaml.safe_load(f)
    before = yaml.safe_dump(template)
    test_variants(template)
    assert yaml.safe_dump(template) == before  # variants are copies
    test_reference_capacity()
    with tempfile.TemporaryDirectory() as tmp:
        test_capacity_and_traction(tmp)
    test_check()
    with tempfile.TemporaryDirectory() as tmp:
        test_bad_options(tmp)
    print("shaft_capacity_study.py: variants, reference capacity, Q_s, tractions, trend check and bad options as expected")
    return 0


if __name__ == "__main__":
    sys.exit(main())
