#!/usr/bin/env bash
# Installs, with apt-get, only the Debian packages pride needs that are missing.
# Idempotent: when everything is present it runs no apt command and returns at once.
# Usage: scripts/deps.sh [--bench]   (--bench adds libpagmo-dev for the side-by-side benchmark)
set -euo pipefail
packages=(build-essential cmake ninja-build pkg-config libeigen3-dev libnlopt-cxx-dev catch2 libfmt-dev libcli11-dev libcairo2-dev libfontconfig-dev libboost-dev libtomlplusplus-dev libsqlite3-dev sqlite3 python3-matplotlib libopenmpi-dev openmpi-bin python3-dev pybind11-dev python3-numpy python3-pytest python3-pandas)
# Map images and ROS map_server files (problems/grid/image_map.cpp, ros_map.cpp).
packages+=(libpng-dev libnetpbm-dev libyaml-cpp-dev)
# Optional OMPL planners (problems/grid/planners/ompl_planner.cpp): OMPL's CMake file names the Boost libraries without depending on them.
packages+=(libompl-dev libboost-filesystem-dev libboost-serialization-dev)
# The browser that tests/test_report_html.cpp opens the HTML report in (headless).
packages+=(chromium)
# The libFuzzer targets (fuzz/, scripts/fuzz.sh, .ci/run): clang with its libFuzzer runtime.
packages+=(clang libfuzzer-14-dev)
[[ "${1:-}" == "--bench" ]] && packages+=(libpagmo-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  # Said first, as apt-get runs quietly: on a fresh machine this step takes minutes.
  echo "deps: installing ${#missing[@]} of ${#packages[@]} Debian packages with apt-get (minutes on a fresh machine): ${missing[*]}" >&2
  sudo_cmd=()
  [[ $(id -u) -ne 0 ]] && sudo_cmd=(sudo)
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
  echo "deps: done" >&2
else
  echo "deps: all ${#packages[@]} Debian packages are installed" >&2
fi
