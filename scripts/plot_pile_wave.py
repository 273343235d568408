#!/usr/bin/env python3
"""Plots of a pile wave run: usage `plot_pile_wave.py OUT_DIR`.

pile_head.png       force and Z*v at the pile head against time (the PDA plot); a second
                    panel with the toe force when toe.csv exists.
stress_envelope.png max compression and tension stress against depth below the head.

Exit status: 0 success, 2 missing/malformed input, 3 matplotlib not available.
"""
import json
import math
import os
import sys

from plot_common import InputError, read_columns, require_matplotlib  # noqa: E402

plt = require_matplotlib(__file__)


def read_title(out_dir):
    path = os.path.join(out_dir, "summary.json")
    if not os.path.exists(path):
        return None
    try:
        with open(path) as f:
            summary = json.load(f)
    except (OSError, ValueError) as e:
        print(f"plot_pile_wave.py: ignoring {path}: {e}", file=sys.stderr)
        return None
    title = summary.get("title") if isinstance(summary, dict) else None
    return str(title) if title else None


def plot_pile_head(out_dir, title):
    head = read_columns(
        os.path.join(out_dir, "pile_head.csv"),
        ["time_s", "force_compression_N", "velocity_down_m_s", "impedance_times_velocity_N"],
    )
    toe_path = os.path.join(out_dir, "toe.csv")
    toe = None
    if os.path.exists(toe_path):
        toe = read_columns(toe_path, ["time_s", "force_compression_N"])

    ms = [t * 1e3 for t in head["time_s"]]
    if toe is None:
        fig, ax = plt.subplots(figsize=(9, 5))
        axes = [ax]
    else:
        fig, axes = plt.subplots(
            2, 1, figsize=(9, 7.5), sharex=True, gridspec_kw={"height_ratios": [3, 2]}
        )
    ax = axes[0]
    ax.plot(ms, [f / 1e6 for f in head["force_compression_N"]], color="tab:blue", lw=1.6,
            label="Force F")
    ax.plot(ms, [f / 1e6 for f in head["impedance_times_velocity_N"]], color="tab:red",
            lw=1.6, ls="--", label="Z·v (impedance × velocity)")
    ax.axhline(0.0, color="0.3", lw=0.7)
    ax.set_ylabel("Force (MN), compression +")
    ax.set_title(title or "Pile head: force and Z·v")
    ax.grid(True, alpha=0.4)
    ax.legend(loc="upper right")

    if toe is not None:
        ax2 = axes[1]
        ax2.plot([t * 1e3 for t in toe["time_s"]], [f / 1e6 for f in toe["force_compression_N"]],
                 color="tab:green", lw=1.4, label="Toe force")
        ax2.axhline(0.0, color="0.3", lw=0.7)
        ax2.set_ylabel("Force (MN), compression +")
        ax2.grid(True, alpha=0.4)
        ax2.legend(loc="upper right")
    axes[-1].set_xlabel("Time (ms)")
    if max(ms) > min(ms):
        axes[-1].set_xlim(min(ms), max(ms))

    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "pile_head.png"), dpi=120)
    plt.close(fig)


def annotate_extreme(ax, stresses, depths, label, color):
    """Marks the largest magnitude in the envelope (sign convention of the CSV is kept).
    The label goes toward the middle of the axes so it never leaves the plot."""
    finite = [(abs(s), s, d) for s, d in zip(stresses, depths) if math.isfinite(s)]
    if not finite:
        return
    _, s, d = max(finite)
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()  # y inverted: y0 is the deepest
    right = (s - x0) > 0.5 * (x1 - x0)
    deep = (d - y1) > 0.5 * (y0 - y1)
    ax.plot([s], [d], "o", color=color, ms=6, zorder=3)
    ax.annotate(f"{label} {s:.1f} MPa\nat {d:.2f} m", xy=(s, d),
                xytext=(-14 if right else 14, 18 if deep else -18), textcoords="offset points",
                ha="right" if right else "left", va="bottom" if deep else "top",
                color=color, fontsize=9,
                bbox={"boxstyle": "round,pad=0.3", "fc": "white", "ec": color, "alpha": 0.9},
                arrowprops={"arrowstyle": "-", "color": color})


def plot_stress_envelope(out_dir, title):
    env = read_columns(
        os.path.join(out_dir, "stress_envelope.csv"),
        ["depth_below_head_m", "max_compression_Pa", "max_tension_Pa"],
    )
    depth = env["depth_below_head_m"]
    comp = [s / 1e6 for s in env["max_compression_Pa"]]
    tens = [s / 1e6 for s in env["max_tension_Pa"]]

    fig, ax = plt.subplots(figsize=(6.5, 8))
    ax.plot(comp, depth, color="tab:blue", lw=1.8, label="Max compression")
    ax.plot(tens, depth, color="tab:red", lw=1.8, label="Max tension")
    ax.axvline(0.0, color="0.3", lw=0.7)
    ax.invert_yaxis()  # depth axis points down
    ax.set_xlabel("Stress (MPa)")
    ax.set_ylabel("Depth below pile head (m)")
    ax.set_title((title + "\n" if title else "") + "Stress envelope")
    ax.grid(True, alpha=0.4)
    ax.margins(x=0.08)
    ax.legend(loc="best")
    annotate_extreme(ax, comp, depth, "max comp.", "tab:blue")
    annotate_extreme(ax, tens, depth, "max tens.", "tab:red")

    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "stress_envelope.png"), dpi=120)
    plt.close(fig)


def main(argv):
    if len(argv) != 2:
        print("usage: plot_pile_wave.py OUT_DIR", file=sys.stderr)
        return 2
    out_dir = argv[1]
    title = read_title(out_dir)
    status = 0
    for plot in (plot_pile_head, plot_stress_envelope):
        try:
            plot(out_dir, title)
        except (OSError, InputError) as e:
            print(f"plot_pile_wave.py: {e}", file=sys.stderr)
            status = 2
    return status


if __name__ == "__main__":
    sys.exit(main(sys.argv))
