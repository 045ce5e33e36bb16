from case_checks import can, events, expect  # noqa: F401
expect(can["counter_failures"] == 1, "the jump is rejected, the next proper step accepted")
