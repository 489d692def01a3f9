"""Figure scripts need matplotlib, and a bare `python3` is often one without it (pyenv, a
virtualenv, conda) while ./swarmnet installed Debian's python3-matplotlib for /usr/bin/python3.

require_matplotlib(), called before a script does any work, returns when this interpreter has
matplotlib; otherwise it restarts the script under /usr/bin/python3 when that one has it, and
else stops with what to install. (`swarmnet plot` makes the same choice for scripts/plot.py.)
"""
import os
import subprocess
import sys

DEBIAN_PYTHON = "/usr/bin/python3"
RESTARTED = "SWARMNET_FIGURE_PYTHON_RESTARTED"


def _has_matplotlib(python):
    try:
        done = subprocess.run([python, "-c", "import matplotlib"], capture_output=True, check=False)
    except OSError:
        return False
    return done.returncode == 0


def require_matplotlib():
    try:
        import matplotlib  # noqa: F401  (only whether it imports)
        return
    except ImportError:
        pass
    same = os.path.realpath(sys.executable) == os.path.realpath(DEBIAN_PYTHON)
    if not same and not os.environ.get(RESTARTED) and _has_matplotlib(DEBIAN_PYTHON):
        print(f"{sys.argv[0]}: {sys.executable} has no matplotlib; running under "
              f"{DEBIAN_PYTHON}", file=sys.stderr)
        os.execve(DEBIAN_PYTHON, [DEBIAN_PYTHON, *sys.argv], dict(os.environ, **{RESTARTED: "1"}))
    sys.exit(f"{sys.argv[0]}: matplotlib is not installed for {sys.executable} (nor for "
             f"{DEBIAN_PYTHON}): install Debian's python3-matplotlib (./swarmnet install plot "
             f"does) or `pip install matplotlib` for this interpreter")
