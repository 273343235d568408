#!/usr/bin/env python3
"""Plots of a saturated-column wave run: usage `plot_poroelastic_wave.py OUT_DIR`.

poroelastic_wave_histories.png  excess pore pressure and vertical effective stress at each
                                probe against time, computed (MPM v-w) and reference (the
                                dynamic poro-elastic half-space, Laplace domain inverted).

Exit status: 0 success, 2 missing/malformed input, 3 matplotlib not available.
"""
import os
import sys

from plot_common import read_columns, read_header, require_matplotlib, run_main  # noqa: E402

plt = require_matplotlib(__file__)


def plot(out_dir):
    path = os.path.join(out_dir, "poroelastic_wave_histories.csv")
    header = read_header(path)
    probes = sorted({c.split("_")[0] for c in header if c.startswith("probe")})
    fields = [("excess_pore_pressure_Pa", "Excess pore pressure (kPa)"),
              ("stress_vertical_Pa", "Vertical effective stress (kPa), tension +")]
    names = ["time_s"] + [f"{p}_{f}_{w}" for p in probes for f, _ in fields for w in ("computed", "reference")]
    cols = read_columns(path, names)
    ms = [t * 1e3 for t in cols["time_s"]]
    fig, axes = plt.subplots(len(fields), 1, figsize=(9, 7), sharex=True)
    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for ax, (field, label) in zip(axes, fields):
        for k, p in enumerate(probes):
            c = colors[k % len(colors)]
            ax.plot(ms, [v / 1e3 for v in cols[f"{p}_{field}_reference"]], color=c, lw=2.2, alpha=0.45,
                    label=f"{p} reference")
            ax.plot(ms, [v / 1e3 for v in cols[f"{p}_{field}_computed"]], color=c, lw=1.0, ls="--",
                    label=f"{p} MPM")
        ax.axhline(0.0, color="0.3", lw=0.7)
        ax.set_ylabel(label)
        ax.grid(True, alpha=0.4)
    axes[0].legend(loc="upper right", fontsize=8)
    axes[0].set_title("Saturated column: probe histories against the dynamic poro-elastic solution")
    axes[-1].set_xlabel("Time (ms)")
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "poroelastic_wave_histories.png"), dpi=120)
    plt.close(fig)
    return 0


if __name__ == "__main__":
    sys.exit(run_main("plot_poroelastic_wave.py", sys.argv, plot))
