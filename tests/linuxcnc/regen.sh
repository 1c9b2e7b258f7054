#!/bin/sh
# Re-records LinuxCNC's canonical output for every program here:
# NAME.ngc -> NAME.out (rs274's standard output, the canonical calls) and
# NAME.err (its standard error: "executing", then on an error the message and
# the offending block). Needs Debian's linuxcnc-uspace (rs274 on PATH).
# No INI, tool table or var file is used; standard input is closed.
set -eu
cd "$(dirname "$0")"
for f in *.ngc; do
	n=${f%.ngc}
	rs274 -g "$f" </dev/null >"$n.out" 2>"$n.err" || true
done
