#!/usr/bin/python3
"""The plastic zone of a run: a cell field of one ParaView snapshot
(accumulated_plastic_strain by default) near the contact, as a PNG.

Usage: fem/bench/plastic_zone.py RUN_DIR [SNAPSHOT_INDEX|last] [OUTPUT.png]
       [--field NAME] [--window MM]

Reads the snapshot's .vtu pieces as impact-fem writes them (deal.II's
VTU: base64, zlib-compressed, UInt32 headers), so that the zone can be
looked at without ParaView. The window is a square of side MM millimetres
(default 2) centred on the initial contact point (r = 0, z = 0).
"""
import argparse
import base64
import glob
import os
import re
import struct
import sys
import zlib
import xml.etree.ElementTree as ET

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.collections import PolyCollection

DTYPES = {"Float32": np.float32, "Float64": np.float64, "Int32": np.int32,
          "UInt32": np.uint32, "Int64": np.int64, "UInt8": np.uint8}


def decode(array, compressed):
    """The values of a binary DataArray (VTK's inline base64 encoding)."""
    text = "".join(array.text.split())
    dtype = DTYPES[array.get("type")]
    if not compressed:
        raw = base64.b64decode(text)
        (size,) = struct.unpack("<I", raw[:4])
        return np.frombuffer(raw[4:4 + size], dtype=dtype)
    (n_blocks,) = struct.unpack("<I", base64.b64decode(text[:8])[:4])
    header_chars = -(-4 * (3 + n_blocks) // 3) * 4
    header = struct.unpack(f"<{3 + n_blocks}I", base64.b64decode(text[:header_chars])[:4 * (3 + n_blocks)])
    data = base64.b64decode(text[header_chars:])
    out, position = [], 0
    for size in header[3:]:
        out.append(zlib.decompress(data[position:position + size]))
        position += size
    return np.frombuffer(b"".join(out), dtype=dtype)


def read_piece(path, field):
    root = ET.parse(path).getroot()
    compressed = root.get("compressor") is not None
    piece = root.find(".//Piece")
    points = decode(piece.find("Points/DataArray"), compressed).reshape(-1, 3)[:, :2]
    cells = {a.get("Name"): a for a in piece.find("Cells")}
    connectivity = decode(cells["connectivity"], compressed)
    offsets = decode(cells["offsets"], compressed)
    data = {a.get("Name"): a for a in piece.find("CellData") or []}
    data.update({a.get("Name"): a for a in piece.find("PointData") or []})
    if field not in data:
        sys.exit(f"plastic_zone: no field '{field}' in {path} (fields: {', '.join(sorted(data))})")
    values = decode(data[field], compressed)
    starts = np.concatenate(([0], offsets[:-1]))
    polygons = [points[connectivity[s:e]] for s, e in zip(starts, offsets)]
    # A point field is shown by its cell mean.
    if len(values) == len(points):
        values = np.array([values[connectivity[s:e]].mean() for s, e in zip(starts, offsets)])
    return polygons, values


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("run")
    parser.add_argument("snapshot", nargs="?", default="last")
    parser.add_argument("output", nargs="?")
    parser.add_argument("--field", default="accumulated_plastic_strain")
    parser.add_argument("--window", type=float, default=2.0)
    args = parser.parse_args()
    records = sorted(glob.glob(os.path.join(args.run, "snapshots", "solution_*.pvtu")))
    if not records:
        sys.exit(f"plastic_zone: no snapshots in {args.run}/snapshots (set Output/Snapshot interval)")
    pvtu = records[-1] if args.snapshot == "last" else records[int(args.snapshot)]
    pieces = [os.path.join(os.path.dirname(pvtu), p.get("Source"))
              for p in ET.parse(pvtu).getroot().iter("Piece")]
    time = ""
    pvd = os.path.join(args.run, "snapshots.pvd")
    if os.path.exists(pvd):
        for d in ET.parse(pvd).getroot().iter("DataSet"):
            if d.get("file").endswith(os.path.basename(pvtu)):
                time = f", t = {float(d.get('timestep')) * 1e6:.2f} us"
    polygons, values = [], []
    for piece in pieces:
        p, v = read_piece(piece, args.field)
        polygons += p
        values.append(v)
    values = np.concatenate(values)
    half = args.window / 2 * 1e-3
    keep = [i for i, p in enumerate(polygons) if p[:, 0].min() < 2 * half and abs(p[:, 1]).min() < half]
    fig, ax = plt.subplots(figsize=(7, 7))
    collection = PolyCollection([polygons[i] * 1e3 for i in keep], array=values[keep],
                                cmap="viridis", edgecolors="face", linewidths=0.2)
    ax.add_collection(collection)
    fig.colorbar(collection, ax=ax, label=args.field, shrink=0.8)
    ax.set_xlim(0, 2 * half * 1e3)
    ax.set_ylim(-half * 1e3, half * 1e3)
    ax.set_aspect("equal")
    ax.set_xlabel("r [mm]")
    ax.set_ylabel("z [mm]")
    ax.set_title(f"{args.field} ({os.path.basename(pvtu)}{time}), largest {values.max():.3g}")
    output = args.output or os.path.join(args.run, f"{args.field}.png")
    fig.savefig(output, dpi=90, bbox_inches="tight")
    print(output)


if __name__ == "__main__":
    main()
