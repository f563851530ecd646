#!/usr/bin/python3
"""Chart edgewise-texture-quality's scores: error (RMSE, log scale) against time per sample,
one panel per texture and view, every method and ISA a point, the Pareto front (the lowest
error for its time, as the tool marked it in the CSV's pareto column) joined by a line.

Usage: /usr/bin/python3 tools/plot_texture_quality.py SCORES.csv [-o CHART.png]
  SCORES.csv  edgewise-texture-quality --csv output (several files may be given; rows of the
              same texture, view and screen size share a panel, but each file's front is its own)
  -o FILE     the chart (default texture_quality.png); the format follows the extension

Needs matplotlib (Debian: apt-get install python3-matplotlib; call /usr/bin/python3, which sees
Debian's packages). Exit status 1 for an unreadable or malformed CSV, 2 for a usage mistake.
"""

import argparse
import csv
import math
import sys

HEADER = ["texture", "view", "size", "method", "isa", "rmse", "psnr_db", "worst",
          "ns_per_sample", "pareto"]
# One marker per ISA, so that the same method on two ISAs reads as a pair.
MARKERS = {"reference": "s", "sse2": "v", "sse4_1": "^", "avx2": "o", "neon": "D", "oiio": "x"}


def read_scores(path):
    """The CSV's rows as dicts with numbers converted; raises ValueError naming the line."""
    with open(path, newline="") as file:
        reader = csv.reader(file)
        header = next(reader, None)
        if header != HEADER:
            raise ValueError(f"{path}:1: expected the header {','.join(HEADER)}")
        rows = []
        for number, fields in enumerate(reader, start=2):
            if len(fields) != len(HEADER):
                raise ValueError(f"{path}:{number}: {len(fields)} fields, expected {len(HEADER)}")
            row = dict(zip(HEADER, fields))
            try:
                for key in ("rmse", "psnr_db", "worst", "ns_per_sample"):
                    row[key] = float(row[key])
            except ValueError:
                raise ValueError(f"{path}:{number}: a figure is not a number") from None
            if row["pareto"] not in ("0", "1"):
                raise ValueError(f"{path}:{number}: pareto is not 0 or 1")
            row["pareto"] = row["pareto"] == "1"
            row["file"] = path
            rows.append(row)
        return rows


def plottable(row):
    # A log axis cannot show 0, inf or NaN: such rows are listed instead of drawn.
    return all(math.isfinite(row[k]) and row[k] > 0 for k in ("rmse", "ns_per_sample"))


def draw(rows, output):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    panels = {}
    for row in rows:
        panels.setdefault((row["texture"], row["view"], row["size"]), []).append(row)
    columns = min(2, len(panels))
    lines = math.ceil(len(panels) / columns)
    figure, axes = plt.subplots(lines, columns, figsize=(8 * columns, 6 * lines), squeeze=False)
    for ax in axes.flat[len(panels):]:
        ax.set_visible(False)
    for ax, ((texture, view, size), panel) in zip(axes.flat, sorted(panels.items())):
        shown = [r for r in panel if plottable(r)]
        for row in panel:
            if not plottable(row):
                print(f"not drawn ({texture}/{view}): {row['method']} {row['isa']} "
                      f"rmse {row['rmse']} ns {row['ns_per_sample']}", file=sys.stderr)
        for row in shown:
            ax.scatter(row["ns_per_sample"], row["rmse"], marker=MARKERS.get(row["isa"], "*"),
                       color="tab:red" if row["pareto"] else "tab:blue", zorder=3)
            ax.annotate(f"{row['method']} ({row['isa']})", (row["ns_per_sample"], row["rmse"]),
                        textcoords="offset points", xytext=(4, 3), fontsize=7)
        for path in sorted({r["file"] for r in shown}):
            front = sorted((r["ns_per_sample"], r["rmse"]) for r in shown
                           if r["pareto"] and r["file"] == path)
            if front:
                # A step line: each front method is the best until the next, faster-to-slower.
                ax.step([p[0] for p in front], [p[1] for p in front], where="post",
                        color="tab:red", linewidth=1, label="Pareto front")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("ns per sample (edgewise-texture-quality's timing, one thread)")
        ax.set_ylabel("RMSE against ground truth (linear)")
        ax.set_title(f"{texture} / {view} {size}")
        ax.grid(True, which="both", linewidth=0.3)
        if any(r["pareto"] for r in shown):
            ax.legend(loc="upper right", fontsize=8)
    figure.tight_layout()
    figure.savefig(output, dpi=110)


def main():
    parser = argparse.ArgumentParser(description="Chart edgewise-texture-quality's CSV.")
    parser.add_argument("csv", nargs="+", help="edgewise-texture-quality --csv output")
    parser.add_argument("-o", "--output", default="texture_quality.png", help="the chart file")
    args = parser.parse_args()
    try:
        rows = [row for path in args.csv for row in read_scores(path)]
    except (OSError, ValueError) as error:
        print(f"plot_texture_quality: {error}", file=sys.stderr)
        return 1
    if not rows:
        print("plot_texture_quality: no scores in the CSV", file=sys.stderr)
        return 1
    try:
        draw(rows, args.output)
    except OSError as error:
        print(f"plot_texture_quality: {error}", file=sys.stderr)
        return 1
    print(f"plot_texture_quality: {len(rows)} scores charted in {args.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
