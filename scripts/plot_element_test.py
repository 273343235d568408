#!/usr/bin/env python3
"""Plots of an element-test run: usage `plot_element_test.py OUT_DIR`.

element_tests.png  three panels over all tests of the run: q against axial strain,
                   void ratio against log p' (when the model carries a void ratio), and
                   the stress path q against p'. Stresses in kPa, compression positive.

Exit status: 0 success, 2 missing/malformed input, 3 matplotlib not available.
"""
import csv
import json
import os
import sys

from plot_common import InputError, read_columns, require_matplotlib  # noqa: E402

plt = require_matplotlib(__file__)


def main(out_dir):
    path = os.path.join(out_dir, "summary.json")
    if not os.path.exists(path):
        raise InputError(f"{path}: not found")
    with open(path) as f:
        summary = json.load(f)
    fig, (ax_q, ax_e, ax_p) = plt.subplots(1, 3, figsize=(15, 4.6))
    has_e = False
    for test in summary.get("tests", []):
        file = os.path.join(out_dir, test["file"])
        with open(file, newline="") as f:
            header = next(csv.reader(f))
        names = ["axial_strain", "mean_effective_stress_Pa", "deviator_stress_Pa"]
        if "void_ratio" in header:
            names.append("void_ratio")
        c = read_columns(file, names)
        label = f"{test['name']} ({test['type']})"
        ax_q.plot([100 * e for e in c["axial_strain"]], [q / 1e3 for q in c["deviator_stress_Pa"]], label=label)
        ax_p.plot([p / 1e3 for p in c["mean_effective_stress_Pa"]], [q / 1e3 for q in c["deviator_stress_Pa"]],
                  label=label)
        if "void_ratio" in c:
            has_e = True
            ax_e.semilogx([p / 1e3 for p in c["mean_effective_stress_Pa"]], c["void_ratio"], label=label)
    ax_q.set(xlabel="axial strain ε_a (%)", ylabel="deviator stress q (kPa)", title="q – ε_a")
    ax_e.set(xlabel="mean effective stress p' (kPa)", ylabel="void ratio e", title="e – log p'")
    if not has_e:
        ax_e.text(0.5, 0.5, "the model has no void ratio", ha="center", transform=ax_e.transAxes)
    ax_p.set(xlabel="mean effective stress p' (kPa)", ylabel="deviator stress q (kPa)", title="stress path q – p'")
    for ax in (ax_q, ax_e, ax_p):
        ax.grid(True, alpha=0.3)
    ax_p.legend(fontsize=8)
    fig.suptitle(f"{summary.get('title', '')} — {summary.get('model', '')}")
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "element_tests.png"), dpi=110)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    try:
        main(sys.argv[1])
    except (InputError, OSError, ValueError, KeyError) as e:
        print(f"plot_element_test.py: {e}", file=sys.stderr)
        sys.exit(2)
