from case_checks import can, events, expect  # noqa: F401
expect(can["error_frames"] == 1, "one error frame")
expect(can["bus_state"] == "error-passive", "an error frame sets error-passive")
e = [e for e in events if e["event"] == "can_error_passive"]
expect(len(e) == 1 and e[0]["detail"].startswith("vcan0: bus up -> error-passive"), "one event")
