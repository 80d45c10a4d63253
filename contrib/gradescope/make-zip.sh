#!/usr/bin/env bash
# make-zip.sh [OUT.zip] - the zip to upload as a Gradescope autograder:
# setup.sh and run_autograder at its root (where Gradescope looks for
# them) and this repository's committed files under rayo/, so that
# setup.sh builds rayo without downloading it.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/../.." && pwd)
out=${1:-rayo-autograder.zip}
case $out in /*) ;; *) out="$PWD/$out" ;; esac
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
git -C "$repo" archive --format=tar --prefix=rayo/ HEAD | tar -x -C "$tmp"
cp "$here/setup.sh" "$here/run_autograder" "$tmp/"
chmod 755 "$tmp/setup.sh" "$tmp/run_autograder"
python3 - "$tmp" "$out.tmp" <<'PY'
import os, sys, zipfile
root, out = sys.argv[1], sys.argv[2]
with zipfile.ZipFile(out, 'w', zipfile.ZIP_DEFLATED) as z:
    for folder, dirs, files in os.walk(root):
        dirs.sort()
        for name in sorted(files):
            path = os.path.join(folder, name)
            info = zipfile.ZipInfo.from_file(path, os.path.relpath(path, root))
            info.compress_type = zipfile.ZIP_DEFLATED
            with open(path, 'rb') as f:
                z.writestr(info, f.read())
PY
mv "$out.tmp" "$out"
echo "wrote $out"
