from case_checks import can, events, expect  # noqa: F401
rx = [e for e in events if e["event"] == "out_of_range" and e["detail"].startswith("rx ")]
expect(len(rx) == 1, "the first clamp at once; the other 4 within the second are counted")
expect(rx[0]["detail"] == "rx EPS_Status.EPS_MotorTorque: 20 outside [-15, 15], clamped to 15;"
       " 1 since the last report", "message, signal, value, range, clamp")
