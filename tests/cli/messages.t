#!/bin/sh
# messages.t - every message is one line whatever a file name or an
# option's value holds: control bytes written as \n, \x1b, ..., a C1
# control or a byte that is not UTF-8 as \xHH, a long option value quoted
# as a prefix and its length (cli/quote.c), and a message cut at 1000
# bytes with "..." (cli/escape.c), in every command.
. "$(dirname "$0")/lib.sh"

# one_line NAME STATUS ARGS...: that exit status (2: bad input, a file
# that cannot be opened included), stderr one line with no control byte but its
# newline; the line in $line.  (Test names never hold $line: the shell's
# echo would turn its \n back into a newline.)
one_line() {
    name=$1 want=$2
    shift 2
    run_capture "$@"
    is "$status" "$want" "$name: exit status $want"
    is "$(wc -l <"$TMP/err" | tr -d ' ')" 1 "$name: one line on stderr"
    LC_ALL=C grep -q "$(printf '[\001-\011\013-\037\177]')" "$TMP/err"
    is "$?" 1 "$name: no control byte in it"
    line=$(cat "$TMP/err")
}

forged=$(printf 'bad\nrayo: the file is fine, exit 0\033[2J.pgm')
rayo -W 8 -H 4 -o "$TMP/small.pbm"

one_line "compare, a name with a newline and ESC" 2 compare "$forged" "$TMP/small.pbm"
case $line in *'bad\nrayo: the file is fine, exit 0\x1b[2J.pgm'*) r=0 ;; *) r=1 ;; esac
ok "$r" "  the name shown escaped"
one_line "view, the same name" 2 view "$forged"
one_line "convert, the same name" 2 convert "$forged" "$TMP/out.png"
one_line "grade, the same name as --reference" 2 grade --no-valgrind \
    --reference "$forged" "$RAYO_SOURCE/tests/grade/correct/main.c"
one_line "render, the same name as a scene" 2 render "$forged"

c1=$(printf 'c1\302\233x.pgm')
one_line "a C1 control (U+009B, CSI) in a name" 2 compare "$c1" "$TMP/small.pbm"
case $line in *'c1\xc2\x9bx.pgm'*) r=0 ;; *) r=1 ;; esac
ok "$r" "  shown as backslash-x c2, backslash-x 9b"
accented=$(printf 'im\303\241gen.pgm')
one_line "valid UTF-8 in a name" 2 compare "$accented" "$TMP/small.pbm"
case $line in *"$accented"*) r=0 ;; *) r=1 ;; esac
ok "$r" "  kept as it is"

digits=$(head -c 100000 /dev/zero | tr '\0' 9)
one_line "a 100000-digit -W" 2 -W "$digits"
is "$line" "rayo: --width: '9999999999999999…' (100000 characters) is out of range; expected 1 to 65536" \
    "  the value quoted as its first 16 digits and its length"

# A name is not quoted short (a cut name cannot be found); a very long
# one still makes one line of at most the 1000 bytes a message may take.
long_name=$(head -c 3000 /dev/zero | tr '\0' n)
one_line "a 3000-byte file name" 2 view "$long_name"
bytes=$(wc -c <"$TMP/err" | tr -d ' ')
[ "$bytes" -le 1010 ]
ok $? "  the message is cut: $bytes bytes"

done_testing
