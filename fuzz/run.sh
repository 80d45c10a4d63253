#!/bin/sh
# run.sh - runs one libFuzzer target built by `make fuzz` for a bounded
# time, the way CI and docs/robustness.md do.
#
#   fuzz/run.sh BUILD-fuzz NAME SECONDS [libFuzzer options...]
#
# The working corpus grows in BUILD-fuzz/work/NAME (seeded from
# fuzz/corpus/NAME and fuzz/regression/NAME, so the tree stays clean);
# a crash, leak, timeout or out-of-memory input is written to
# BUILD-fuzz/artifacts/NAME/ and the script exits non-zero.  Copy such an
# input into fuzz/regression/NAME/ once it is fixed, so `make check`
# replays it for ever.  The last line printed is libFuzzer's summary
# (executions, coverage, corpus).
set -eu
[ $# -ge 3 ] || { echo "usage: $0 BUILD-fuzz NAME SECONDS [options]" >&2; exit 2; }
build=$1 name=$2 seconds=$3
shift 3
bin="$build/fuzz/fuzz-$name"
[ -x "$bin" ] || { echo "$0: $bin: not built; run 'make fuzz'" >&2; exit 2; }
work="$build/work/$name"
artifacts="$build/artifacts/$name"
mkdir -p "$work" "$artifacts"
cp -n fuzz/corpus/"$name"/* "$work/" 2>/dev/null || true
find fuzz/regression/"$name" -type f ! -name '.*' -exec cp -n {} "$work/" \;
log="$build/fuzz-$name.log"
status=0
# -close_fd_mask=3: the command-line parsers print; libFuzzer keeps its
# own report on a copy of stderr.  2 GiB of RSS and 1 GiB per malloc are
# far above what any input within the limits needs (limits.h).
"$bin" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -malloc_limit_mb=1024 -max_len=8192 -close_fd_mask=3 -print_final_stats=1 \
    -artifact_prefix="$artifacts/" "$@" "$work" >"$log" 2>&1 || status=$?
grep -E '^#[0-9]+.*(DONE|pulse|NEW|REDUCE)' "$log" | tail -1
grep -E '^stat::(number_of_executed_units|average_exec_per_sec|peak_rss_mb)' "$log" || true
if [ "$status" != 0 ]; then
    echo "$0: $name: libFuzzer found a problem (status $status); see $log and $artifacts" >&2
    grep -E 'ERROR|SUMMARY|==[0-9]+==' "$log" | head -5 >&2
fi
exit "$status"
