"""`pathtracer view` run for the browser test: started on a free port, its
URL read from what it prints, its status asked over HTTP, and stopped with
Ctrl-C (SIGINT) as a user stops it."""

import json
import signal
import subprocess
import tempfile
import time
import urllib.request


class Viewer:
    def __init__(self, binary, scene, args, cwd):
        # Its output goes to a file, which can never fill up and block it.
        self.log = tempfile.TemporaryFile()
        self.process = subprocess.Popen(
            [binary, "view", str(scene), "--port", "0", *args],
            cwd=cwd,
            stdin=subprocess.DEVNULL,
            stdout=self.log,
            stderr=subprocess.STDOUT,
        )
        deadline = time.monotonic() + 60
        while True:
            self.log.seek(0)
            printed = self.log.read().decode(errors="replace")
            if "http://127.0.0.1:" in printed:
                self.url = "http://127.0.0.1:" + printed.split("http://127.0.0.1:")[1].split("/")[0] + "/"
                return
            if self.process.poll() is not None or time.monotonic() > deadline:
                self.stop()
                raise RuntimeError(f"view printed no URL: {printed.strip()}")
            time.sleep(0.05)

    def status(self):
        with urllib.request.urlopen(self.url + "status", timeout=20) as answer:
            return json.load(answer)

    def wait_for(self, what, done, limit):
        """The first status for which `done` holds, asked every 0.1 s."""
        deadline = time.monotonic() + limit
        while True:
            status = self.status()
            if done(status):
                return status
            if time.monotonic() > deadline:
                raise RuntimeError(f"{what}: not after {limit} s (status {status})")
            time.sleep(0.1)

    def stop(self):
        """Ctrl-C, and the exit code it gave."""
        if self.process.poll() is None:
            self.process.send_signal(signal.SIGINT)
            try:
                self.process.wait(timeout=20)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait()
                raise RuntimeError("view did not stop within 20 s of Ctrl-C")
        return self.process.returncode
