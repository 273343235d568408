"""Start-up shared by the plot scripts: matplotlib with the Agg backend.

Debian's matplotlib lives with /usr/bin/python3; a pyenv/venv `python3` first on PATH may
lack it, so the calling script is re-run once with the system interpreter before giving up
(exit status 3: no plots written).
"""
import csv
import os
import sys

_REEXEC_GUARD = "PILEMPM_PLOT_REEXEC"
_SYSTEM_PYTHON = "/usr/bin/python3"


def require_matplotlib(script):
    """Returns matplotlib.pyplot, or re-runs the invoked script under the system python, or exits 3."""
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        return plt
    except ImportError:
        if (
            not os.environ.get(_REEXEC_GUARD)
            and os.path.exists(_SYSTEM_PYTHON)
            and os.path.realpath(sys.executable) != os.path.realpath(_SYSTEM_PYTHON)
        ):
            os.environ[_REEXEC_GUARD] = "1"
            # What was run (a test importing the script, or the script itself), not the module.
            os.execv(_SYSTEM_PYTHON, [_SYSTEM_PYTHON, os.path.abspath(sys.argv[0])] + sys.argv[1:])
        print(f"{os.path.basename(script)}: matplotlib not available, no plots written", file=sys.stderr)
        sys.exit(3)


class InputError(Exception):
    """Missing or malformed input: the script reports it and exits 2."""


def read_columns(path, names):
    """The named columns of a CSV file as lists of floats ("nan"/"inf" are numbers too)."""
    if not os.path.exists(path):
        raise InputError(f"{path}: not found")
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        missing = [n for n in names if n not in (reader.fieldnames or [])]
        if missing:
            raise InputError(f"{path}: missing column(s) {', '.join(missing)}")
        cols = {n: [] for n in names}
        for line, row in enumerate(reader, start=2):
            try:
                for n in names:
                    cols[n].append(float(row[n]))
            except (TypeError, ValueError):
                raise InputError(f"{path}:{line}: not a number in {row}")
    if not cols[names[0]]:
        raise InputError(f"{path}: no data rows")
    return cols


def read_header(path):
    """The column names of a CSV file."""
    if not os.path.exists(path):
        raise InputError(f"{path}: not found")
    with open(path, newline="") as f:
        return next(csv.reader(f), [])


def run_main(prog, argv, plot):
    """`prog OUT_DIR`: calls plot(out_dir) and turns input errors into exit status 2."""
    if len(argv) != 2:
        print(f"usage: {prog} OUT_DIR", file=sys.stderr)
        return 2
    try:
        return plot(argv[1]) or 0
    except (OSError, ValueError, KeyError, InputError) as e:
        print(f"{prog}: {e}", file=sys.stderr)
        return 2


def save_figure(fig, path, legend_axes=()):
    """Grid and small legends on the given axes, then a tight layout saved at 120 dpi and closed."""
    for ax in legend_axes:
        ax.grid(True, alpha=0.4)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
