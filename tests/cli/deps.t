#!/bin/sh
# deps.t - scripts/deps.sh: nothing to do on a machine that has it all;
# on one that lacks everything (a PATH of stand-ins), one line per set of
# packages, apt-get told to wait for the dpkg lock, apt's output in the
# log and not on the terminal; when apt fails, the log's last lines and
# its name, and a failure.  apt-get itself is a stand-in: nothing is
# installed.
. "$(dirname "$0")/lib.sh"

deps=$RAYO_SOURCE/scripts/deps.sh
sh -n "$deps"
ok $? "deps.sh parses"
out=$(sh "$deps" check 2>&1)
is "$?:$out" "0:" "everything installed: silent, exit 0"

# A bare machine: only the utilities deps.sh itself uses, a root id, and an
# apt-get that records its arguments and talks a lot.
bin=$TMP/bin
mkdir "$bin"
for tool in sh sed tr tail mktemp cat printf; do
    p=$(command -v "$tool") && ln -s "$p" "$bin/$tool"
done
printf '#!/bin/sh\necho 0\n' >"$bin/id"
cat >"$bin/apt-get" <<'STUB'
#!/bin/sh
echo "$*" >>"$APT_CALLS"
i=0
while [ $i -lt 50 ]; do echo "Get:$i http://deb.debian.org noise"; i=$((i + 1)); done
[ "${APT_FAIL:-}" = "$3" ] && { echo "E: Could not get lock /var/lib/dpkg/lock-frontend" >&2; exit 100; }
exit 0
STUB
chmod +x "$bin/id" "$bin/apt-get"
export APT_CALLS=$TMP/calls
status=0
PATH=$bin RAYO_DEPS_LOG=$TMP/deps.log sh "$deps" check >"$TMP/out" 2>"$TMP/err" || status=$?
is "$status" 0 "bare machine: exit 0"
is "$(cat "$TMP/err")" "rayo: updating the package lists (apt's output: $TMP/deps.log)
rayo: installing build tools: gcc libc6-dev make pkg-config gettext
rayo: installing libpng's and libjpeg's headers: libpng-dev libjpeg-dev
rayo: installing test tools: netpbm perl jq python3 admesh
rayo: installing the grader's sandbox: bubblewrap" "one line per package set"
is "$(wc -c <"$TMP/out" | tr -d ' ')" 0 "nothing on stdout"
is "$(grep -c noise "$TMP/deps.log")" 250 "apt's output is in the log (an update, four installs)"
is "$(cut -d' ' -f1-3 "$APT_CALLS" | sort -u)" "-o DPkg::Lock::Timeout=600 install
-o DPkg::Lock::Timeout=600 update" "every apt-get waits for the lock (600 s)"
grep -q "install -y --no-install-recommends netpbm perl jq python3 admesh" "$APT_CALLS"
ok $? "a set's packages in one apt-get install"
: >"$APT_CALLS"
status=0
PATH=$bin RAYO_DEPS_LOG=$TMP/deps.log sh "$deps" build >"$TMP/out" 2>"$TMP/err" || status=$?
is "$(grep -c install "$APT_CALLS")" 2 "build: two sets (no test tools)"

# apt fails: the end of the log, its name, exit 1, and no further sets.
: >"$APT_CALLS"
status=0
APT_FAIL=install PATH=$bin RAYO_DEPS_LOG=$TMP/deps.log sh "$deps" check >"$TMP/out" 2>"$TMP/err" || status=$?
is "$status" 1 "apt-get install fails: exit 1"
grep -q "^rayo: apt-get install failed (exit status 100); the end of $TMP/deps.log:$" "$TMP/err"
ok $? "  says which apt-get failed and where its log is"
grep -q "^    E: Could not get lock" "$TMP/err"
ok $? "  shows the log's last lines"
is "$(grep -c noise "$TMP/err")" 14 "  only the last lines (15 in all)"
is "$(grep -c install "$APT_CALLS")" 1 "  and stops there"
# Not root: the one command to run.
printf '#!/bin/sh\necho 1000\n' >"$bin/id"
status=0
PATH=$bin sh "$deps" build >"$TMP/out" 2>"$TMP/err" || status=$?
is "$status:$(cat "$TMP/err")" "1:rayo needs: gcc libc6-dev make pkg-config gettext libpng-dev libjpeg-dev; run: sudo apt-get install -y gcc libc6-dev make pkg-config gettext libpng-dev libjpeg-dev" "not root: names the command"

# web: the page's toolchain, with the runtime of the clang that is there
# (any clang: the unversioned package), the paths it looks at moved into
# $TMP where nothing is.
export RAYO_WASI_INCLUDE="$TMP/no/wasm32-wasi" RAYO_LLVM_LIB="$TMP/no/lib"
status=0
PATH=$bin sh "$deps" web >"$TMP/out" 2>"$TMP/err" || status=$?
is "$status:$(cat "$TMP/err")" "1:rayo needs: gcc libc6-dev make pkg-config gettext libpng-dev libjpeg-dev clang lld wasi-libc libclang-rt-dev-wasm32; run: sudo apt-get install -y gcc libc6-dev make pkg-config gettext libpng-dev libjpeg-dev clang lld wasi-libc libclang-rt-dev-wasm32" \
    "web, no clang: the toolchain with any clang's wasm32 runtime"
printf '#!/bin/sh\necho "Debian clang version 14.0.6"\n' >"$bin/clang"
chmod +x "$bin/clang"
status=0
PATH=$bin sh "$deps" web >"$TMP/out" 2>"$TMP/err" || status=$?
is "$status:$(cat "$TMP/err")" "1:rayo needs: gcc libc6-dev make pkg-config gettext libpng-dev libjpeg-dev lld wasi-libc libclang-rt-14-dev-wasm32; run: sudo apt-get install -y gcc libc6-dev make pkg-config gettext libpng-dev libjpeg-dev lld wasi-libc libclang-rt-14-dev-wasm32" \
    "web, clang 14: its own wasm32 runtime"
mkdir -p "$TMP/no/lib/llvm-14/lib/clang/14.0.6/lib/wasi" "$TMP/no/wasm32-wasi"
: >"$TMP/no/lib/llvm-14/lib/clang/14.0.6/lib/wasi/libclang_rt.builtins-wasm32.a"
printf '#!/bin/sh\nexit 0\n' >"$bin/wasm-ld"
chmod +x "$bin/wasm-ld"
status=0
PATH=$bin sh "$deps" web >"$TMP/out" 2>"$TMP/err" || status=$?
is "$status:$(cat "$TMP/err")" "1:rayo needs: gcc libc6-dev make pkg-config gettext libpng-dev libjpeg-dev; run: sudo apt-get install -y gcc libc6-dev make pkg-config gettext libpng-dev libjpeg-dev" \
    "web, toolchain there: only what the build lacks"
rm -f "$bin/clang" "$bin/wasm-ld"
unset RAYO_WASI_INCLUDE RAYO_LLVM_LIB

# bench: the peers' packages (python3, libembree-dev, povray) are
# optional.  With the build's tools present (stand-ins), a root machine
# installs them; when it cannot, or is not root, it says so and succeeds.
for tool in cc make pkg-config msgfmt; do
    printf '#!/bin/sh\nexit 0\n' >"$bin/$tool"
    chmod +x "$bin/$tool"
done
printf '#!/bin/sh\necho 0\n' >"$bin/id"
: >"$APT_CALLS"
export RAYO_EMBREE_HEADER="$TMP/no/rtcore.h"
status=0
PATH=$bin RAYO_DEPS_LOG=$TMP/deps.log sh "$deps" bench >"$TMP/out" 2>"$TMP/err" || status=$?
is "$status:$(sed -n 2p "$TMP/err")" "0:rayo: installing the bench's peers: python3 libembree-dev povray" \
    "bench, root: installs the peers' packages"
grep -q "install -y --no-install-recommends python3 libembree-dev povray" "$APT_CALLS"
ok $? "  in one apt-get install"
out=$(PATH=$bin sh "$deps" build 2>&1)
is "$?:$out" "0:" "  build: they are not its business"
status=0
APT_FAIL=install PATH=$bin RAYO_DEPS_LOG=$TMP/deps.log sh "$deps" bench >"$TMP/out" 2>"$TMP/err" || status=$?
is "$status:$(tail -n 1 "$TMP/err")" "0:rayo: apt-get could not install python3 libembree-dev povray ($TMP/deps.log); the bench's rows against Embree and POV-Ray will say skipped" \
    "bench, apt-get fails: said, exit 0"
printf '#!/bin/sh\necho 1000\n' >"$bin/id"
status=0
PATH=$bin sh "$deps" bench >"$TMP/out" 2>"$TMP/err" || status=$?
is "$status:$(cat "$TMP/err")" "0:rayo: the bench's rows against Embree and POV-Ray will say skipped (not root); to have them: apt-get install -y python3 libembree-dev povray" \
    "bench, not root: names the command, exit 0"
done_testing
