#!/usr/bin/env python3
"""Plots of an FE pile in MPM soil: usage `plot_pile_installation.py OUT_DIR`.

pile_load_settlement.png  the jack's force and the soil's resistance split into outer
                          shaft, inner shaft and base against the head's settlement.
pile_tractions.png        normal and shear traction along the outer and inner shaft at
                          the end of the run, against elevation.
pile_probes.png           with probes: each probe's radial stress over its initial one and
                          its volumetric strain against its height above the toe over the
                          pile's radius, h / R (negative while the toe is above it), as
                          calibration-chamber sensors are shown (Jardine et al. 2013).
pile_driving.png          with a drive (blows.csv): blows per 0.25 m and cumulative blows
                          against toe depth, as the drivability sheet draws them (depth
                          down), and per blow the set, the largest compression and tension
                          in the steel, ENTHRU, and (saturated soil) the largest and smallest
                          excess pore pressure under the toe and beside the shaft's thirds.
drive_ledger.png          with a drive: per blow, ENTHRU, the energy the absorbing
                          boundaries took in the blow, the pile's and the soil's energy left
                          at its end; and the change since the run began of the soil's mass,
                          the grains' volume (1 - n) V and the pore water's volume n V: a
                          long drive's drift, if it has any.

Exit status: 0 success, 2 missing/malformed input, 3 matplotlib not available.
"""
import os
import sys

from plot_common import read_columns, read_header, require_matplotlib, run_main  # noqa: E402

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
    names = ["elevation_m", "normal_traction_compression_Pa", "shear_traction_Pa",
             "stage_mean_normal_traction_compression_Pa", "stage_mean_shear_traction_Pa"]
    for side, style, colour in (("outer", "-", "C0"), ("inner", "--", "C1")):
        path = os.path.join(out_dir, f"pile_tractions_{side}.csv")
        with open(path) as f:
            if sum(1 for _ in f) < 2:  # a closed-ended pile has no inner shaft
                continue
        t = read_columns(path, names)
        # The last stage's mean bold, its last step faint (a chattering contact's on-off).
        for k, column in enumerate(("normal_traction_compression_Pa", "shear_traction_Pa")):
            last, mean = t[column], t["stage_mean_" + column]
            axes[k].plot([v / 1e3 for v in last], t["elevation_m"], style, color=colour, alpha=0.3, lw=0.8,
                         label=f"{side}, last step")
            axes[k].plot([v / 1e3 for v in mean], t["elevation_m"], style, color=colour, label=f"{side}, last stage's mean")
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


def probe_paths(out_dir):
    """Per probe: h / R (height above the toe over the outer radius), sigma_r / sigma_r0
    (compression ratio) and volumetric strain, and the probe's initial radius over R."""
    history = os.path.join(out_dir, "history.csv")
    header = read_header(history)
    probes = sorted({int(c[5:c.index("_")]) for c in header if c.startswith("probe") and c.endswith("_elevation_m")})
    if not probes or "pile_toe_elevation_m" not in header:
        return None, []
    radius = max(read_columns(os.path.join(out_dir, "pile_tractions_outer.csv"), ["radius_m"])["radius_m"])
    names = ["pile_toe_elevation_m", "time_s"]
    for k in probes:
        names += [f"probe{k}_stress_x_Pa", f"probe{k}_volumetric_strain", f"probe{k}_elevation_m"]
    h = read_columns(history, names)
    paths = []
    for k in probes:
        s0 = h[f"probe{k}_stress_x_Pa"][0]
        hr = [(z - toe) / radius for z, toe in zip(h[f"probe{k}_elevation_m"], h["pile_toe_elevation_m"])]
        ratio = [s / s0 if s0 != 0.0 else float("nan") for s in h[f"probe{k}_stress_x_Pa"]]
        paths.append((k, hr, ratio, h[f"probe{k}_volumetric_strain"]))
    return radius, paths


def plot_probes(out_dir):
    radius, paths = probe_paths(out_dir)
    if not paths:
        return
    fig, axes = plt.subplots(1, 2, figsize=(10, 6.5), sharey=True)
    for k, hr, ratio, ev in paths:
        axes[0].plot(ratio, hr, lw=1.0, label=f"probe {k}")
        axes[1].plot([100.0 * e for e in ev], hr, lw=1.0, label=f"probe {k}")
    axes[0].set_xlabel("Radial stress / initial radial stress")
    axes[1].set_xlabel("Volumetric strain (%), dilation +")
    axes[0].set_ylabel(f"h / R (height of the probe above the toe, R = {radius * 1e3:.1f} mm)")
    for ax in axes:
        ax.axhline(0.0, color="k", lw=0.6)
        ax.grid(True, alpha=0.4)
    axes[0].legend(fontsize=8)
    fig.suptitle("Soil at the probes as the toe passes them")
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "pile_probes.png"), dpi=120)
    plt.close(fig)


def plot_driving(out_dir):
    blows_csv = os.path.join(out_dir, "blows.csv")
    if not os.path.exists(blows_csv):
        return
    b = read_columns(blows_csv, ["blow", "toe_depth_m", "set_m", "max_compression_Pa", "max_tension_Pa", "enthru_J"])
    c = read_columns(os.path.join(out_dir, "blow_count.csv"),
                     ["depth_top_m", "depth_bottom_m", "blows", "cumulative_blows"])
    header = read_header(blows_csv)
    pore_keys = [("toe_pore_pressure_Pa", "under the toe", "k"), ("shaft_pore_pressure_upper_Pa", "shaft, upper third", "c"),
                 ("shaft_pore_pressure_middle_Pa", "shaft, middle third", "b"),
                 ("shaft_pore_pressure_lower_Pa", "shaft, lower third", "m")]
    wanted = [f"{side}_{key}" for key, _, _ in pore_keys for side in ("max", "min")]
    pores = read_columns(blows_csv, wanted) if all(k in header for k in wanted) else None
    if pores and not any(x != 0.0 for k in wanted for x in pores[k]):
        pores = None  # dry soil
    fig, axes = plt.subplots(1, 5 if pores else 4, figsize=(16 if pores else 13, 6.5), sharey=True)
    for top, bottom, n in zip(c["depth_top_m"], c["depth_bottom_m"], c["blows"]):
        axes[0].plot([n, n], [top, bottom], "b-", lw=1.6)
    axes[0].set_xlabel("Blows per 0.25 m")
    axes[1].plot(c["cumulative_blows"], c["depth_bottom_m"], "k.-")
    axes[1].set_xlabel("Cumulative blows")
    axes[2].plot([1e3 * x for x in b["set_m"]], b["toe_depth_m"], "g.-")
    axes[2].set_xlabel("Set per blow (mm)")
    axes[3].plot([x / 1e6 for x in b["max_compression_Pa"]], b["toe_depth_m"], "r.-", label="compression")
    axes[3].plot([x / 1e6 for x in b["max_tension_Pa"]], b["toe_depth_m"], "m.--", label="tension")
    axes[3].set_xlabel("Largest axial stress in the blow (MPa)")
    axes[3].legend(fontsize=8)
    if pores:
        for key, label, colour in pore_keys:
            axes[4].plot([x / 1e3 for x in pores["max_" + key]], b["toe_depth_m"], colour + ".-", ms=3, lw=1.0, label=label)
            axes[4].plot([x / 1e3 for x in pores["min_" + key]], b["toe_depth_m"], colour + ".--", ms=3, lw=1.0)
        axes[4].axvline(0.0, color="k", lw=0.6)
        axes[4].set_xlabel("Excess pore pressure in the blow (kPa)\nlargest -, smallest --")
        axes[4].legend(fontsize=8)
    axes[0].set_ylabel("Toe depth (m)")
    axes[0].invert_yaxis()
    for ax in axes:
        ax.grid(True, alpha=0.4)
    fig.suptitle(f"Coupled drive: {len(b['blow'])} blows, ENTHRU {min(b['enthru_J']) / 1e3:.3g} to "
                 f"{max(b['enthru_J']) / 1e3:.3g} kJ")
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "pile_driving.png"), dpi=120)
    plt.close(fig)


def plot_drive_ledger(out_dir):
    blows_csv = os.path.join(out_dir, "blows.csv")
    if not os.path.exists(blows_csv) or "grain_volume_change" not in read_header(blows_csv):
        return
    b = read_columns(blows_csv, ["blow", "enthru_J", "radiated_energy_J", "pile_energy_end_J",
                                 "soil_kinetic_energy_end_J", "soil_mass_change", "grain_volume_change",
                                 "pore_water_volume_m3"])
    n = b["blow"]
    fig, axes = plt.subplots(1, 2, figsize=(12, 5.5))
    for key, label, style in [("enthru_J", "ENTHRU (into the pile)", "k.-"),
                              ("radiated_energy_J", "through the absorbing boundaries (soil, per radian)", "b.-"),
                              ("pile_energy_end_J", "left in the pile at the blow's end", "r.-"),
                              ("soil_kinetic_energy_end_J", "soil's kinetic energy at the end (per radian)", "g.-")]:
        axes[0].plot(n, [max(x, 1e-3) / 1e3 for x in b[key]], style, ms=3, lw=1.0, label=label)
    axes[0].set_yscale("log")
    axes[0].set_ylabel("Energy (kJ)")
    axes[0].set_title("Energy per blow")
    for key, label, style in [("soil_mass_change", "soil mass", "k.-"),
                              ("grain_volume_change", "grains' volume (1 - n) V", "b.-")]:
        axes[1].plot(n, [max(abs(x), 1e-17) for x in b[key]], style, ms=3, lw=1.0, label=label)
    axes[1].set_yscale("log")
    axes[1].set_ylabel("|change since the run began| (relative; 1e-17: none)")
    water = axes[1].twinx()
    w0 = b["pore_water_volume_m3"][0]
    water.plot(n, [1e3 * (w - w0) for w in b["pore_water_volume_m3"]], "c.--", ms=3, lw=1.0,
               label="pore water n V (right, litres per radian)")
    water.set_ylabel("Pore water volume change (litres per radian)")
    axes[1].set_title("What the drive conserves")
    lines = axes[1].get_legend_handles_labels()
    more = water.get_legend_handles_labels()
    axes[1].legend(lines[0] + more[0], lines[1] + more[1], fontsize=8, loc="upper left")
    axes[0].legend(fontsize=8)
    for ax in axes:
        ax.set_xlabel("Blow")
        ax.grid(True, alpha=0.4)
    fig.suptitle(f"Drive ledger, {len(n)} blows")
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "drive_ledger.png"), dpi=120)
    plt.close(fig)


def plot(out_dir):
    plot_driving(out_dir)
    plot_drive_ledger(out_dir)
    if not os.path.exists(os.path.join(out_dir, "history.csv")):
        return 0  # a drive in progress (its working folder): its tables so far only
    plot_load_settlement(out_dir)
    plot_tractions(out_dir)
    plot_probes(out_dir)
    return 0


if __name__ == "__main__":
    sys.exit(run_main("plot_pile_installation.py", sys.argv, plot))
