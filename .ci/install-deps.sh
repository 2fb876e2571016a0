#!/usr/bin/env bash
# Installs what Stoa needs to build, render headless, run the window under Xvfb,
# run the tests and build the docs. Debian 12 and Ubuntu 22.04 or newer: apt-get
# (through sudo when not root). Elsewhere: prints the packages to look for.
set -euo pipefail

packages=(
  build-essential cmake pkg-config git ninja-build ccache
  freeglut3-dev libglew-dev libglm-dev libstb-dev libtinyobjloader-dev libimgui-dev libmeshoptimizer-dev libpugixml-dev
  nlohmann-json3-dev libopenal-dev libvorbis-dev
  libosmesa6-dev libegl-dev libgl1-mesa-dri
  catch2 xvfb xauth xdotool mkdocs python3-pymdownx python3-pygments libjs-mathjax
  zip unzip python3
)

if ! command -v apt-get >/dev/null 2>&1; then
  echo "Stoa's installer knows Debian and Ubuntu (apt-get). On this system, install the equivalents of:"
  printf '  %s\n' "${packages[@]}"
  echo "(a C++17 compiler, CMake >= 3.16, pkg-config, freeglut, GLEW, GLM, stb, tinyobjloader, Dear ImGui, meshoptimizer, pugixml,"
  echo " nlohmann-json 3, OpenAL Soft, libvorbis (its encoder, for the generated sounds),"
  echo " Mesa with llvmpipe, OSMesa (optional where Mesa >= 25.1), EGL, Catch2, Xvfb, MkDocs with"
  echo " pymdown-extensions and Pygments, MathJax 2.7 (STOA_MATHJAX_DIR: its folder))"
  exit 1
fi

missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages are installed" >&2   # a status line: stdout is the report
  exit 0
fi

run_as_root=()
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then run_as_root=(sudo); else
    echo "install-deps: need root (or sudo) to install: ${missing[*]}" >&2
    exit 1
  fi
fi

echo "install-deps: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
"${run_as_root[@]}" apt-get update -q
# Mesa >= 25.1 has no OSMesa: install the rest and let EGL do the headless work.
if ! "${run_as_root[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"; then
  without_osmesa=()
  for package in "${missing[@]}"; do [ "$package" = libosmesa6-dev ] || without_osmesa+=("$package"); done
  echo "install-deps: retrying without libosmesa6-dev (headless rendering will use EGL)" >&2
  "${run_as_root[@]}" apt-get install -y -q --no-install-recommends "${without_osmesa[@]}"
fi
