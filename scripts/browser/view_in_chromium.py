#!/usr/bin/env python3
"""`make test-browser`: the page of `pathtracer view` in headless Chromium.

Each step fails (exit 1, with what was seen) when its property does not hold:
1. the page shows the picture (a canvas of the render's size, not blank) and
   the last film of the finished render;
2. dragging the exposure slider brightens the pixels with no new render:
   the server's frame and render counters stay, the page asks for no film;
3. saving a changed scene file (the white ball made red) brings the new
   picture: red where it was grey;
4. saving a broken scene shows its located error and keeps the last picture;
5. `view --against` with a coursework render (a pair of
   ../shared/reference/pairs.tsv) shows theirs beside ours with the figures
   and the FLIP heat map, and the page is written to the screenshot file.
Step 5 is skipped, saying so, when ../shared is absent.
"""

import argparse
import pathlib
import re
import shutil
import sys
import tempfile
import time

from chromium import Chromium
from viewer import Viewer

ROOT = pathlib.Path(__file__).resolve().parents[2]
SCENE = ROOT / "testcases" / "tutorial2_sphere.txt"
BALL_WHITE = "color 0.8 0.8 0.8  diffusionRate 1"
BALL_RED = "color 0.8 0 0  diffusionRate 1"
# The pair of the screenshot: Cambrian-yzt's motion-blurred spheres.
PAIR = ("cambrian-pathtracer", "testcases/sample_rec.txt", "renders/sample_rec.png")

# A canvas's 8-bit channel means and range, and the frame the page drew.
STATS = """(() => {
  const canvas = document.getElementById(%r);
  if (canvas.width < 2) return null;
  const data = canvas.getContext("2d").getImageData(0, 0, canvas.width, canvas.height).data;
  const sums = [0, 0, 0];
  let low = 255, high = 0;
  for (let i = 0; i < data.length; i += 4) {
    for (let c = 0; c < 3; c++) {
      sums[c] += data[i + c];
      low = Math.min(low, data[i + c]);
      high = Math.max(high, data[i + c]);
    }
  }
  const n = data.length / 4;
  return {
    width: canvas.width, height: canvas.height, low, high,
    red: sums[0] / n, green: sums[1] / n, blue: sums[2] / n,
    mean: (sums[0] + sums[1] + sums[2]) / (3 * n),
    frame: Number(document.body.dataset.frame || 0),
    draws: Number(document.body.dataset.draws || 0),
  };
})()"""


class Failed(Exception):
    pass


def check(condition, message):
    if not condition:
        raise Failed(message)


def stats(browser, canvas="image"):
    return browser.evaluate(STATS % canvas)


def not_blank(s, width, height):
    return s is not None and s["width"] == width and s["height"] == height and s["high"] - s["low"] >= 32


def finished(browser, viewer, render):
    """Waits for render number `render` to finish and the page to draw its last film."""
    status = viewer.wait_for(f"render {render} done", lambda s: s["render"] == render and s["done"], 180)
    browser.wait_until(
        f"the page draws frame {status['frame']}",
        f"Number(document.body.dataset.frame) >= {status['frame']}",
        30,
    )
    return status


def shows_the_picture(browser, viewer):
    browser.call("Page.navigate", {"url": viewer.url})
    browser.wait_until("a picture that is not blank", f"(s => s && s.high - s.low >= 32)({STATS % 'image'})", 120)
    status = finished(browser, viewer, 1)
    s = stats(browser)
    check(not_blank(s, status["width"], status["height"]), f"the finished picture is blank or of another size: {s}")
    check(s["frame"] == status["frame"], f"the page drew frame {s['frame']}, the server's last is {status['frame']}")
    # The count that step 2 expects to stay at 0 does see the page's requests.
    films = browser.requests_since(0, "/film")
    check(films >= 1, "no /film request seen: the network events are not counted")
    return f"{s['width']}x{s['height']}, mean {s['mean']:.1f} of 255, frame {s['frame']} at {status['spp']:.0f} spp, {films} /film requests"


def exposure_changes_pixels_without_a_render(browser, viewer):
    before = stats(browser)
    status_before = viewer.status()
    mark = len(browser.events)
    box = browser.evaluate('(r => [r.left, r.top, r.width, r.height])($("exposure").getBoundingClientRect())')
    left, top, width, height = box
    y = top + height / 2
    # From the middle (0 EV) to three quarters of the track (+4 EV).
    browser.drag(left + width / 2, y, left + width * 0.75, y)
    time.sleep(1.0)
    exposure = float(browser.evaluate('$("exposure").value'))
    after = stats(browser)
    status_after = viewer.status()
    check(2 <= exposure <= 6, f"the slider went to {exposure} EV, not about +4")
    check(after["draws"] > before["draws"], "the page did not draw again")
    check(after["mean"] > before["mean"] * 1.5 + 1, f"pixels not brighter: mean {before['mean']:.1f} -> {after['mean']:.1f}")
    for counter in ["frame", "render"]:
        check(
            status_after[counter] == status_before[counter],
            f"the server's {counter} went {status_before[counter]} -> {status_after[counter]}",
        )
    check(after["frame"] == before["frame"], "the page drew another frame")
    films = browser.requests_since(mark, "/film")
    check(films == 0, f"the page asked for the film {films} times")
    return (
        f"+{exposure:.1f} EV: mean {before['mean']:.1f} -> {after['mean']:.1f}, "
        f"{after['draws'] - before['draws']} draws, server frame {status_after['frame']} and render "
        f"{status_after['render']} unchanged, no /film request"
    )


def saving_the_scene_shows_the_new_picture(browser, viewer, scene):
    before = stats(browser)
    check(abs(before["red"] - before["green"]) < 0.05 * before["red"] + 1, f"a grey ball to start with: {before}")
    scene.write_text(scene.read_text().replace(BALL_WHITE, BALL_RED))
    started = time.monotonic()
    status = finished(browser, viewer, 2)
    after = stats(browser)
    check(after["red"] > 3 * after["green"] + 1, f"the ball is not red: {after}")
    return (
        f"new picture {time.monotonic() - started:.1f} s after the save (render 2, {status['spp']:.0f} spp): "
        f"red/green mean {before['red']:.1f}/{before['green']:.1f} -> {after['red']:.1f}/{after['green']:.1f}"
    )


def a_broken_scene_shows_its_error(browser, viewer, scene):
    before = stats(browser)
    scene.write_text(scene.read_text().replace("radius 3", "radius three"))
    viewer.wait_for("the scene's error", lambda s: s["error"], 60)
    shown = browser.wait_until("the error on the page", '!$("error").hidden && $("error").textContent', 30)
    check(re.search(r"\.txt:\d+:\d+", shown), f"the error is not located (file:line:col): {shown!r}")
    after = stats(browser)
    check(after == before, f"the picture changed: {before} -> {after}")
    return f"{shown.splitlines()[0]!r}, picture kept"


def stopped(viewer):
    code = viewer.stop()
    check(code == 130, f"view exited {code} on Ctrl-C, not 130 (docs/guide/view.md)")
    return "exit 130"


def comparison_screenshot(browser, binary, shared, screenshot):
    folder, scene, render = PAIR
    folder = shared / "reference" / folder
    size = ["--width", "320", "--height", "240", "--spp", "32"]
    viewer = Viewer(binary, scene, [*size, "--against", render], cwd=folder)
    try:
        browser.call("Page.navigate", {"url": viewer.url})
        status = viewer.wait_for(
            "the figures of the finished render",
            lambda s: s["done"] and s.get("against") and s["against"].get("frame") == s["frame"],
            300,
        )
        browser.wait_until(
            "theirs and the map of the last measure",
            f"Number(document.body.dataset.compared) >= {status['frame']}"
            f" && Number(document.body.dataset.frame) >= {status['frame']}",
            30,
        )
        figures = browser.evaluate('$("figures").textContent')
        check("FLIP" in figures and "mean" in figures, f"no figures on the page: {figures!r}")
        for canvas in ["image", "theirs", "heat"]:
            s = stats(browser, canvas)
            check(not_blank(s, 320, 240), f"{canvas}: blank or not at our size: {s}")
        check(not browser.evaluate('$("theirs").hidden'), "theirs is not shown beside ours")
        png = browser.screenshot()
        check(png.startswith(b"\x89PNG") and len(png) < 600_000, f"a screenshot of {len(png)} bytes")
        screenshot.parent.mkdir(parents=True, exist_ok=True)
        partial = screenshot.with_suffix(".partial")
        partial.write_bytes(png)
        partial.replace(screenshot)
        code = viewer.stop()
        check(code == 130, f"view exited {code} on Ctrl-C, not 130")
        return f"{figures}; {screenshot} ({len(png) // 1024} KB)"
    finally:
        viewer.stop()


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--binary", default=str(ROOT / "target" / "release" / "pathtracer"))
    parser.add_argument("--chromium", default="/usr/bin/chromium")
    parser.add_argument("--shared", default=str(ROOT.parent / "shared"))
    parser.add_argument("--screenshot", default=str(ROOT / "docs" / "images" / "view_against.png"))
    args = parser.parse_args()
    work = pathlib.Path(tempfile.mkdtemp(prefix="pathtracer-browser-"))
    scene = work / "ball.txt"
    shutil.copy(SCENE, scene)
    if BALL_WHITE not in scene.read_text():
        print(f"FAILED: {SCENE} no longer has the line {BALL_WHITE!r} this test edits")
        return 1
    started = time.monotonic()
    shared = pathlib.Path(args.shared)
    against = (shared / "reference" / PAIR[0]).is_dir()
    if not against:
        print(f"skipped: against a coursework render ({shared}/reference/{PAIR[0]} is absent), no screenshot")
    browser = viewer = None
    name = "starting Chromium and view"
    try:
        browser = Chromium(args.chromium, 960, 600)
        viewer = Viewer(args.binary, scene, ["--width", "160", "--height", "120", "--spp", "16"], cwd=work)
        steps = [
            ("the page shows the picture", lambda: shows_the_picture(browser, viewer)),
            ("exposure without a render", lambda: exposure_changes_pixels_without_a_render(browser, viewer)),
            ("edit and see", lambda: saving_the_scene_shows_the_new_picture(browser, viewer, scene)),
            ("a broken scene", lambda: a_broken_scene_shows_its_error(browser, viewer, scene)),
            ("stopped by Ctrl-C", lambda: stopped(viewer)),
        ]
        if against:
            screenshot = pathlib.Path(args.screenshot)
            steps.append(
                ("against a coursework render", lambda: comparison_screenshot(browser, args.binary, shared, screenshot))
            )
        for name, step in steps:
            step_started = time.monotonic()
            found = step()
            print(f"ok: {name} ({time.monotonic() - step_started:.1f} s): {found}", flush=True)
    except Exception as failure:  # every failure is reported the same way
        print(f"FAILED: {name}: {failure}")
        return 1
    finally:
        if viewer:
            viewer.stop()
        if browser:
            browser.close()
        shutil.rmtree(work, ignore_errors=True)
    print(f"make test-browser: all {len(steps)} steps passed in {time.monotonic() - started:.1f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
