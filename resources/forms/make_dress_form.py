#!/usr/bin/env python3
"""Writes dress-form.obj: a torso-like closed surface to drape fabric over.

A surface of revolution about the z axis, hip to neck, squashed front to back
(a torso is deeper side to side than front to back), with flat caps at the base
and the neck. Metres. Outward-facing, closed, no degenerate triangles, so it
passes the mesh obstacle checks without repair.

    python3 make_dress_form.py [output.obj]
"""

import math
import sys

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


def half_width(z):
    """Catmull-Rom through PROFILE: smooth, and through every point."""
    for k in range(len(PROFILE) - 1):
        z0, z1 = PROFILE[k][0], PROFILE[k + 1][0]
        if z <= z1 or k == len(PROFILE) - 2:
            break
    p0 = PROFILE[max(k - 1, 0)]
    p1, p2 = PROFILE[k], PROFILE[k + 1]
    p3 = PROFILE[min(k + 2, len(PROFILE) - 1)]
    # Tangents by the neighbours' slope (non-uniform spacing in z).
    m1 = (p2[1] - p0[1]) / (p2[0] - p0[0]) * (z1 - z0)
    m2 = (p3[1] - p1[1]) / (p3[0] - p1[0]) * (z1 - z0)
    t = (z - z0) / (z1 - z0)
    h00 = 2 * t**3 - 3 * t**2 + 1
    h10 = t**3 - 2 * t**2 + t
    h01 = -2 * t**3 + 3 * t**2
    h11 = t**3 - t**2
    return h00 * p1[1] + h10 * m1 + h01 * p2[1] + h11 * m2


def build():
    vertices = []
    for i in range(PROFILE_POINTS):
        z = HEIGHT * i / (PROFILE_POINTS - 1)
        r = half_width(z)
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
        volume += (pa[0] * (pb[1] * pc[2] - pb[2] * pc[1]) -
                   pa[1] * (pb[0] * pc[2] - pb[2] * pc[0]) +
                   pa[2] * (pb[0] * pc[1] - pb[1] * pc[0])) / 6
    assert all((b, a) in edges for a, b in edges), "open edge"
    assert volume > 0, "inward-facing"
    return volume


def main():
    output = sys.argv[1] if len(sys.argv) > 1 else "dress-form.obj"
    vertices, triangles = build()
    volume = check(vertices, triangles)
    with open(output, "w") as f:
        f.write("# Dress form: written by make_dress_form.py; edit that, not this.\n")
        f.write(f"# {len(vertices)} vertices, {len(triangles)} triangles, "
                f"{HEIGHT} m tall, volume {volume * 1e3:.2f} L, metres, z up.\n")
        for x, y, z in vertices:
            f.write(f"v {x:.6f} {y:.6f} {z:.6f}\n")
        for a, b, c in triangles:
            f.write(f"f {a + 1} {b + 1} {c + 1}\n")


if __name__ == "__main__":
    main()
