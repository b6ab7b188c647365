#!/usr/bin/env bash
# Regenerates the README's screenshots docs/studio-*.png: each workspace of polarform-studio
# rendered headless under Xvfb (Mesa llvmpipe) after its computations settle.
# usage: ui/studio/tools/screenshots.sh BUILD_DIR   (run from the repository root)
set -euo pipefail
build=${1:-build}
studio="$build/ui/studio/polarform-studio"
size=1600x1000
work="$build/screenshots"
mkdir -p "$work" docs
python3 ui/studio/tools/synthetic_scan.py "$work/egg_scan.xyz" 40000

shoot() {  # workspace project output
  echo "screenshot: $3"
  xvfb-run -a -s "-screen 0 1920x1200x24" \
    "$studio" --workspace "$1" --project "$2" --screenshot "$3" --size "$size" \
    > "$work/$1.log" 2>&1 || { cat "$work/$1.log"; exit 1; }
}

shoot cam examples/cams/roller.xml docs/studio-cam.png
shoot study examples/cams/roller.xml docs/studio-study.png
shoot vessel examples/vessels/torispherical_100_6.xml docs/studio-vessel.png
shoot fit "$work/egg_scan.xyz" docs/studio-fit.png
