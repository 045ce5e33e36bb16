"""rig-scope [--lcm-url URL] [--prefix P]... [--port 8765]: the rig's live dashboard."""
import argparse
import os
import signal
import sys
import threading

from rig_lcm.udpm import DEFAULT_URL, parse_url


def parse(argv):
    p = argparse.ArgumentParser(
        prog="rig-scope",
        description="Live dashboard of running rigs: subscribes to their LCM channels "
                    "(<prefix>RIG_STATE, RIG_STATUS) and serves a page on 127.0.0.1.")
    p.add_argument("--lcm-url", default=os.environ.get("LCM_DEFAULT_URL") or DEFAULT_URL,
                   help="udpm URL the rigs publish on (default: $LCM_DEFAULT_URL or %(default)s)")
    p.add_argument("--prefix", action="append", default=None, metavar="P",
                   help="channel prefix of a rig ([lcm] channel_prefix); repeat for several "
                        "rigs (default: one rig, no prefix)")
    p.add_argument("--port", type=int, default=8765,
                   help="TCP port on 127.0.0.1 (default %(default)s; 0: any free port)")
    args = p.parse_args(argv)
    try:
        parse_url(args.lcm_url)
    except ValueError as error:
        p.error(f"--lcm-url: {error}")
    if not 0 <= args.port <= 65535:
        p.error(f"--port {args.port}: need 0..65535")
    prefixes = args.prefix or [""]
    if len(set(prefixes)) != len(prefixes):
        p.error("--prefix: the same prefix twice")
    return args, prefixes


# what the page loads besides its own files: uPlot from npm (scripts/setup: npm ci in rig/scope)
PAGE_LIBRARY = ("uPlot.iife.min.js", "uPlot.min.css")


def missing_library(web_dirs):
    """The page's library files found in none of web_dirs."""
    return [name for name in PAGE_LIBRARY
            if not any(os.path.isfile(os.path.join(d, name)) for d in web_dirs)]


def main(argv, web_dirs):
    from .server import Scope, Server, handler_class

    args, prefixes = parse(argv)
    missing = missing_library(web_dirs)
    if missing:  # a page without its plotting library would load and never draw
        print(f"rig-scope: {', '.join(missing)} not found in {', '.join(map(str, web_dirs))}: "
              "run scripts/setup (npm ci in rig/scope)", file=sys.stderr)
        return 1
    try:
        scope = Scope(args.lcm_url, prefixes)
    except OSError as error:
        print(f"rig-scope: cannot receive {args.lcm_url}: {error} (a multicast route? "
              "ip route add 224.0.0.0/4 dev lo)", file=sys.stderr)
        return 1
    try:
        httpd = Server(("127.0.0.1", args.port), handler_class(scope, web_dirs))
    except OSError as error:
        print(f"rig-scope: cannot serve on 127.0.0.1:{args.port}: {error.strerror} "
              "(another --port?)", file=sys.stderr)
        return 1
    threads = [threading.Thread(target=scope.receive_forever, daemon=True),
               threading.Thread(target=scope.tick_forever, daemon=True)]
    for t in threads:
        t.start()

    def stop(*_):
        scope.stop()
        threading.Thread(target=httpd.shutdown, daemon=True).start()

    for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):
        signal.signal(sig, stop)
    shown = ", ".join(repr(p) for p in prefixes)
    print(f"rig-scope: http://127.0.0.1:{httpd.server_address[1]}/ (rigs {shown} on "
          f"{args.lcm_url})", flush=True)
    httpd.serve_forever(poll_interval=0.2)
    httpd.server_close()
    return 0
