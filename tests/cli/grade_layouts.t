#!/bin/sh
# grade_layouts.t - a class as teachers receive it: `rayo grade --each`
# groups a flat folder of files named by student, Moodle's download
# (folders, flat files, online text), zip files per student and GitHub
# Classroom's repositories, and says how (a line per student on stderr,
# files it could not place listed); hostile zips (a path that climbs
# out, an absolute path, a link, a bomb, one whose header lies about its
# size) are refused with one line each and write nothing outside;
# --feedback DIR writes each student's report, the one `rayo grade`
# prints, named safely from the student's name.  The zips are made with
# python3's zipfile, the reader under test being rayo's own.
. "$(dirname "$0")/lib.sh"

STUDENTS="$RAYO_SOURCE/tests/grade"
NV=--no-valgrind
CORRECT="$STUDENTS/correct/main.c"

# results FILE: "student=result" of a --json class, one a line.
results() { jq -r '.[] | .student + "=" + .result' "$1" | tr '\n' ' '; }

# ---- a flat folder of files named by student ----
mkdir "$TMP/flat"
# ana's main.c includes her own header, so her files must be copied
# under their own names (nota.h) to compile.
{ echo '#include "nota.h"'; cat "$CORRECT"; } >"$TMP/flat/ana_main.c"
echo '/* ana */' >"$TMP/flat/ana_nota.h"
cp "$STUDENTS/norma_int/main.c" "$TMP/flat/ana_perez_main.c"
cp "$STUDENTS/degrees/main.c" "$TMP/flat/beto-main.c"
echo 'notes' >"$TMP/flat/README.txt"
cp "$CORRECT" "$TMP/flat/main.c"
run_capture grade $NV -j 2 --json --each "$TMP/flat"
is "$(results "$TMP/out")" "ana=pass ana_perez=fail beto=fail " \
    "flat: three students; ana's header went with her main.c"
is "$(cat "$TMP/err")" "rayo: $TMP/flat: how the submissions were grouped (3 in all)
rayo: ana (files named by student): ana_main.c, ana_nota.h
rayo: ana_perez (files named by student): ana_perez_main.c
rayo: beto (files named by student): beto-main.c
rayo: left out: README.txt (not a C source, header or zip file)
rayo: left out: main.c (no student's name before the file's own name; expected NAME_main.c)" \
    "flat: a line per student and per file left out; 'main.c', which everyone hands in, is the own name"
is "$(jq -r '.[1].criteria[1].reasons[0]' "$TMP/out" | cut -c 1-24)" "norma(0.5, 0.5, 0.5) ret" \
    "flat: ana_perez is graded on her own file"

# The split is the class's: the own name most files share, then the
# name most files could have, then the longer name.  (The compiler is
# 'false': only the grouping is looked at.)
mkdir "$TMP/split"
for f in ana_main.c ana_vector_utils.c beto_main.c beto_vector_utils.c \
    carla_lopez_main.c carla_lopez_vec.h dan-main.c; do
    echo 'int x;' >"$TMP/split/$f"
done
run_capture grade $NV --cc false --each "$TMP/split"
is "$(sed 1d "$TMP/err")" "rayo: ana (files named by student): ana_main.c, ana_vector_utils.c
rayo: beto (files named by student): beto_main.c, beto_vector_utils.c
rayo: carla_lopez (files named by student): carla_lopez_main.c, carla_lopez_vec.h
rayo: dan (files named by student): dan-main.c" \
    "flat: underscores in the name and in the own name, split by the class"

# ---- Moodle ----
mkdir "$TMP/moodle"
a="$TMP/moodle/Ana Pérez_12345_assignsubmission_file_"
b="$TMP/moodle/Beto Gómez_12346_assignsubmission_file_"
mkdir "$a" "$b" "$TMP/moodle/Beto Gómez_12346_assignsubmission_onlinetext_"
cp "$CORRECT" "$a/main.c"
cp "$STUDENTS/lowercase_magic/main.c" "$b/main.c"
cp "$STUDENTS/dimensions_x/main.c" "$TMP/moodle/Caro Díaz_12347_assignsubmission_file_main.c"
# Dani uploaded a folder: the sources are two folders down.
mkdir -p "$TMP/moodle/Dani Ruiz_12348_assignsubmission_file_/tp1/src"
cp "$CORRECT" "$TMP/moodle/Dani Ruiz_12348_assignsubmission_file_/tp1/src/"
run_capture grade $NV -j 2 --each "$TMP/moodle" --feedback "$TMP/fb"
is "$status" 1 "Moodle: exit 1 (two failed)"
is "$(cat "$TMP/err")" "rayo: $TMP/moodle: how the submissions were grouped (4 in all)
rayo: Ana Pérez (Moodle): Ana Pérez_12345_assignsubmission_file_/main.c
rayo: Beto Gómez (Moodle): Beto Gómez_12346_assignsubmission_file_/main.c
rayo: Caro Díaz (Moodle): Caro Díaz_12347_assignsubmission_file_main.c
rayo: Dani Ruiz (Moodle): Dani Ruiz_12348_assignsubmission_file_/tp1/src/main.c
rayo: left out: Beto Gómez_12346_assignsubmission_onlinetext_ (Moodle's online text, not a file)" \
    "Moodle: the name before _ID_assignsubmission_, folders (one inside another too) and flat files"
is "$(sed -n '3,6p' "$TMP/out" | awk '{ print $1, $2, $NF }' | tr '\n' ' ')" \
    "Ana Pérez PASS Beto Gómez FAIL Caro Díaz FAIL Dani Ruiz PASS " "Moodle: the table's rows"

# ---- --feedback ----
is "$(ls "$TMP/fb" | LC_ALL=C sort | tr '\n' ' ')" "Ana_Pérez.txt Beto_Gómez.txt Caro_Díaz.txt Dani_Ruiz.txt " \
    "--feedback: one report per student, named from the name, nothing else left"
untimed() { sed 's/ran to the end in [0-9.]* s/ran to the end in T s/'; }
rayo grade $NV "$b" 2>/dev/null | untimed >"$TMP/beto.txt"
untimed <"$TMP/fb/Beto_Gómez.txt" | cmp -s - "$TMP/beto.txt"
ok $? "--feedback: the file is the report 'rayo grade' prints for that submission"
grep -q "^output     FAIL     the magic number is 'p1' in lowercase" "$TMP/fb/Beto_Gómez.txt"
ok $? "--feedback: Beto's report names his mistake"
tail -n 1 "$TMP/fb/Caro_Díaz.txt" | grep -q '^FAIL: 1 of 6 criteria failed (output)'
ok $? "--feedback: Caro's report (a flat Moodle file) ends with its verdict"

# Names that could escape the folder or collide, and a student who
# cannot be graded.
mkdir "$TMP/odd" "$TMP/odd/a b" "$TMP/odd/a_b" "$TMP/odd/x*\"y" \
    "$TMP/odd/$(printf 'new\nline')" "$TMP/odd/empty"
for d in "a b" a_b "x*\"y" "$(printf 'new\nline')"; do cp "$CORRECT" "$TMP/odd/$d/"; done
run_capture grade $NV -j 2 --each "$TMP/odd" --feedback "$TMP/fb2"
is "$(ls -A "$TMP/fb2" | LC_ALL=C sort | tr '\n' ' ')" "a_b-2.txt a_b.txt empty.txt new_line.txt x_y.txt " \
    "--feedback: unsafe names made safe ('x*\"y' -> 'x_y', a newline -> '_'), collisions numbered"
is "$(cat "$TMP/fb2/empty.txt")" \
    "rayo grade could not grade this submission: $TMP/odd/empty: no .c file in this folder; expected the submission's C sources" \
    "--feedback: a student who could not be graded is told why"
grep -c 'new\\nline' "$TMP/err" | grep -q '^1$'
ok $? "the grouping's lines escape a newline in a name"
expect_usage_error "--feedback without --each" "--feedback: writes one report per student" \
    grade --feedback "$TMP/fb3" "$CORRECT"
echo x >"$TMP/not_a_dir"
run_capture grade $NV --each "$TMP/odd" --feedback "$TMP/not_a_dir"
is "$status:$(tail -n 1 "$TMP/err")" "2:rayo: --feedback: $TMP/not_a_dir: not a folder; expected a folder for the students' reports" \
    "--feedback onto a file: refused, exit 2, before grading"

# ---- zip files ----
mkdir "$TMP/zips" "$TMP/zips/caro"
cat >"$TMP/mkzip.py" <<'PY'
import struct, sys, zipfile
out, correct, degrees = sys.argv[1:4]
src = open(correct, 'rb').read()
def make(name, entries):
    with zipfile.ZipFile(out + '/' + name, 'w', zipfile.ZIP_DEFLATED) as z:
        for n, data, mode in entries:
            info = zipfile.ZipInfo(n)
            info.compress_type = zipfile.ZIP_DEFLATED
            if mode is not None:
                info.create_system = 3
                info.external_attr = mode << 16
            z.writestr(info, data)
make('ana.zip', [('ana/main.c', src, None), ('__MACOSX/ana/._main.c', b'junk', None),
                 ('ana/notas.txt', b'x', None)])
make('beto.zip', [('main.c', open(degrees, 'rb').read(), None)])
make('caro/entrega.zip', [('main.c', src, None)])
make('h_climb.zip', [('main.c', src, None), ('../escaped.c', b'int x;\n', None)])
make('h_absolute.zip', [('/tmp/rayo-escaped.c', b'int x;\n', None)])
make('h_link.zip', [('main.c', src, None), ('vector.h', b'/etc/passwd', 0o120777)])
make('h_bomb.zip', [('main.c', b'\0' * (20 << 20), None)])
make('h_liar.zip', [('main.c', b'/' * (5 << 20), None)])
# The liar's headers say 100 bytes: only the inflating can stop it.
b = bytearray(open(out + '/h_liar.zip', 'rb').read())
struct.pack_into('<I', b, 22, 100)
struct.pack_into('<I', b, b.find(b'PK\x01\x02') + 24, 100)
open(out + '/h_liar.zip', 'wb').write(b)
PY
python3 "$TMP/mkzip.py" "$TMP/zips" "$CORRECT" "$STUDENTS/degrees/main.c"
ok $? "python3 makes the zips"
is "$(wc -c <"$TMP/zips/h_bomb.zip" | awk '{ print ($1 < 100000) }')" 1 \
    "the bomb is small (it inflates to 20 MiB)"
run_capture grade $NV -j 2 --json --each "$TMP/zips"
is "$(results "$TMP/out")" \
    "ana=pass beto=fail caro=pass h_absolute=error h_bomb=error h_climb=error h_liar=error h_link=error " \
    "zip: each zip a student (and a zip alone in a folder); hostile ones refused"
is "$(grep -c '' "$TMP/err"):$(sed -n '2,4p' "$TMP/err" | tr '\n' '|')" \
    "9:rayo: ana (a zip file): ana.zip, main.c|rayo: beto (a zip file): beto.zip, main.c|rayo: caro (a folder): caro/entrega.zip, main.c|" \
    "zip: the zip and the sources taken from it (macOS's ._ files and other entries left out)"
error_of() { jq -r --arg s "$1" '.[] | select(.student == $s) | .error' "$TMP/out"; }
is "$(error_of h_climb)" "$TMP/zips/h_climb.zip: the entry '../escaped.c' climbs out of the folder with '..'; refusing the archive" \
    "a zip with '..': refused, one line saying which entry and why"
is "$(error_of h_absolute)" "$TMP/zips/h_absolute.zip: the entry '/tmp/rayo-escaped.c' is an absolute path; refusing the archive" \
    "a zip with an absolute path: refused"
is "$(error_of h_link)" "$TMP/zips/h_link.zip: the entry 'vector.h' is a symbolic link; refusing the archive" \
    "a zip with a symbolic link: refused"
is "$(error_of h_bomb)" "$TMP/zips/h_bomb.zip: the entry 'main.c' inflates past the 1 MiB a source may have; refusing the archive" \
    "a zip bomb: refused by its declared size"
is "$(error_of h_liar)" "$TMP/zips/h_liar.zip: the entry 'main.c' inflates past the 1 MiB a source may have; refusing the archive" \
    "a zip bomb whose headers lie: stopped while inflating"
test ! -e "$TMP/escaped.c" && test ! -e "$TMP/zips/escaped.c" && test ! -e /tmp/rayo-escaped.c
ok $? "nothing was written outside rayo's folder"
mkdir "$TMP/tmpdir"
TMPDIR="$TMP/tmpdir" run_capture grade $NV --each "$TMP/zips"
grep -q '^h_climb    error: .*climbs out of the folder' "$TMP/out"
ok $? "the table: the refused zip's row is one line saying why"
is "$(ls -A "$TMP/tmpdir")" "" "rayo's folder of copied sources is removed at the end"

# The fuzz corpus's other refusals (fuzz/corpus/generate_zip.py).
mkdir "$TMP/more"
for z in bad-crc bad-duplicate bad-encrypted bad-truncated; do
    cp "$RAYO_SOURCE/fuzz/corpus/zip/$z.zip" "$TMP/more/"
done
run_capture grade $NV --cc false --json --each "$TMP/more"
is "$(jq -r '.[].error' "$TMP/out" | sed "s|^$TMP/more/||")" "bad-crc.zip: the entry 'main.c' is damaged (its size or CRC does not match)
bad-duplicate.zip: the entries 'a/main.c' and 'b/main.c' have the same name; expected one of each source
bad-encrypted.zip: the entry 'e.c' is encrypted; refusing the archive
bad-truncated.zip: not a zip file (no end of central directory); expected a zip archive" \
    "zip: a wrong CRC, two sources of one name, encryption, a cut end: refused, one line each"

# ---- GitHub Classroom ----
mkdir "$TMP/gh" "$TMP/gh/ej1-rayo-ana" "$TMP/gh/ej1-rayo-anabel"
cp "$CORRECT" "$TMP/gh/ej1-rayo-ana/"
cp "$STUDENTS/dimensions_x/main.c" "$TMP/gh/ej1-rayo-anabel/"
run_capture grade $NV -j 2 --json --each "$TMP/gh"
is "$(results "$TMP/out")" "ana=pass anabel=fail " \
    "Classroom: the shared 'assignment-' prefix is not the name"
is "$(sed -n 2p "$TMP/err")" "rayo: ana (a GitHub Classroom repository): ej1-rayo-ana/main.c" \
    "Classroom: said so"

# ---- nothing to grade ----
mkdir "$TMP/none"
echo x >"$TMP/none/notes.txt"
run_capture grade $NV --each "$TMP/none"
is "$status:$(cat "$TMP/err")" "2:rayo: $TMP/none: no submissions inside; --each expects a folder, zip file or files named NAME_main.c per student" \
    "a folder with no submission: exit 2, one line"

done_testing
