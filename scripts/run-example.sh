#!/usr/bin/env bash
# The README's main job: design the bundled roller cam, convert it to an exact NURBS profile
# within 1 µm and write every output (CAD files, plots, report) to out/roller.
set -euo pipefail
build=${1:-build}
out=out/roller
mkdir -p "$out"
"$build/ui/cli/polarform" cam examples/cams/roller.xml --out "$out"
echo
echo "Outputs of the roller-cam example are in $(cd "$out" && pwd):"
ls -1 "$out" | sed 's/^/  /'
echo "Open report.html in a browser for the plots and the key figures."
