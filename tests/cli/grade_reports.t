#!/bin/sh
# grade_reports.t - `rayo grade` gives, byte for byte, the reports
# recorded in tests/data/grade/reports.txt: every student program of
# tests/grade/ (its exercise named by its folder's prefix) and every
# fixture of tests/grade/functions/, in English and in Spanish, without
# valgrind; and a handful with valgrind, the ones whose valgrind
# criterion has something to say.  This is what lets the grader's
# insides move (one functions engine, the course's catalogue of
# mistakes) without a report changing unnoticed.
#
# Two things vary from run to run and machine to machine and are
# normalised before comparing: the report's first line (how this
# machine isolates a run) and the seconds a run took ("in 0.08 s",
# "en 0,08 s").
#
# To record them again, only after a deliberate change of a report:
#   RECORD=1 RAYO=build/rayo RAYO_SOURCE=. sh tests/cli/grade_reports.t \
#       >tests/data/grade/reports.txt
. "$(dirname "$0")/lib.sh"

WANT="$RAYO_SOURCE/tests/data/grade/reports.txt"
if [ "${RAYO_VALGRIND:-0}" = 1 ]; then
    # The reports do not depend on how rayo itself is run; the other
    # grade tests run it under valgrind.
    echo "1..0 # SKIP the recorded reports are checked by make check"
    exit 0
fi
cd "$RAYO_SOURCE" || exit 1

# exercise PATH: ej2 or ej3 for a name starting so, else ej1.
exercise() {
    case $(basename "$1") in
    ej2_*) echo ej2 ;;
    ej3_*) echo ej3 ;;
    *) echo ej1 ;;
    esac
}

# report FILE NAME ARGS...: into FILE, "== NAME", the normalised report
# and its exit status.
report() {
    file=$1 name=$2
    shift 2
    status=0
    "$RAYO" grade --cc cc --timeout 10 "$@" </dev/null >"$file.raw" 2>&1 || status=$?
    {
        echo "== $name"
        sed -e '1{/^sandbox: /d;}' -e 's/ \(in\|en\) [0-9][0-9.,]* s\b/ \1 N s/g' "$file.raw"
        echo "== exit status $status"
    } >"$file"
    rm -f "$file.raw"
}

# The cases, one line each: a name and the options, tab-separated.
case_list() {
    for dir in tests/grade/*/ tests/grade/functions/*.c; do
        dir=${dir%/}
        file=$dir
        [ -d "$dir" ] && file=$dir/main.c
        [ -f "$file" ] || continue
        printf '%s en\t--lang en --no-valgrind --exercise %s %s\n' "$dir" "$(exercise "$dir")" "$file"
    done
    # Spanish: the criteria's own lines and the summary.
    for dir in correct segfault rows_flipped ej2_no_shadows ej2_nan_miss ej3_correct ej3_sphere_moved \
            ej2_first_sphere ej2_wrapped ej3_no_shadows ej3_ka_kd_swapped; do
        printf 'tests/grade/%s es\t--lang es --no-valgrind --exercise %s tests/grade/%s/main.c\n' "$dir" "$(exercise "$dir")" "$dir"
    done
    # Spanish, every criterion's own lines (grade's catalogue outside
    # functions/): a compile error and a warning made one, a crash and a
    # limit, a header, the image's mistakes and its notes.
    for dir in werror macro_parameter infinite_loop dimensions_x lowercase_magic degrees pi_course literal_rows no_normalise extra_row ej2_pi_course ej2_correct; do
        printf 'tests/grade/%s es\t--lang es --no-valgrind --exercise %s tests/grade/%s/main.c\n' "$dir" "$(exercise "$dir")" "$dir"
    done
    if command -v valgrind >/dev/null 2>&1; then
        for dir in leak ej3_write_past_end; do
            printf 'tests/grade/%s valgrind es\t--lang es --exercise %s tests/grade/%s/main.c\n' "$dir" "$(exercise "$dir")" "$dir"
        done
    fi
    if command -v valgrind >/dev/null 2>&1; then
        for dir in leak interior_pointer ej3_leak ej3_realloc_loses ej3_write_past_end; do
            printf 'tests/grade/%s valgrind\t--exercise %s tests/grade/%s/main.c\n' "$dir" "$(exercise "$dir")" "$dir"
        done
    fi
}

# cases: every case's report, in the list's order, two at a time.
cases() {
    mkdir -p "$TMP/cases"
    case_list >"$TMP/list"
    n=0
    while IFS='	' read -r name options; do
        n=$((n + 1))
        # shellcheck disable=SC2086
        report "$TMP/cases/$(printf %04d "$n")" "$name" $options &
        [ $((n % 2)) -ne 0 ] || wait
    done <"$TMP/list"
    wait
    cat "$TMP/cases"/[0-9]*
}

if [ -n "${RECORD:-}" ]; then
    cases
    exit 0
fi

cases >"$TMP/got"
# One assert per case, keyed by its name (so that a case added or taken
# away fails alone and names the program).
split_cases() { # FILE DIR: each case into DIR, in a file named after it
    mkdir -p "$2"
    awk -v dir="$2" '/^== / && !/^== exit status/ {
                         file = substr($0, 4); gsub(/[^A-Za-z0-9_.-]/, "_", file) }
                     { print > (dir "/" file) }' "$1"
}
split_cases "$TMP/got" "$TMP/g"
split_cases "$WANT" "$TMP/w"
for want in "$TMP"/w/*; do
    i=$(basename "$want")
    name=$(head -n 1 "$want" | cut -c4-)
    same=1
    cmp -s "$want" "$TMP/g/$i" && same=0
    ok "$same" "$name: the report as recorded"
    [ "$same" -eq 0 ] || diff "$want" "$TMP/g/$i" 2>&1 | sed 's/^/#   /' | head -20
done
is "$(ls "$TMP/g" | wc -l | tr -d ' ')" "$(ls "$TMP/w" | wc -l | tr -d ' ')" \
    "as many cases as recorded"
done_testing
