#!/usr/bin/python3
"""Writes the example scenes' triangle meshes (OBJ, metres, y up) into scenes/meshes/.

The OBJ files are generated, not drawn or downloaded: this script is their source. Every mesh is
closed and oriented outward from the solid (or liquid) it bounds -- every edge shared by exactly
two triangles running along it in opposite directions, triangles counter-clockwise seen from
outside -- as io/mesh_file.h and io/mesh_closedness.h require. Each surface piece (a disk, a
band between two rings) is turned so that its triangles' normals agree with the outward
direction of that piece, and the script checks the result before it writes anything: the edge
rule, and a signed volume (sum of v0 . (v1 x v2) / 6) equal to the volume of the polygonal solid
computed in closed form.

- glass.obj: a drinking glass, origin at the centre of its base, axis +y. Inner radius 0.030 m,
  wall 0.002 m (outer radius 0.032 m), height 0.100 m, base 0.004 m thick, 48 segments. An open
  cup: outer side, inner side, top rim annulus, outer bottom disk, inner bottom (the floor of the
  cup at y = 0.004 m). The wall is thinner than a 5 mm grid cell on purpose (thin-wall tests).
- basin.obj: a rectangular wash basin, origin at the centre of its base, axis +y. Outside
  0.26 m (x) by 0.20 m (z), 0.08 m high; walls and floor 0.015 m thick (three 5 mm cells: it
  needs no thin-wall handling), so the inside is 0.23 m by 0.17 m above a floor at y = 0.015 m.
  Fits a 0.3 x 0.2 x 0.3 m domain. Rectangular and axis-aligned on purpose: every face then lies
  on a node plane of a 5 mm grid centred on it, and still water stays still in it; in a round
  basin the staircased wall stirs still water and the bubble model makes bubbles there
  (docs/scenes.md, "tap_drip").
- basin_water.obj: the water resting in basin.obj placed at the origin: the inside of the basin
  from its floor (y = 0.015 m) up to y = 0.035 m (2 cm deep, 0.782 L), a closed box. Liquid
  meshes are used as written (docs/scene.md), so this one is in the basin's frame: a scene puts
  the basin at the origin to use it.
- bowl.obj: a round block with a hemispherical hollow, origin at the centre of its base, axis
  +y. Block radius 0.08 m, 0.06 m high; the hollow a hemisphere of radius 0.05 m centred on the
  top face (12 rings of latitude, 48 segments), so its bottom is 0.01 m above the base. A
  concave, curved wall for still water to rest against (issue 4's bowl: a primitive sphere solid
  is convex; this is its inside).
- stone.obj: a low-poly pebble about 0.02 m in radius, centred at the origin: an icosahedron
  split once (42 vertices, 80 triangles), each vertex pushed out to a radius drawn uniformly
  from 0.017-0.023 m and the whole flattened to 0.7 in y. Star-shaped about its centre, so it
  stays closed and outward. Deterministic: random.Random(STONE_SEED), random() only (whose
  sequence Python keeps the same across versions).

Numbers are written with 7 decimals (0.1 micrometre), so the files are byte-identical wherever
the script runs. Standard library only.

Usage: /usr/bin/python3 tools/make_meshes.py [--out DIR]    (default DIR: <repo>/scenes/meshes)
       /usr/bin/python3 tools/make_meshes.py --check [--out DIR]
         (writes nothing; exit status 1 if a file in DIR differs from what the script makes)
"""

import argparse
import math
import os
import random
import sys
import tempfile

SEGMENTS = 48  # around the axis of the glass

# glass.obj [m]
GLASS_INNER_RADIUS = 0.030
GLASS_WALL = 0.002
GLASS_HEIGHT = 0.100
GLASS_BASE = 0.004

# basin.obj [m]
BASIN_OUTER_HALF = (0.13, 0.10)  # half sizes along x and z
BASIN_WALL = 0.015
BASIN_HEIGHT = 0.08
BASIN_FLOOR = 0.015
BASIN_WATER_TOP = 0.035  # water surface height in basin_water.obj [m]

# stone.obj
STONE_SEED = 7
STONE_RADIUS_MIN = 0.017  # m
STONE_RADIUS_MAX = 0.023  # m
STONE_FLATTENING = 0.7    # y scale

DECIMALS = 7


class Mesh:
    """Vertices [m] and triangles (0-based index triples, counter-clockwise from outside)."""

    def __init__(self):
        self.vertices = []
        self.triangles = []

    def vertex(self, p):
        self.vertices.append(tuple(p))
        return len(self.vertices) - 1

    def ring(self, outline, y):
        """The (x, z) points of `outline` as vertices at height y."""
        return [self.vertex((x, y, z)) for x, z in outline]

    def triangle(self, a, b, c, outward):
        """Adds (a, b, c), turned so that its normal points along `outward` (a vector)."""
        n = cross(sub(self.vertices[b], self.vertices[a]), sub(self.vertices[c], self.vertices[a]))
        self.triangles.append((a, b, c) if dot(n, outward) > 0 else (a, c, b))

    def band(self, ring_a, ring_b, outward):
        """Quads between two rings of equal length, each split in two triangles; `outward(p)`
        is the outward direction of the surface near point p."""
        n = len(ring_a)
        for k in range(n):
            a0, a1, b0, b1 = ring_a[k], ring_a[(k + 1) % n], ring_b[k], ring_b[(k + 1) % n]
            for tri in ((a0, a1, b1), (a0, b1, b0)):
                self.triangle(*tri, outward(centroid(self, tri)))

    def disk(self, centre, ring, outward):
        """A fan from the vertex `centre` to `ring`, facing the constant direction `outward`."""
        n = len(ring)
        for k in range(n):
            self.triangle(centre, ring[k], ring[(k + 1) % n], outward)


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def centroid(mesh, tri):
    ps = [mesh.vertices[i] for i in tri]
    return tuple(sum(p[a] for p in ps) / 3 for a in range(3))


def radial(p):
    """Away from the y axis."""
    return (p[0], 0.0, p[2])


def towards_axis(p):
    return (-p[0], 0.0, -p[2])


UP, DOWN = (0.0, 1.0, 0.0), (0.0, -1.0, 0.0)


def circle(radius, segments=SEGMENTS):
    """The regular polygon inscribed in a circle about the y axis, as (x, z) points, turning from
    +x towards +z."""
    return [(radius * math.cos(2 * math.pi * k / segments), radius * math.sin(2 * math.pi * k / segments))
            for k in range(segments)]


def rectangle(half_x, half_z):
    """The rectangle |x| <= half_x, |z| <= half_z as (x, z) corners, turning as circle() does."""
    return [(half_x, half_z), (-half_x, half_z), (-half_x, -half_z), (half_x, -half_z)]


def area(outline):
    """Area enclosed by an (x, z) outline [m^2] (shoelace formula)."""
    n = len(outline)
    return abs(sum(outline[k][0] * outline[(k + 1) % n][1] - outline[(k + 1) % n][0] * outline[k][1]
                   for k in range(n))) / 2


def frustum_volume(bottom, top, height):
    """Volume between two similar (x, z) outlines `height` apart, their points joined in pairs
    [m^3]: h/3 (A1 + A2 + sqrt(A1 A2)) (a prism when the outlines are equal)."""
    a1, a2 = area(bottom), area(top)
    return height / 3 * (a1 + a2 + math.sqrt(a1 * a2))


# bowl.obj [m]
BOWL_RADIUS = 0.08          # the block's
BOWL_HEIGHT = 0.06
BOWL_HOLLOW_RADIUS = 0.05   # the hemisphere's, centred on the top face
BOWL_LATITUDES = 12         # rings from the rim down to the bottom pole

# ---- the meshes -------------------------------------------------------------------------------

def cup(outer, inner_floor, inner_rim, height, base):
    """An open-topped cup (glass or basin), origin at the centre of its base, axis +y, from
    three (x, z) outlines of equal length: the outside (a prism), the inside at the floor and at
    the rim (similar outlines; a frustum when they differ). Surfaces: outer bottom, outer side,
    rim, inner side, inner floor. Returns (mesh, volume of the solid [m^3])."""
    m = Mesh()
    bottom_centre = m.vertex((0.0, 0.0, 0.0))
    outer_bottom = m.ring(outer, 0.0)
    outer_top = m.ring(outer, height)
    inner_top = m.ring(inner_rim, height)
    inner_bottom = m.ring(inner_floor, base)
    floor_centre = m.vertex((0.0, base, 0.0))
    m.disk(bottom_centre, outer_bottom, DOWN)
    m.band(outer_bottom, outer_top, radial)
    m.band(outer_top, inner_top, lambda p: UP)
    m.band(inner_top, inner_bottom, towards_axis)  # faces the hollow: outward from the material
    m.disk(floor_centre, inner_bottom, UP)
    return m, area(outer) * height - frustum_volume(inner_floor, inner_rim, height - base)


def glass():
    inner = circle(GLASS_INNER_RADIUS)
    return cup(circle(GLASS_INNER_RADIUS + GLASS_WALL), inner, inner, GLASS_HEIGHT, GLASS_BASE)


def basin_inside():
    return rectangle(BASIN_OUTER_HALF[0] - BASIN_WALL, BASIN_OUTER_HALF[1] - BASIN_WALL)


def basin():
    inside = basin_inside()
    return cup(rectangle(*BASIN_OUTER_HALF), inside, inside, BASIN_HEIGHT, BASIN_FLOOR)


def basin_water():
    """The inside of basin() from its floor to BASIN_WATER_TOP: a closed box."""
    inside = basin_inside()
    m = Mesh()
    bottom_centre = m.vertex((0.0, BASIN_FLOOR, 0.0))
    bottom = m.ring(inside, BASIN_FLOOR)
    top = m.ring(inside, BASIN_WATER_TOP)
    top_centre = m.vertex((0.0, BASIN_WATER_TOP, 0.0))
    m.disk(bottom_centre, bottom, DOWN)
    m.band(bottom, top, radial)
    m.disk(top_centre, top, UP)
    return m, area(inside) * (BASIN_WATER_TOP - BASIN_FLOOR)


def bowl():
    """A round block with a hemispherical hollow (see the module docstring): outer bottom disk,
    outer side, top annulus, then the hollow from the rim ring down to a fan around its pole."""
    m = Mesh()
    outer = circle(BOWL_RADIUS)
    bottom_centre = m.vertex((0.0, 0.0, 0.0))
    outer_bottom = m.ring(outer, 0.0)
    outer_top = m.ring(outer, BOWL_HEIGHT)
    m.disk(bottom_centre, outer_bottom, DOWN)
    m.band(outer_bottom, outer_top, radial)
    # Ring n at the polar angle (pi/2)(1 - n/N) from the downward axis: n = 0 is the rim.
    outlines, heights = [], []
    for n in range(BOWL_LATITUDES):
        polar = math.pi / 2 * (1 - n / BOWL_LATITUDES)
        outlines.append(circle(BOWL_HOLLOW_RADIUS * math.sin(polar)))
        heights.append(BOWL_HEIGHT - BOWL_HOLLOW_RADIUS * math.cos(polar))
    rings = [m.ring(o, y) for o, y in zip(outlines, heights)]
    m.band(outer_top, rings[0], lambda p: UP)
    centre = (0.0, BOWL_HEIGHT, 0.0)
    for a, b in zip(rings, rings[1:]):
        m.band(a, b, lambda p: sub(centre, p))  # faces the hollow: outward from the material
    pole_y = BOWL_HEIGHT - BOWL_HOLLOW_RADIUS
    pole = m.vertex((0.0, pole_y, 0.0))
    m.disk(pole, rings[-1], UP)
    # The hollow: frustums between the rings and a cone from the last ring to the pole.
    hollow = sum(frustum_volume(outlines[n + 1], outlines[n], heights[n] - heights[n + 1])
                 for n in range(BOWL_LATITUDES - 1))
    hollow += area(outlines[-1]) * (heights[-1] - pole_y) / 3
    return m, area(outer) * BOWL_HEIGHT - hollow


def stone():
    """Icosahedron split once, radii jittered, flattened in y (see the module docstring)."""
    t = (1 + math.sqrt(5)) / 2
    directions = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
                  (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
             (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
             (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    midpoints = {}

    def midpoint(a, b):
        key = (min(a, b), max(a, b))
        if key not in midpoints:
            directions.append(tuple((directions[a][i] + directions[b][i]) / 2 for i in range(3)))
            midpoints[key] = len(directions) - 1
        return midpoints[key]

    split = []
    for a, b, c in faces:
        ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
        split += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
    rng = random.Random(STONE_SEED)
    m = Mesh()
    for d in directions:
        length = math.sqrt(dot(d, d))
        r = STONE_RADIUS_MIN + (STONE_RADIUS_MAX - STONE_RADIUS_MIN) * rng.random()
        m.vertex((r * d[0] / length, STONE_FLATTENING * r * d[1] / length, r * d[2] / length))
    for tri in split:
        m.triangle(*tri, centroid(m, tri))  # star-shaped about the origin: out = away from it
    return m, None  # no closed form: the check requires a positive volume only


MESHES = {"glass.obj": glass, "basin.obj": basin, "basin_water.obj": basin_water, "bowl.obj": bowl,
          "stone.obj": stone}


# ---- checks and output ------------------------------------------------------------------------

def rounded(p):
    # + 0.0 turns -0.0 into 0.0, so a coordinate that rounds to zero prints without a sign.
    return tuple(round(c, DECIMALS) + 0.0 for c in p)


def check_closed(name, mesh, volume):
    """The rules of io/mesh_closedness.h on the rounded vertices, and the signed volume."""
    positions = [rounded(p) for p in mesh.vertices]
    weld = {}
    index = [weld.setdefault(p, i) for i, p in enumerate(positions)]
    directed = {}
    for tri in mesh.triangles:
        a, b, c = (index[i] for i in tri)
        if len({a, b, c}) < 3:
            sys.exit(f"make_meshes.py: {name}: degenerate triangle {tri}")
        for e in ((a, b), (b, c), (c, a)):
            directed[e] = directed.get(e, 0) + 1
    for (a, b), count in directed.items():
        if count != 1 or directed.get((b, a), 0) != 1:
            sys.exit(f"make_meshes.py: {name}: edge {a}-{b} is not shared by exactly two "
                     f"triangles running along it in opposite directions")
    signed = signed_volume(positions, mesh.triangles)
    if not signed > 0:
        sys.exit(f"make_meshes.py: {name}: signed volume {signed} m^3 is not positive (inward?)")
    if volume is not None:
        # Before rounding the mesh is the polygonal solid itself: equal to float rounding (1e-9).
        exact = signed_volume(mesh.vertices, mesh.triangles)
        if abs(exact - volume) > 1e-9 * volume:
            sys.exit(f"make_meshes.py: {name}: signed volume {exact} m^3, expected {volume} m^3")
        # Rounding moves each vertex by at most sqrt(3)/2 * 1e-7 m: at most that times the area.
        if abs(signed - volume) > surface_area(positions, mesh.triangles) * math.sqrt(3) / 2 * 10.0 ** -DECIMALS:
            sys.exit(f"make_meshes.py: {name}: rounded signed volume {signed} m^3, expected {volume} m^3")
    return signed


def signed_volume(positions, triangles):
    """Sum of v0 . (v1 x v2) / 6 [m^3]: the enclosed volume of a closed mesh, positive when its
    triangles turn counter-clockwise seen from outside."""
    return sum(dot(positions[a], cross(positions[b], positions[c])) for a, b, c in triangles) / 6


def surface_area(positions, triangles):
    """Surface area [m^2]."""
    total = 0.0
    for a, b, c in triangles:
        n = cross(sub(positions[b], positions[a]), sub(positions[c], positions[a]))
        total += math.sqrt(dot(n, n)) / 2
    return total


def obj_text(name, mesh, signed_volume):
    lines = [f"# {name}: written by tools/make_meshes.py (the source of this file; do not edit).",
             "# Metres, y up; closed, triangles counter-clockwise seen from outside.",
             f"# {len(mesh.vertices)} vertices, {len(mesh.triangles)} triangles, "
             f"enclosed volume {signed_volume * 1e6:.4f} cm^3"]
    for p in mesh.vertices:
        lines.append("v " + " ".join(f"{c:.{DECIMALS}f}" for c in rounded(p)))
    for a, b, c in mesh.triangles:
        lines.append(f"f {a + 1} {b + 1} {c + 1}")
    return "\n".join(lines) + "\n"


def write_atomically(path, text):
    folder = os.path.dirname(path)
    fd, temporary = tempfile.mkstemp(dir=folder, prefix=".tmp-", suffix=".obj")
    try:
        with os.fdopen(fd, "w", newline="\n") as out:
            out.write(text)
        os.replace(temporary, path)
    except BaseException:
        os.unlink(temporary)
        raise


def main():
    repo = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=os.path.join(repo, "scenes", "meshes"))
    parser.add_argument("--check", action="store_true",
                        help="compare the files in --out with what the script makes; write nothing")
    args = parser.parse_args()
    texts = {}
    for name, make in MESHES.items():
        mesh, volume = make()
        texts[name] = obj_text(name, mesh, check_closed(name, mesh, volume))
    if args.check:
        stale = []
        for name, text in texts.items():
            path = os.path.join(args.out, name)
            try:
                with open(path, encoding="utf-8", newline="") as f:
                    same = f.read() == text
            except OSError:
                same = False
            if not same:
                stale.append(path)
        for path in stale:
            print(f"make_meshes.py: {path}: differs from what tools/make_meshes.py writes "
                  f"(run it again and commit the result)", file=sys.stderr)
        return 1 if stale else 0
    os.makedirs(args.out, exist_ok=True)
    for name, text in texts.items():
        write_atomically(os.path.join(args.out, name), text)
        print(os.path.join(args.out, name))
    return 0


if __name__ == "__main__":
    sys.exit(main())
