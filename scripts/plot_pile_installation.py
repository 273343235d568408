#!/usr/bin/env python3
"""Plots of an FE pile in MPM soil: usage `plot_pile_installation.py OUT_DIR`.

pile_load_settlement.png  the jack's force and the soil's resistance split into outer
                          shaft, inner shaft and base against the head's settlement.
pile_tractions.png        normal and shear traction along the outer and inner shaft at
                          the end of the run, against elevation.

Exit status: 0 success, 2 missing/malformed input, 3 matplotlib not available.
"""
import os
import sys

from plot_common import read_columns, require_matplotlib, run_main  # noqa: E402

plt = require_matplotlib(__file__)


def plot_load_settlement(out_dir):
    h = read_columns(os.path.join(out_dir, "history.csv"),
                     ["pile_head_settlement_m", "pile_head_force_N", "outer_shaft_resistance_N",
                      "inner_shaft_resistance_N", "base_resistance_N"])
    s = [x * 1e3 for x in h["pile_head_settlement_m"]]
    fig, ax = plt.subplots(figsize=(8, 5.5))
    for key, label, style in [("pile_head_force_N", "Head (jack)", "-"), ("base_resistance_N", "Base", "--"),
                              ("outer_shaft_resistance_N", "Outer shaft", "-."),
                              ("inner_shaft_resistance_N", "Inner shaft", ":")]:
        ax.plot(s, [f / 1e3 for f in h[key]], style, lw=1.4, label=label)
    ax.set_xlabel("Head settlement (mm)")
    ax.set_ylabel("Force (kN), compression / resistance +")
    ax.set_title("Pile head load and its split against settlement")
    ax.grid(True, alpha=0.4)
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "pile_load_settlement.png"), dpi=120)
    plt.close(fig)


def plot_tractions(out_dir):
    fig, axes = plt.subplots(1, 2, figsize=(9, 6), sharey=True)
    names = ["elevation_m", "normal_traction_compression_Pa", "shear_traction_Pa"]
    for side, style in (("outer", "-"), ("inner", "--")):
        t = read_columns(os.path.join(out_dir, f"pile_tractions_{side}.csv"), names)
        axes[0].plot([v / 1e3 for v in t["normal_traction_compression_Pa"]], t["elevation_m"], style, label=side)
        axes[1].plot([v / 1e3 for v in t["shear_traction_Pa"]], t["elevation_m"], style, label=side)
    axes[0].set_xlabel("Normal traction (kPa), compression +")
    axes[1].set_xlabel("Shear traction (kPa), up +")
    axes[0].set_ylabel("Elevation (m)")
    for ax in axes:
        ax.grid(True, alpha=0.4)
        ax.legend()
    fig.suptitle("Contact tractions along the shaft, end of run")
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "pile_tractions.png"), dpi=120)
    plt.close(fig)


def plot(out_dir):
    plot_load_settlement(out_dir)
    plot_tractions(out_dir)
    return 0


if __name__ == "__main__":
    sys.exit(run_main("plot_pile_installation.py", sys.argv, plot))
