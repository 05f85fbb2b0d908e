"""Headless Chromium driven through the Chrome DevTools Protocol over --remote-debugging-pipe.

The pipe transport is two plain file descriptors (Chromium reads commands on fd 3 and writes
replies and events on fd 4, each message a JSON object followed by a NUL byte), so the Python 3
standard library is enough: no websocket client, no npm package, no downloaded browser.
"""

import fcntl
import json
import os
import queue
import shutil
import subprocess
import tempfile
import threading
import time

# Flags known to work headless as root in a container. The resolver rule sends every host but
# 127.0.0.1 nowhere, so a page can only load what the local server serves.
CHROMIUM_FLAGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--disable-dev-shm-usage",
    "--no-first-run",
    "--no-default-browser-check",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--disable-extensions",
    "--mute-audio",
    "--no-proxy-server",
    "--host-resolver-rules=MAP * ~NOTFOUND, EXCLUDE 127.0.0.1",
]


class BrowserError(RuntimeError):
    """Chromium failed to start, closed the pipe, reported a protocol error or timed out."""


class Deadline:
    """One time budget for the whole check, so nothing can wait forever."""

    def __init__(self, seconds):
        self.end = time.monotonic() + seconds

    def remaining(self, cap=None):
        left = self.end - time.monotonic()
        if left <= 0:
            raise BrowserError("time budget exhausted")
        return left if cap is None else min(left, cap)


class Chromium:
    """One headless Chromium process and the DevTools session of one tab."""

    def __init__(self, executable, deadline):
        self.deadline = deadline
        self.profile = tempfile.mkdtemp(prefix="site-check-profile-")
        self.log_path = os.path.join(self.profile, "chromium.log")
        self.messages = queue.Queue()
        self.pending_events = []
        self.next_id = 0
        self.session = None
        self.process = None
        self._start(executable)

    # -- process and pipe ------------------------------------------------------------------

    def _start(self, executable):
        to_browser_read, to_browser_write = os.pipe()
        from_browser_read, from_browser_write = os.pipe()

        def map_pipe_to_fds_3_and_4():
            # Runs in the child between fork and exec; the checker starts no thread before this.
            # Copies above 9 first, so that neither end overwrites the other on its way to 3 or 4.
            commands = fcntl.fcntl(to_browser_read, fcntl.F_DUPFD, 10)
            replies = fcntl.fcntl(from_browser_write, fcntl.F_DUPFD, 10)
            os.dup2(commands, 3)
            os.dup2(replies, 4)
            os.set_inheritable(3, True)
            os.set_inheritable(4, True)

        args = [executable, *CHROMIUM_FLAGS, "--remote-debugging-pipe",
                f"--user-data-dir={self.profile}", "about:blank"]
        try:
            with open(self.log_path, "wb") as log:
                self.process = subprocess.Popen(
                    args, stdin=subprocess.DEVNULL, stdout=log, stderr=log,
                    close_fds=False,  # every other descriptor of ours is close-on-exec
                    preexec_fn=map_pipe_to_fds_3_and_4)
        except OSError as error:
            for fd in (to_browser_read, to_browser_write, from_browser_read, from_browser_write):
                os.close(fd)
            shutil.rmtree(self.profile, ignore_errors=True)
            raise BrowserError(f"cannot start {executable}: {error}") from None
        os.close(to_browser_read)
        os.close(from_browser_write)
        self.command_fd = to_browser_write
        self.reply_fd = from_browser_read
        threading.Thread(target=self._read_replies, daemon=True).start()

    def _read_replies(self):
        buffer = b""
        while True:
            try:
                chunk = os.read(self.reply_fd, 1 << 16)
            except OSError:
                chunk = b""
            if not chunk:
                self.messages.put(None)  # the browser closed the pipe
                return
            buffer += chunk
            *complete, buffer = buffer.split(b"\0")
            for raw in complete:
                self.messages.put(json.loads(raw))

    def log_tail(self, lines=20):
        try:
            with open(self.log_path, encoding="utf-8", errors="replace") as log:
                return "".join(log.readlines()[-lines:])
        except OSError:
            return ""

    def close(self):
        if self.process and self.process.poll() is None:
            try:
                self.call("Browser.close", timeout=5, in_session=False)
            except BrowserError:
                pass
            try:
                self.process.wait(timeout=5)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait(timeout=5)
        for fd in (getattr(self, "command_fd", None), getattr(self, "reply_fd", None)):
            if fd is not None:
                try:
                    os.close(fd)
                except OSError:
                    pass
        shutil.rmtree(self.profile, ignore_errors=True)

    # -- protocol --------------------------------------------------------------------------

    def _next_message(self, timeout):
        try:
            message = self.messages.get(timeout=self.deadline.remaining(timeout))
        except queue.Empty:
            raise BrowserError(f"no message from Chromium within {timeout:.0f} s") from None
        if message is None:
            raise BrowserError("Chromium closed the DevTools pipe:\n" + self.log_tail())
        return message

    def call(self, method, params=None, timeout=30, in_session=True):
        """Sends one command and returns its result; events that arrive meanwhile are kept."""
        self.next_id += 1
        command = {"id": self.next_id, "method": method, "params": params or {}}
        if in_session and self.session:
            command["sessionId"] = self.session
        try:
            os.write(self.command_fd, json.dumps(command).encode() + b"\0")
        except OSError as error:
            raise BrowserError(f"cannot send {method}: {error}\n" + self.log_tail()) from None
        end = time.monotonic() + timeout
        while True:
            message = self._next_message(max(0.1, end - time.monotonic()))
            if message.get("id") == self.next_id:
                if "error" in message:
                    raise BrowserError(f"{method} failed: {message['error']}")
                return message.get("result", {})
            if "method" in message:
                self.pending_events.append(message)
            if time.monotonic() > end:
                raise BrowserError(f"{method}: no reply within {timeout} s")

    def wait_event(self, method, timeout=30):
        """Returns the first event `method` of the tab's session, waiting at most `timeout` s."""
        end = time.monotonic() + timeout
        while True:
            for index, event in enumerate(self.pending_events):
                if event["method"] == method and event.get("sessionId") == self.session:
                    return self.pending_events.pop(index)
            if time.monotonic() > end:
                raise BrowserError(f"no {method} within {timeout} s")
            message = self._next_message(max(0.1, end - time.monotonic()))
            if "method" in message:
                self.pending_events.append(message)

    def take_events(self, method):
        """Removes and returns every pending event `method` of the tab's session."""
        taken = [e for e in self.pending_events
                 if e["method"] == method and e.get("sessionId") == self.session]
        self.pending_events = [e for e in self.pending_events if e not in taken]
        return taken

    # -- one tab ---------------------------------------------------------------------------

    def open_tab(self, script_on_every_document):
        target = self.call("Target.createTarget", {"url": "about:blank"}, in_session=False)
        attached = self.call("Target.attachToTarget",
                             {"targetId": target["targetId"], "flatten": True}, in_session=False)
        self.session = attached["sessionId"]
        self.call("Page.enable")
        self.call("Runtime.enable")
        self.call("Page.addScriptToEvaluateOnNewDocument", {"source": script_on_every_document})

    def load(self, url, timeout=30):
        """Navigates the tab to `url` and waits for its load event (all images settled)."""
        self.pending_events = [e for e in self.pending_events
                               if e["method"] not in ("Page.loadEventFired",
                                                      "Runtime.exceptionThrown")]
        navigation = self.call("Page.navigate", {"url": url}, timeout=timeout)
        if navigation.get("errorText"):
            raise BrowserError(f"cannot open {url}: {navigation['errorText']}")
        self.wait_event("Page.loadEventFired", timeout=timeout)

    def evaluate(self, expression, timeout=30):
        """Evaluates `expression` in the page (awaiting a promise) and returns its JSON value."""
        reply = self.call("Runtime.evaluate", {"expression": expression, "awaitPromise": True,
                                               "returnByValue": True}, timeout=timeout)
        if "exceptionDetails" in reply:
            raise BrowserError(f"page script failed: {reply['exceptionDetails']}")
        return reply["result"].get("value")
