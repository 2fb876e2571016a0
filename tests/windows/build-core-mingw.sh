#!/bin/sh
# stoa_core on Windows (issue 26): cross-compiles stoa_core's sources and the
# unit tests of stoa-tests-core with Debian's MinGW-w64 compiler and runs the
# test program under Wine.
#
#   tests/windows/build-core-mingw.sh OUT [CATCH ARGS...]
#
# Exit status: the test program's (0: every test passed); 77 when the cross
# compiler or Wine is missing (apt-get install g++-mingw-w64-x86-64-posix wine64);
# 1 when the build fails. OUT holds the objects, the program
# (stoa-tests-core.exe), the build's log and the Wine prefix (made at the first
# run, which takes a while).
#
# The sources are read from the build's own lists, so that a new file joins by
# itself: target_sources(stoa_core ...) in framework/CMakeLists.txt and
# target_sources(stoa-tests-core ...) in tests/*/CMakeLists.txt. Left out:
#   - what needs pugixml or meshoptimizer, which Debian builds for Linux only
#     (no vendored copies): the crowd XML loader (src/crowd/CrowdXml.cpp,
#     Xml*.cpp, src/assets/DataAssets.cpp), the levels of detail
#     (src/geometry/LevelOfDetail.cpp), and their tests (AssetCacheTests.cpp
#     too: it loads crowd worlds through DataAssets);
#   - tests of other libraries than stoa_core: the grader's (stoa_grader runs
#     lab programs as POSIX child processes) and the generated assets'
#     (stoa_asset_generator);
#   - tests that make FIFOs, read /dev/zero or fork (ImageHardeningTests.cpp,
#     ObjLoaderHardeningTests.cpp, EditorSceneSafeSaveTests.cpp): POSIX cases;
#     the same refusals and saves are checked on every platform by
#     tests/windows/PlatformTests.cpp.
# Header-only libraries come from Debian's /usr/include through a folder of
# links to just them (OUT/include): /usr/include itself is never on the path.
set -eu

if [ $# -lt 1 ]; then
  echo "usage: $0 OUT [CATCH ARGS...]" >&2
  exit 2
fi
mkdir -p "$1"
OUT=$(cd "$1" && pwd)
shift
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
CXX=${STOA_MINGW_CXX:-x86_64-w64-mingw32-g++-posix}
JOBS=${STOA_MINGW_JOBS:-2}
CCACHE=$(command -v ccache || true)   # a second run compiles only what changed

if ! command -v "$CXX" >/dev/null 2>&1; then
  echo "build-core-mingw: skipped: no $CXX (apt-get install g++-mingw-w64-x86-64-posix)"
  exit 77
fi
WINE=$(command -v wine64 || command -v wine || true)
# Debian's wine64 alone (without its recommended wine) has no command on the PATH.
[ -n "$WINE" ] || [ ! -x /usr/lib/wine/wine64 ] || WINE=/usr/lib/wine/wine64
if [ -z "$WINE" ]; then
  echo "build-core-mingw: skipped: no wine64 or wine (apt-get install wine64)"
  exit 77
fi

start=$(date +%s)
# 1. The header-only libraries, each a link.
include="$OUT/include"
rm -rf "$include"
mkdir -p "$include"
for header in /usr/include/glm /usr/include/nlohmann /usr/include/catch2 /usr/include/tiny_obj_loader.h \
              /usr/include/stb/stb_image.h /usr/include/stb/stb_image_write.h /usr/include/stb/stb_vorbis.h; do
  if [ ! -e "$header" ]; then
    echo "build-core-mingw: $header is missing (libglm-dev, nlohmann-json3-dev, catch2, libtinyobjloader-dev, libstb-dev)" >&2
    exit 1
  fi
  ln -s "$header" "$include/"
done
# Debian links their code as libraries; here one file compiles it (stb's, unless
# stoa_core's list holds src/image/StbImplementation.cpp, which does that).
{
  echo "// The code of the header-only libraries, compiled once (build-core-mingw.sh)."
  echo "#define TINYOBJLOADER_IMPLEMENTATION"
  echo "#include <tiny_obj_loader.h>"
  if ! grep -q "src/image/StbImplementation.cpp" "$ROOT/framework/CMakeLists.txt"; then
    echo "#define STB_IMAGE_IMPLEMENTATION"
    echo "#include <stb_image.h>"
    echo "#define STB_IMAGE_WRITE_IMPLEMENTATION"
    echo "#include <stb_image_write.h>"
    echo "#include <stb_vorbis.h>"
  fi
} > "$OUT/HeaderLibraries.cpp"

# 2. The sources: the build's lists, less what is left out (see above). No
# folder in the paths may hold a space.
sources_of() { # sources_of TARGET CMAKELISTS...: the .cpp files its target_sources() calls name
  target=$1
  shift
  for list in "$@"; do
    awk -v target="$target" -v folder="$(dirname "$list")" '
      $0 ~ "target_sources\\(" target "[ )]" { inside = 1 }
      inside {
        line = $0; sub(/#.*/, "", line)
        n = split(line, word, /[ \t()]+/)
        for (i = 1; i <= n; i++) if (word[i] ~ /\.cpp$/) {
          name = word[i]; sub(/^\$\{CMAKE_CURRENT_SOURCE_DIR\}\//, "", name); print folder "/" name
        }
        if (line ~ /\)/) inside = 0
      }' "$list"
  done
}
core=$(sources_of stoa_core "$ROOT/framework/CMakeLists.txt" |
       grep -v -E '/(CrowdXml|XmlAttributes|XmlFile|XmlText|DataAssets|LevelOfDetail)\.cpp$')
tests=$(sources_of stoa-tests-core "$ROOT"/tests/*/CMakeLists.txt |
        grep -v -E '/tests/grader/|/(CrowdXml[A-Za-z]*|LevelOfDetail|AssetCache|[A-Za-z]*Assets|ImageHardening|ObjLoaderHardening|EditorSceneSafeSave)Tests\.cpp$')
tests="$tests
$ROOT/tests/support/main.cpp"

# 3. Compile, JOBS at a time, and link one static program (no DLLs to find under Wine).
# As the Linux build: a warning fails it (STOA_WERROR=OFF: not). Wine shows the
# Linux root as the drive Z:. _USE_MATH_DEFINES: Windows' <cmath> has M_PI only then.
werror=-Werror
[ "${STOA_WERROR:-ON}" = OFF ] && werror=
# shellcheck disable=SC2089,SC2090 # the quotes are the macros' own: STOA_SOURCE_DIR is a string
flags="-std=c++17 -O1 -Wall -Wextra $werror -D_USE_MATH_DEFINES -DGLM_FORCE_CXX17 -DGLM_ENABLE_EXPERIMENTAL
 -DSTOA_SOURCE_DIR=\"Z:$ROOT\" -DSTOA_TEST_DATA_DIR=\"Z:$ROOT/tests/data\"
 -I$ROOT/tests/support -I$ROOT/framework/include -isystem $include"
rm -rf "$OUT/objects" "$OUT/pch"
mkdir -p "$OUT/objects" "$OUT/pch"
log="$OUT/build.log"
# Precompiled headers, as the Linux build has them (most of a file's compile
# time is parsing the standard library and GLM): the headers of
# framework/cmake/StoaPrecompiledHeaders.cmake, and Catch for the tests.
headers=$(sed -n '/^set(STOA_PRECOMPILED/,/)/p' "$ROOT/framework/cmake/StoaPrecompiledHeaders.cmake" | grep -o '<[^>]*>')
for name in core tests; do
  {
    for header in $headers; do echo "#include $header"; done
    [ "$name" = core ] || echo "#include \"$ROOT/tests/support/catch.hpp\""
  } > "$OUT/pch/$name.hpp"
done
# shellcheck disable=SC2090
export CCACHE CXX flags OUT ROOT
# ccache takes precompiled headers only when told that their time stamps may differ.
export CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime
# shellcheck disable=SC2016 # expanded by the sh that xargs starts
printf '%s\n' "$OUT/pch/core.hpp" "$OUT/pch/tests.hpp" |
  xargs -P "$JOBS" -I{} sh -c '$CCACHE $CXX $flags -x c++-header -c "$1" -o "$1.gch" > "$1.log" 2>&1 ||
                                echo "build-core-mingw: cannot compile $1" >> "$1.log"' _ {}
cat "$OUT"/pch/*.log > "$log"
# Each file with its precompiled header; main.cpp (CATCH_CONFIG_MAIN before Catch) and the libraries' code without.
# shellcheck disable=SC2016 # expanded by the sh that xargs starts
printf '%s\n' "$core" "$tests" "$OUT/HeaderLibraries.cpp" |
  xargs -P "$JOBS" -I{} sh -c '
    case "$1" in
      */tests/support/main.cpp|*/HeaderLibraries.cpp) pch= ;;
      "$ROOT"/tests/*) pch="-include $OUT/pch/tests.hpp" ;;
      *) pch="-include $OUT/pch/core.hpp" ;;
    esac
    object="$OUT/objects/$(echo "${1#"$ROOT"/}" | tr / _).o"
    $CCACHE $CXX $flags $pch -c "$1" -o "$object" > "$object.log" 2>&1 || echo "build-core-mingw: cannot compile $1" >> "$object.log"' _ {}
cat "$OUT"/objects/*.log >> "$log"
rm -f "$OUT"/objects/*.log
if grep -q "^build-core-mingw: cannot compile" "$log"; then
  cat "$log" >&2
  exit 1
fi
if ! "$CXX" -static -o "$OUT/stoa-tests-core.exe" "$OUT"/objects/*.o >> "$log" 2>&1; then
  cat "$log" >&2
  echo "build-core-mingw: cannot link $OUT/stoa-tests-core.exe" >&2
  exit 1
fi
echo "build-core-mingw: built $OUT/stoa-tests-core.exe from $(echo "$core" | wc -l) sources of stoa_core" \
     "and $(echo "$tests" | wc -l) test files in $(( $(date +%s) - start )) s"

# 4. Run it under Wine, in a prefix of its own; no Mono or Gecko installer dialogs.
export WINEPREFIX="$OUT/wineprefix" WINEDEBUG=-all WINEDLLOVERRIDES="mscoree,mshtml="
cd "$OUT"
exec "$WINE" "$OUT/stoa-tests-core.exe" "$@"
