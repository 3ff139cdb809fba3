#!/usr/bin/env python3
"""Writes the dress form in three sizes, and forms.json, their catalogue.

A surface of revolution about the z axis, hip to neck, squashed front to back
(a torso is deeper side to side than front to back), with flat caps at the base
and the neck. Metres. Outward-facing, closed, no degenerate triangles, so it
passes the mesh obstacle checks without repair.

dress-form.obj is the medium, the form the example scenes use. The small and
the large are its profile widened or narrowed so that the mesh's girths at the
hip, waist and bust levels (LEVELS) are the medium's minus or plus SIZE_STEP,
about one women's size: the half-widths are multiplied by a factor that runs
linearly in z between the three levels, constant below the hip, and from the
bust up to the shoulders, then half as far from 1 at the neck, and each
level's factor is refined until the girth is on target. All three are 0.60 m
tall. A girth is what a tape around the mesh measures: the perimeter of the
mesh's cross-section by the plane z = level, on the coordinates as written.
forms.json states the girths to 0.1 cm, and the small and large OBJ headers
too (the medium's header predates them and is kept as it was, byte for byte).

    python3 make_dress_form.py                     # all three and forms.json, here
    python3 make_dress_form.py --size small|medium|large [output.obj]
    python3 make_dress_form.py [output.obj]        # the medium, as before
"""

import argparse
import json
import math
import os

HEIGHT = 0.60  # base to neck [m]
DEPTH_RATIO = 0.80  # front-back over side-side half-width
PROFILE_POINTS = 40  # rings, base and neck included
SEGMENTS = 48  # around

# (z, half-width) through which the profile passes: hip, waist, bust,
# shoulder slope, neck. Roughly a size-38 form.
PROFILE = [
    (0.00, 0.135),
    (0.05, 0.152),
    (0.12, 0.160),
    (0.20, 0.145),
    (0.28, 0.117),
    (0.34, 0.126),
    (0.42, 0.150),
    (0.47, 0.148),
    (0.52, 0.133),
    (0.55, 0.112),
    (0.575, 0.075),
    (0.59, 0.052),
    (0.60, 0.045),
]

# Where the tape goes [m]: at the medium's fullest hip, narrowest waist and
# fullest bust (each within 0.1 cm of girth of the extreme), whole
# centimetres, between rings so that no vertex lies on a level.
LEVELS = {"bust": 0.43, "waist": 0.29, "hip": 0.11}
SIZE_STEP = 0.04  # girth difference between neighbouring sizes [m]
SIZES = {"small": -1, "medium": 0, "large": 1}  # steps from the medium
FILES = {"small": "dress-form-small.obj", "medium": "dress-form.obj",
         "large": "dress-form-large.obj"}
SHOULDER = 0.47  # up to here the bust's factor holds; the neck gets half of it
DESCRIPTIONS = {
    "small": "The medium form one size down: the same torso with bust, waist "
             "and hip girths 4 cm smaller and the shoulders and neck a little "
             "narrower.",
    "medium": "The torso the example scenes drape over: hip to neck, wider "
              "side to side than front to back, with a flat base and a flat "
              "neck.",
    "large": "The medium form one size up: the same torso with bust, waist "
             "and hip girths 4 cm larger and the shoulders and neck a little "
             "wider.",
}


def half_width(z, profile=PROFILE):
    """Catmull-Rom through the profile: smooth, and through every point."""
    for k in range(len(profile) - 1):
        z0, z1 = profile[k][0], profile[k + 1][0]
        if z <= z1 or k == len(profile) - 2:
            break
    p0 = profile[max(k - 1, 0)]
    p1, p2 = profile[k], profile[k + 1]
    p3 = profile[min(k + 2, len(profile) - 1)]
    # Tangents by the neighbours' slope (non-uniform spacing in z).
    m1 = (p2[1] - p0[1]) / (p2[0] - p0[0]) * (z1 - z0)
    m2 = (p3[1] - p1[1]) / (p3[0] - p1[0]) * (z1 - z0)
    t = (z - z0) / (z1 - z0)
    h00 = 2 * t**3 - 3 * t**2 + 1
    h10 = t**3 - 2 * t**2 + t
    h01 = -2 * t**3 + 3 * t**2
    h11 = t**3 - t**2
    return h00 * p1[1] + h10 * m1 + h01 * p2[1] + h11 * m2


def build(profile=PROFILE):
    vertices = []
    for i in range(PROFILE_POINTS):
        z = HEIGHT * i / (PROFILE_POINTS - 1)
        r = half_width(z, profile)
        for j in range(SEGMENTS):
            phi = 2 * math.pi * j / SEGMENTS
            vertices.append((r * math.cos(phi), DEPTH_RATIO * r * math.sin(phi), z))
    base = len(vertices)
    vertices.append((0.0, 0.0, 0.0))
    neck = len(vertices)
    vertices.append((0.0, 0.0, HEIGHT))

    def ring(i, j):
        return i * SEGMENTS + j % SEGMENTS

    # Counter-clockwise seen from outside: around (φ) then up (z) points out.
    triangles = []
    for i in range(PROFILE_POINTS - 1):
        for j in range(SEGMENTS):
            a, b = ring(i, j), ring(i, j + 1)
            c, d = ring(i + 1, j + 1), ring(i + 1, j)
            triangles += [(a, b, c), (a, c, d)]
    top = PROFILE_POINTS - 1
    for j in range(SEGMENTS):
        triangles.append((base, ring(0, j + 1), ring(0, j)))
        triangles.append((neck, ring(top, j), ring(top, j + 1)))
    return vertices, triangles


def check(vertices, triangles):
    edges = {}
    volume = 0.0
    for a, b, c in triangles:
        for e in ((a, b), (b, c), (c, a)):
            assert e not in edges, "edge used twice in one direction"
            edges[e] = True
        pa, pb, pc = vertices[a], vertices[b], vertices[c]
        u = [pb[k] - pa[k] for k in range(3)]
        w = [pc[k] - pa[k] for k in range(3)]
        assert math.hypot(u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
                          u[0] * w[1] - u[1] * w[0]) > 1e-9, "degenerate triangle"
        volume += (pa[0] * (pb[1] * pc[2] - pb[2] * pc[1]) -
                   pa[1] * (pb[0] * pc[2] - pb[2] * pc[0]) +
                   pa[2] * (pb[0] * pc[1] - pb[1] * pc[0])) / 6
    assert all((b, a) in edges for a, b in edges), "open edge"
    assert volume > 0, "inward-facing"
    return volume


def as_written(vertices):
    """The vertices as the OBJ file holds them (to the micrometre)."""
    return [tuple(float(f"{c:.6f}") for c in v) for v in vertices]


def girth(vertices, triangles, level):
    """Perimeter of the mesh's cross-section by the plane z = level [m].

    A vertex on the plane counts as above it, so that a closed mesh gives
    closed cross-sections however the plane meets it.
    """
    total = 0.0
    for triangle in triangles:
        points = [vertices[i] for i in triangle]
        cut = []
        for k in range(3):
            a, b = points[k], points[(k + 1) % 3]
            da, db = a[2] - level, b[2] - level
            if (da >= 0) != (db >= 0):
                s = da / (da - db)
                cut.append((a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1])))
        if len(cut) == 2:
            total += math.dist(cut[0], cut[1])
    return total


def girths(vertices, triangles):
    return {name: girth(vertices, triangles, z) for name, z in LEVELS.items()}


def scaled_profile(factors):
    """PROFILE with its half-widths times a factor linear in z between the
    levels: the hip's below the hip, the bust's from the bust to SHOULDER,
    then down to halfway to 1 at the neck."""
    bust = factors["bust"]
    knots = [(LEVELS["hip"], factors["hip"]), (LEVELS["waist"], factors["waist"]),
             (LEVELS["bust"], bust), (SHOULDER, bust), (HEIGHT, (1 + bust) / 2)]

    def factor(z):
        if z <= knots[0][0]:
            return knots[0][1]
        for (z0, f0), (z1, f1) in zip(knots, knots[1:]):
            if z <= z1:
                return f0 + (f1 - f0) * (z - z0) / (z1 - z0)
        return knots[-1][1]

    return [(z, r * factor(z)) for z, r in PROFILE]


def size_profile(size):
    """The profile of a size: PROFILE itself for the medium; for the others
    scaled until each girth is the medium's plus the size's steps."""
    steps = SIZES[size]
    if steps == 0:
        return PROFILE
    medium = girths(*build())
    target = {name: g + steps * SIZE_STEP for name, g in medium.items()}
    factors = {name: target[name] / g for name, g in medium.items()}
    for _ in range(50):
        measured = girths(*build(scaled_profile(factors)))
        if all(abs(measured[n] - target[n]) < 1e-8 for n in LEVELS):
            break
        for name in LEVELS:
            factors[name] *= target[name] / measured[name]
    else:
        raise AssertionError(f"{size}: girths did not converge")
    return scaled_profile(factors)


def cm(metres, digits=1):
    """"80.2 cm"; digits=0 gives "60 cm"."""
    return f"{metres * 100:.{digits}f} cm"


def write_form(size, output):
    """Writes one size's OBJ; returns its catalogue entry."""
    vertices, triangles = build(size_profile(size))
    volume = check(vertices, triangles)
    written = as_written(vertices)
    measured = girths(written, triangles)
    zs = [v[2] for v in written]
    height = max(zs) - min(zs)
    with open(output, "w") as f:
        if size == "medium":
            f.write("# Dress form: written by make_dress_form.py; edit that, not this.\n")
        else:
            f.write(f"# Dress form, {size}: written by make_dress_form.py; "
                    f"edit that, not this.\n")
        f.write(f"# {len(vertices)} vertices, {len(triangles)} triangles, "
                f"{HEIGHT} m tall, volume {volume * 1e3:.2f} L, metres, z up.\n")
        if size != "medium":
            f.write("# Girths of this mesh (perimeter of its cross-section at z): " +
                    ", ".join(f"{name} {cm(measured[name])} at z = {cm(z, 0)}"
                              for name, z in LEVELS.items()) + ".\n")
        for x, y, z in vertices:
            f.write(f"v {x:.6f} {y:.6f} {z:.6f}\n")
        for a, b, c in triangles:
            f.write(f"f {a + 1} {b + 1} {c + 1}\n")
    entry = {"name": f"Dress form, {size}", "file": FILES[size], "size": size,
             "height": cm(height, 0)}
    entry.update({name: cm(measured[name]) for name in LEVELS})
    entry["levels"] = {name: cm(z, 0) for name, z in LEVELS.items()}
    entry["description"] = DESCRIPTIONS[size]
    print(f"{output}: {size}, height {cm(height)}, " +
          ", ".join(f"{name} {cm(measured[name])} at {cm(z, 0)}"
                    for name, z in LEVELS.items()))
    return entry


def write_catalogue(entries, output):
    """forms.json, one form to a few lines."""
    def items(d, keys):
        return ", ".join(f"{json.dumps(k)}: {json.dumps(d[k])}" for k in keys)

    lines = ['{"drape_forms": 1,', ' "forms": [']
    for k, e in enumerate(entries):
        lines += ["  {" + items(e, ["name", "file", "size"]) + ",",
                  "   " + items(e, ["height", "bust", "waist", "hip"]) + ",",
                  "   " + items(e, ["levels"]) + ",",
                  "   " + items(e, ["description"]) + "}" +
                  ("," if k + 1 < len(entries) else "]}")]
    text = "\n".join(lines) + "\n"
    assert json.loads(text)["forms"] == entries
    with open(output, "w") as f:
        f.write(text)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--size", choices=SIZES)
    parser.add_argument("output", nargs="?")
    args = parser.parse_args()
    if args.size is None and args.output is None:
        here = os.path.dirname(os.path.abspath(__file__))
        entries = [write_form(size, os.path.join(here, FILES[size])) for size in SIZES]
        write_catalogue(entries, os.path.join(here, "forms.json"))
    else:
        size = args.size or "medium"
        write_form(size, args.output or FILES[size])


if __name__ == "__main__":
    main()
