"""Start-up shared by the plot scripts: matplotlib with the Agg backend.

Debian's matplotlib lives with /usr/bin/python3; a pyenv/venv `python3` first on PATH may
lack it, so the calling script is re-run once with the system interpreter before giving up
(exit status 3: no plots written).
"""
import os
import sys

_REEXEC_GUARD = "PILEMPM_PLOT_REEXEC"
_SYSTEM_PYTHON = "/usr/bin/python3"


def require_matplotlib(script):
    """Returns matplotlib.pyplot, or re-runs `script` under the system python, or exits 3."""
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
            os.execv(_SYSTEM_PYTHON, [_SYSTEM_PYTHON, os.path.abspath(script)] + sys.argv[1:])
        print(f"{os.path.basename(script)}: matplotlib not available, no plots written", file=sys.stderr)
        sys.exit(3)
