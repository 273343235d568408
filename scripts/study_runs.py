"""Running the derived cases of a validation study (shaft_capacity_study.py,
centrifuge_study.py): each case goes to OUT.yaml and is run into OUT by pilempm; a complete
run of the very same case there, newer than pilempm and the study's template, is read
instead of repeated, so an interrupted study picks up where it stopped.
"""
import os
import subprocess
import sys

import yaml


def up_to_date(out_dir, case, pilempm, template):
    """A complete run of this very case, newer than the executable and the template."""
    history, case_file = os.path.join(out_dir, "history.csv"), out_dir + ".yaml"
    if not (os.path.exists(history) and os.path.exists(case_file)):
        return False
    with open(case_file) as f:
        if yaml.safe_load(f) != case:
            return False
    return os.path.getmtime(history) > max(os.path.getmtime(pilempm), os.path.getmtime(template))


def run_case(case, out_dir, pilempm, threads, template):
    """Runs the case into out_dir unless an up-to-date run is there; returns out_dir.
    RuntimeError when pilempm fails."""
    if up_to_date(out_dir, case, pilempm, template):
        return out_dir
    os.makedirs(os.path.dirname(out_dir) or ".", exist_ok=True)
    case_file = out_dir + ".yaml"
    with open(case_file, "w") as f:
        yaml.safe_dump(case, f, default_flow_style=None, sort_keys=False, width=100)
    env = dict(os.environ, OMP_NUM_THREADS=str(threads))
    print(f"running {os.path.basename(out_dir)} ...", flush=True)
    r = subprocess.run([pilempm, "run", case_file, "--out", out_dir, "--quiet"], env=env)
    if r.returncode != 0:
        raise RuntimeError(f"{case_file}: pilempm exited {r.returncode}")
    return out_dir


def numbers(text, option, what):
    """A list of numbers separated by commas, given as `option`; ValueError (bad input)
    naming the option and what was expected when it is not one, or a number is not above 0."""
    try:
        values = [float(x) for x in text.split(",")]
    except ValueError:
        raise ValueError(f"{option}: expected {what} separated by commas, got '{text}'")
    if not values or any(v <= 0.0 for v in values):
        raise ValueError(f"{option}: expected positive {what}, got '{text}'")
    return values


def exit_with(prog, main, input_errors):
    """Runs main() and exits with its status: 2 on bad input (the exception types in
    input_errors, and YAML errors), 1 when a run failed (RuntimeError)."""
    try:
        sys.exit(main())
    except (OSError, ValueError, KeyError, yaml.YAMLError) + tuple(input_errors) as e:
        print(f"{prog}: {e}", file=sys.stderr)
        sys.exit(2)
    except RuntimeError as e:
        print(f"{prog}: {e}", file=sys.stderr)
        sys.exit(1)


def trends_status(failed):
    """Prints each trend not met; the exit status of a --check (1 if any)."""
    for f in failed:
        print("TREND NOT MET: " + f)
    return 1 if failed else 0
