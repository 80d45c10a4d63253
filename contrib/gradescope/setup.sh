#!/usr/bin/env bash
# setup.sh - Gradescope runs this once, as root, when it builds the
# autograder's image (Ubuntu): it installs what rayo needs and builds and
# installs rayo from the copy of the repository that make-zip.sh put in
# the zip (/autograder/source/rayo).  Nothing is downloaded but Ubuntu's
# packages.
set -euo pipefail
source_dir=${AUTOGRADER_ROOT:-/autograder}/source

export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
# The compiler the course grades with, libpng for rayo, valgrind for the
# memory criterion, bubblewrap for the sandbox (where the container
# allows user namespaces; else the report says the run was not isolated,
# and the container is the isolation).
apt-get install -y -qq build-essential pkg-config libpng-dev valgrind \
    bubblewrap >/dev/null

make -C "$source_dir/rayo" -j"$(nproc)"
make -C "$source_dir/rayo" install PREFIX=/usr/local
rayo --version
