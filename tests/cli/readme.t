#!/bin/sh
# readme.t - the README's examples, and those of LEEME.md (the students'
# guide in Spanish, whose console blocks include standard error), run as
# written after `make run`, from
# a folder laid out like the source tree (build/rayo is the rayo under
# test; examples/ and tests/ are the repository's).  Every ```sh block's
# lines must exit 0; every ```console block is run as one script and its
# output must be the README's, line for line (times such as "0.11 s" or "0,11 s" are
# compared as numbers of seconds, a line "..." stands for any lines; a
# grade report's "; limits: ..." clause, which depends on the machine's
# cgroups, is compared up to its first words).
#
# Not run here: the quick start itself (`make run`, `make check`: this is
# make check; `make run`'s two renders are done first instead) and the
# block that runs `make install PREFIX=$HOME/.local` (tests/cli/install.t
# installs and builds a student's program the same way), and the page's
# `make web` and its server (make check-web builds and serves it).  The two slow
# console blocks (grading EJ3 under valgrind, about 20 s, and a class
# whose infinite loop waits out its 10 s limit) run only with
# RAYO_README_ALL=1 (CI); otherwise they are reported as skipped.
. "$(dirname "$0")/lib.sh"

work=$TMP/w
mkdir -p "$work/build"
ln -s "$RAYO" "$work/build/rayo"
ln -s "$RAYO_SOURCE/examples" "$work/examples"
# tests/grade is copied, not linked: grade shows a source's name as typed
# only when it leads there without a link (the sandbox binds the real
# folder), as in a student's own folder.
mkdir "$work/tests"
for entry in "$RAYO_SOURCE"/tests/*; do
    ln -s "$entry" "$work/tests/${entry##*/}"
done
rm "$work/tests/grade" && cp -r "$RAYO_SOURCE/tests/grade" "$work/tests/grade"
cd "$work" || exit 1
# make run
build/rayo -o esfera.pbm && build/rayo -o esfera.png
ok $? "make run's renders: esfera.pbm and esfera.png"

RAYO_README_ALL=${RAYO_README_ALL:-0} python3 - "$RAYO_SOURCE/README.md" "$TMP" "$tap_n" "$RAYO_SOURCE/LEEME.md" <<'EOF'
import os, re, subprocess, sys

tmp = sys.argv[2]
# (file, kind, line, body): the README's blocks, then the Spanish guide's,
# whose console blocks show what a student sees on the terminal, standard
# error included (merged into the output compared).
blocks = []
for readme in [sys.argv[1]] + sys.argv[4:]:
    lines = open(readme, encoding="utf-8").read().split("\n")
    i = 0
    while i < len(lines):
        m = re.match(r"^```(sh|console)\s*$", lines[i])
        if m:
            j = i + 1
            while not lines[j].startswith("```"):
                j += 1
            blocks.append((os.path.basename(readme), m.group(1), i + 1,
                           lines[i + 1:j]))
            i = j
        i += 1

first = n = int(sys.argv[3])
failed = 0
def tap(good, name, extra=""):
    global n, failed
    n += 1
    failed += 0 if good else 1
    print(("ok" if good else "not ok") + " %d - %s%s" % (n, name, extra))

env = dict(os.environ)
env.pop("CC", None)  # grade's compile line shows cc, as for a student
env.pop("COLUMNS", None)
def run(script, merge=False):
    p = subprocess.run(["sh", "-c", script], stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT if merge else subprocess.PIPE,
                       env=env)
    return p.returncode, p.stdout.decode("utf-8", "replace"), \
        (p.stderr or b"").decode("utf-8", "replace")

def seconds(text):
    text = re.sub(r"; limits: (cgroup v[12] on the whole tree|per process "
                  r"only)[^\n]*", "; limits: ...", text)
    return re.sub(r"\b\d+[.,]\d+ s\b", "N.NN s", text)

slow = ("--exercise ej3", "--each")
for doc, kind, line, body in blocks:
    text = "\n".join(body)
    guide = doc != "README.md"
    if kind == "sh":
        # make web and its server: make check-web builds and serves it.
        if "make install" in text or "make web" in text or body[:1] in (["make run      # builds build/rayo and renders the sphere to esfera.pbm and esfera.png"], ["make run"]):
            tap(True, "%s line %d: not run here" % (doc, line), " # skip see the header")
            continue
        for k, command in enumerate(body):
            if not command.strip():
                continue
            status, out, err = run(command)
            tap(status == 0, "%s line %d: %s" % (doc, line + 1 + k, command[:60]))
            if status != 0:
                print("#   exit %d; stderr: %s" % (status, err.strip()[:400]))
        continue
    commands = [l[2:] for l in body if l.startswith("$ ")]
    expected = [l for l in body if not l.startswith("$ ")]
    shown = [c for c in commands if "rayo" in c] or commands
    name = "%s line %d: $ %s" % (doc, line + 1 + body.index("$ " + shown[0]),
                                 shown[0][:60])
    # The guide's picture of the sphere drawn because standard output is
    # a terminal: here it is a pipe (tests/cli/progress.t and i18n.t run
    # rayo on a terminal).
    if guide and commands == ["build/rayo --lang es"]:
        tap(True, name, " # skip needs a terminal")
        continue
    if any(s in c for c in commands for s in slow) and \
            os.environ.get("RAYO_README_ALL") != "1":
        tap(True, name, " # skip slow: RAYO_README_ALL=1 runs it")
        continue
    status, out, err = run("\n".join(commands), merge=guide)
    pattern = "".join("(?:.*\n)*?" if l.strip() == "..." else
                      re.escape(seconds(l)) + "\n" for l in expected)
    good = re.fullmatch(pattern, seconds(out)) is not None
    tap(good, name)
    if not good:
        got = out.split("\n")
        for a, b in zip(expected + [""] * len(got), got):
            if a != b:
                print("#   expected: %s\n#   got:      %s" % (a, b))
                break
        print("#   stderr: %s" % err.strip()[:400])
open(os.path.join(tmp, "count"), "w").write("%d %d\n" % (n - first, failed))
EOF
# The python part printed its own TAP lines; count them in.
py_n=0 py_failed=1
read -r py_n py_failed <"$TMP/count"
tap_n=$((tap_n + py_n))
tap_failed=$((tap_failed + py_failed))
done_testing
