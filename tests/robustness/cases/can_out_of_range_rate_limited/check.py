from case_checks import can, events, expect  # noqa: F401
rx = [e for e in events if e["event"] == "out_of_range" and e["detail"].startswith("rx ")]
import re
counts = [int(re.search(r"; (\d+) since the last report$", e["detail"]).group(1)) for e in rx]
expect(2 <= len(rx) <= 4, "the first at once, then at most one a second (~2.7 s)")
expect(counts[0] == 1, "the first report is the first clamp")
expect(sum(counts) == 150, "the counts add up to the 150 clamped frames")
expect(all(e["detail"].startswith("rx EPS_Status.EPS_MotorTorque: -20 outside [-15, 15], "
                                  "clamped to -15;") for e in rx), "each names the signal")
