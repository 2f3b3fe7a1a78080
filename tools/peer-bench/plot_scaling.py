#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""plot_scaling.py - `make bench`: the Delaunay build's time per site
against log2 n as a PNG (the axes of seed 000's Fig. 5.1).

    tools/peer-bench/plot_scaling.py CSV PNG

CSV is what `delaunay-host --scaling-csv` writes: "log2n,library,ns_per_site"
rows, one line per library in the plot. Needs matplotlib: if this python3 lacks it, the script
runs again under /usr/bin/python3, first installing Debian's
python3-matplotlib through tools/apt-install.sh if that lacks it too (as
root; otherwise that prints the command and this exits 1).
"""

import csv
import os
import subprocess
import sys


SYSTEM_PYTHON = "/usr/bin/python3"  # the interpreter Debian's packages are for


def has_matplotlib(python):
    return subprocess.call([python, "-c", "import matplotlib"],
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL) == 0


def load_matplotlib():
    """matplotlib.pyplot; installs it or re-runs this script under Debian's
    python3 (another python3, e.g. pyenv's, may come first in PATH)."""
    try:
        import matplotlib
    except ImportError:
        if not has_matplotlib(SYSTEM_PYTHON):
            root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
            status = subprocess.call([os.path.join(root, "tools", "apt-install.sh"),
                                      "plot_scaling.py", "python3-matplotlib"])
            if status != 0:
                sys.exit(1)
        if os.path.realpath(sys.executable) != os.path.realpath(SYSTEM_PYTHON):
            os.execv(SYSTEM_PYTHON, [SYSTEM_PYTHON] + sys.argv)
        import matplotlib
    matplotlib.use("Agg")  # no display: write files only
    import matplotlib.pyplot as plt
    return plt


def main():
    if len(sys.argv) != 3:
        print("usage: plot_scaling.py CSV PNG", file=sys.stderr)
        return 2
    series = {}
    with open(sys.argv[1], newline="") as f:
        for row in csv.DictReader(f):
            series.setdefault(row["library"], []).append(
                (int(row["log2n"]), float(row["ns_per_site"]) / 1000.0))
    if not series:
        print("plot_scaling.py: no data", file=sys.stderr)
        return 1
    plt = load_matplotlib()
    fig, ax = plt.subplots(figsize=(7, 4.5), dpi=100)
    styles = {"vor incremental": "o-", "vor D&C": "s-", "vor D&C quadtree": "^-",
              "CGAL": "d--", "Boost": "v--"}
    for name, points in series.items():
        points.sort()
        ax.plot([p[0] for p in points], [p[1] for p in points], styles.get(name, "x-"),
                label=name, markersize=4)
    ax.set_xlabel("log2 n (uniform full-range int32 sites)")
    ax.set_ylabel("time per site (us)")
    ax.set_ylim(bottom=0)
    ax.grid(True, alpha=0.3)
    ax.legend()
    ax.set_title("Delaunay build, host (make bench)")
    fig.tight_layout()
    fig.savefig(sys.argv[2])
    return 0


if __name__ == "__main__":
    sys.exit(main())
