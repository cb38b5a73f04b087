#!/usr/bin/env python3
"""Writes mesh/torus.obj: a low-poly torus for the Mitsuba cross-check scene.

The torus lies in the xz plane around the origin: major radius 1, minor radius
0.35, 24 x 12 quads split into 576 triangles. Faces are wound so that their
geometric normals point outwards. Deterministic: the same bytes on every run.

    python3 scripts/make_mesh.py [OUT.obj]
"""

import math
import os
import sys

MAJOR, MINOR = 1.0, 0.35
RING, TUBE = 24, 12


def torus():
    vertices = []
    for i in range(RING):
        phi = 2.0 * math.pi * i / RING
        for j in range(TUBE):
            theta = 2.0 * math.pi * j / TUBE
            r = MAJOR + MINOR * math.cos(theta)
            vertices.append((r * math.cos(phi), MINOR * math.sin(theta), -r * math.sin(phi)))
    faces = []
    for i in range(RING):
        for j in range(TUBE):
            a = i * TUBE + j
            b = ((i + 1) % RING) * TUBE + j
            c = ((i + 1) % RING) * TUBE + (j + 1) % TUBE
            d = i * TUBE + (j + 1) % TUBE
            faces.append((a, b, c))
            faces.append((a, c, d))
    return vertices, faces


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "mesh", "torus.obj")
    vertices, faces = torus()
    lines = [f"# torus: major {MAJOR}, minor {MINOR}, {RING}x{TUBE} quads; scripts/make_mesh.py"]
    lines += [f"v {x:.6f} {y:.6f} {z:.6f}" for x, y, z in vertices]
    lines += [f"f {a + 1} {b + 1} {c + 1}" for a, b, c in faces]
    os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
    with open(out, "w", newline="\n") as f:
        f.write("\n".join(lines) + "\n")
    print(f"{out}: {len(vertices)} vertices, {len(faces)} triangles")


if __name__ == "__main__":
    main()
