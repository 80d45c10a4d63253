#!/usr/bin/env bash
# grade.sh [FOLDER] - the grading step of rayo-grade.yml, as a script so
# that it runs the same anywhere: grades FOLDER (default: the current
# one, the student's repository) with rayo, prints the report, adds it
# to the job's summary ($GITHUB_STEP_SUMMARY) when there is one, and
# exits 0 when every criterion passed, 1 when one failed, 2 when it
# could not grade.
set -u
EXERCISE=${RAYO_EXERCISE:-ej1}
OPTIONS=${RAYO_OPTIONS:-}
folder=${1:-.}
report=$(mktemp)
trap 'rm -f "$report"' EXIT

# shellcheck disable=SC2086 # OPTIONS is a list of words
rayo grade --exercise "$EXERCISE" $OPTIONS "$folder" >"$report" 2>&1
status=$?
cat "$report"
if [ -n "${GITHUB_STEP_SUMMARY:-}" ]; then
    {
        echo "## rayo grade ($EXERCISE)"
        echo
        echo '```'
        cat "$report"  # escaped by rayo: no raw control bytes
        echo '```'
    } >>"$GITHUB_STEP_SUMMARY"
fi
exit "$status"
