from case_checks import can, events, expect  # noqa: F401
# Before the latch each of these frames opened a new sequence and read valid.
expect(can["counter_failures"] == 12, "12 frozen frames, 12 counter failures")
