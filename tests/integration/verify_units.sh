#!/bin/sh
# systemd-analyze verify exits 0 on many errors, so any stderr output is a failure.
# verify_units.sh RIG_BINARY SOURCE_DIR: checks the unit of systemd/rig.service.in with ExecStart
# pointing at the built binary (verify requires it to exist), after proving that a bad key is
# reported. The installed unit: tests/install (install_staging).
set -eu
rig=$1 src=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
sed "s#@RIG_BINDIR@/rig#$rig#; s#@RIG_SYSCONFDIR@#/etc#; s#@RIG_DOCDIR@#/usr/share/doc/rig#" \
  "$src/systemd/rig.service.in" > "$dir/rig.service"
sed 's/^\[Service\]/[Service]\nBogusKey=1/' "$dir/rig.service" > "$dir/rig-bad.service"
systemd-analyze verify "$dir/rig-bad.service" 2> "$dir/bad.err" || true
grep -q "BogusKey" "$dir/bad.err" || { echo "FAIL: verify does not report errors on stderr"; exit 1; }
systemd-analyze verify "$dir/rig.service" 2> "$dir/err"
if [ -s "$dir/err" ]; then echo "FAIL: systemd-analyze verify:"; cat "$dir/err"; exit 1; fi
echo "PASS: rig.service verifies quietly"
