#!/usr/bin/env python3
"""Opens a page in headless Chromium, waits for its <pre id="selftest-result"> to be shown and prints
its text; optionally saves a screenshot afterwards. Drives Chromium over the DevTools protocol on a
pipe (--remote-debugging-pipe: JSON messages ended by NUL on file descriptors 3 and 4), with the
standard library only. Unlike --dump-dom with --virtual-time-budget, the page runs in real time, so
its performance.now() measures (the designer's ms per tick).

    run-page.py CHROMIUM URL TIMEOUT_SECONDS [SCREENSHOT.png] [WIDTHxHEIGHT]

With EMINI_FILE_INPUT=PATH and EMINI_FILE_READY=EXPR, once EXPR is true in the page the file is put
into the page's file input (#open) as a user's choice would (DOM.setFileInputFiles), and
EMINI_FILE_THEN (an expression) runs after its change event.
"""
import base64
import json
import os
import subprocess
import sys
import tempfile
import time


class Browser:
    def __init__(self, chromium, size):
        self.profile = tempfile.TemporaryDirectory()
        to_chrome_r, self.to_chrome = os.pipe()
        self.from_chrome, from_chrome_w = os.pipe()

        def fds():
            os.dup2(to_chrome_r, 3)
            os.dup2(from_chrome_w, 4)

        flags = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                 "--disable-background-networking", "--disable-component-update", "--disable-sync",
                 "--allow-file-access-from-files", "--remote-debugging-pipe", "--window-size=" + size,
                 "--user-data-dir=" + self.profile.name, "about:blank"]
        self.proc = subprocess.Popen([chromium] + flags, preexec_fn=fds, pass_fds=(3, 4),
                                     stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        os.close(to_chrome_r)
        os.close(from_chrome_w)
        self.buf = b""
        self.next_id = 0
        self.session = None

    def call(self, method, params=None, session=True):
        self.next_id += 1
        msg = {"id": self.next_id, "method": method, "params": params or {}}
        if session and self.session:
            msg["sessionId"] = self.session
        os.write(self.to_chrome, json.dumps(msg).encode() + b"\0")
        while True:
            while b"\0" not in self.buf:
                chunk = os.read(self.from_chrome, 1 << 20)
                if not chunk:
                    raise RuntimeError("Chromium closed the pipe")
                self.buf += chunk
            raw, self.buf = self.buf.split(b"\0", 1)
            reply = json.loads(raw)
            if reply.get("id") == self.next_id:
                if "error" in reply:
                    raise RuntimeError(method + ": " + json.dumps(reply["error"]))
                return reply.get("result", {})

    def open(self, url):
        targets = self.call("Target.getTargets", session=False)["targetInfos"]
        page = next(t for t in targets if t["type"] == "page")
        self.session = self.call("Target.attachToTarget", {"targetId": page["targetId"], "flatten": True},
                                 session=False)["sessionId"]
        self.call("Page.enable")
        self.call("Page.navigate", {"url": url})

    def evaluate(self, expression):
        r = self.call("Runtime.evaluate", {"expression": expression, "returnByValue": True})
        return r.get("result", {}).get("value")

    def close(self):
        try:
            self.call("Browser.close", session=False)
        except (RuntimeError, OSError):
            pass
        try:
            self.proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.proc.kill()
        self.profile.cleanup()


def main():
    chromium, url, timeout = sys.argv[1], sys.argv[2], float(sys.argv[3])
    shot = sys.argv[4] if len(sys.argv) > 4 else None
    size = sys.argv[5] if len(sys.argv) > 5 else "1300,720"
    browser = Browser(chromium, size.replace("x", ","))
    try:
        browser.open(url)
        deadline = time.time() + timeout
        path = os.environ.get("EMINI_FILE_INPUT")
        if path:
            ready = os.environ.get("EMINI_FILE_READY", "true")
            while time.time() < deadline and not browser.evaluate("(() => { try { return !!(%s); } catch (e) { return false; } })()" % ready):
                time.sleep(0.25)
            root = browser.call("DOM.getDocument")["root"]["nodeId"]
            node = browser.call("DOM.querySelector", {"nodeId": root, "selector": "#open"})["nodeId"]
            browser.call("DOM.setFileInputFiles", {"files": [os.path.abspath(path)], "nodeId": node})
            then = os.environ.get("EMINI_FILE_THEN")
            if then:
                while time.time() < deadline and not browser.evaluate("!!(ui.replay)"):
                    time.sleep(0.25)
                browser.evaluate(then)
        text = None
        while time.time() < deadline:
            text = browser.evaluate("(() => { const e = document.getElementById('selftest-result');"
                                    " return e && !e.hidden ? e.textContent : null; })()")
            if text:
                break
            time.sleep(0.25)
        if shot:
            data = browser.call("Page.captureScreenshot", {"format": "png"})["data"]
            with open(shot, "wb") as f:
                f.write(base64.b64decode(data))
        if not text:
            status = browser.evaluate("document.getElementById('status') ? document.getElementById('status').textContent : ''")
            print("run-page: no self-test result within %.0f s (status: %s)" % (timeout, status), file=sys.stderr)
            sys.exit(1)
        print(text)
    finally:
        browser.close()


if __name__ == "__main__":
    main()
