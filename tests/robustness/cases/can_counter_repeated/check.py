from case_checks import can, events, expect  # noqa: F401
expect(can["counter_failures"] == 1, "exactly the repeated frame is rejected")
expect(can["checksum_failures"] == 0 and can["bad_frames"] == 0, "nothing else")
