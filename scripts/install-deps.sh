#!/usr/bin/env bash
# Installs the Debian packages polarform needs, and nothing when they are all present.
# Idempotent: run it as often as you like. Works as root; uses sudo otherwise.
# --fuzz adds clang and its libFuzzer/sanitizer runtimes for `make fuzz`.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libeigen3-dev libnlopt-cxx-dev libtinyxml2-dev libcli11-dev nlohmann-json3-dev
  libglfw3-dev libimgui-dev libstb-dev libgl-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libocct-data-exchange-dev libocct-modeling-algorithms-dev libsisl-dev python3-ezdxf
  xvfb xauth libgl1-mesa-dri fonts-dejavu-core
)
if [ "${1:-}" = "--fuzz" ]; then
  packages+=(clang libclang-rt-dev)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
    missing+=("$p")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "install-deps: installing ${missing[*]}" >&2
if [ "$(id -u)" -eq 0 ]; then sudo=(); else sudo=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
"${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
