"""Opens a page in headless Chromium through the DevTools protocol (over a pipe: no network,
no extra package), collects console errors and uncaught exceptions, measures elements and
takes a screenshot.

As a program it writes a screenshot of a report, for the README:
    chromium_page.py REPORT.html OUT.png [--width 1400] [--height 1000] [--scale 0.6]
"""
import argparse
import base64
import fcntl
import json
import os
import pathlib
import subprocess
import tempfile

FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--no-first-run", "--disable-background-networking",
         "--disable-component-update", "--disable-sync",
         # Containers often have a small /dev/shm.
         "--disable-dev-shm-usage",
         # WebGL from the CPU (SwiftShader): with --disable-gpu Chromium asks for this opt-in.
         "--enable-unsafe-swiftshader",
         "--remote-debugging-pipe"]


class Page:
    def __init__(self, width, height):
        self.profile = tempfile.TemporaryDirectory(prefix="tubemesh-chromium-")
        to_chromium_r, to_chromium_w = os.pipe()
        from_chromium_r, from_chromium_w = os.pipe()
        # Chromium reads commands on fd 3 and writes replies on fd 4.
        child_in = fcntl.fcntl(to_chromium_r, fcntl.F_DUPFD, 10)
        child_out = fcntl.fcntl(from_chromium_w, fcntl.F_DUPFD, 10)

        def connect():
            os.dup2(child_in, 3)
            os.dup2(child_out, 4)

        self.proc = subprocess.Popen(["chromium", *FLAGS, f"--user-data-dir={self.profile.name}", "about:blank"],
                                     stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                                     close_fds=False, preexec_fn=connect)
        for fd in (to_chromium_r, from_chromium_w, child_in, child_out):
            os.close(fd)
        self.out, self.inp = to_chromium_w, os.fdopen(from_chromium_r, "rb")
        self.next_id, self.events, self.buffer = 0, [], b""
        target = self.call("Target.createTarget", url="about:blank")["targetId"]
        self.session = self.call("Target.attachToTarget", targetId=target, flatten=True)["sessionId"]
        for domain in ("Runtime", "Log", "Page"):
            self.call(f"{domain}.enable", session=True)
        self.call("Emulation.setDeviceMetricsOverride", session=True, width=width, height=height,
                  deviceScaleFactor=1, mobile=False)

    def read(self):
        while b"\0" not in self.buffer:
            chunk = self.inp.read1(1 << 16)
            if not chunk:
                raise RuntimeError("chromium closed the DevTools pipe")
            self.buffer += chunk
        message, self.buffer = self.buffer.split(b"\0", 1)
        return json.loads(message)

    def call(self, method, session=False, **params):
        self.next_id += 1
        message = {"id": self.next_id, "method": method, "params": params}
        if session:
            message["sessionId"] = self.session
        os.write(self.out, json.dumps(message).encode() + b"\0")
        while True:
            reply = self.read()
            if reply.get("id") != self.next_id:
                self.events.append(reply)
                continue
            if "error" in reply:
                raise RuntimeError(f"{method}: {reply['error']}")
            return reply["result"]

    def wait_for(self, method):
        for event in self.events:
            if event.get("method") == method:
                return event
        while True:
            event = self.read()
            self.events.append(event)
            if event.get("method") == method:
                return event

    def open(self, path):
        self.call("Page.navigate", session=True, url=pathlib.Path(path).resolve().as_uri())
        self.wait_for("Page.loadEventFired")
        # Two animation frames: whatever the page drew at load is on screen.
        self.evaluate("new Promise(done => requestAnimationFrame(() => requestAnimationFrame(done)))")

    def evaluate(self, expression):
        result = self.call("Runtime.evaluate", session=True, expression=expression, awaitPromise=True,
                           returnByValue=True)
        if "exceptionDetails" in result:
            raise RuntimeError(f"{expression}: {result['exceptionDetails']}")
        return result["result"].get("value")

    def errors(self):
        """Console errors, failed assertions, uncaught exceptions and error log entries."""
        found = []
        for e in self.events:
            method, params = e.get("method"), e.get("params", {})
            if method == "Runtime.consoleAPICalled" and params["type"] in ("error", "assert"):
                found.append(" ".join(str(a.get("value", a.get("description"))) for a in params["args"]))
            elif method == "Runtime.exceptionThrown":
                details = params["exceptionDetails"]
                found.append(details.get("exception", {}).get("description", details.get("text")))
            elif method == "Log.entryAdded" and params["entry"]["level"] == "error":
                found.append(params["entry"]["text"])
        return found

    def screenshot(self, path):
        data = self.call("Page.captureScreenshot", session=True, format="png")["data"]
        pathlib.Path(path).write_bytes(base64.b64decode(data))

    def close(self):
        try:
            self.call("Browser.close")
        except RuntimeError:
            pass
        self.proc.wait(timeout=60)
        os.close(self.out)
        self.inp.close()
        self.profile.cleanup()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("report")
    parser.add_argument("png")
    parser.add_argument("--width", type=int, default=1400)
    parser.add_argument("--height", type=int, default=1450)
    parser.add_argument("--scale", type=float, default=0.6)
    args = parser.parse_args()
    from PIL import Image
    with Page(args.width, args.height) as page:
        page.open(args.report)
        if page.errors():
            raise SystemExit(f"errors on the page: {page.errors()}")
        full = args.png + ".full.png"
        page.screenshot(full)
    image = Image.open(full).convert("RGB")
    os.remove(full)
    size = (round(image.width * args.scale), round(image.height * args.scale))
    image.resize(size, Image.LANCZOS).quantize(colors=256).save(args.png, optimize=True)


if __name__ == "__main__":
    main()
