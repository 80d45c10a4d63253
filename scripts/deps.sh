#!/bin/sh
# deps.sh - makes sure a Debian machine has what rayo needs, so the quick
# start (`make run`, `make check`) works on a fresh one.
#
#   scripts/deps.sh build   a C compiler, pkg-config and libpng's headers
#   scripts/deps.sh check   also the Netpbm tools the tests cross-check with,
#                           and jq and python3, which read their JSON
#
# It installs with apt-get only when something is missing, and only as
# root; otherwise it names the command to run and fails.  It never
# downloads anything but Debian packages.
set -eu
profile=${1:-build}
need=""
has_pkg() { dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q 'ok installed'; }
command -v cc >/dev/null 2>&1 || need="$need gcc libc6-dev"
command -v make >/dev/null 2>&1 || need="$need make"
command -v pkg-config >/dev/null 2>&1 || need="$need pkg-config"
pkg-config --exists libpng 2>/dev/null || need="$need libpng-dev"
if [ "$profile" = check ]; then
    command -v pngtopnm >/dev/null 2>&1 || need="$need netpbm"
    command -v prove >/dev/null 2>&1 || need="$need perl"
    command -v jq >/dev/null 2>&1 || need="$need jq"
    command -v python3 >/dev/null 2>&1 || need="$need python3"
fi
[ -z "$need" ] && exit 0
if ! command -v apt-get >/dev/null 2>&1; then
    echo "rayo needs:$need (install them with your system's package manager)" >&2
    exit 1
fi
if [ "$(id -u)" != 0 ]; then
    echo "rayo needs:$need; run: sudo apt-get install -y$need" >&2
    exit 1
fi
echo "installing:$need" >&2
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq >&2
apt-get install -y -qq $need >&2
