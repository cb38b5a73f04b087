#!/usr/bin/env python3
"""The pictures of the docs: our render of a scene next to the image its own
coursework renderer made (where ../shared/reference has one).

    .venv-crosscheck/bin/python scripts/gallery.py [NAME...]   (numpy and Pillow: make gallery)

Each entry of ENTRIES renders the scene with target/release/pathtracer at a
small size and the given spp, then writes docs/gallery/<name>.png: ours on
the left, theirs (resized to the same height) on the right, each captioned.
Each strip of STRIPS writes docs/images/<name>.png: a row of such panels,
all scaled to the strip's height (the README's first picture and the
tutorial's steps). With NAMEs, only those entries and strips are made. The
pictures stay small (tens of KB: a palette of 96 colours) so that they can
live in the repository.
"""

import os
import subprocess
import sys
import tempfile

from PIL import Image, ImageDraw

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SHARED = os.path.join(ROOT, "..", "shared")
BINARY = os.path.join(ROOT, "target", "release", "pathtracer")
CAPTION = 14
GAP = 4

# name, scene, reference render (or None), width, height, spp, extra arguments, caption
ENTRIES = [
    ("scene07_shine", "reference/cambrian-pathtracer/testcases/scene07_shine.txt",
     "reference/cambrian-pathtracer/renders/scene07_shine.png", 192, 192, 64, [],
     "PA1 Phong, shininess 1..128"),
    ("scene17_bump", "reference/coursework/W-Solaris+computer-graphics/testcases/scene17_bump.txt",
     "reference/coursework/W-Solaris+computer-graphics/renders/scene17_bump.png", 176, 176, 256,
     [], "bump (height) map"),
    ("bunny_smooth", "reference/cambrian-pathtracer/testcases/bunny_and_wineglass.txt",
     "reference/cambrian-pathtracer/renders/bunny_and_wineglass.png", 224, 168, 128, [],
     "smooth bunny_1k (no vn)"),
    ("fuzz_sweep", None, None, 360, 144, 256, ["--gamma", "2.2"],
     "MetalMaterial fuzz 0, 0.1, 0.25, 0.5, 1 (gamma 2.2)"),
]

CAMBRIAN = "reference/cambrian-pathtracer/"
COURSEWORK = "reference/coursework/"
# name, panel height, panels: (scene, width, height, spp, extra arguments,
# caption) for ours, or ("theirs", image, caption); a scene under testcases/
# is the project's, any other is in ../shared.
STRIPS = [
    ("readme_strip", 104, [
        (CAMBRIAN + "testcases/sample_rec.txt", 160, 120, 1024, [], "ours"),
        ("theirs", CAMBRIAN + "renders/sample_rec.png", "Cambrian-yzt"),
        (COURSEWORK + "yuzc19+Ray-tracing-engine/testcases/vase.txt", 160, 160, 512, [], "ours"),
        ("theirs", COURSEWORK + "yuzc19+Ray-tracing-engine/renders/vase.png", "yuzc19"),
        (COURSEWORK + "one-step-beh1nd+THU2024Spring-CG-Final/testcases/glossy.txt",
         160, 160, 512, [], "ours"),
        ("theirs", COURSEWORK + "one-step-beh1nd+THU2024Spring-CG-Final/renders/glossy.png",
         "one-step-beh1nd"),
        (COURSEWORK + "aliezlo+dzy_gxgz_my/testcases/scene10_wineglass.txt",
         160, 160, 1, [], "ours"),
        ("theirs", COURSEWORK + "aliezlo+dzy_gxgz_my/renders/scene10_wineglass.png",
         "aliezlo (PA1)"),
    ]),
    ("tutorial_steps", 120, [
        ("testcases/tutorial1_camera.txt", 160, 120, 1, [], "1: camera"),
        ("testcases/tutorial2_sphere.txt", 160, 120, 256, [], "2: ball and lamp"),
        ("testcases/tutorial3_box.txt", 160, 120, 256, [], "3: the box"),
        ("testcases/tutorial4_cornell.txt", 160, 120, 256, [], "4: Cornell box"),
        ("testcases/tutorial4_cornell.txt", 160, 120, 256, ["--gamma", "2.2"],
         "4 at gamma 2.2"),
    ]),
]


def captioned(image, text):
    out = Image.new("RGB", (image.width, image.height + CAPTION), (255, 255, 255))
    out.paste(image, (0, CAPTION))
    ImageDraw.Draw(out).text((3, 1), text, fill=(0, 0, 0))
    return out


def scene_path(scene):
    if scene.startswith("testcases/"):
        return os.path.join(ROOT, scene)
    return os.path.join(SHARED, scene)


def render(scene, width, height, spp, extra):
    """Our render of `scene` (a path) as an RGB image."""
    with tempfile.TemporaryDirectory() as tmp:
        ours_path = os.path.join(tmp, "ours.png")
        subprocess.run([BINARY, "render", scene, "--width", str(width), "--height",
                        str(height), "--spp", str(spp), "-o", ours_path, "--quiet"] + extra,
                       check=True, stderr=subprocess.DEVNULL)
        return Image.open(ours_path).convert("RGB")


def scaled(image, height):
    return image.resize((round(image.width * height / image.height), height),
                        Image.Resampling.LANCZOS)


def side_by_side(panels):
    total = Image.new("RGB", (sum(p.width for p in panels) + GAP * (len(panels) - 1),
                              max(p.height for p in panels)), (255, 255, 255))
    x = 0
    for panel in panels:
        total.paste(panel, (x, 0))
        x += panel.width + GAP
    return total


def save(image, path):
    # A palette of 96 colours (dithered) keeps the files small.
    image.quantize(96, dither=Image.Dither.FLOYDSTEINBERG).save(path, optimize=True)
    print(f"{path}: {image.width}x{image.height}, {os.path.getsize(path)} bytes")


def make_entry(out_dir, name, scene, theirs, width, height, spp, extra, caption):
    path = scene_path(scene) if scene else os.path.join(ROOT, "testcases", f"{name}.txt")
    if not os.path.exists(path):
        print(f"skipped {name}: {path} not found", file=sys.stderr)
        return
    panels = [captioned(render(path, width, height, spp, extra), f"ours: {caption}")]
    if theirs:
        image = scaled(Image.open(os.path.join(SHARED, theirs)).convert("RGB"), height)
        panels.append(captioned(image, "theirs: the repository's render"))
    save(side_by_side(panels), os.path.join(out_dir, f"{name}.png"))


def make_strip(out_dir, name, height, panels):
    images = []
    for panel in panels:
        if panel[0] == "theirs":
            path = os.path.join(SHARED, panel[1])
            if not os.path.exists(path):
                print(f"skipped {name}: {path} not found", file=sys.stderr)
                return
            image, caption = Image.open(path).convert("RGB"), panel[2]
        else:
            scene, width, panel_height, spp, extra, caption = panel
            path = scene_path(scene)
            if not os.path.exists(path):
                print(f"skipped {name}: {path} not found", file=sys.stderr)
                return
            image = render(path, width, panel_height, spp, extra)
        images.append(captioned(scaled(image, height), caption))
    save(side_by_side(images), os.path.join(out_dir, f"{name}.png"))


def main():
    wanted = set(sys.argv[1:])
    subprocess.run(["cargo", "build", "--release", "--quiet"], cwd=ROOT, check=True)
    for directory in ("gallery", "images"):
        os.makedirs(os.path.join(ROOT, "docs", directory), exist_ok=True)
    for entry in ENTRIES:
        if not wanted or entry[0] in wanted:
            make_entry(os.path.join(ROOT, "docs", "gallery"), *entry)
    for name, height, panels in STRIPS:
        if not wanted or name in wanted:
            make_strip(os.path.join(ROOT, "docs", "images"), name, height, panels)


if __name__ == "__main__":
    main()
