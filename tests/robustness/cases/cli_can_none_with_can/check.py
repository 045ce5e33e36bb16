"""assist_torque_nm (routed to CAN, CAN off): 0 and invalid in every logged cycle; one --can none warning."""
import csv, subprocess, sys
rows = list(csv.DictReader(open('csv/RIG_SIGNALS.csv')))
assert rows, 'no RIG_SIGNALS rows'
for r in rows:
    assert float(r['assist_torque_nm']) == 0.0, r['assist_torque_nm']
    assert int(float(r['assist_torque_nm_valid'])) == 0, r
lines = [l for l in open('stderr.txt') if '--can none' in l]
assert len(lines) == 1, lines
