#!/usr/bin/env python3
"""Opens an HTML report in headless Chromium (the real client, docs/reliability.md) and checks it.

  check_page.py REPORT.html SCREENSHOT.png [--min-images N] [--chromium PATH]

Drives Chromium through the DevTools protocol on a pipe (--remote-debugging-pipe: no port, no
extra Python modules). Fails (exit 1) when the page logs a console error or warning of level
error, throws, fails to load a resource, or has an image that did not load (naturalWidth 0);
exit 2 when Chromium cannot be started. Keeps a full-page screenshot. Standard library only.
"""
import argparse
import base64
import json
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile
import time


class Browser:
    def __init__(self, exe, profile):
        r_chrome, w_ours = os.pipe()  # we write commands, Chromium reads fd 3
        r_ours, w_chrome = os.pipe()  # Chromium writes fd 4, we read
        args = [exe, "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run", "--no-default-browser-check",
                "--disable-extensions", "--disable-background-networking", "--disable-dev-shm-usage",
                "--hide-scrollbars", "--user-data-dir=" + profile, "--remote-debugging-pipe", "about:blank"]

        def child_fds():
            os.dup2(r_chrome, 3)
            os.dup2(w_chrome, 4)

        self.proc = subprocess.Popen(args, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                                     stderr=open(os.path.join(profile, "chromium.log"), "wb"),
                                     preexec_fn=child_fds, pass_fds=(3, 4))
        os.close(r_chrome)
        os.close(w_chrome)
        self.w, self.r = os.fdopen(w_ours, "wb"), os.fdopen(r_ours, "rb")
        self.next_id, self.buffer, self.events = 0, b"", []

    def _read_message(self):
        while b"\0" not in self.buffer:
            chunk = self.r.read1(1 << 16)
            if not chunk:
                raise RuntimeError("Chromium closed the DevTools pipe (crashed or failed to start)")
            self.buffer += chunk
        raw, self.buffer = self.buffer.split(b"\0", 1)
        return json.loads(raw)

    def send(self, method, params=None, session=None, timeout=60):
        self.next_id += 1
        msg = {"id": self.next_id, "method": method, "params": params or {}}
        if session:
            msg["sessionId"] = session
        self.w.write(json.dumps(msg).encode() + b"\0")
        self.w.flush()
        deadline = time.time() + timeout
        while time.time() < deadline:
            m = self._read_message()
            if m.get("id") == self.next_id:
                if "error" in m:
                    raise RuntimeError(f"{method}: {m['error']}")
                return m.get("result", {})
            self.events.append(m)
        raise RuntimeError(f"{method}: no answer in {timeout} s")

    def wait_event(self, method, timeout=60):
        deadline = time.time() + timeout
        while True:
            for k, e in enumerate(self.events):
                if e.get("method") == method:
                    return self.events.pop(k)
            if time.time() > deadline:
                raise RuntimeError(f"no {method} in {timeout} s")
            self.events.append(self._read_message())

    def close(self):
        try:
            self.send("Browser.close", timeout=10)
        except Exception:
            pass
        try:
            self.proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()


IMAGES_JS = """JSON.stringify(Array.from(document.images).map(i => ({
  src: i.getAttribute('src'), complete: i.complete, w: i.naturalWidth, h: i.naturalHeight})))"""


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("page")
    ap.add_argument("screenshot")
    ap.add_argument("--min-images", type=int, default=1)
    ap.add_argument("--chromium", default=None)
    a = ap.parse_args()
    exe = a.chromium or shutil.which("chromium") or shutil.which("chromium-browser")
    if not exe:
        print("check_page: FAIL: chromium is not installed (scripts/install-deps.sh: the clients group)")
        return 2
    page = pathlib.Path(a.page).resolve()
    if not page.is_file():
        print(f"check_page: FAIL: no page {page}")
        return 1
    problems = []
    with tempfile.TemporaryDirectory(prefix="paddy_chromium_") as profile:
        try:
            b = Browser(exe, profile)
        except OSError as e:
            print(f"check_page: FAIL: cannot start {exe}: {e}")
            return 2
        try:
            target = b.send("Target.createTarget", {"url": "about:blank"})["targetId"]
            s = b.send("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
            for domain in ("Page", "Runtime", "Log", "Network"):
                b.send(domain + ".enable", session=s)
            b.send("Emulation.setDeviceMetricsOverride",
                   {"width": 1280, "height": 900, "deviceScaleFactor": 1, "mobile": False}, session=s)
            nav = b.send("Page.navigate", {"url": page.as_uri()}, session=s)
            if nav.get("errorText"):
                problems.append(f"navigation failed: {nav['errorText']}")
            b.wait_event("Page.loadEventFired")
            images = json.loads(b.send("Runtime.evaluate", {"expression": IMAGES_JS, "returnByValue": True},
                                       session=s)["result"]["value"])
            metrics = b.send("Page.getLayoutMetrics", session=s)
            size = metrics.get("cssContentSize") or metrics["contentSize"]
            width, height = max(1, int(size["width"])), min(16384, max(1, int(size["height"])))
            shot = b.send("Page.captureScreenshot",
                          {"format": "png", "captureBeyondViewport": True,
                           "clip": {"x": 0, "y": 0, "width": width, "height": height, "scale": 1}}, session=s)
            pathlib.Path(a.screenshot).parent.mkdir(parents=True, exist_ok=True)
            pathlib.Path(a.screenshot).write_bytes(base64.b64decode(shot["data"]))
            # Events that arrived up to now (the page has no scripts and no network: all are in).
            b.send("Runtime.evaluate", {"expression": "1"}, session=s)
        except RuntimeError as e:
            print(f"check_page: FAIL: {e}")
            b.close()
            return 2
        for e in b.events:
            m, p = e.get("method"), e.get("params", {})
            if m == "Runtime.consoleAPICalled" and p.get("type") in ("error", "assert"):
                problems.append("console error: " + " ".join(str(x.get("value", x.get("description")))
                                                            for x in p.get("args", [])))
            elif m == "Runtime.exceptionThrown":
                problems.append("exception: " + p["exceptionDetails"].get("text", ""))
            elif m == "Log.entryAdded" and p["entry"].get("level") == "error":
                problems.append(f"console error: {p['entry'].get('text')} {p['entry'].get('url', '')}")
            elif m == "Network.loadingFailed":
                problems.append(f"resource failed to load: {p.get('errorText')} (request {p.get('requestId')})")
        b.close()
    for i in images:
        if not (i["complete"] and i["w"] > 0 and i["h"] > 0):
            problems.append(f"image did not load: {i['src']} (naturalWidth {i['w']})")
    if len(images) < a.min_images:
        problems.append(f"only {len(images)} images, expected at least {a.min_images}")
    print(f"check_page: {page}: {len(images)} images, {len(problems)} problems; screenshot {a.screenshot} "
          f"({width}x{height})")
    for p in problems:
        print("check_page: FAIL: " + p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
