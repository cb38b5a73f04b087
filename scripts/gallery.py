#!/usr/bin/env python3
"""Side-by-side pictures of docs/gallery/: our render of a scene next to the
image its own coursework renderer made (where ../shared/reference has one).

    .venv-crosscheck/bin/python scripts/gallery.py   (numpy and Pillow: make gallery)

Each entry renders the scene with target/release/pathtracer at a small size
and the given spp, then writes docs/gallery/<name>.png: ours on the left,
theirs (resized to the same height) on the right, each captioned. The
pictures stay small (tens of KB: 96 colours) so that they can live in the
repository.
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


def captioned(image, text):
    out = Image.new("RGB", (image.width, image.height + CAPTION), (255, 255, 255))
    out.paste(image, (0, CAPTION))
    ImageDraw.Draw(out).text((3, 1), text, fill=(0, 0, 0))
    return out


def main():
    subprocess.run(["cargo", "build", "--release", "--quiet"], cwd=ROOT, check=True)
    out_dir = os.path.join(ROOT, "docs", "gallery")
    os.makedirs(out_dir, exist_ok=True)
    for name, scene, theirs, width, height, spp, extra, caption in ENTRIES:
        scene_path = (os.path.join(SHARED, scene) if scene
                      else os.path.join(ROOT, "testcases", f"{name}.txt"))
        if not os.path.exists(scene_path):
            print(f"skipped {name}: {scene_path} not found", file=sys.stderr)
            continue
        with tempfile.TemporaryDirectory() as tmp:
            ours_path = os.path.join(tmp, "ours.png")
            subprocess.run([BINARY, "render", scene_path, "--width", str(width), "--height",
                            str(height), "--spp", str(spp), "-o", ours_path, "--quiet"] + extra,
                           check=True, stderr=subprocess.DEVNULL)
            ours = captioned(Image.open(ours_path).convert("RGB"), f"ours: {caption}")
        panels = [ours]
        if theirs:
            image = Image.open(os.path.join(SHARED, theirs)).convert("RGB")
            image = image.resize((round(image.width * height / image.height), height),
                                 Image.Resampling.LANCZOS)
            panels.append(captioned(image, "theirs: the repository's render"))
        total = Image.new("RGB", (sum(p.width for p in panels) + 4 * (len(panels) - 1),
                                  max(p.height for p in panels)), (255, 255, 255))
        x = 0
        for panel in panels:
            total.paste(panel, (x, 0))
            x += panel.width + 4
        path = os.path.join(out_dir, f"{name}.png")
        # A palette of 96 colours (dithered) keeps the files small.
        total.quantize(96, dither=Image.Dither.FLOYDSTEINBERG).save(path, optimize=True)
        print(f"{path}: {total.width}x{total.height}, {os.path.getsize(path)} bytes")


if __name__ == "__main__":
    main()
