#!/usr/bin/python3
"""Draw the method atlas: every study's charts (PNG and SVG) and one self-contained HTML page.

Usage: /usr/bin/python3 tools/atlas/plot_atlas.py DIR [--summary]
  DIR        the folder edgewise-atlas-study wrote: STUDY.csv (chart, series, x, y and, where
             a series has several points, a label for each, its ISA) and
             STUDY.json (the study's title, the CPU, and per chart its title, axes, scales, kind
             and a line of reading) for each study
  --summary  also print, per chart, its title and reading (tools/edgewise-atlas prints them)

Writes DIR/charts/<chart>.png and .svg, DIR/index.html, which holds the SVG charts inline with
their readings and the CPU, so it can be read without the other files, and DIR/README.md, the
same in Markdown with the PNG charts. Needs matplotlib
(Debian: python3-matplotlib). Exit status 1 for a missing or malformed input, 2 for a usage
mistake.
"""

import argparse
import csv
import html
import json
import math
import os
import sys

CSV_HEADER = ["chart", "series", "x", "y"]
LABELLED_HEADER = CSV_HEADER + ["label"]
CHART_KEYS = {"id", "title", "x_label", "y_label", "x_log", "y_log", "kind", "reading"}
MARKERS = ["o", "s", "^", "v", "D", "x", "P", "*"]


class InputError(Exception):
    pass


# The page's order: from the pixel's coverage to what is drawn in it; other studies follow.
ORDER = ["coverage", "interpolation", "depth", "texture", "aa"]


def study_order(json_name):
    stem = json_name[: -len(".json")]
    return (ORDER.index(stem) if stem in ORDER else len(ORDER), stem)


def read_study(directory, json_name):
    """The study's description and its points, grouped by chart then series."""
    json_path = os.path.join(directory, json_name)
    try:
        with open(json_path) as file:
            study = json.load(file)
    except (OSError, json.JSONDecodeError) as error:
        raise InputError(f"{json_path}: {error}") from None
    for key in ("study", "title", "cpu", "charts"):
        if key not in study:
            raise InputError(f"{json_path}: no '{key}'")
    for chart in study["charts"]:
        if set(chart) != CHART_KEYS:
            raise InputError(f"{json_path}: a chart has keys {sorted(chart)}")
    csv_path = os.path.join(directory, study["study"] + ".csv")
    points = {}
    try:
        with open(csv_path, newline="") as file:
            reader = csv.reader(file)
            header = next(reader, None)
            if header not in (CSV_HEADER, LABELLED_HEADER):
                raise InputError(f"{csv_path}:1: expected the header {','.join(CSV_HEADER)}"
                                 f" or {','.join(LABELLED_HEADER)}")
            for number, fields in enumerate(reader, start=2):
                if len(fields) != len(header):
                    raise InputError(
                        f"{csv_path}:{number}: {len(fields)} fields, expected {len(header)}")
                chart, series, x, y = fields[:4]
                label = fields[4] if len(fields) > 4 else ""
                try:
                    y = float(y)
                except ValueError:
                    raise InputError(f"{csv_path}:{number}: y is not a number") from None
                points.setdefault(chart, {}).setdefault(series, []).append((x, y, label))
    except OSError as error:
        raise InputError(f"{csv_path}: {error}") from None
    for chart in study["charts"]:
        if chart["id"] not in points:
            raise InputError(f"{csv_path}: no points for chart {chart['id']}")
    return study, points


def scale_y(axis, chart, values):
    """A log axis where asked; symmetric log where the values include 0 (an exact method)."""
    if not chart["y_log"]:
        return
    positive = [v for v in values if v > 0 and math.isfinite(v)]
    if positive and len(positive) < len(values):
        # Linear from 0 up to the smallest positive value, logarithmic above; the zeros sit on
        # the bottom edge.
        axis.set_yscale("symlog", linthresh=min(positive))
        axis.set_ylim(0, max(positive) * 3)
    elif positive:
        axis.set_yscale("log")


def draw_chart(plt, study, chart, series, path_stem):
    figure, axis = plt.subplots(figsize=(7.5, 4.6))
    values = [y for points in series.values() for _, y, _ in points]
    kind = chart["kind"]
    if kind == "images":
        plt.close(figure)
        draw_images(plt, study, chart, series, path_stem)
        return
    if kind == "bar":
        labels = [x for points in series.values() for x, _, _ in points]
        heights = [y for points in series.values() for _, y, _ in points]
        bars = axis.bar(range(len(labels)), heights, color="#4477aa")
        axis.set_xticks(range(len(labels)), labels, rotation=30, ha="right", fontsize=8)
        axis.bar_label(bars, fmt="%.3g", fontsize=7)
    elif kind == "scatter":
        draw_scatter(plt, figure, axis, series)
    else:
        # Twenty colours, and markers cycling apart from them, tell up to twenty series apart.
        colours = series_colours(plt, len(series))
        for index, (name, points) in enumerate(series.items()):
            xs = [float(x) for x, _, _ in points]
            ys = [y for _, y, _ in points]
            axis.plot(xs, ys, marker=MARKERS[index % len(MARKERS)],
                      color=colours[index % len(colours)], label=name, clip_on=False)
        place_legend(figure, axis, len(series))
    if kind in ("line", "scatter"):
        if chart["x_log"]:
            axis.set_xscale("log", base=2 if kind == "line" else 10)
    scale_y(axis, chart, values)
    axis.set_xlabel(chart["x_label"])
    axis.set_ylabel(chart["y_label"])
    axis.set_title(chart["title"], fontsize=11)
    figure.text(0.99, 0.01, study["cpu"], ha="right", va="bottom", fontsize=7, color="#555555")
    axis.grid(True, which="major", alpha=0.3)
    figure.tight_layout(rect=(0, 0.03, 1, 1))
    for extension in ("png", "svg"):
        figure.savefig(f"{path_stem}.{extension}", dpi=110)
    plt.close(figure)


def series_colours(plt, count):
    return plt.get_cmap("tab20").colors if count > 10 else plt.get_cmap("tab10").colors


def place_legend(figure, axis, entries, **options):
    if entries > 6:  # beside the axes, where it hides no point
        figure.set_size_inches(10.5, 4.6)
        return axis.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0), **options)
    return axis.legend(fontsize=8, **options)


def pareto_front(points):
    """The points no other point beats on both axes (lower is better on each), by x."""
    front = []
    for x, y in sorted(points, key=lambda p: (p[0], p[1])):
        if not front or y < front[-1][1]:
            front.append((x, y))
    return front


def draw_scatter(plt, figure, axis, series):
    """Error against time: a colour per series (a method), a marker per point label (the ISA
    it ran on), and the Pareto front, the methods that nothing beats on both time and error."""
    from matplotlib.lines import Line2D

    colours = series_colours(plt, len(series))
    labels = []
    for points in series.values():
        for _, _, label in points:
            if label and label not in labels:
                labels.append(label)
    marker_of = {label: MARKERS[i % len(MARKERS)] for i, label in enumerate(labels)}
    method_handles = []
    for index, (name, points) in enumerate(series.items()):
        colour = colours[index % len(colours)]
        # A series of one unlabelled point (a peer's) is a star; without labels, markers cycle.
        unlabelled = "*" if labels else MARKERS[index % len(MARKERS)]
        labelled = any(label for _, _, label in points)
        for x, y, label in points:
            axis.scatter([float(x)], [y], color=colour, marker=marker_of.get(label, unlabelled),
                         zorder=3, clip_on=False)
        method_handles.append(Line2D([], [], color=colour, marker="s" if labelled else unlabelled,
                                     linestyle="", label=name))
    front = pareto_front([(float(x), y) for points in series.values() for x, y, _ in points])
    axis.plot([x for x, _ in front], [y for _, y in front], drawstyle="steps-post",
              color="#222222", linewidth=1.0, alpha=0.7, zorder=2)
    # Rings mark the front's points, so that a front of one point shows too.
    axis.scatter([x for x, _ in front], [y for _, y in front], s=130, facecolors="none",
                 edgecolors="#222222", linewidths=1.0, zorder=4, clip_on=False)
    front_handle = Line2D([], [], color="#222222", linewidth=1.0, alpha=0.7, marker="o",
                          markersize=9, markerfacecolor="none", label="Pareto front")
    # One legend beside the axes, so that the lower left, where the best points lie, stays clear:
    # the methods' colours, the front, then the ISAs' markers.
    isa_handles = [Line2D([], [], color="#555555", marker=marker_of[label], linestyle="",
                          label=f"on {label}") for label in labels]
    handles = method_handles + [front_handle] + isa_handles
    columns = 1 if len(handles) <= 16 else 2
    figure.set_size_inches(10.5 + 2.5 * (columns - 1), 4.6)
    axis.legend(handles=handles, fontsize=8, ncol=columns, loc="upper left",
                bbox_to_anchor=(1.01, 1.0))


def draw_images(plt, study, chart, series, path_stem):
    """The study's images side by side, each under its caption (the series)."""
    directory = os.path.dirname(os.path.dirname(path_stem))
    figure, axes = plt.subplots(1, len(series), figsize=(4 * len(series), 4.4), squeeze=False)
    for axis, (caption, points) in zip(axes[0], series.items()):
        path = os.path.join(directory, points[0][0])
        try:
            image = plt.imread(path)
        except (OSError, ValueError) as error:
            raise InputError(f"{path}: {error}") from None
        axis.imshow(image, interpolation="nearest")
        axis.set_title(caption, fontsize=10)
        axis.set_axis_off()
    figure.suptitle(chart["title"], fontsize=11)
    figure.text(0.99, 0.01, study["cpu"], ha="right", va="bottom", fontsize=7, color="#555555")
    for extension in ("png", "svg"):
        figure.savefig(f"{path_stem}.{extension}", dpi=110)
    plt.close(figure)


def inline_svg(path):
    with open(path) as file:
        text = file.read()
    start = text.find("<svg")
    return text[start:] if start >= 0 else text


def write_page(directory, studies):
    parts = [
        "<!DOCTYPE html>",
        '<html lang="en"><head><meta charset="utf-8"><title>edgewise method atlas</title>',
        "<style>body{font-family:sans-serif;max-width:60em;margin:2em auto;padding:0 1em}"
        "figure{margin:2em 0}figcaption{max-width:50em}svg{max-width:100%;height:auto}"
        ".cpu{color:#555}</style></head><body>",
        "<h1>edgewise method atlas</h1>",
        "<p>Every method's error against ground truth and its time, measured by the library's "
        "own code paths; each chart names the CPU it was measured on. The numbers are in the "
        "CSV file of each study, beside this page.</p>",
    ]
    for study, points in studies:
        parts.append(f"<h2>{html.escape(study['title'])}</h2>")
        parts.append(
            f'<p class="cpu">Measured on {html.escape(study["cpu"])}. Numbers: '
            f'<a href="{html.escape(study["study"])}.csv">{html.escape(study["study"])}.csv</a>.</p>'
        )
        for chart in study["charts"]:
            svg = inline_svg(os.path.join(directory, "charts", chart["id"] + ".svg"))
            parts.append(f'<figure id="{html.escape(chart["id"])}">{svg}')
            parts.append(f"<figcaption>{html.escape(chart['reading'])}</figcaption></figure>")
    parts.append("</body></html>")
    with open(os.path.join(directory, "index.html"), "w") as file:
        file.write("\n".join(parts) + "\n")


def write_markdown(directory, studies):
    """README.md: the same page in Markdown, with the PNG charts (for a published copy)."""
    lines = [
        "# edgewise method atlas",
        "",
        "Generated by `tools/edgewise-atlas`: every method's error against ground truth and its "
        "time, measured by the library's own code paths, with the CPU named on each chart. The "
        "numbers are in each study's CSV file beside this page.",
    ]
    for study, _ in studies:
        lines += ["", f"## {study['title']}", "",
                  f"Measured on {study['cpu']}. Numbers: [{study['study']}.csv]({study['study']}.csv)."]
        for chart in study["charts"]:
            lines += ["", f"![{chart['title']}](charts/{chart['id']}.png)", "", chart["reading"]]
    with open(os.path.join(directory, "README.md"), "w") as file:
        file.write("\n".join(lines) + "\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("directory")
    parser.add_argument("--summary", action="store_true")
    arguments = parser.parse_args()
    try:
        names = sorted((n for n in os.listdir(arguments.directory) if n.endswith(".json")),
                       key=study_order)
    except OSError as error:
        print(f"plot_atlas.py: {error}", file=sys.stderr)
        return 1
    if not names:
        print(f"plot_atlas.py: no study (*.json) in {arguments.directory}", file=sys.stderr)
        return 1
    try:
        studies = [read_study(arguments.directory, name) for name in names]
    except InputError as error:
        print(f"plot_atlas.py: {error}", file=sys.stderr)
        return 1
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    plt.rcParams["svg.fonttype"] = "none"  # text stays text in the page
    charts_dir = os.path.join(arguments.directory, "charts")
    os.makedirs(charts_dir, exist_ok=True)
    try:
        for study, points in studies:
            for chart in study["charts"]:
                stem = os.path.join(charts_dir, chart["id"])
                draw_chart(plt, study, chart, points[chart["id"]], stem)
                if arguments.summary:
                    print(f"{chart['title']}: {chart['reading']}")
    except InputError as error:
        print(f"plot_atlas.py: {error}", file=sys.stderr)
        return 1
    write_page(arguments.directory, studies)
    write_markdown(arguments.directory, studies)
    print(f"page: {os.path.join(arguments.directory, 'index.html')}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
