"""Headless Chromium driven over its DevTools protocol, with the standard
library only: Chromium started with --remote-debugging-pipe reads commands
from its file descriptor 3 and writes answers and events to 4, each one
JSON message ended by a NUL byte."""

import base64
import fcntl
import json
import os
import select
import shutil
import subprocess
import tempfile
import time

# Chromium as root, with nothing that talks to the network by itself.
FLAGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--disable-default-apps",
    "--disable-extensions",
    "--hide-scrollbars",
    "--mute-audio",
    "--remote-debugging-pipe",
]


class BrowserError(Exception):
    """A command Chromium refused, or a wait that ran out."""


class Chromium:
    """One headless Chromium with a fresh profile, and one page in it."""

    def __init__(self, executable, width, height):
        self.profile = tempfile.mkdtemp(prefix="pathtracer-chromium-")
        to_browser_read, self.to_browser = os.pipe()
        self.from_browser, from_browser_write = os.pipe()

        def descriptors():
            # The pipe ends as 3 and 4 in the child only (by way of free
            # numbers above both, so neither overwrites the other).
            reading = fcntl.fcntl(to_browser_read, fcntl.F_DUPFD, 10)
            writing = fcntl.fcntl(from_browser_write, fcntl.F_DUPFD, 10)
            os.dup2(reading, 3)
            os.dup2(writing, 4)

        self.process = subprocess.Popen(
            [executable, *FLAGS, f"--user-data-dir={self.profile}", f"--window-size={width},{height}", "about:blank"],
            stdin=subprocess.DEVNULL,
            stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL,
            pass_fds=(3, 4),
            preexec_fn=descriptors,
        )
        os.close(to_browser_read)
        os.close(from_browser_write)
        self.buffer = b""
        self.next_id = 0
        self.events = []
        self.session = None
        target = self.call("Target.createTarget", {"url": "about:blank"}, session=False)
        attached = self.call("Target.attachToTarget", {"targetId": target["targetId"], "flatten": True}, session=False)
        self.session = attached["sessionId"]
        self.call(
            "Emulation.setDeviceMetricsOverride",
            {"width": width, "height": height, "deviceScaleFactor": 1, "mobile": False},
        )
        for domain in ["Page", "Runtime", "Network"]:
            self.call(f"{domain}.enable")

    def close(self):
        try:
            self.call("Browser.close", session=False, timeout=5)
        except (BrowserError, OSError):
            pass
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()
        for descriptor in (self.to_browser, self.from_browser):
            os.close(descriptor)
        shutil.rmtree(self.profile, ignore_errors=True)

    def _read_message(self, deadline):
        while b"\0" not in self.buffer:
            left = deadline - time.monotonic()
            if left <= 0:
                raise BrowserError("Chromium did not answer in time")
            ready, _, _ = select.select([self.from_browser], [], [], left)
            if ready:
                chunk = os.read(self.from_browser, 1 << 20)
                if not chunk:
                    raise BrowserError(f"Chromium closed its pipe (exit {self.process.poll()})")
                self.buffer += chunk
        message, self.buffer = self.buffer.split(b"\0", 1)
        return json.loads(message)

    def call(self, method, params=None, session=True, timeout=30):
        """Sends one command and returns its result (events met meanwhile are kept)."""
        self.next_id += 1
        message = {"id": self.next_id, "method": method, "params": params or {}}
        if session and self.session:
            message["sessionId"] = self.session
        os.write(self.to_browser, json.dumps(message).encode() + b"\0")
        deadline = time.monotonic() + timeout
        while True:
            answer = self._read_message(deadline)
            if answer.get("id") == self.next_id:
                if "error" in answer:
                    raise BrowserError(f"{method}: {answer['error'].get('message')}")
                return answer.get("result", {})
            if "method" in answer:
                self.events.append(answer)

    def evaluate(self, expression):
        """The value of a JavaScript expression in the page (awaited if a promise)."""
        result = self.call(
            "Runtime.evaluate",
            {"expression": expression, "returnByValue": True, "awaitPromise": True},
        )
        if "exceptionDetails" in result:
            raise BrowserError(f"{expression[:60]}...: {result['exceptionDetails'].get('text')}")
        return result["result"].get("value")

    def wait_until(self, what, expression, limit):
        """Evaluates `expression` until it is truthy; its value."""
        deadline = time.monotonic() + limit
        while True:
            # An exception (the page still loading) counts as not yet.
            try:
                value = self.evaluate(expression)
                seen = value
            except BrowserError as error:
                value, seen = None, error
            if value:
                return value
            if time.monotonic() > deadline:
                raise BrowserError(f"{what}: not after {limit} s (last {seen})")
            time.sleep(0.1)

    def drag(self, x0, y0, x1, y1, steps=8):
        """A left-button drag from (x0, y0) to (x1, y1), as a hand does it."""
        mouse = "Input.dispatchMouseEvent"
        self.call(mouse, {"type": "mouseMoved", "x": x0, "y": y0})
        self.call(mouse, {"type": "mousePressed", "x": x0, "y": y0, "button": "left", "clickCount": 1})
        for step in range(1, steps + 1):
            x = x0 + (x1 - x0) * step / steps
            y = y0 + (y1 - y0) * step / steps
            self.call(mouse, {"type": "mouseMoved", "x": x, "y": y, "button": "left", "buttons": 1})
        self.call(mouse, {"type": "mouseReleased", "x": x1, "y": y1, "button": "left", "clickCount": 1})

    def requests_since(self, mark, path):
        """How many requests for `path` the page sent since event `mark`."""
        return sum(
            1
            for event in self.events[mark:]
            if event.get("method") == "Network.requestWillBeSent"
            and event["params"]["request"]["url"].split("?")[0].endswith(path)
        )

    def screenshot(self):
        """The page as PNG bytes."""
        return base64.b64decode(self.call("Page.captureScreenshot", {"format": "png"})["data"])
