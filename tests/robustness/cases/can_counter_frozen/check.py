from case_checks import can, events, expect  # noqa: F401
# Every frozen frame is rejected, also those after a timeout (before: 1 in 4 passed, as a
# timeout started a new counter sequence).
expect(can["counter_failures"] == 30, "30 frozen frames, 30 counter failures")
expect(can["checksum_failures"] == 0 and can["bad_frames"] == 0, "only counter failures")
