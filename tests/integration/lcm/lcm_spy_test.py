#!/usr/bin/python3
"""scripts/lcm-spy under xvfb-run against a replayed rig log (network namespace of its own): the
rig's LCM log (`rig run --offline` of the demo, 2 s) is replayed by lcm-logplayer, twice, while
lcm-spy runs. lcm-spy must find exactly the rig's 3 types on its class path ("Found 3 LCM types";
with a jar without types: 0, so the 3 are the rig's), print no Java exception, still run after
the replay (Java 17 refused Debian's own start script), and its window is written as a PNG from
Xvfb's frame buffer (-fbdir, XWD) to OUTPNG.

usage: lcm_spy_test.py BINDIR SOURCEDIR OUTPNG
"""
import os
import pathlib
import shutil
import signal
import struct
import subprocess
import sys
import tempfile
import time
import zipfile
import zlib

BIN, SOURCE, OUTPNG = (pathlib.Path(a) for a in sys.argv[1:4])
sys.path.insert(0, str(SOURCE / "tests" / "support"))
from netns import in_netns  # noqa: E402

SPY = SOURCE / "scripts" / "lcm-spy"


def xwd_to_png(xwd, png):
    """Xvfb's screen (XWD, 24-bit TrueColor in 32-bit pixels) as a PNG."""
    data = xwd.read_bytes()
    header_size = struct.unpack_from(">I", data, 0)[0]
    fields = struct.unpack_from(">25I", data, 0)
    width, height, bits_per_pixel, bytes_per_line = fields[4], fields[5], fields[11], fields[12]
    ncolors = fields[19]
    assert bits_per_pixel == 32, bits_per_pixel
    pixels = data[header_size + 12 * ncolors:]
    rows = []
    little = fields[7] == 0  # byte order LSBFirst
    for y in range(height):
        row = pixels[y * bytes_per_line:y * bytes_per_line + 4 * width]
        rgb = bytearray(3 * width)
        if little:  # B G R X
            rgb[0::3], rgb[1::3], rgb[2::3] = row[2::4], row[1::4], row[0::4]
        else:  # X R G B
            rgb[0::3], rgb[1::3], rgb[2::3] = row[1::4], row[2::4], row[3::4]
        rows.append(b"\0" + bytes(rgb))

    def chunk(kind, body):
        return (struct.pack(">I", len(body)) + kind + body
                + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF))

    png.write_bytes(b"\x89PNG\r\n\x1a\n"
                    + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
                    + chunk(b"IDAT", zlib.compress(b"".join(rows), 6)) + chunk(b"IEND", b""))


def run_spy(tmp, log, env_extra, replay):
    fb = tmp / "fb"
    shutil.rmtree(fb, ignore_errors=True)
    fb.mkdir()
    env = dict(os.environ, **env_extra)
    spy = subprocess.Popen(["xvfb-run", "-a", "-s", f"-screen 0 1280x800x24 -fbdir {fb}",
                            str(SPY)], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                           text=True, env=env, start_new_session=True)
    out = []
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline:  # up when it has looked for its types
        line = spy.stdout.readline()
        if not line:
            break
        out.append(line)
        if "LCM types" in line:
            break
    alive = None
    if replay:
        time.sleep(2.0)  # its window and its LCM subscription
        for _ in range(2):
            subprocess.run(["lcm-logplayer", str(log)], check=True, stdout=subprocess.DEVNULL)
        time.sleep(1.5)
        alive = spy.poll() is None
        xwd_to_png(fb / "Xvfb_screen0", OUTPNG)
    os.killpg(spy.pid, signal.SIGTERM)  # xvfb-run, Xvfb and java: its own process group
    rest, _ = spy.communicate(timeout=20)
    return "".join(out) + rest, alive


def main():
    in_netns()
    for tool in ("xvfb-run", "java"):
        if shutil.which(tool) is None:
            print(f"SKIP: {tool} missing (scripts/setup installs it)")
            return 77
    with tempfile.TemporaryDirectory() as tmp_name:
        tmp = pathlib.Path(tmp_name)
        log = tmp / "run.lcm"
        subprocess.run([BIN / "rig", "run", "--config", SOURCE / "config/rig.toml", "--offline",
                        "--duration", "2", "--lcm-url", "none", "--lcm-log", log], check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        OUTPNG.parent.mkdir(parents=True, exist_ok=True)
        output, alive = run_spy(tmp, log, {}, replay=True)
        assert "Found 3 LCM types" in output, output
        assert "Exception" not in output and "Error" not in output, output
        assert alive, f"lcm-spy ended during the replay:\n{output}"
        assert OUTPNG.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"

        empty = tmp / "empty.jar"
        with zipfile.ZipFile(empty, "w") as z:
            z.writestr("README", "no LCM types here")
        control, _ = run_spy(tmp, log, {"RIG_LCMTYPES_JAR": str(empty)}, replay=False)
        assert "Found 0 LCM types" in control, control
    print(f"PASS: lcm-spy found the rig's 3 types and ran through the replay; window {OUTPNG}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
