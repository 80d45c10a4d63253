#!/bin/sh
# readme.t - the README's examples run as written after `make run`, from
# a folder laid out like the source tree (build/rayo is the rayo under
# test; examples/ and tests/ are the repository's).  Every ```sh block's
# lines must exit 0; every ```console block is run as one script and its
# output must be the README's, line for line (times such as "0.11 s" are
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

RAYO_README_ALL=${RAYO_README_ALL:-0} python3 - "$RAYO_SOURCE/README.md" "$TMP" "$tap_n" <<'EOF'
import os, re, subprocess, sys

readme, tmp = sys.argv[1], sys.argv[2]
lines = open(readme, encoding="utf-8").read().split("\n")
blocks, i = [], 0
while i < len(lines):
    m = re.match(r"^```(sh|console)\s*$", lines[i])
    if m:
        j = i + 1
        while not lines[j].startswith("```"):
            j += 1
        blocks.append((m.group(1), i + 1, lines[i + 1:j]))
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
def run(script):
    p = subprocess.run(["sh", "-c", script], stdout=subprocess.PIPE,
                       stderr=subprocess.PIPE, env=env)
    return p.returncode, p.stdout.decode("utf-8", "replace"), \
        p.stderr.decode("utf-8", "replace")

def seconds(text):
    text = re.sub(r"; limits: (cgroup v[12] on the whole tree|per process "
                  r"only)[^\n]*", "; limits: ...", text)
    return re.sub(r"\b\d+\.\d+ s\b", "N.NN s", text)

slow = ("--exercise ej3", "--each")
for kind, line, body in blocks:
    text = "\n".join(body)
    if kind == "sh":
        # make web and its server: make check-web builds and serves it.
        if "make install" in text or "make web" in text or body[:1] == ["make run      # builds build/rayo and renders the sphere to esfera.pbm and esfera.png"]:
            tap(True, "README line %d: not run here" % line, " # skip see the header")
            continue
        for k, command in enumerate(body):
            if not command.strip():
                continue
            status, out, err = run(command)
            tap(status == 0, "README line %d: %s" % (line + 1 + k, command[:60]))
            if status != 0:
                print("#   exit %d; stderr: %s" % (status, err.strip()[:400]))
        continue
    commands = [l[2:] for l in body if l.startswith("$ ")]
    expected = [l for l in body if not l.startswith("$ ")]
    shown = [c for c in commands if "rayo" in c] or commands
    name = "README line %d: $ %s" % (line + 1 + body.index("$ " + shown[0]),
                                     shown[0][:60])
    if any(s in c for c in commands for s in slow) and \
            os.environ.get("RAYO_README_ALL") != "1":
        tap(True, name, " # skip slow: RAYO_README_ALL=1 runs it")
        continue
    status, out, err = run("\n".join(commands))
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
