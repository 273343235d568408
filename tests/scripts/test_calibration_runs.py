#!/usr/bin/env python3
"""calibration_runs.py --from-drive on a synthetic drive (six blows at known depths): each
window is the `--blows` blows from the first that began at its depth, blows.csv those rows,
history.csv the head record of the last of them only; a depth the drive never reached, or
too few blows after it, is an input error (exit 2) naming the drive and how deep it went."""
import csv
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = os.path.join(os.path.dirname(os.path.dirname(HERE)), "scripts", "calibration_runs.py")


def main():
    with tempfile.TemporaryDirectory() as tmp:
        drive = os.path.join(tmp, "drive")
        os.makedirs(drive)
        with open(os.path.join(drive, "blows.csv"), "w") as f:
            f.write("blow,stage,start_time_s,toe_depth_before_m,toe_depth_m,set_m,enthru_J\n")
            for b in range(6):  # blows in stages 2, 4, ..., 12; the toe from 5.0 m by 0.1 m a blow
                f.write(f"{b + 1},{2 * b + 2},{1.25 * b},{5.0 + 0.1 * b:.1f},{5.1 + 0.1 * b:.1f},0.1,1.5e6\n")
        with open(os.path.join(drive, "history.csv"), "w") as f:
            f.write("time_s,step,stage,pile_head_force_N,pile_head_velocity_m_s,kinetic_energy_J\n")
            for stage in range(1, 14):
                for i in range(3):
                    f.write(f"{stage + 0.01 * i},{10 * stage + i},{stage},{1000 * stage + i},{0.1 * i},7\n")
        out = os.path.join(tmp, "targets")
        run = subprocess.run([sys.executable, SCRIPT, "--from-drive", drive, "--depths", "5.2,5.3", "--blows", "2",
                              "--export", out], capture_output=True, text=True)
        assert run.returncode == 0, run.stderr
        with open(os.path.join(out, "drive-5.2m", "blows.csv")) as f:
            rows = list(csv.DictReader(f))
        assert [r["blow"] for r in rows] == ["3", "4"], rows
        with open(os.path.join(out, "drive-5.3m", "history.csv")) as f:
            history = list(csv.DictReader(f))
        assert list(history[0].keys()) == ["time_s", "stage", "pile_head_force_N", "pile_head_velocity_m_s"]
        assert [r["stage"] for r in history] == ["10"] * 3, history  # blow 5's stage only
        assert history[2]["pile_head_force_N"] == "10002"
        for depths in ("5.6", "9.0"):  # blows 6 and 7 needed / never that deep
            bad = subprocess.run([sys.executable, SCRIPT, "--from-drive", drive, "--depths", depths, "--blows", "2",
                                  "--export", out], capture_output=True, text=True)
            assert bad.returncode == 2, (depths, bad.returncode, bad.stderr)
            assert "reached 5.60 m" in bad.stderr and "blows.csv" in bad.stderr, bad.stderr
    print("calibration_runs.py --from-drive: windows, records and errors as expected")
    return 0


if __name__ == "__main__":
    sys.exit(main())
