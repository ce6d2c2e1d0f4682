#!/usr/bin/python3
"""ECDF plots of runtimes, COCO style (called by `pride report --plots DIR`, docs/analysis.md).

Reads the ECDF curves that pride computed (experiment/report/coco.hpp, written as DIR/ecdf.json, so
that the plots and the ERT tables share one definition) and draws, per group ("all", then each
BBOB function group present), one line per algorithm: the fraction of (run, target) pairs
reached against log10(evaluations / dimension), with a cross at the largest budget of the runs.
Each figure is written as PNG and SVG: ecdf_all, ecdf_<group>.

Usage: plot_ecdf.py ECDF.json DIR
"""
import json
import math
import os
import sys
import warnings

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


class CannotWrite(Exception):
    """A figure that cannot be written: its file and the system's reason."""


def save(fig, folder, stem):
    for ext in ("png", "svg"):
        path = os.path.join(folder, f"{stem}.{ext}")
        try:
            fig.savefig(path, dpi=120, bbox_inches="tight")
        except OSError as e:
            raise CannotWrite(f"{path}: cannot write: {e.strerror or e}") from e
    plt.close(fig)


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: plot_ecdf.py ECDF.json DIR")
    with open(sys.argv[1], encoding="utf-8") as f:
        data = json.load(f)
    folder = sys.argv[2]
    styles = ["-", "--", ":", "-."]
    precisions = data["precisions"]
    for group in data["groups"]:
        fig, ax = plt.subplots(figsize=(6.4, 4.2))
        budgets = [c["max_budget"] for c in group["curves"] if c["max_budget"] is not None]
        right = max(budgets) if budgets else 1.0
        lefts = [c["x"][0] for c in group["curves"] if c["x"]]
        left = min(min(lefts), 0.0) if lefts else 0.0
        for index, curve in enumerate(group["curves"]):
            # A step function: 0 before the first runtime, constant up to the next, then flat
            # to the run's largest budget, where the cross marks the end of the data.
            xs = [left] + curve["x"] + [curve["max_budget"] if curve["max_budget"] is not None else right]
            ys = [0.0] + curve["y"] + [curve["y"][-1] if curve["y"] else 0.0]
            line, = ax.step(xs, ys, where="post", linestyle=styles[index % len(styles)], linewidth=1.8,
                            label=f"{curve['algorithm']} ({curve['pairs']} pairs)")
            ax.plot([xs[-1]], [ys[-1]], "x", color=line.get_color(), markersize=9, markeredgewidth=2)
            restarts = curve.get("restarts")  # COCO's ECDF with simulated restarts (thin, same colour)
            if restarts and restarts["x"]:
                rxs = [left] + restarts["x"] + [max(right, restarts["x"][-1])]
                rys = [0.0] + restarts["y"] + [restarts["y"][-1]]
                ax.step(rxs, rys, where="post", linestyle=":", linewidth=1.0, color=line.get_color(),
                        label=f"{curve['algorithm']}, simulated restarts")
                right = max(right, restarts["x"][-1])
        dims = ", ".join(str(d) for d in group["dims"])
        ax.set_title(f"{data['campaign']}: {group['title']}, D = {dims}\n"
                     f"{len(precisions)} targets f_opt + 10^[{_span(precisions)}]", fontsize="medium")
        ax.set_xlabel("log10(# evaluations / dimension)")
        ax.set_ylabel("fraction of (run, target) pairs")
        ax.set_ylim(-0.02, 1.02)
        ax.set_xlim(left, right + 0.1 * max(right - left, 1.0))
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize="small", loc="best")
        save(fig, folder, f"ecdf_{group['group']}")


def _span(precisions):
    """The targets' exponents as a range, e.g. 2..-8."""
    exps = [math.log10(p) for p in precisions if p > 0]
    if not exps:
        return "?"
    return f"{max(exps):.3g}..{min(exps):.3g}"


if __name__ == "__main__":
    # One clear line on failure, never a traceback; library warnings are not for the user.
    warnings.simplefilter("ignore")
    try:
        main()
    except CannotWrite as e:
        print(e, file=sys.stderr)
        sys.exit(2)
    except Exception as e:  # noqa: BLE001
        print(f"plot_ecdf.py: {type(e).__name__}: {e}".splitlines()[0], file=sys.stderr)
        sys.exit(1)
