from case_checks import can, events, expect  # noqa: F401
expect(can["counter_failures"] == 3, "jump + 2 latched steps rejected (unlatch_steps = 3)")
