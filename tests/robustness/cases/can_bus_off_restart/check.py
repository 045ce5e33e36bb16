from case_checks import can, events, expect  # noqa: F401
expect(can["bus_state"] == "up", "up again after the restart")
expect(can["error_frames"] == 2, "two error frames")
names = [e["event"] for e in events if e["event"].startswith("can_")]
expect(names == ["can_bus_off", "can_bus_up"], "bus-off, then up")
