from case_checks import can, events, expect  # noqa: F401
expect(can["bad_frames"] == 5, "5 RTR frames, 5 bad frames")
expect(can["counter_failures"] == 0 and can["checksum_failures"] == 0, "never decoded")
expect(can["frames_received"] >= 5, "the frames arrived")
