#!/usr/bin/env bash
# Installs what Stoa needs to build, render headless, run the window (under Xvfb,
# or in a browser through tools/web-window.sh), grade and build the docs.
#   .ci/install-deps.sh           what a student or an instructor needs
#   .ci/install-deps.sh --tests   and what the project's own tests use besides
#                                 (clang, Chromium, MinGW-w64 and Wine): CI's set
# Debian 12 and Ubuntu 22.04 or newer: apt-get (through sudo when not root).
# macOS and Windows: prints the Homebrew and vcpkg steps (nothing is installed);
# other systems: the packages to look for.
set -euo pipefail

packages=(
  build-essential cmake pkg-config git ninja-build ccache
  freeglut3-dev libglew-dev libglm-dev libstb-dev libtinyobjloader-dev libimgui-dev libmeshoptimizer-dev libpugixml-dev
  nlohmann-json3-dev libopenal-dev libvorbis-dev libogg-dev
  libosmesa6-dev libegl-dev libgl1-mesa-dri
  catch2 xvfb xauth xdotool mkdocs python3-pymdownx python3-pygments libjs-mathjax
  x11vnc websockify novnc
  zip unzip python3 similarity-tester
)
test_packages=(
  clang                                 # the second compiler's build (.ci/test-all.sh)
  chromium                              # the browser tests (the window through noVNC, the class report)
  g++-mingw-w64-x86-64-posix wine64     # stoa_core built for Windows, its tests run under Wine: tests/windows/
)
case "${1:-}" in
  "") ;;
  --tests) packages+=("${test_packages[@]}") ;;
  *) echo "install-deps: unknown option '$1' (usage: .ci/install-deps.sh [--tests])" >&2; exit 2 ;;
esac

# Other systems: the same libraries from vcpkg (vcpkg.json, through
# CMakePresets.json), and the build tools from the system's own manager.
print_other_system_steps() {
  case "$(uname -s)" in
    Darwin)
      echo "macOS: the build tools from Homebrew, the libraries from vcpkg (vcpkg.json lists them):"
      echo "  brew install cmake ninja pkg-config"
      echo "  git clone https://github.com/microsoft/vcpkg \"\$HOME/vcpkg\" && \"\$HOME/vcpkg/bootstrap-vcpkg.sh\""
      echo "  export VCPKG_ROOT=\"\$HOME/vcpkg\""
      echo "  cmake --preset macos && cmake --build --preset macos"
      echo "Not yet verified on macOS: the lab window needs a GLFW window (planned); the shaders already run on its OpenGL 4.1."
      echo "The dev container (.devcontainer/, docs/student-guide.md) runs everything, the lab window included." ;;
    MINGW*|MSYS*|CYGWIN*)
      echo "Windows: Visual Studio 2022 (C++ workload) and vcpkg; vcpkg.json lists the libraries:"
      echo "  git clone https://github.com/microsoft/vcpkg %USERPROFILE%\\vcpkg && %USERPROFILE%\\vcpkg\\bootstrap-vcpkg.bat"
      echo "  set VCPKG_ROOT=%USERPROFILE%\\vcpkg"
      echo "  cmake --preset windows-vcpkg && cmake --build --preset windows-vcpkg"
      echo "Verified on Windows: stoa_core's unit tests (MinGW-w64 under Wine, tests/windows/); the rest is not yet."
      echo "The dev container (.devcontainer/, docs/student-guide.md) runs everything, the lab window included." ;;
    *)
      echo "Stoa's installer knows Debian and Ubuntu (apt-get). On this system, install the equivalents of:"
      printf '  %s\n' "${packages[@]}"
      echo "or take the libraries from vcpkg (vcpkg.json; cmake --preset windows-vcpkg works on Linux too),"
      echo "or use the dev container (.devcontainer/), which runs everything." ;;
  esac
}

if ! command -v apt-get >/dev/null 2>&1; then
  print_other_system_steps
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
