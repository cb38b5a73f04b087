#!/usr/bin/env python3
"""Cross-check of pathtracer against Mitsuba 3 on a canonical-dialect scene.

    python3 scripts/crosscheck.py [--scene testcases/crosscheck.txt] [--spp 64]
        [--reference-spp 1024] [--width 256 --height 192] [--variant scalar_rgb]
        [--seed 1] [--out output/crosscheck] [--mitsuba-only] [--tolerance 0.03]
        [--match-filter]

Steps: (a) translate the scene into a Mitsuba scene dict (a small, tolerant
reader of the canonical grammar of docs/scene-format.md Part 1); (b) render
Mitsuba at --reference-spp (the reference) and at --spp, and ours at --spp,
same size, timing each; (c) compare with numpy: RMSE and relative MSE (the
definition of `pathtracer compare`, epsilon 1e-2) of ours and of Mitsuba at
--spp against the reference, and the per-channel ratio of mean radiance
(ours / reference), which is ~1 when the two estimators agree in expectation.
Prints a table and writes OUT/crosscheck.json (plus the PFM images and PNG
previews, never committed).

How the estimators are matched:
- path integrator, max_depth 6 (ours: emission at the camera hit and after each
  of at most 5 scattering vertices = 6 segments), rr_depth 100 (no roulette);
- perspective sensor, vertical fov 2*atan(0.5135/2) unless `angle`, near_clip =
  canvasDistance (Mitsuba starts rays on the near *plane*, checked at run time);
- BSDFs two-sided (ours shades with the normal facing the ray); diffuse ->
  diffuse, mirror -> conductor 'none', mixtures -> blendbsdf by the rates,
  glass -> dielectric (ours uses Schlick's Fresnel: glass differs slightly);
- film: box filter (ours: 2x2 sub-pixel tent), so edges differ slightly;
  --match-filter renders Mitsuba at twice the size with a tent of radius 1
  and samples beyond the border, and averages 2x2 blocks: the expectation
  of our filter in every pixel (--spp is then per pixel of our size);
- depth of field -> thinlens (focal plane at focusDistance along the view
  direction, uniform disk of radius interfereRatio, rays start at near_clip =
  canvasDistance, as ours);
- textures on spheres and planes: a nearest-texel, repeating, raw bitmap with
  our uv maps (sphere rotated so that Mitsuba's uv equals ours; plane rectangle
  in our orthonormal_basis frame with a to_uv giving 10 texels per unit),
  checked texel for texel against ours from Mitsuba's position AOV;
- approximations, each warned at run time: textures on other shapes (or all,
  with --flat-textures) become the flat mean texel; moving spheres (`motion`)
  are frozen at mid-shutter
  (Mitsuba 3 shapes have no motion blur); PA1 Lights are ignored (ours ignores
  them too when the scene has emitters);
- the Cambrian dialect (`PhongMaterial { type DIFF|SPEC|REFR ... refractive_rate }`,
  horizontal `angle`) is detected or forced with --dialect.
scripts/mitsuba_converge.py draws Mitsuba's error-against-time curve with this
translator, in the CSV format of `pathtracer converge`.
Keep emitters clear of other surfaces: Mitsuba ends shadow rays ~1e-3 of their
length short of the light, so smallpt's radius-600 light grazing the ceiling
leaks through it (Mitsuba +13% on the floor below it, ours matches the exact
value), and testcases/smallpt.txt differs by ~5% for that reason alone.

Exit status: 0 when every channel's mean ratio is within --tolerance of 1,
1 when not, 2 when our renderer could not be run (the Mitsuba side is still
rendered and reported).
"""

import argparse
import json
import math
import os
import shutil
import subprocess
import sys
import time

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RELATIVE_MSE_EPSILON = 1e-2  # as src/metrics/mod.rs
ORIGINAL_PLANE_SCALE = 0.5135  # the original's image-plane height at distance 1
PLANE_HALF_SIZE = 1e4
PLANE_TEXELS_PER_UNIT = 10.0  # as src/geometry/plane.rs
WARNINGS = []


def warn(message):
    WARNINGS.append(message)
    print(f"warning: {message}", file=sys.stderr)


# ----------------------------------------------------------------------------
# A tolerant reader of the canonical dialect
# ----------------------------------------------------------------------------

class Block:
    def __init__(self, name, items):
        self.name = name
        self.items = items  # words (str) and Blocks, in order


def tokenize(text):
    tokens = []
    for line in text.splitlines():
        for marker in ("#", "//"):
            cut = line.find(marker)
            if cut >= 0:
                line = line[:cut]
        for word in line.split():
            # `{ } [ ]` are tokens even when glued to a word.
            current = ""
            for ch in word:
                if ch in "{}[]":
                    if current:
                        tokens.append(current)
                        current = ""
                    tokens.append(ch)
                else:
                    current += ch
            if current:
                tokens.append(current)
    return tokens


def parse_blocks(tokens):
    """Nests `word { ... }` into Blocks; other tokens stay words."""
    position = 0

    def items_until_close():
        nonlocal position
        items = []
        while position < len(tokens):
            token = tokens[position]
            if token == "}":
                position += 1
                return items
            if position + 1 < len(tokens) and tokens[position + 1] == "{":
                position += 2
                items.append(Block(token, items_until_close()))
            elif token == "{":  # anonymous block: keep its contents
                position += 1
                items.append(Block("", items_until_close()))
            else:
                items.append(token)
                position += 1
        return items

    return items_until_close()


class Cursor:
    def __init__(self, items, where):
        self.items = items
        self.i = 0
        self.where = where

    def next(self):
        if self.i >= len(self.items):
            return None
        item = self.items[self.i]
        self.i += 1
        return item

    def numbers(self, n, key):
        values = []
        for _ in range(n):
            item = self.next()
            try:
                values.append(float(item))
            except (TypeError, ValueError):
                raise SystemExit(f"{self.where}: '{key}' expects {n} numbers, got {item!r}")
        return values

    def word(self, key):
        item = self.next()
        if not isinstance(item, str):
            raise SystemExit(f"{self.where}: '{key}' expects a word")
        return item

    def skip_numbers(self):
        while self.i < len(self.items) and isinstance(self.items[self.i], str):
            try:
                float(self.items[self.i])
            except ValueError:
                return
            self.i += 1


def read_fields(block, shapes):
    """Keyed fields of a block: {key: [numbers] or word}; unknown keys warned."""
    fields = {}
    cursor = Cursor(block.items, block.name)
    while (item := cursor.next()) is not None:
        if isinstance(item, Block):
            fields.setdefault("_blocks", []).append(item)
            continue
        if item in shapes:
            shape = shapes[item]
            if shape == "word":
                fields[item] = cursor.word(item)
            elif shape == 0:
                fields[item] = True
            else:
                fields[item] = cursor.numbers(shape, item)
        else:
            warn(f"{block.name}: unknown field '{item}' skipped")
            cursor.skip_numbers()
    return fields


CAMERA_FIELDS = {"center": 3, "direction": 3, "up": 3, "width": 1, "height": 1, "angle": 1,
                 "canvasDistance": 1, "focusDistance": 1, "interfereRatio": 1,
                 # Cambrian's flag that turns materials' `cauchy` on (see
                 # scripts/crosscheck_dispersion.py; here: one index)
                 "dispersion": 0}
MATERIAL_FIELDS = {"color": 3, "diffuseColor": 3, "emission": 3, "diffusionRate": 1,
                   "specularRate": 1, "refractRate": 1, "refractiveIndex": 1, "texture": "word",
                   "specularColor": 3, "shininess": 1, "roughness": 1,
                   # Cambrian (cam) dialect: `type DIFF|SPEC|REFR`, IOR `refractive_rate`
                   "type": "word", "refractive_rate": 1, "texture_file": "word",
                   # participating media (docs/guide/dispersion-and-media.md)
                   "interface": 0,
                   # dispersion (docs/guide/dispersion-and-media.md): Mitsuba's dielectric takes
                   # one index, `ior` (crosscheck_dispersion.py sets it per render)
                   "cauchy": 2}
MEDIUM_FIELDS = {"sigmaA": 3, "sigma_a": 3, "sigmaS": 3, "sigma_s": 3, "g": 1}


def read_medium(block):
    """A `Medium { sigmaA sigmaS g }` block as {sigma_a, sigma_s, g}."""
    f = read_fields(block, MEDIUM_FIELDS)
    return {"sigma_a": f.get("sigmaA", f.get("sigma_a", [0.0, 0.0, 0.0])),
            "sigma_s": f.get("sigmaS", f.get("sigma_s", [0.0, 0.0, 0.0])),
            "g": f.get("g", [0.0])[0]}


def mitsuba_medium(medium):
    """Mitsuba's homogeneous medium: sigma_t and albedo per channel, HG phase."""
    sigma_t = [a + s for a, s in zip(medium["sigma_a"], medium["sigma_s"])]
    albedo = [s / t if t > 0 else 0.0 for s, t in zip(medium["sigma_s"], sigma_t)]
    return {"type": "homogeneous", "sigma_t": rgb(sigma_t), "albedo": rgb(albedo),
            "scale": 1.0, "phase": {"type": "hg", "g": float(medium["g"])}}
CAMBRIAN_TYPES = {"DIFF": (1.0, 0.0, 0.0), "SPEC": (0.0, 1.0, 0.0), "REFR": (0.0, 0.0, 1.0)}
MIN_ROUGHNESS = 1e-3  # as src/bsdf/microfacet.rs: below it, mirror and smooth glass


def resolve_path(relative, scene_path):
    """As the renderer: scene's parent's parent, the scene's folder, the cwd."""
    if os.path.isabs(relative):
        return relative
    scene_dir = os.path.dirname(os.path.abspath(scene_path))
    for base in (os.path.dirname(scene_dir), scene_dir, os.getcwd()):
        candidate = os.path.join(base, relative)
        if os.path.exists(candidate):
            return candidate
    raise SystemExit(f"{scene_path}: file '{relative}' not found")


def translate(m):
    t = np.eye(4)
    t[:3, 3] = m
    return t


def scale(s):
    return np.diag([s[0], s[1], s[2], 1.0])


def rotation(axis, degrees):
    axis = np.asarray(axis, float) / np.linalg.norm(axis)
    x, y, z = axis
    a = math.radians(degrees)
    c, s = math.cos(a), math.sin(a)
    r = np.eye(4)
    r[:3, :3] = [[c + x * x * (1 - c), x * y * (1 - c) - z * s, x * z * (1 - c) + y * s],
                 [y * x * (1 - c) + z * s, c + y * y * (1 - c), y * z * (1 - c) - x * s],
                 [z * x * (1 - c) - y * s, z * y * (1 - c) + x * s, c + z * z * (1 - c)]]
    return r


def frame_matrix(normal):
    """Rotation taking +z to `normal` (right-handed frame s, t, n)."""
    n = np.asarray(normal, float)
    n = n / np.linalg.norm(n)
    helper = np.array([1.0, 0.0, 0.0]) if abs(n[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    s = np.cross(helper, n)
    s /= np.linalg.norm(s)
    t = np.cross(n, s)
    r = np.eye(4)
    r[:3, 0], r[:3, 1], r[:3, 2] = s, t, n
    return r


class Scene:
    """The parts of a canonical scene that the cross-check needs.

    Also reads the Cambrian (cam) dialect of docs/scene-format.md Part 2:
    `PhongMaterial { type DIFF|SPEC|REFR color emission refractive_rate }`,
    Sphere `motion`, and `angle` as a HORIZONTAL field of view. The dialect is
    detected from a word-valued material `type` or a `refractive_rate`."""

    def __init__(self, path, dialect="auto"):
        self.path = path
        self.dialect = dialect
        with open(path, encoding="utf-8", errors="replace") as f:
            top = parse_blocks(tokenize(f.read()))
        self.camera = None
        self.background = [0.0, 0.0, 0.0]
        self.materials = []
        self.shapes = []  # dicts: kind, material, matrix, + shape fields
        self.current_material = 0
        self.cambrian_seen = False
        self.has_lights = False
        self.medium = None
        for item in top:
            if not isinstance(item, Block):
                warn(f"stray top-level word '{item}' skipped")
                continue
            if item.name == "PerspectiveCamera":
                self.camera = read_fields(item, CAMERA_FIELDS)
            elif item.name == "Background":
                self.background = read_fields(item, {"color": 3, "ambientLight": 3}).get(
                    "color", [0.0, 0.0, 0.0])
            elif item.name == "Materials":
                self.read_materials(item)
            elif item.name == "Group":
                self.read_group(item, np.eye(4))
            elif item.name == "Lights":
                self.has_lights = True
            elif item.name == "Medium":
                self.medium = read_medium(item)
            else:
                warn(f"top-level block '{item.name}' skipped")
        if self.camera is None:
            raise SystemExit(f"{path}: no PerspectiveCamera")
        if self.dialect == "auto":
            self.dialect = "cambrian" if self.cambrian_seen else "canonical"
        if self.has_lights:
            if any(max(m["emission"]) > 0 for m in self.materials):
                warn("Lights ignored (as ours does: a scene with emissive materials is lit "
                     "by its emitters alone)")
            else:
                warn("Lights (PA1 point/directional lights) are not translated")

    def read_materials(self, block):
        for item in block.items:
            if not isinstance(item, Block):
                continue  # numMaterials n
            if item.name not in ("Material", "PhongMaterial"):
                warn(f"material kind '{item.name}' read as Material")
            f = read_fields(item, MATERIAL_FIELDS)
            color = f.get("color", f.get("diffuseColor", [1.0, 1.0, 1.0]))
            specular = f.get("specularRate", [0.0])[0]
            refract = f.get("refractRate", [0.0])[0]
            diffuse = f.get("diffusionRate", [1.0 - specular - refract])[0]
            ior = f.get("refractiveIndex", [1.5])[0]
            if "type" in f or "refractive_rate" in f:  # Cambrian material
                self.cambrian_seen = True
                kind = f.get("type", "DIFF")
                if kind not in CAMBRIAN_TYPES:
                    warn(f"material type '{kind}' not DIFF/SPEC/REFR: read as DIFF")
                    kind = "DIFF"
                diffuse, specular, refract = CAMBRIAN_TYPES[kind]
                ior = f.get("refractive_rate", [ior])[0]
            if abs(diffuse + specular + refract - 1.0) > 1e-6:
                raise SystemExit(f"{self.path}: material rates do not sum to 1")
            texture = f.get("texture", f.get("texture_file"))
            if texture is not None:
                try:
                    texture = resolve_path(texture, self.path)
                except SystemExit as error:
                    warn(f"{error}: texture ignored")
                    texture = None
            if "specularColor" in f and max(f["specularColor"]) > 0:
                warn("specularColor/shininess (our Phong lobe) are not translated")
            interior = None
            for nested in f.get("_blocks", []):
                if nested.name == "Medium":
                    interior = read_medium(nested)
                else:
                    warn(f"block '{nested.name}' in a material skipped")
            self.materials.append({
                "interior": interior, "interface": f.get("interface", False),
                "color": color, "emission": f.get("emission", [0.0, 0.0, 0.0]),
                "diffuse": diffuse, "specular": specular, "refract": refract,
                "ior": ior, "texture": texture, "cauchy": f.get("cauchy"),
                "roughness": f.get("roughness", [0.0])[0]})

    def add(self, kind, matrix, **fields):
        if not 0 <= self.current_material < len(self.materials):
            raise SystemExit(f"{self.path}: MaterialIndex {self.current_material} out of range")
        self.shapes.append(dict(kind=kind, material=self.current_material, matrix=matrix, **fields))

    def read_group(self, block, matrix):
        cursor = Cursor(block.items, block.name)
        while (item := cursor.next()) is not None:
            if isinstance(item, Block):
                self.read_object(item, matrix)
            elif item in ("MaterialIndex", "materialIndex"):
                self.current_material = int(cursor.numbers(1, item)[0])
            elif item == "numObjects":
                cursor.numbers(1, item)
            else:
                warn(f"Group: unknown word '{item}' skipped")

    def read_object(self, block, matrix):
        name = block.name
        if name == "Group":
            self.read_group(block, matrix)
        elif name == "Sphere":
            f = read_fields(block, {"center": 3, "radius": 1, "motion": 3})
            center = np.array(f.get("center", [0, 0, 0]), float)
            motion = np.array(f.get("motion", [0, 0, 0]), float)
            if np.any(motion != 0):
                # Mitsuba 3 shapes have no motion blur (ray time is ignored by
                # shapes): the sphere is frozen at mid-shutter, center + motion/2.
                warn(f"Sphere motion {motion.tolist()}: no motion blur in Mitsuba 3, sphere "
                     f"frozen at its mid-shutter position {(center + motion / 2).tolist()}")
                center = center + motion / 2
            self.add("sphere", matrix, center=center.tolist(),
                     radius=f.get("radius", [1.0])[0])
        elif name == "Plane":
            f = read_fields(block, {"normal": 3, "offset": 1, "d": 1})
            self.add("plane", matrix, normal=f.get("normal", [0, 1, 0]),
                     offset=f.get("offset", f.get("d", [0.0]))[0])
        elif name == "Triangle":
            f = read_fields(block, {"vertex0": 3, "vertex1": 3, "vertex2": 3})
            self.add("triangle", matrix, vertices=[f["vertex0"], f["vertex1"], f["vertex2"]])
        elif name in ("TriangleMesh", "Mesh"):
            f = read_fields(block, {"obj_file": "word", "smooth": 0, "normalInterpolation": 0,
                                    "disableDiffuseTexture": 0, "disableNormalTexture": 0})
            self.add("mesh", matrix, file=resolve_path(f["obj_file"], self.path),
                     smooth=bool(f.get("smooth") or f.get("normalInterpolation")))
        elif name == "Transform":
            self.read_transform(block, matrix)
        else:
            warn(f"object '{name}' is not translated to Mitsuba, skipped")

    def read_transform(self, block, parent):
        local = np.eye(4)
        children = []
        cursor = Cursor(block.items, block.name)
        while (item := cursor.next()) is not None:
            if isinstance(item, Block):
                if item.name == "Rotate":
                    c = Cursor(item.items, "Rotate")
                    values = c.numbers(4, "Rotate")
                    local = local @ rotation(values[:3], values[3])
                elif item.name in ("Matrix4f", "Matrix4d"):
                    values = Cursor(item.items, item.name).numbers(16, item.name)
                    # as the renderer: column-major, and M = Op * M
                    local = np.array(values).reshape(4, 4).T @ local
                else:
                    children.append(item)
            elif item == "Translate":
                local = local @ translate(cursor.numbers(3, item))
            elif item == "Scale":
                local = local @ scale(cursor.numbers(3, item))
            elif item == "UniformScale":
                s = cursor.numbers(1, item)[0]
                local = local @ scale([s, s, s])
            elif item in ("XRotate", "YRotate", "ZRotate"):
                axis = {"X": [1, 0, 0], "Y": [0, 1, 0], "Z": [0, 0, 1]}[item[0]]
                local = local @ rotation(axis, cursor.numbers(1, item)[0])
            elif item in ("MaterialIndex", "materialIndex"):
                self.current_material = int(cursor.numbers(1, item)[0])
            else:
                warn(f"Transform: unknown word '{item}' skipped")
        for child in children:
            self.read_object(child, parent @ local)


# ----------------------------------------------------------------------------
# Mitsuba scene dict
# ----------------------------------------------------------------------------

def rgb(value):
    return {"type": "rgb", "value": [float(v) for v in value]}


def mitsuba_bsdf(material, texture=None):
    """`texture`: a Mitsuba texture dict replacing the colour (ours: a textured
    material's object colour is the texel, for every lobe)."""
    color = material["color"]
    spec = texture if texture is not None else rgb(color)
    lobes = []
    if material["diffuse"] > 0:
        lobes.append((material["diffuse"], {"type": "diffuse", "reflectance": spec}))
    # GGX of the same alpha, sampled by visible normals, Smith's separable
    # masking: our rough conductor and rough dielectric (src/bsdf).
    alpha = float(material.get("roughness", 0.0))
    rough = {"distribution": "ggx", "alpha": alpha, "sample_visible": True}
    if material["specular"] > 0:
        conductor = {"type": "conductor", "material": "none", "specular_reflectance": spec}
        if alpha >= MIN_ROUGHNESS:
            conductor = dict(conductor, type="roughconductor", **rough)
        lobes.append((material["specular"], conductor))
    if material["refract"] > 0:
        dielectric = {"type": "dielectric", "int_ior": float(material["ior"]), "ext_ior": 1.0,
                      "specular_reflectance": spec, "specular_transmittance": spec}
        if alpha >= MIN_ROUGHNESS:
            dielectric = dict(dielectric, type="roughdielectric", **rough)
        lobes.append((material["refract"], dielectric))
    if (texture is None and max(color) <= 0) or not lobes:  # ours stops on a black colour
        return {"type": "diffuse", "reflectance": rgb([0, 0, 0])}
    weight, bsdf = lobes[0]
    for w, other in lobes[1:]:
        total = weight + w
        bsdf = {"type": "blendbsdf", "weight": w / total, "a": bsdf, "b": other}
        weight = total
    if material["refract"] > 0:
        if len(lobes) > 1:
            warn("glass mixed with other lobes: not two-sided in Mitsuba")
        return bsdf  # dielectric is two-sided by nature; twosided refuses it
    return {"type": "twosided", "bsdf": bsdf}


def texture_pixels(mi, path):
    """An image as ours reads it: (H, W, 3) float, top row first, bytes / 255,
    no gamma."""
    pixels = bmp_pixels(path) if path.lower().endswith(".bmp") else None
    if pixels is None:
        bitmap = mi.Bitmap(path)
        pixels = np.array(bitmap, dtype=np.float64)
        if pixels.ndim == 2:
            pixels = pixels[..., None]
        if bitmap.component_format() == mi.Struct.Type.UInt8:
            pixels = pixels / 255.0
        elif bitmap.component_format() == mi.Struct.Type.UInt16:
            pixels = pixels / 65535.0
        if pixels.shape[2] < 3:
            pixels = np.repeat(pixels[..., :1], 3, axis=2)
    return np.ascontiguousarray(pixels[..., :3], dtype=np.float32)


def texture_mean(mi, path):
    """Mean texel of an image as ours reads it."""
    mean = texture_pixels(mi, path).reshape(-1, 3).astype(np.float64).mean(axis=0)
    return [float(v) for v in mean]


def bitmap_texture(mi, pixels, to_uv=None):
    """Nearest-texel, repeating, raw (no gamma) bitmap. Mitsuba reads data row
    floor(v * H) and column floor(u * W) (row 0 at v = 0), checked in a test."""
    texture = {"type": "bitmap", "bitmap": mi.Bitmap(pixels), "filter_type": "nearest",
               "wrap_mode": "repeat", "raw": True}
    if to_uv is not None:
        texture["to_uv"] = mi.ScalarTransform4f(to_uv.tolist())
    return texture


def orthonormal_basis(n):
    """As src/math.rs (Duff et al. 2017): the frame of our plane textures."""
    sign = math.copysign(1.0, n[2])
    a = -1.0 / (sign + n[2])
    b = n[0] * n[1] * a
    return (np.array([1.0 + sign * n[0] * n[0] * a, sign * b, -sign * n[0]]),
            np.array([b, sign + n[1] * n[1] * a, -n[1]]))


# Our sphere uv: u = 0.5 - atan2(w.z, w.x)/(2 pi), texel row (from the top)
# floor(acos(w.y)/pi * H). Mitsuba's sphere: u = atan2(l.y, l.x)/(2 pi) mod 1,
# v = acos(l.z)/pi. With local l = (-w.x, w.z, w.y) the two agree; this is the
# rotation taking l to w.
SPHERE_UV_ROTATION = np.array([[-1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0],
                               [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0]])


def bmp_pixels(path):
    """An uncompressed 24/32-bit BMP as (H, W, 3) in [0, 1], top row first
    (Mitsuba's reader refuses BITMAPV5 headers); None for other kinds."""
    import struct
    with open(path, "rb") as f:
        data = f.read()
    offset = struct.unpack("<I", data[10:14])[0]
    width, height, _, bits, compression = struct.unpack("<iiHHI", data[18:34])
    if bits not in (24, 32) or compression not in (0, 3):
        return None
    channels = bits // 8
    stride = (width * channels + 3) // 4 * 4
    rows = np.frombuffer(data, np.uint8, count=stride * abs(height), offset=offset)
    pixels = rows.reshape(abs(height), stride)[:, :width * channels].reshape(
        abs(height), width, channels)
    if height > 0:  # stored bottom-up
        pixels = pixels[::-1]
    return pixels[..., 2::-1].astype(np.float64) / 255.0


def camera_frame(camera):
    center = np.array(camera.get("center", [0, 0, 0]), float)
    direction = np.array(camera.get("direction", [0, 0, -1]), float)
    direction /= np.linalg.norm(direction)
    up = np.array(camera.get("up", [0, 1, 0]), float)
    return center, direction, up


def mitsuba_scene_dict(mi, scene, args, spp, tmpdir):
    camera = scene.camera
    center, direction, up = camera_frame(camera)
    fov_axis = "y"
    if "angle" in camera:
        fov = camera["angle"][0]
        if scene.dialect == "cambrian":
            fov_axis = "x"  # the Cambrian dialect's angle is horizontal
    else:
        fov = math.degrees(2.0 * math.atan(ORIGINAL_PLANE_SCALE / 2.0))
    canvas = camera.get("canvasDistance", [0.0])[0]
    lens_radius = camera.get("interfereRatio", [0.0])[0]
    sensor_type = "perspective"
    lens = {}
    if lens_radius >= 1e-4:
        # Ours: focus point F = center + d * focusDistance with d . direction = 1,
        # i.e. a focal PLANE at focusDistance along the view direction; the lens
        # is sampled uniformly on a disk of radius interfereRatio (concentric
        # map); rays start on the plane at canvasDistance from the lens plane.
        # Mitsuba's thinlens: focal plane at camera-space z = focus_distance,
        # uniform (concentric) disk of aperture_radius, ray starts at z = near_clip.
        if "focusDistance" not in camera:
            warn("depth of field without focusDistance: focus_distance 1 assumed")
        sensor_type = "thinlens"
        lens = {"aperture_radius": float(lens_radius),
                "focus_distance": float(camera.get("focusDistance", [1.0])[0])}
    if any(c > 0 for c in scene.background):
        warn("non-black Background: ours shows it to camera rays only; Mitsuba gets black")
    T = mi.ScalarTransform4f
    media = scene.medium is not None or any(m["interior"] for m in scene.materials)
    max_depth = getattr(args, "max_depth", None)
    film = {"type": "hdrfilm", "width": args.width, "height": args.height,
            "rfilter": {"type": "box"}, "pixel_format": "rgb", "component_format": "float32"}
    if getattr(args, "match_filter", False):
        # Ours: each pixel's samples go to its 2x2 sub-pixels, each spread by
        # a tent of half-width one sub-pixel. Mitsuba at twice the size with
        # a tent of radius 1 (its pixels) and samples beyond the border has
        # that expectation in each of its pixels; downsample() averages them.
        film = dict(film, width=2 * args.width, height=2 * args.height,
                    rfilter={"type": "tent", "radius": 1.0}, sample_border=True)
    d = {
        "type": "scene",
        "integrator": {"type": "volpath" if media else "path",
                       "max_depth": (max_depth or 5) + 1, "rr_depth": 100,
                       "hide_emitters": False},
        "sensor": {
            "type": sensor_type,
            "to_world": T().look_at(origin=center.tolist(), target=(center + direction).tolist(),
                                    up=up.tolist()),
            "fov": float(fov),
            "fov_axis": fov_axis,
            **lens,
            "near_clip": float(canvas) if canvas > 1e-4 else 1e-4,
            "far_clip": 1e7,
            "film": film,
            "sampler": {"type": "independent", "sample_count": spp},
        },
    }
    if any(m["refract"] > 0 for m in scene.materials) and getattr(args, "look", "") != "physical":
        warn("glass: Mitsuba's dielectric uses the exact Fresnel equations, ours Schlick's "
             "approximation in the original look (use --look physical): glass differs")
    planes = [(np.array(s["normal"], float), s["offset"]) for s in scene.shapes
              if s["kind"] == "plane" and np.allclose(s["matrix"], np.eye(4))]
    for s in scene.shapes:
        if (s["kind"] == "sphere" and max(scene.materials[s["material"]]["emission"]) > 0
                and np.allclose(s["matrix"], np.eye(4))):
            for n, offset in planes:
                gap = abs(np.dot(n, s["center"]) - offset) / np.linalg.norm(n) - s["radius"]
                if abs(gap) < 0.1 * s["radius"]:  # a cap through (or grazing) the plane
                    warn(f"emissive sphere at {list(s['center'])} r {s['radius']} "
                         f"{'crosses' if gap < 0 else 'grazes'} plane n={n.tolist()} "
                         f"d={offset} (gap {gap:.3g}): Mitsuba's shadow-ray epsilon leaks "
                         "its light past the plane (brighter than ours nearby)")
    if scene.medium is not None:
        d["sensor"]["medium"] = mitsuba_medium(scene.medium)
    images = {}
    for index, shape in enumerate(scene.shapes):
        material = scene.materials[shape["material"]]
        matrix = shape["matrix"]
        kind = shape["kind"]
        texture = None
        pixels = None
        uv_rotation = np.eye(4)
        if material.get("texture"):
            path = material["texture"]
            if path not in images:
                images[path] = texture_pixels(mi, path)
            pixels = images[path]
            if getattr(args, "flat_textures", False) or kind not in ("sphere", "plane"):
                mean = pixels.reshape(-1, 3).astype(np.float64).mean(axis=0)
                # ours: the texel replaces the colour
                material = dict(material, color=[float(v) for v in mean], texture=None)
                warn(f"texture {os.path.relpath(path)} on a {kind}: not mapped, Mitsuba gets "
                     f"the flat mean texel {[round(v, 4) for v in mean]}")
            elif kind == "sphere":
                texture = bitmap_texture(mi, pixels)
                uv_rotation = SPHERE_UV_ROTATION
        if kind == "sphere":
            linear = matrix[:3, :3]
            singular = np.linalg.svd(linear, compute_uv=False)
            if singular.max() - singular.min() > 1e-6 * singular.max():
                warn("sphere under a non-uniform scale: Mitsuba's sphere cannot follow it")
            if np.allclose(matrix, np.eye(4)) and texture is None:
                entry = {"type": "sphere", "center": [float(v) for v in shape["center"]],
                         "radius": float(shape["radius"])}
            else:
                r = shape["radius"]
                entry = {"type": "sphere", "to_world": T(
                    (matrix @ translate(shape["center"]) @ uv_rotation
                     @ scale([r, r, r])).tolist())}
        elif kind == "plane":
            n = np.array(shape["normal"], float)
            length = np.linalg.norm(n)
            # centre the rectangle on the point of the plane nearest the camera
            unit = n / length
            point = center - unit * (np.dot(unit, center) - shape["offset"] / length)
            local = translate(point) @ frame_matrix(n) @ scale(
                [PLANE_HALF_SIZE, PLANE_HALF_SIZE, 1.0])
            if material.get("texture"):
                # Ours: texel column floor(x) mod W, row (from the top) floor(-y) mod H,
                # x = 10 p.e1, y = 10 p.e2 (e1, e2 from orthonormal_basis(n)). The
                # rectangle spans point + S (lx e1 + ly e2), lx = 2u - 1, ly = 2v - 1
                # (Mitsuba's uv), so Mitsuba's (s, t) = (x / W, -y / H) is affine in uv.
                e1, e2 = orthonormal_basis(unit)
                rotation = np.eye(4)
                rotation[:3, 0], rotation[:3, 1], rotation[:3, 2] = e1, e2, unit
                half = PLANE_HALF_SIZE
                local = translate(point) @ rotation @ scale([half, half, 1.0])
                h, w = pixels.shape[:2]
                tiling = PLANE_TEXELS_PER_UNIT
                to_uv = np.eye(4)
                to_uv[0, 0] = 2 * half * tiling / w
                to_uv[0, 3] = math.fmod(tiling * (np.dot(point, e1) - half) / w, 1.0)
                to_uv[1, 1] = -2 * half * tiling / h
                to_uv[1, 3] = math.fmod(-tiling * (np.dot(point, e2) - half) / h, 1.0)
                texture = bitmap_texture(mi, pixels, to_uv)
            entry = {"type": "rectangle", "to_world": T((matrix @ local).tolist())}
            if max(material["emission"]) > 0:
                warn("emissive Plane: Mitsuba's area emitter is one-sided (along the normal), "
                     "ours emits on both sides")
        elif kind == "triangle":
            obj = os.path.join(tmpdir, f"triangle_{index}.obj")
            with open(obj, "w") as f:
                for v in shape["vertices"]:
                    f.write(f"v {v[0]!r} {v[1]!r} {v[2]!r}\n")
                f.write("f 1 2 3\n")
            entry = {"type": "obj", "filename": obj, "face_normals": True,
                     "to_world": T(matrix.tolist())}
        elif kind == "mesh":
            entry = {"type": "obj", "filename": shape["file"], "face_normals": not shape["smooth"],
                     "to_world": T(matrix.tolist())}
        else:
            continue
        entry["bsdf"] = ({"type": "null"} if material.get("interface")
                         else mitsuba_bsdf(material, texture))
        if material.get("interior"):
            entry["interior"] = mitsuba_medium(material["interior"])
        elif scene.medium is not None:
            # ours: crossing a surface without a Medium of its own keeps the
            # ray's medium (the scene's inside a glass ball in fog), and so
            # does reflection; Mitsuba's volpath takes the medium on the side
            # a ray leaves to (after reflection too: a plane whose normal
            # points out of the box would send reflected rays into vacuum)
            entry["interior"] = mitsuba_medium(scene.medium)
        if scene.medium is not None:
            entry["exterior"] = mitsuba_medium(scene.medium)
        if max(material["emission"]) > 0:
            entry["emitter"] = {"type": "area", "radiance": rgb(material["emission"])}
        d[f"shape_{index:03d}_{kind}"] = entry
    return d


def check_near_plane(mi):
    """Mitsuba must start camera rays on the near *plane* (d . forward = near),
    as ours does on its canvas. An emitter 1% in front of the near plane must be
    invisible everywhere (a spherical near clip would show it in the corners),
    and one 1% behind it visible everywhere."""
    T = mi.ScalarTransform4f
    seen = []
    for depth in (9.9, 10.1):
        scene = mi.load_dict({
            "type": "scene", "integrator": {"type": "path", "max_depth": 2},
            "sensor": {"type": "perspective", "fov": 60, "fov_axis": "y", "near_clip": 10.0,
                       "to_world": T().look_at(origin=[0, 0, 0], target=[0, 0, -1], up=[0, 1, 0]),
                       "film": {"type": "hdrfilm", "width": 32, "height": 24,
                                "rfilter": {"type": "box"}},
                       "sampler": {"type": "independent", "sample_count": 1}},
            "wall": {"type": "rectangle", "to_world": T().translate([0, 0, -depth]).scale(100),
                     "emitter": {"type": "area", "radiance": rgb([1, 1, 1])}},
        })
        seen.append(np.array(mi.render(scene)))
    planar = bool(np.all(seen[0] == 0) and np.allclose(seen[1], 1.0))
    return {"planar_near_clip": planar,
            "visible_fraction_before": float(np.mean(seen[0][..., 0] > 0)),
            "visible_fraction_behind": float(np.mean(seen[1][..., 0] > 0))}


# ----------------------------------------------------------------------------
# Images and metrics
# ----------------------------------------------------------------------------

def read_pfm(path):
    """A colour PFM as an (H, W, 3) float array, top row first."""
    with open(path, "rb") as f:
        data = f.read()
    header = []
    position = 0
    while len(header) < 4:
        while data[position:position + 1].isspace():
            position += 1
        start = position
        while not data[position:position + 1].isspace():
            position += 1
        header.append(data[start:position].decode("ascii"))
    position += 1  # the single whitespace after the scale
    kind, width, height, scale_factor = header[0], int(header[1]), int(header[2]), float(header[3])
    channels = {"PF": 3, "Pf": 1}[kind]
    dtype = "<f4" if scale_factor < 0 else ">f4"
    pixels = np.frombuffer(data, dtype=dtype, count=width * height * channels, offset=position)
    image = pixels.reshape(height, width, channels).astype(np.float32)
    if channels == 1:
        image = np.repeat(image, 3, axis=2)
    return image[::-1]  # PFM rows run bottom to top


def write_pfm(path, image):
    image = np.ascontiguousarray(np.asarray(image, dtype="<f4")[::-1])
    with open(path, "wb") as f:
        f.write(f"PF\n{image.shape[1]} {image.shape[0]}\n-1.0\n".encode("ascii"))
        f.write(image.tobytes())


def metrics(test, reference):
    diff2 = (test.astype(np.float64) - reference) ** 2
    rel = diff2 / (reference.astype(np.float64) ** 2 + RELATIVE_MSE_EPSILON)
    means_test = test.reshape(-1, 3).mean(axis=0).astype(np.float64)
    means_ref = reference.reshape(-1, 3).mean(axis=0).astype(np.float64)
    ratio = means_test / means_ref
    # standard error of the ratio from the pixel errors (pixels independent)
    pixels = test.shape[0] * test.shape[1]
    error_se = np.sqrt(diff2.reshape(-1, 3).mean(axis=0) / pixels) / means_ref
    # ratio on a 4x4 grid of tiles (Rec. 709 luminance): geometry mismatches show up here
    lum = np.array([0.2126, 0.7152, 0.0722])
    lt, lr = test @ lum, reference @ lum
    h, w = lt.shape
    tiles = [lt[i * h // 4:(i + 1) * h // 4, j * w // 4:(j + 1) * w // 4].mean()
             / max(lr[i * h // 4:(i + 1) * h // 4, j * w // 4:(j + 1) * w // 4].mean(), 1e-12)
             for i in range(4) for j in range(4)]
    return {
        "rmse": float(np.sqrt(diff2.mean())),
        "rel_mse": float(rel.mean()),
        "mean_ratio_rgb": [float(v) for v in ratio],
        "mean_ratio_standard_error_rgb": [float(v) for v in error_se],
        "tile_ratio_min": float(min(tiles)),
        "tile_ratio_max": float(max(tiles)),
        "mean_rgb": [float(v) for v in means_test],
        "nonfinite_pixels": int((~np.isfinite(test)).any(axis=2).sum()),
    }


def downsample(image):
    """The mean of each 2x2 block: a --match-filter render at our size."""
    h, w = image.shape[0] // 2, image.shape[1] // 2
    blocks = image[:2 * h, :2 * w].astype(np.float64).reshape(h, 2, w, 2, -1)
    return blocks.mean(axis=(1, 3)).astype(np.float32)


def render_mitsuba(mi, scene_dict, spp, seed, pass_spp):
    """Renders in passes of at most pass_spp samples (the JIT variants keep one
    lane per sample in memory) and averages them: with a box filter every pass
    is a plain mean, so the average of equal passes is the mean of all samples.
    `spp` counts samples per pixel of our size: a --match-filter render (twice
    the size) takes a quarter of them in each of its pixels."""
    matched = scene_dict["sensor"]["film"]["rfilter"]["type"] == "tent"
    if matched:
        spp, pass_spp = -(-spp // 4), max(1, pass_spp // 4)
    passes = [pass_spp] * (spp // pass_spp) + ([spp % pass_spp] if spp % pass_spp else [])
    t0 = time.perf_counter()
    loaded = mi.load_dict(scene_dict)
    t1 = time.perf_counter()
    total = None
    for index, n in enumerate(passes):
        image = np.array(mi.render(loaded, spp=n, seed=seed * 7919 + index), dtype=np.float64)
        total = image * n if total is None else total + image * n
    t2 = time.perf_counter()
    image = (total / spp)[..., :3].astype(np.float32)
    if matched:
        image = downsample(image)
    return image, t1 - t0, t2 - t1


def render_ours(args, out_path):
    binary = os.path.join(ROOT, "target", "release", "pathtracer")
    if not os.path.exists(binary):
        print("building target/release/pathtracer (cargo build --release) ...", flush=True)
        subprocess.run(["cargo", "build", "--release"], cwd=ROOT, check=True)
    command = [binary, "render", args.scene, "-o", out_path, "--spp", str(args.spp),
               "--seed", str(args.seed), "--width", str(args.width), "--height",
               str(args.height), "--look", args.look, "--quiet"]
    if args.max_depth is not None:
        command += ["--max-depth", str(args.max_depth)]
    t0 = time.perf_counter()
    result = subprocess.run(command, capture_output=True, text=True)
    elapsed = time.perf_counter() - t0
    if result.returncode != 0:
        raise RuntimeError(f"{' '.join(command)} failed ({result.returncode}):\n"
                           f"{result.stderr.strip()[-2000:]}")
    return read_pfm(out_path), elapsed, command


def preview(mi, path, image):
    try:
        mi.util.write_bitmap(path, mi.TensorXf(np.ascontiguousarray(image, dtype=np.float32)))
    except Exception as error:  # previews are a convenience only
        warn(f"preview {path} not written: {error}")


# ----------------------------------------------------------------------------


def check_tolerance(report, mean_ratios, tolerance):
    """Records in `report` and prints whether every mean ratio is within
    `tolerance` of 1; returns whether it is."""
    off = max(abs(r - 1.0) for r in mean_ratios)
    report["within_tolerance"] = off <= tolerance
    if off > tolerance:
        print(f"MISMATCH: mean ratio off by {off:.4f} > tolerance {tolerance}")
    else:
        print(f"agreement: mean ratio within {off:.4f} of 1 (tolerance {tolerance})")
    return off <= tolerance


def write_report(out, report):
    """Writes `report` to OUT/crosscheck.json."""
    path = os.path.join(out, "crosscheck.json")
    with open(path, "w") as f:
        json.dump(report, f, indent=2)
    print(f"wrote {path}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--scene", default="testcases/crosscheck.txt")
    parser.add_argument("--spp", type=int, default=64, help="equal spp for both renderers")
    parser.add_argument("--reference-spp", type=int, default=1024)
    parser.add_argument("--width", type=int, default=256)
    parser.add_argument("--height", type=int, default=192)
    parser.add_argument("--variant", default="scalar_rgb", choices=["scalar_rgb", "llvm_ad_rgb"])
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--pass-spp", type=int, default=None,
                        help="Mitsuba samples per render pass (default: all at once for "
                             "scalar_rgb, 64 for llvm_ad_rgb)")
    parser.add_argument("--out", default="output/crosscheck")
    parser.add_argument("--mitsuba-only", action="store_true", help="skip our renderer")
    parser.add_argument("--dialect", default="auto", choices=["auto", "canonical", "cambrian"])
    parser.add_argument("--look", default="original", choices=["original", "physical"],
                        help="our look: physical for the exact Fresnel equations of glass")
    parser.add_argument("--flat-textures", action="store_true",
                        help="give textured materials their mean texel instead of the map")
    parser.add_argument("--max-depth", type=int, default=None,
                        help="scattering vertices (ours; Mitsuba's max_depth is one more); "
                             "default: the look's, 5")
    parser.add_argument("--tolerance", type=float, default=0.03,
                        help="largest accepted |mean ratio - 1| per channel")
    parser.add_argument("--match-filter", action="store_true",
                        help="Mitsuba at twice the size with a tent filter, averaged down: "
                             "the expectation of our 2x2 sub-pixel tents in every pixel")
    args = parser.parse_args()
    os.chdir(ROOT)
    os.makedirs(args.out, exist_ok=True)

    if args.variant.startswith("llvm") and not os.environ.get("DRJIT_LIBLLVM_PATH"):
        for candidate in ("/usr/lib/x86_64-linux-gnu/libLLVM-19.so",
                          "/usr/lib/x86_64-linux-gnu/libLLVM.so.19.1",
                          "/usr/lib/llvm-19/lib/libLLVM.so"):
            if os.path.exists(candidate):
                os.environ["DRJIT_LIBLLVM_PATH"] = candidate
                break
    import mitsuba as mi
    mi.set_variant(args.variant)
    if args.pass_spp is None:
        args.pass_spp = 64 if args.variant.startswith("llvm") else max(args.spp, args.reference_spp)

    scene = Scene(args.scene, dialect=args.dialect)
    if scene.camera.get("dispersion") and any(m.get("cauchy") for m in scene.materials):
        warn("dispersive glass (cauchy with the camera's flag): Mitsuba gets one index, ours "
             "disperses; scripts/crosscheck_dispersion.py compares dispersion")
    tmpdir = os.path.join(args.out, "mitsuba_inputs")
    os.makedirs(tmpdir, exist_ok=True)
    scene_dict = mitsuba_scene_dict(mi, scene, args, args.spp, os.path.abspath(tmpdir))
    print(f"scene {args.scene}: {len(scene.shapes)} shapes, {len(scene.materials)} materials; "
          f"Mitsuba {mi.__version__} {args.variant}; {args.width}x{args.height}; "
          f"threads: all {os.cpu_count()} cores", flush=True)

    near = check_near_plane(mi)
    print(f"near-plane check: planar={near['planar_near_clip']}", flush=True)
    if not near["planar_near_clip"]:
        warn("Mitsuba's near clip is not a plane: rays do not start on our canvas")

    print(f"Mitsuba reference at {args.reference_spp} spp ...", flush=True)
    reference, ref_load, ref_time = render_mitsuba(mi, scene_dict, args.reference_spp,
                                                   args.seed + 1000, args.pass_spp)
    print(f"Mitsuba at {args.spp} spp ...", flush=True)
    mitsuba, mts_load, mts_time = render_mitsuba(mi, scene_dict, args.spp, args.seed,
                                                 args.pass_spp)
    write_pfm(os.path.join(args.out, "mitsuba_reference.pfm"), reference)
    write_pfm(os.path.join(args.out, f"mitsuba_{args.spp}spp.pfm"), mitsuba)
    preview(mi, os.path.join(args.out, "mitsuba_reference.png"), reference)
    preview(mi, os.path.join(args.out, f"mitsuba_{args.spp}spp.png"), mitsuba)

    report = {
        "scene": args.scene, "width": args.width, "height": args.height, "spp": args.spp,
        "reference_spp": args.reference_spp, "seed": args.seed, "variant": args.variant,
        "mitsuba_pass_spp": args.pass_spp,
        "mitsuba_version": mi.__version__, "cpu_count": os.cpu_count(),
        "relative_mse_epsilon": RELATIVE_MSE_EPSILON,
        "near_plane_check": near,
        "mitsuba_reference": {"seconds": ref_time, "load_seconds": ref_load,
                              "mean_rgb": [float(v) for v in reference.reshape(-1, 3).mean(0)]},
        "mitsuba": dict(seconds=mts_time, load_seconds=mts_load, **metrics(mitsuba, reference)),
        "ours": None,
        "notes": [
            ("pixel filter matched: Mitsuba at twice the size, tent of radius 1, averaged 2x2"
             if args.match_filter else
             "pixel filter differs: Mitsuba box, ours a 2x2 sub-pixel tent; edges differ slightly"),
            "Mitsuba samples emitters (NEE + MIS), ours does not: equal expectation, "
            "different variance",
            "max_depth 6 (6 segments = ours: 5 scattering vertices), rr_depth 100",
            "emitters touching other surfaces at grazing angles leak light in Mitsuba "
            "(shadow-ray epsilon): keep lights clear of walls",
        ],
    }
    status = 0
    if not args.mitsuba_only:
        print(f"ours at {args.spp} spp ...", flush=True)
        try:
            ours, ours_time, command = render_ours(args, os.path.join(args.out, "ours.pfm"))
            preview(mi, os.path.join(args.out, "ours.png"), ours)
            report["ours"] = dict(seconds=ours_time, command=" ".join(command),
                                  **metrics(ours, reference))
        except (RuntimeError, subprocess.CalledProcessError, OSError) as error:
            print(f"error: our renderer did not run: {error}", file=sys.stderr)
            report["ours_error"] = str(error)
            status = 2
    report["warnings"] = WARNINGS

    # table
    rows = [("Mitsuba reference", args.reference_spp, ref_time, None)]
    rows.append((f"Mitsuba {args.variant}", args.spp, mts_time, report["mitsuba"]))
    if report["ours"]:
        rows.append(("pathtracer (ours)", args.spp, report["ours"]["seconds"], report["ours"]))
    print()
    print(f"{'renderer':<24}{'spp':>6}{'seconds':>9}{'rmse':>10}{'relMSE':>11}"
          f"{'  mean ratio R G B (vs reference)':<36}{'tiles min..max':>16}")
    for name, spp, seconds, m in rows:
        if m is None:
            print(f"{name:<24}{spp:>6}{seconds:>9.2f}{'-':>10}{'-':>11}")
            continue
        ratio = " ".join(f"{r:.4f}" for r in m["mean_ratio_rgb"])
        se = max(m["mean_ratio_standard_error_rgb"])
        print(f"{name:<24}{spp:>6}{seconds:>9.2f}{m['rmse']:>10.5f}{m['rel_mse']:>11.6f}"
              f"  {ratio} (s.e. {se:.4f})"
              f"{m['tile_ratio_min']:>9.3f}..{m['tile_ratio_max']:.3f}")
    if report["ours"]:
        o, m = report["ours"], report["mitsuba"]
        report["ours_over_mitsuba_rel_mse"] = o["rel_mse"] / m["rel_mse"]
        report["ours_over_mitsuba_seconds"] = o["seconds"] / m["seconds"]
        print(f"\nrelMSE ours / Mitsuba at {args.spp} spp: {report['ours_over_mitsuba_rel_mse']:.2f}"
              f"; time ours / Mitsuba: {report['ours_over_mitsuba_seconds']:.3f}")
        if not check_tolerance(report, o["mean_ratio_rgb"], args.tolerance):
            status = status or 1
    if not args.match_filter:
        print("note: pixel filters differ (Mitsuba box, ours 2x2 tent): edges differ slightly "
              "(--match-filter matches them)")
    print("note: both sample lights (ours with --integrator path, the default)")
    write_report(args.out, report)
    return status


if __name__ == "__main__":
    sys.exit(main())
