"""rig-scope's threads: the receiver (udpm -> RigViews), the ticker (one frame for every page
FRAME_HZ times a second) and the HTTP server on 127.0.0.1 (the page, its scripts and the
/events stream of frames as server-sent events). Everything runs outside the rig's process:
a slow page loses frames (and gets a full one again), the receiver loses datagrams, the rig
never waits."""
import collections
import http.server
import json
import pathlib
import threading
import time

from rig_lcm import Datagrams
from rig_lcm.types import _generated, decode_as, type_of

from .view import RigView

FRAME_HZ = 50     # frames a second to the pages (the page draws at its display's rate, >= 30)
RING_FRAMES = 250  # frames kept for pages that lag; beyond, a page gets a full frame again
CONTENT_TYPES = {".html": "text/html; charset=utf-8", ".js": "text/javascript; charset=utf-8",
                 ".css": "text/css; charset=utf-8"}


class Scope:
    def __init__(self, url, prefixes):
        self.url = url
        self.views = {p: RigView(p) for p in prefixes}
        self.channels = {}
        for view in self.views.values():
            self.channels[view.state_channel] = (view.on_state, _generated.vehicle_state_t)
            self.channels[view.status_channel] = (view.on_status, _generated.rig_status_t)
        self.lock = threading.Lock()
        self.new_frame = threading.Condition(self.lock)
        self.ring = collections.deque(maxlen=RING_FRAMES)  # (seq, json text)
        self.seq = 0
        self.received = 0
        self.running = True
        self.sock = Datagrams(url)

    def receive_forever(self):
        while self.running:
            got = self.sock.receive(0.2)
            if got is None:
                continue
            channel, payload = got
            handler = self.channels.get(channel)
            if handler is None or type_of(payload) is not handler[1]:
                continue
            msg = decode_as(handler[1], payload)
            with self.lock:
                self.received += 1
                handler[0](msg, time.monotonic())

    def tick_forever(self):
        period = 1.0 / FRAME_HZ
        next_t = time.monotonic()
        while self.running:
            next_t += period
            time.sleep(max(0.0, next_t - time.monotonic()))
            with self.lock:
                text = self._frame_text(full=False)
                for view in self.views.values():
                    view.frame_sent()
                self.seq += 1
                self.ring.append((self.seq, text))
                self.new_frame.notify_all()

    def _frame_text(self, full):
        now = time.monotonic()
        rigs = {}
        for prefix, view in self.views.items():
            frame = view.frame(now, full)
            if frame is not None:
                rigs[prefix] = frame
        return json.dumps({"seq": self.seq, "full": full, "received": self.received,
                           "prefixes": list(self.views), "rigs": rigs},
                          separators=(",", ":"), allow_nan=False)

    def full_frame(self):
        """(seq, text) of a frame with everything so far (lock held by the caller)."""
        return self.seq, self._frame_text(full=True)

    def stop(self):
        self.running = False
        with self.lock:
            self.new_frame.notify_all()


def handler_class(scope, web_dirs):
    class Handler(http.server.BaseHTTPRequestHandler):
        protocol_version = "HTTP/1.1"

        def log_message(self, *args):  # quiet: the console is the user's
            pass

        def do_GET(self):
            path = self.path.split("?")[0]
            if path == "/events":
                return self._events()
            name = "index.html" if path == "/" else path.lstrip("/")
            for folder in web_dirs:
                file = pathlib.Path(folder) / name
                if "/" not in name and file.is_file():
                    return self._send(file.read_bytes(), CONTENT_TYPES.get(file.suffix))
            self.send_error(404)

        def _send(self, body, content_type):
            self.send_response(200)
            self.send_header("Content-Type", content_type or "application/octet-stream")
            self.send_header("Content-Length", str(len(body)))
            self.send_header("Cache-Control", "no-store")
            self.end_headers()
            self.wfile.write(body)

        def _events(self):
            self.send_response(200)
            self.send_header("Content-Type", "text/event-stream")
            self.send_header("Cache-Control", "no-store")
            self.end_headers()
            try:
                self._stream()
            except (BrokenPipeError, ConnectionResetError):
                pass
            self.close_connection = True

        def _stream(self):
            with scope.lock:
                seq, text = scope.full_frame()
            self._event(text)
            while scope.running:
                with scope.lock:
                    scope.new_frame.wait_for(lambda: scope.seq > seq or not scope.running, 1.0)
                    if scope.ring and scope.ring[0][0] > seq + 1:  # fell behind: start anew
                        seq, text = scope.full_frame()
                        texts = [text]
                    else:
                        texts = [t for s, t in scope.ring if s > seq]
                        seq = scope.seq
                for text in texts:
                    self._event(text)
                if not texts:
                    self.wfile.write(b": idle\n\n")
                    self.wfile.flush()

        def _event(self, text):
            self.wfile.write(b"data: " + text.encode() + b"\n\n")
            self.wfile.flush()

    return Handler


class Server(http.server.ThreadingHTTPServer):
    daemon_threads = True
    allow_reuse_address = True
