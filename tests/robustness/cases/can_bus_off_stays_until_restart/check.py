from case_checks import can, events, expect  # noqa: F401
expect(can["bus_state"] == "bus-off", "only a restart ends bus-off")
expect(can["error_frames"] == 3, "three error frames")
