from case_checks import can, events, expect  # noqa: F401
expect(can["bad_frames"] == 6, "6 FD frames on a classic id, 6 bad frames")
expect(can["counter_failures"] == 0 and can["checksum_failures"] == 0, "never decoded")
