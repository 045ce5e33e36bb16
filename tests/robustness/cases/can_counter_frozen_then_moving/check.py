from case_checks import can, events, expect  # noqa: F401
expect(can["counter_failures"] == 20, "the 20 frozen frames only")
