#!/usr/bin/python3
"""Draw sweep plans dumped as GeoJSON (tests' sweeptest::writeGeoJson) to PNG: area, zones, cells,
photos and the flown path. Usage: plot_sweep.py IN.geojson... (writes IN.png beside each).
The dumps: PF_SWEEP_PICTURES=DIR pf_core_tests --gtest_filter=SweepPlanner.TimeAgainstTheYardstick
ZOOM=x0,y0,x1,y1 in the environment draws only that window, with the photos' real footprints."""
import json
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

for path in sys.argv[1:]:
    with open(path) as f:
        fc = json.load(f)
    fig, ax = plt.subplots(figsize=(9, 9))
    for feat in fc["features"]:
        role, g = feat["properties"]["role"], feat["geometry"]
        if g["type"] == "Polygon":
            ring = g["coordinates"][0]
            xs, ys = zip(*ring)
            if role == "area":
                ax.fill(xs, ys, color="#eef5e9", zorder=0)
                ax.plot(xs, ys, color="#3a7d2c", lw=1.2, zorder=1)
            elif role == "zone":
                ax.fill(xs, ys, color="#e8a0a0", zorder=2)
            elif role == "hole":
                ax.fill(xs, ys, color="#ff00ff", zorder=6)
            elif role == "cell":
                ax.plot(xs, ys, color="#9aa7c7", lw=0.6, ls="--", zorder=1)
        elif g["type"] == "MultiPoint" and g["coordinates"]:
            xs, ys = zip(*g["coordinates"])
            ax.plot(xs, ys, ".", color="#222222", ms=2.5, zorder=4)
        elif g["type"] == "LineString" and g["coordinates"]:
            xs, ys = zip(*g["coordinates"])
            ax.plot(xs, ys, color="#1f5fbf", lw=0.8, zorder=3)
            ax.plot(xs[0], ys[0], "o", color="green", zorder=5)
            ax.plot(xs[-1], ys[-1], "s", color="red", zorder=5)
    zoom = os.environ.get("ZOOM")
    if zoom:
        x0, y0, x1, y1 = map(float, zoom.split(","))
        ax.set_xlim(x0, x1)
        ax.set_ylim(y0, y1)
    ax.set_aspect("equal")
    ax.set_title(path.rsplit("/", 1)[-1])
    fig.tight_layout()
    fig.savefig(path.rsplit(".", 1)[0] + ".png", dpi=80)
    plt.close(fig)
