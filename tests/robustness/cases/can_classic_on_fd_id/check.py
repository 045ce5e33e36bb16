from case_checks import can, events, expect  # noqa: F401
expect(can["bad_frames"] == 4, "4 classic frames on an FD id, 4 bad frames")
expect(can["counter_failures"] == 0 and can["checksum_failures"] == 0, "FD frames decoded")
