#!/usr/bin/env python3
"""Draws the figures of impact-report from the data file it writes.

usage: report_figures.py DATA.json OUTPUT_DIRECTORY

DATA.json = {"figures": [{"file", "title" (none or "": no title line), "columns",
"shared_legend" (optional: one legend below the panels instead of one per panel),
"legend_columns" (of the shared legend, default 2), "width" (optional: of the figure [in],
default 5 per column), "row_height" (optional: of a row of panels [in], default 3.6),
"panels": [panel, ...]}, ...]}, a panel = {"title", "xlabel", "ylabel", "xscale", "yscale"
("linear", "log" or "symlog": linear within +-"linthresh", logarithmic beyond), "series":
[series, ...], "xticks", "yticks" (optional: tick positions, labelled as plain numbers), "hlines": [{"y", "label",
"color", "linestyle"}], "bands": [{"y0", "y1", "color", "alpha", "label"}], "vbands": [{"x0",
"x1", "color", "alpha", "hatch", "label"}] (spans of x), "note"}; a series is a line {"label", "x", "y", "color", "linestyle", "marker",
"markerfacecolor" (optional), "yerr": [lower, upper] (optional)} or a shaded band
{"fill": true, "label", "x", "y0", "y1", "color", "alpha"}.
A validity map is a figure {"kind": "map", "file", "title", "xlabel", "ylabel", "yscale",
"columns_values" (the velocities), "rows_values" (the other axis, null when not a number),
"rows_labels", "classes": [{"name", "color"}], "cells": [{"column", "row", "class" (index into
classes), "text"}], "note"}: one coloured rectangle per cell, its text written in it; with
"yscale" "log" the rows sit at their values on a log axis. Every number is computed by
impact-report (C++); this script only draws (null = missing value, not drawn).
Exit codes: 0 all figures written, 1 an error (message on stderr).
"""

import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def values(items):
    return [math.nan if v is None else float(v) for v in items]


def draw_panel(axes, panel, legend=True):
    for series in panel.get("series", []):
        if series.get("fill"):
            x, y0, y1 = values(series["x"]), values(series["y0"]), values(series["y1"])
            if any(math.isfinite(v) for v in y0 + y1):
                axes.fill_between(x, y0, y1, color=series.get("color", "grey"),
                                  alpha=series.get("alpha", 0.2), label=series.get("label"),
                                  linewidth=0)
            continue
        x, y = values(series["x"]), values(series["y"])
        if not any(math.isfinite(v) for v in y):
            continue
        style = dict(color=series.get("color", "black"), label=series.get("label"),
                     linestyle=series.get("linestyle", "-") or "-",
                     marker=series.get("marker") or None, markersize=5)
        if series.get("markerfacecolor"):
            style["markerfacecolor"] = series["markerfacecolor"]
        if "yerr" in series:
            lower, upper = values(series["yerr"][0]), values(series["yerr"][1])
            errors = [[0 if not math.isfinite(v) else v for v in lower],
                      [0 if not math.isfinite(v) else v for v in upper]]
            axes.errorbar(x, y, yerr=errors, capsize=3, **style)
        else:
            axes.plot(x, y, **style)
    for band in panel.get("bands", []):
        axes.axhspan(band["y0"], band["y1"], color=band.get("color", "grey"),
                     alpha=band.get("alpha", 0.15), label=band.get("label"))
    for band in panel.get("vbands", []):
        axes.axvspan(band["x0"], band["x1"], facecolor=band.get("color", "grey"),
                     alpha=band.get("alpha", 0.1), hatch=band.get("hatch"),
                     edgecolor=band.get("edgecolor", "0.75"), linewidth=0, label=band.get("label"))
    for line in panel.get("hlines", []):
        if line.get("y") is not None:
            axes.axhline(line["y"], color=line.get("color", "grey"),
                         linestyle=line.get("linestyle", ":"), label=line.get("label"))
    if panel.get("note"):
        axes.text(0.5, 0.5, panel["note"], transform=axes.transAxes, ha="center",
                  va="center", fontsize=8, wrap=True, color="tab:red")
    axes.set_xscale(panel.get("xscale", "linear"))
    if panel.get("yscale") == "symlog":
        axes.set_yscale("symlog", linthresh=panel["linthresh"], linscale=2)
    else:
        axes.set_yscale(panel.get("yscale", "linear"))
    if panel.get("yticks"):
        ticks = sorted(values(panel["yticks"]))
        axes.set_yticks(ticks)
        axes.set_yticklabels(["%g" % tick for tick in ticks])
        axes.minorticks_off()
    if panel.get("xticks"):
        ticks = values(panel["xticks"])
        axes.set_xticks(ticks)
        axes.set_xticklabels(["%g" % tick for tick in ticks])
        if panel.get("xscale") == "log":
            axes.minorticks_off()
    axes.set_title(panel.get("title", ""), fontsize=10)
    axes.set_xlabel(panel.get("xlabel", ""))
    axes.set_ylabel(panel.get("ylabel", ""))
    axes.grid(True, alpha=0.3)
    if legend and axes.get_legend_handles_labels()[0]:
        axes.legend(fontsize=7)


def legend_entries(axes_grid):
    labelled = {}
    for row in axes_grid:
        for panel_axes in row:
            for handle, label in zip(*panel_axes.get_legend_handles_labels()):
                labelled.setdefault(label, handle)
    return labelled


def row_edges(values, logarithmic):
    """Cell boundaries between the rows: geometric (log) or arithmetic midpoints."""
    if len(values) == 1:
        v = values[0]
        return [v / 1.5, v * 1.5] if logarithmic else [v - 0.5 * abs(v or 1), v + 0.5 * abs(v or 1)]
    if logarithmic:
        logs = [math.log(v) for v in values]
    else:
        logs = list(values)
    middles = [(a + b) / 2 for a, b in zip(logs, logs[1:])]
    edges = [logs[0] - (middles[0] - logs[0])] + middles + [logs[-1] + (logs[-1] - middles[-1])]
    return [math.exp(e) for e in edges] if logarithmic else edges


def draw_map(figure, directory):
    from matplotlib.patches import Patch, Rectangle

    velocities = values(figure["columns_values"])
    labels = figure["rows_labels"]
    numeric = all(v is not None for v in figure["rows_values"])
    rows = values(figure["rows_values"]) if numeric else list(range(len(labels)))
    logarithmic = numeric and figure.get("yscale") == "log"
    edges = row_edges(rows, logarithmic)
    classes = figure["classes"]
    width = max(6.0, 1.35 * len(velocities) + 2.5)
    height = max(3.0, 0.95 * len(rows) + 2.2)
    fig, axes = plt.subplots(figsize=(width, height))
    for cell in figure["cells"]:
        column, row = cell["column"], cell["row"]
        kind = classes[cell["class"]]
        axes.add_patch(Rectangle((column - 0.5, edges[row]), 1, edges[row + 1] - edges[row],
                                 facecolor=kind["color"], edgecolor="0.35", linewidth=0.8))
        middle = math.sqrt(edges[row] * edges[row + 1]) if logarithmic else \
            (edges[row] + edges[row + 1]) / 2
        axes.text(column, middle, cell["text"], ha="center", va="center", fontsize=7.5)
    axes.set_xlim(-0.5, len(velocities) - 0.5)
    axes.set_xticks(range(len(velocities)))
    axes.set_xticklabels(["%g" % v for v in velocities])
    if logarithmic:
        axes.set_yscale("log")
    axes.set_ylim(edges[0], edges[-1])
    axes.set_yticks(rows)
    axes.set_yticklabels(labels)
    axes.minorticks_off()
    axes.set_xlabel(figure.get("xlabel", ""))
    axes.set_ylabel(figure.get("ylabel", "") + (" (log scale)" if logarithmic else ""))
    axes.set_title(figure.get("title", ""), fontsize=11)
    handles = [Patch(facecolor=kind["color"], edgecolor="0.35", label=kind["name"])
               for kind in classes]
    fig.legend(handles=handles, loc="lower center", ncol=min(len(handles), 3), fontsize=8,
               frameon=False)
    if figure.get("note"):
        fig.text(0.5, 1 - 0.12 / height, figure["note"], ha="center", va="top", fontsize=7.5,
                 color="0.3")
    legend_rows = math.ceil(len(handles) / 3)
    fig.tight_layout(rect=(0, (0.3 * legend_rows + 0.15) / height, 1, 1 - 0.25 / height))
    fig.savefig(os.path.join(directory, figure["file"]), dpi=90)
    plt.close(fig)


def draw_figure(figure, directory):
    if figure.get("kind") == "map":
        draw_map(figure, directory)
        return
    panels = figure["panels"]
    columns = max(1, min(int(figure.get("columns", 2)), len(panels)))
    rows = max(1, math.ceil(len(panels) / columns))
    width = figure.get("width") or (5.0 * columns if columns > 1 else 9.0)
    shared = bool(figure.get("shared_legend"))
    title = 0.4 if figure.get("title") else 0.0  # [in] for the title line
    height = figure.get("row_height", 3.6) * rows + title
    fig, axes = plt.subplots(rows, columns, figsize=(width, height), squeeze=False)
    top = 1 - title / height
    for index, panel in enumerate(panels):
        draw_panel(axes[index // columns][index % columns], panel, legend=not shared)
    for index in range(len(panels), rows * columns):
        axes[index // columns][index % columns].set_visible(False)
    if title:
        fig.suptitle(figure["title"])
    if shared:
        # One legend below the panels: the figure grows by the legend's height.
        labelled = legend_entries(axes)
        legend_columns = int(figure.get("legend_columns", 2))
        legend_height = 0.2 * math.ceil(len(labelled) / legend_columns) + 0.15
        fig.set_size_inches(width, height + legend_height)
        fig.tight_layout(rect=(0, legend_height / (height + legend_height), 1,
                               1 - title / (height + legend_height)))
        fig.legend(list(labelled.values()), list(labelled.keys()), loc="lower center",
                   ncol=legend_columns, fontsize=8, frameon=False)
    else:
        fig.tight_layout(rect=(0, 0, 1, top))
    path = os.path.join(directory, figure["file"])
    fig.savefig(path, dpi=90)
    plt.close(fig)


def main(arguments):
    if len(arguments) != 3:
        sys.stderr.write(__doc__)
        return 1
    with open(arguments[1], encoding="utf-8") as data_file:
        data = json.load(data_file)
    os.makedirs(arguments[2], exist_ok=True)
    for figure in data["figures"]:
        draw_figure(figure, arguments[2])
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv))
    except Exception as error:  # report any failure as one line for impact-report
        sys.stderr.write("report_figures.py: error: %s: %s\n" % (type(error).__name__, error))
        sys.exit(1)
