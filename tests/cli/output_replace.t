#!/bin/sh
# output_replace.t - `-o FILE` (and convert's and compare --diff's
# output) replaces an existing file only as a shell's `>` could write
# it, and keeps what the file was: an ordinary user's rayo refuses a
# file the user may not write (exit 1, one line, "Permission denied",
# the file intact, no temporary file); a replaced file keeps its mode
# and, for root, its owner and group; a symbolic link is followed only
# where the kernel's protected_symlinks rule would follow it (not, in a
# sticky world-writable directory, a link owned by neither us nor the
# directory's owner), whatever the kernel's own setting.
#
# Needs root (to make files of two users) and setpriv (util-linux) to
# run rayo as user nobody (65534); skipped otherwise.
. "$(dirname "$0")/lib.sh"

if [ "$(id -u)" != 0 ] || ! command -v setpriv >/dev/null 2>&1; then
    echo "1..0 # SKIP needs root and setpriv to act as two users"
    exit 0
fi

leftovers() { find "$1" -name '.*.??????' | wc -l | tr -d ' '; }
one_line() { wc -l <"$1" | tr -d ' '; }
owner_mode() { stat -c '%u:%g %a' "$1"; }
# as_nobody ARGS...: rayo ARGS as user and group 65534, no other groups;
# stderr in $TMP/err, the exit status in $status.
as_nobody() {
    status=0
    setpriv --reuid=65534 --regid=65534 --clear-groups "$RAYO" "$@" \
        >/dev/null 2>"$TMP/err" || status=$?
}
as_root() {
    status=0
    rayo "$@" >/dev/null 2>"$TMP/err" || status=$?
}

chmod 755 "$TMP" # nobody must reach the directories below
printf 'P2\n2 2\n255\n0 64 128 255\n' >"$TMP/a.pgm"
printf 'P2\n2 2\n255\n0 64 128 250\n' >"$TMP/b.pgm"
chmod 644 "$TMP/a.pgm" "$TMP/b.pgm"

# --- an ordinary user, a world-writable directory, root's 0444 file ---
mkdir "$TMP/open"
chmod 777 "$TMP/open"
refused() { # refused NAME FILE ARGS...
    what=$1 file=$2
    shift 2
    printf 'root\n' >"$file"
    chmod 444 "$file"
    as_nobody "$@"
    is "$status" 1 "$what: a user's rayo over root's 0444 file: exit 1"
    is "$(cat "$TMP/err")" "rayo: $file: Permission denied" "$what: one line: the file and the reason"
    is "$(cat "$file")" root "$what: the file is intact"
    is "$(owner_mode "$file")" "0:0 444" "$what: still root's, still 0444"
    is "$(leftovers "$TMP/open")" 0 "$what: no temporary file left"
}
refused render "$TMP/open/ro.pbm" render -W 8 -H 2 -o "$TMP/open/ro.pbm"
refused convert "$TMP/open/ro.png" convert "$TMP/a.pgm" "$TMP/open/ro.png"
refused "compare --diff" "$TMP/open/diff.png" compare "$TMP/a.pgm" "$TMP/b.pgm" --diff "$TMP/open/diff.png"

# A file the user may write is replaced, and keeps its mode.
printf 'mine\n' >"$TMP/open/mine.pbm"
chown 65534:65534 "$TMP/open/mine.pbm"
chmod 600 "$TMP/open/mine.pbm"
as_nobody render -W 8 -H 2 -o "$TMP/open/mine.pbm"
is "$status" 0 "the user's own 0600 file: replaced"
is "$(head -c 2 "$TMP/open/mine.pbm")" P1 "with the image"
is "$(owner_mode "$TMP/open/mine.pbm")" "65534:65534 600" "still the user's, still 0600"

# A file the user may write but, in a sticky directory, not replace
# (it is another user's): refused before rendering, as the rename would.
mkdir "$TMP/sticky-user"
chmod 1777 "$TMP/sticky-user"
printf 'shared\n' >"$TMP/sticky-user/shared.pbm"
chmod 666 "$TMP/sticky-user/shared.pbm"
as_nobody render -W 8 -H 2 -o "$TMP/sticky-user/shared.pbm"
is "$status" 1 "another user's 0666 file in a sticky directory: exit 1"
is "$(cat "$TMP/err")" "rayo: $TMP/sticky-user/shared.pbm: Operation not permitted" "one line: the file and the reason"
is "$(cat "$TMP/sticky-user/shared.pbm")" shared "the file is intact"
is "$(leftovers "$TMP/sticky-user")" 0 "no temporary file left"

# --- root replacing another user's file keeps its owner and mode ------
printf 'theirs\n' >"$TMP/open/theirs.ppm"
chown 65534:65534 "$TMP/open/theirs.ppm"
chmod 640 "$TMP/open/theirs.ppm"
as_root render -W 8 -H 2 --shade phong -o "$TMP/open/theirs.ppm"
is "$status" 0 "root replaces nobody's 0640 file"
is "$(head -c 2 "$TMP/open/theirs.ppm")" P3 "with the image"
is "$(owner_mode "$TMP/open/theirs.ppm")" "65534:65534 640" "which keeps its owner, group and mode"
as_root convert "$TMP/a.pgm" "$TMP/open/theirs.ppm" --format pgm
is "$(owner_mode "$TMP/open/theirs.ppm")" "65534:65534 640" "convert too"

# --- root and a link another user planted in a sticky directory -------
mkdir "$TMP/sticky" "$TMP/private"
chmod 1777 "$TMP/sticky"
printf 'secret\n' >"$TMP/private/secret.pbm"
chmod 600 "$TMP/private/secret.pbm"
setpriv --reuid=65534 --regid=65534 --clear-groups \
    ln -s "$TMP/private/secret.pbm" "$TMP/sticky/planted.pbm"
is "$(stat -c %u "$TMP/sticky/planted.pbm")" 65534 "a link owned by nobody in a sticky /tmp-like directory"
for cmd in render convert; do
    if [ "$cmd" = render ]; then
        as_root render -W 8 -H 2 -o "$TMP/sticky/planted.pbm"
    else
        as_root convert "$TMP/a.pgm" "$TMP/sticky/planted.pbm" --format pgm
    fi
    is "$status" 1 "$cmd: root does not follow it: exit 1"
    is "$(one_line "$TMP/err")" 1 "$cmd: one line"
    grep -q "^rayo: $TMP/sticky/planted.pbm: Permission denied (a symbolic link" "$TMP/err"
    ok $? "$cmd: the link and the reason"
    is "$(cat "$TMP/private/secret.pbm")" secret "$cmd: root's 0600 file is intact"
    ok "$([ -L "$TMP/sticky/planted.pbm" ]; echo $?)" "$cmd: the link is left as it was"
    is "$(leftovers "$TMP/sticky")$(leftovers "$TMP/private")" 00 "$cmd: no temporary file left"
done

# Root's own link there, and nobody's link in a directory that is not
# sticky, are followed: the link stays, its target is replaced.
ln -s "$TMP/private/secret.pbm" "$TMP/sticky/own.pbm"
as_root render -W 8 -H 2 -o "$TMP/sticky/own.pbm"
is "$status" 0 "root's own link in the sticky directory: followed"
is "$(head -c 2 "$TMP/private/secret.pbm")" P1 "its target replaced"
is "$(owner_mode "$TMP/private/secret.pbm")" "0:0 600" "keeping its mode"
ok "$([ -L "$TMP/sticky/own.pbm" ]; echo $?)" "the link stays a link"
mkdir "$TMP/plain"
chmod 777 "$TMP/plain"
printf 'secret\n' >"$TMP/private/other.pbm"
setpriv --reuid=65534 --regid=65534 --clear-groups \
    ln -s "$TMP/private/other.pbm" "$TMP/plain/link.pbm"
as_root render -W 8 -H 2 -o "$TMP/plain/link.pbm"
is "$status" 0 "nobody's link in a world-writable directory that is not sticky: followed"
is "$(head -c 2 "$TMP/private/other.pbm")" P1 "its target replaced"

# A link to a link: each is judged where it lies.
printf 'secret\n' >"$TMP/private/secret.pbm"
ln -s "$TMP/sticky/planted.pbm" "$TMP/plain/chain.pbm"
as_root render -W 8 -H 2 -o "$TMP/plain/chain.pbm"
is "$status" 1 "a link to nobody's link in the sticky directory: refused"
is "$(cat "$TMP/private/secret.pbm")" secret "the file it leads to is intact"
done_testing
