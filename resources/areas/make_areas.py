#!/usr/bin/env python3
"""Writes the sample areas of resources/areas/ (run from this folder: python3 make_areas.py).

Each area is drawn as a mask of cells ('#' = inside the area, '.' = outside, 'X' = inside a no-fly
zone) at the cell size stored in the file. The outline is traced along the cell edges, then moved
5 cm inwards (no-fly zones 5 cm outwards) so that a grid of that cell size at angle 0 has exactly the
drawn cells: no cell is touched by a boundary lying on its edge. Coordinates are WGS84, placed north
of the demo site near Karlsruhe with the ellipsoid's radii of curvature at the area's latitude.
"""
import json
import math

CELL = 20.0   # metres
EPS = 0.05    # metres
SCALE = 2     # cells per drawn character, each way

AREAS = {
    # Concave contour: a C opening to the east with a stepped west side.
    "a_concave": """
..##################
.###################
####################
####################
#########...........
########............
########............
########............
#########...........
####################
####################
.###################
..##################
..##################
""",
    # Teeth along the north and south edges.
    "b_teeth": """
#.#.##.#..#.#.##.#.#.#
#.#.##.####.#.##.###.#
######################
######################
######################
######################
######################
######################
##.###.#####.###.#####
#..#.#..#.##..#...#.#.
""",
    # An L.
    "c_l_shape": """
########..........
########..........
########..........
########..........
########..........
########..........
########..........
##################
##################
##################
##################
##################
""",
    # Several no-fly zones inside a rectangle with a cut corner (paper's figure 7c).
    "d_nofly": """
######################
######################
###XXX#########XX#####
###XXX#########XX#####
###XXX################
##########XXXX########
##########XXXX########
######################
#####XX###############
#####XX#######XXX#####
##############XXX#####
#################.....
#################.....
""",
    # A staircase outline (an area drawn across the grid's axes).
    "e_staircase": """
..............######
...........#########
.........###########
.......#############
.....###############
...#################
..#################.
#################...
###############.....
#############.......
###########.........
########............
""",
    # A complex contour with notches and holes.
    "f_complex": """
....##########......
...############.....
..##############....
.######XX#########..
#######XX##########.
####################
###XX######....#####
###XX######....#####
###########....#####
################XX##
######XXX#######XX##
######XXX###########
.###############....
..#############.....
""",
}


def trace(cells):
    """Rings (lists of integer vertices) around a set of (col, row) cells, counter-clockwise for the
    outline and clockwise for holes, collinear vertices removed."""
    edges = {}
    for (c, r) in cells:
        # Counter-clockwise around the cell; keep the edges whose other side is outside.
        if (c, r - 1) not in cells:
            edges[(c, r)] = (c + 1, r)
        if (c + 1, r) not in cells:
            edges[(c + 1, r)] = (c + 1, r + 1)
        if (c, r + 1) not in cells:
            edges[(c + 1, r + 1)] = (c, r + 1)
        if (c - 1, r) not in cells:
            edges[(c, r + 1)] = (c, r)
    rings = []
    while edges:
        start, nxt = next(iter(edges.items()))
        ring = [start]
        del edges[start]
        while nxt != start:
            ring.append(nxt)
            nxt2 = edges.pop(nxt)
            nxt = nxt2
        # Drop collinear vertices.
        out = []
        n = len(ring)
        for i in range(n):
            a, b, c = ring[i - 1], ring[i], ring[(i + 1) % n]
            if (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0]) != 0:
                out.append(b)
        rings.append(out)
    return rings


def offset(ring, d):
    """Moves each edge of a rectilinear ring by d to its left (inwards for a counter-clockwise ring)."""
    out = []
    n = len(ring)
    for i in range(n):
        a, b, c = ring[i - 1], ring[i], ring[(i + 1) % n]
        def left(p, q):
            dx, dy = q[0] - p[0], q[1] - p[1]
            l = math.hypot(dx, dy)
            return (-dy / l, dx / l)
        n1, n2 = left(a, b), left(b, c)
        out.append((b[0] * CELL + d * (n1[0] + n2[0]), b[1] * CELL + d * (n1[1] + n2[1])))
    return out


def components(cells):
    cells = set(cells)
    parts = []
    while cells:
        stack = [cells.pop()]
        part = set(stack)
        while stack:
            c, r = stack.pop()
            for n in ((c + 1, r), (c - 1, r), (c, r + 1), (c, r - 1)):
                if n in cells:
                    cells.remove(n)
                    part.add(n)
                    stack.append(n)
        parts.append(part)
    return parts


def to_geo(pts, lon0, lat0, w, h):
    a, e2 = 6378137.0, 0.00669437999014
    phi = math.radians(lat0)
    s = 1 - e2 * math.sin(phi) ** 2
    m = a * (1 - e2) / s ** 1.5
    n = a / math.sqrt(s)
    out = []
    for (x, y) in pts:
        x -= w * CELL / 2
        y -= h * CELL / 2
        out.append([round(lon0 + math.degrees(x / (n * math.cos(phi))), 9), round(lat0 + math.degrees(y / m), 9)])
    out.append(out[0])
    return out


def main():
    for k, (name, art) in enumerate(sorted(AREAS.items())):
        # Each drawn character is SCALE x SCALE cells.
        lines = [l.replace("#", "#" * SCALE).replace(".", "." * SCALE).replace("X", "X" * SCALE)
                 for l in art.strip("\n").split("\n") for _ in range(SCALE)]
        h, w = len(lines), len(lines[0])
        area, zones = set(), set()
        for i, line in enumerate(lines):
            assert len(line) == w, name
            r = h - 1 - i
            for c, ch in enumerate(line):
                if ch in "#X":
                    area.add((c, r))
                if ch == "X":
                    zones.add((c, r))
        rings = trace(area)
        def signed(r):
            return sum(r[i - 1][0] * r[i][1] - r[i][0] * r[i - 1][1] for i in range(len(r))) / 2
        outer = [r for r in rings if signed(r) > 0]
        holes = [r for r in rings if signed(r) < 0]
        assert len(outer) == 1, name + ": the area must be one piece"
        lon0, lat0 = 8.3300 + 0.0075 * (k % 3), 49.0190 + 0.0060 * (k // 3)
        features = [{
            "type": "Feature",
            "properties": {"role": "area", "name": name, "cell_size_m": CELL,
                           "cells": len(area) - len(zones)},
            "geometry": {"type": "Polygon",
                         "coordinates": [to_geo(offset(r, EPS), lon0, lat0, w, h) for r in outer + holes]},
        }]
        for j, part in enumerate(sorted(components(zones), key=lambda p: min(p))):
            ring = trace(part)[0]
            features.append({
                "type": "Feature",
                "properties": {"role": "nofly", "name": "zone %d" % (j + 1)},
                "geometry": {"type": "Polygon",
                             "coordinates": [to_geo(offset(ring, -EPS), lon0, lat0, w, h)]},
            })
        doc = {"type": "FeatureCollection", "name": name, "cell_size_m": CELL, "features": features}
        with open(name + ".geojson", "w") as f:
            json.dump(doc, f, indent=1)
            f.write("\n")
        print(name, len(area) - len(zones), "cells")


if __name__ == "__main__":
    main()
