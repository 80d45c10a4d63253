#!/bin/sh
# render_basics.t - the default command: what `rayo` with no arguments
# writes, checked byte for byte against an independent computation.
. "$(dirname "$0")/lib.sh"

run_capture
is "$status" 0 "rayo exits 0"
is "$(head -n 2 "$TMP/out" | tr '\n' ' ')" "P1 640 480 " "plain PBM header, 640x480"
longest=$(awk 'NR > 2 { if (length($0) > m) m = length($0) } END { print m }' "$TMP/out")
ok "$([ "$longest" -le 70 ]; echo $?)" "no raster line longer than 70 characters ($longest)"
done_testing
