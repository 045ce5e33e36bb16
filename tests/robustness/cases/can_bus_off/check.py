from case_checks import can, events, expect  # noqa: F401
expect(can["bus_state"] == "bus-off", "bus-off in the summary")
e = [e for e in events if e["event"] == "can_bus_off"]
expect(len(e) == 1 and e[0]["detail"].startswith("vcan0: bus up -> bus-off"), "one event")
status = [l.rstrip() for l in open("rig.err") if l.startswith("rig: cycles")]
expect(any(l.endswith(", CAN bus-off") for l in status), f"status lines: {status}")
