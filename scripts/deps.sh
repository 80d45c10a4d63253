#!/bin/sh
# deps.sh - makes sure a Debian machine has what rayo needs, so the quick
# start (`make run`, `make check`) works on a fresh one.
#
#   scripts/deps.sh build   a C compiler, make, pkg-config, gettext's
#                           msgfmt, and libpng's and libjpeg's headers
#   scripts/deps.sh check   also the Netpbm tools and ADMesh the tests
#                           cross-check images and meshes with, prove
#                           (perl), jq and python3, which read their
#                           JSON, and bubblewrap, grade's sandbox
#   scripts/deps.sh bench   build's, and for `make bench`'s rows against
#                           Embree and POV-Ray (bench/peers.c, meshes.c) python3,
#                           libembree-dev and povray: optional, so
#                           without them (not root, no such package)
#                           it says so and succeeds, and those rows say
#                           skipped
#   scripts/deps.sh web     build's, and the page's WebAssembly toolchain
#                           (`make web`): clang, lld, wasi-libc and the
#                           wasm32 runtime of the clang that is installed
#
# It installs with apt-get only when something is missing, and only as
# root; otherwise it names the command to run and fails.  It never
# downloads anything but Debian packages.  While another apt or dpkg holds
# the lock (unattended upgrades on a fresh machine), it waits for it, up
# to $RAYO_APT_LOCK_TIMEOUT seconds (default 600), instead of giving up.
# It prints one line per set of packages; apt's own output goes to a log
# file ($RAYO_DEPS_LOG, else a new file in $TMPDIR or /tmp), whose last
# lines and name are printed when apt fails.
set -eu
profile=${1:-build}
case $profile in
build | check | bench | web) ;;
*)
    echo "deps.sh: '$profile': expected build, check, bench or web" >&2
    exit 2
    ;;
esac

# The sets, each "label: packages", one a line.
sets=""
add_set() { # add_set LABEL PACKAGES
    [ -n "$2" ] && sets="$sets$1:$2
"
    return 0
}
tools=""
command -v cc >/dev/null 2>&1 || tools="$tools gcc libc6-dev"
command -v make >/dev/null 2>&1 || tools="$tools make"
command -v pkg-config >/dev/null 2>&1 || tools="$tools pkg-config"
command -v msgfmt >/dev/null 2>&1 || tools="$tools gettext"
add_set "build tools" "$tools"
images=""
pkg-config --exists libpng 2>/dev/null || images="$images libpng-dev"
pkg-config --exists libjpeg 2>/dev/null || images="$images libjpeg-dev"
add_set "libpng's and libjpeg's headers" "$images"
if [ "$profile" = check ]; then
    tests=""
    command -v pngtopnm >/dev/null 2>&1 || tests="$tests netpbm"
    command -v prove >/dev/null 2>&1 || tests="$tests perl"
    command -v jq >/dev/null 2>&1 || tests="$tests jq"
    command -v python3 >/dev/null 2>&1 || tests="$tests python3"
    command -v admesh >/dev/null 2>&1 || tests="$tests admesh"
    add_set "test tools" "$tests"
    # rayo grade runs submissions in a bubblewrap sandbox, and the tests
    # run it for real (docs/grading.md).
    sandbox=""
    command -v bwrap >/dev/null 2>&1 || sandbox=" bubblewrap"
    add_set "the grader's sandbox" "$sandbox"
fi
if [ "$profile" = web ]; then
    # What `clang --target=wasm32-wasi` needs: the linker, the C library
    # and the builtins of the clang version that is (or will be) there.
    wasm=""
    command -v clang >/dev/null 2>&1 || wasm="$wasm clang"
    command -v wasm-ld >/dev/null 2>&1 || wasm="$wasm lld"
    [ -d "${RAYO_WASI_INCLUDE:-/usr/include/wasm32-wasi}" ] || wasm="$wasm wasi-libc"
    version=$(clang --version 2>/dev/null | sed -n '1s/.*clang version \([0-9]*\).*/\1/p')
    runtime=""
    for f in "${RAYO_LLVM_LIB:-/usr/lib}"/llvm-"$version"/lib/clang/*/lib/wasi/libclang_rt.builtins-wasm32.a; do
        [ -n "$version" ] && [ -f "$f" ] && runtime=$f
    done
    if [ -z "$version" ]; then
        wasm="$wasm libclang-rt-dev-wasm32"
    elif [ -z "$runtime" ]; then
        wasm="$wasm libclang-rt-$version-dev-wasm32"
    fi
    add_set "the page's WebAssembly toolchain" "$wasm"
fi
optional=""
if [ "$profile" = bench ]; then
    command -v python3 >/dev/null 2>&1 || optional="$optional python3"
    [ -f "${RAYO_EMBREE_HEADER:-/usr/include/embree3/rtcore.h}" ] ||
        optional="$optional libembree-dev"
    command -v povray >/dev/null 2>&1 || optional="$optional povray"
fi
[ -z "$sets" ] && [ -z "$optional" ] && exit 0
need=$(printf '%s' "$sets" | sed 's/^[^:]*://' | tr '\n' ' ' | sed 's/  */ /g; s/ $//')

# without_optional REASON: the optional packages are left out, saying so.
without_optional() {
    [ -n "$optional" ] && echo "rayo: the bench's rows against Embree and" \
        "POV-Ray will say skipped ($1); to have them: apt-get install -y$optional" >&2
    [ -z "$sets" ] && exit 0
    optional=""
}
if ! command -v apt-get >/dev/null 2>&1; then
    without_optional "no apt-get"
    echo "rayo needs:$need (install them with your system's package manager)" >&2
    exit 1
fi
if [ "$(id -u)" != 0 ]; then
    without_optional "not root"
    echo "rayo needs:$need; run: sudo apt-get install -y$need" >&2
    exit 1
fi

if [ -n "${RAYO_DEPS_LOG:-}" ]; then
    log=$RAYO_DEPS_LOG
    : >"$log"
else
    log=$(mktemp "${TMPDIR:-/tmp}/rayo-deps-log.XXXXXX")
fi
timeout=${RAYO_APT_LOCK_TIMEOUT:-600}
export DEBIAN_FRONTEND=noninteractive

# apt ARGS...: apt-get, waiting for the lock, its output into the log; on
# failure, the log's last lines and its name.
apt() {
    echo "+ apt-get $*" >>"$log"
    if apt-get -o DPkg::Lock::Timeout="$timeout" "$@" >>"$log" 2>&1; then
        return 0
    else
        status=$?
    fi
    echo "rayo: apt-get $1 failed (exit status $status); the end of $log:" >&2
    tail -n 15 "$log" | sed 's/^/    /' >&2
    exit 1
}

echo "rayo: updating the package lists (apt's output: $log)" >&2
apt update
printf '%s' "$sets" | while IFS=: read -r label packages; do
    echo "rayo: installing $label:$packages" >&2
    # shellcheck disable=SC2086 # one word a package
    apt install -y --no-install-recommends $packages
done
if [ -n "$optional" ]; then
    echo "rayo: installing the bench's peers:$optional" >&2
    echo "+ apt-get install$optional" >>"$log"
    # shellcheck disable=SC2086 # one word a package
    apt-get -o DPkg::Lock::Timeout="$timeout" install -y \
        --no-install-recommends $optional >>"$log" 2>&1 ||
        echo "rayo: apt-get could not install$optional ($log); the bench's" \
            "rows against Embree and POV-Ray will say skipped" >&2
fi
