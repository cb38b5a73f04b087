#!/usr/bin/env python3
"""Checks the translator's texture maps against ours, texel for texel:
renders Mitsuba's albedo and position AOVs of the textured sphere and the
textured wall of report_scene15_spheres (scalar_rgb, 1 spp, so each pixel is
one hit) and recomputes, from each hit position, the texel that ours looks up
(src/geometry/sphere.rs, src/geometry/plane.rs, src/texture/mod.rs).

    scripts/mitsuba_texture_check.py [--scene ../shared/scenes/report_scene15_spheres.txt]

Prints the fraction of hits whose albedo equals our texel (1.0 for the sphere,
~0.995 for the plane: hits within float error of a texel boundary differ)."""

import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import crosscheck as cc  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--scene", default="../shared/scenes/report_scene15_spheres.txt")
    args = parser.parse_args()
    import mitsuba as mi
    mi.set_variant("scalar_rgb")

    class Size:
        width, height = 160, 120

    scene = cc.Scene(args.scene)
    d = cc.mitsuba_scene_dict(mi, scene, Size, 1, "/tmp")
    d["integrator"] = {"type": "aov", "aovs": "a:albedo,p:position"}
    T = mi.ScalarTransform4f
    worst = 1.0
    for shape in scene.shapes:
        material = scene.materials[shape["material"]]
        if not material.get("texture") or shape["kind"] not in ("sphere", "plane"):
            continue
        pixels = cc.texture_pixels(mi, material["texture"])
        h, w = pixels.shape[:2]
        if shape["kind"] == "sphere":
            c, r = np.array(shape["center"], float), shape["radius"]
            origin, target = c + np.array([0, 0, 4 * r]), c
        else:
            n = np.array(shape["normal"], float)
            n /= np.linalg.norm(n)
            eye = np.array(scene.camera.get("center", [0, 0, 0]), float)
            offset = shape["offset"] / np.linalg.norm(shape["normal"])
            target = eye - n * (np.dot(n, eye) - offset)  # nearest the scene's camera
            origin = target - 30 * n
        up = [0, 1, 0] if abs(np.dot(target - origin, [0, 1, 0])) < 0.9 * np.linalg.norm(
            target - origin) else [1, 0, 0]
        d["sensor"]["to_world"] = T().look_at(origin=origin.tolist(), target=target.tolist(), up=up)
        d["sensor"]["near_clip"] = 1e-3
        image = np.array(mi.render(mi.load_dict(d), spp=1))
        albedo = image[..., 0:3].reshape(-1, 3)
        position = image[..., 3:6].reshape(-1, 3).astype(np.float64)
        if shape["kind"] == "sphere":
            v = position - c
            radius = np.linalg.norm(v, axis=1)
            selected = np.abs(radius - r) < 1e-3 * r
            v = v[selected] / radius[selected, None]
            u = 0.5 - np.arctan2(v[:, 2], v[:, 0]) / (2 * math.pi)
            vv = 0.5 + np.arcsin(np.clip(v[:, 1], -1, 1)) / math.pi
            i = np.clip(np.floor(u * w), 0, w - 1).astype(int)
            j = np.clip(np.floor((1 - vv) * h), 0, h - 1).astype(int)
        else:
            selected = np.abs(position @ n - offset) < 1e-2
            e1, e2 = cc.orthonormal_basis(n)
            x = cc.PLANE_TEXELS_PER_UNIT * position[selected] @ e1
            y = cc.PLANE_TEXELS_PER_UNIT * position[selected] @ e2
            i = np.mod(np.floor(x), w).astype(int)
            j = np.mod(np.floor(-y), h).astype(int)
        ours = pixels[j, i]
        match = float(np.mean(np.abs(ours - albedo[selected]).max(axis=1) < 1e-4))
        worst = min(worst, match)
        print(f"{shape['kind']:<7} {os.path.basename(material['texture'])}: "
              f"{int(selected.sum())} hits, {match:.4f} equal to our texel")
    return 0 if worst > 0.99 else 1


if __name__ == "__main__":
    sys.exit(main())
