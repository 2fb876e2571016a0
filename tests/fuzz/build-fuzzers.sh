#!/usr/bin/env bash
# Builds one libFuzzer harness per loader with Debian's clang 14 and
# -fsanitize=fuzzer,address,undefined:
#   fuzz-obj        OBJ text (+ MTL text after a line "#@mtl"), stoa::parseObj
#   fuzz-image      any image file, stoa::Image::decode
#   fuzz-heightmap  any image file, stoa::decodeHeightMap
#   fuzz-md2        a Quake 2 MD2 model, stoa::decodeMd2
#   fuzz-crowd_xml  a crowd world's XML, stoa::parseCrowdWorld (linked with Debian's pugixml)
#   fuzz-editor_scene  an editor scene file's JSON, stoa::editorSceneFromJson (Debian's nlohmann-json)
#   fuzz-sound      a sound file (Ogg Vorbis or WAV), stoa::SoundClip::decode; stb_vorbis is
#                   Debian's libstb, not instrumented (Debian ships no stb_vorbis source),
#                   and bounded instead: it decodes in a 4 MiB buffer of its own
# Usage: tests/fuzz/build-fuzzers.sh [OUT_DIR]   (default: build-fuzz)
# stb_image is Debian's copy (/usr/include/stb), compiled here with the same
# sanitizers so that undefined behaviour inside it is reported too.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
out=${1:-$root/build-fuzz}
cxx=${CXX_FUZZ:-clang++-14}
cc=${CC_FUZZ:-clang-14}
mkdir -p "$out/obj"

sanitize="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
flags="-O1 -g $sanitize -fsanitize=fuzzer-no-link -I$root/framework/include -I/usr/include/stb -DNDEBUG"
sources=(
  framework/src/core/Errors.cpp framework/src/core/InputFile.cpp
  framework/src/geometry/Mesh.cpp framework/src/geometry/ObjLoader.cpp framework/src/geometry/FaceTriangulation.cpp
  framework/src/image/Image.cpp framework/src/image/ImageFile.cpp framework/src/image/JpegCheck.cpp
  framework/src/image/HeightMap.cpp
  framework/src/geometry/Md2Model.cpp
  framework/src/crowd/CrowdWorld.cpp framework/src/crowd/CrowdXml.cpp framework/src/crowd/XmlAttributes.cpp framework/src/crowd/XmlFile.cpp framework/src/crowd/XmlText.cpp
  framework/src/editor/EditorScene.cpp framework/src/editor/EditorSceneFile.cpp framework/src/editor/JsonDocument.cpp
  framework/src/editor/SafeSave.cpp
  framework/src/audio/SoundClip.cpp
  tests/fuzz/FuzzTargets.cpp
)
objects=()
pids=()
jobs=${FUZZ_BUILD_JOBS:-2}
for source in "${sources[@]}"; do
  object="$out/obj/$(basename "${source%.*}").o"
  objects+=("$object")
  if [[ ! -f "$object" || "$root/$source" -nt "$object" || -n "$(find "$root/framework/include" "$root/framework/src" "$root/tests/fuzz" -name '*.hpp' -newer "$object" -print -quit)" ]]; then
    echo "compile $source"
    $cxx -std=c++17 $flags -c "$root/$source" -o "$object" &
    pids+=($!)
    if (( ${#pids[@]} >= jobs )); then wait "${pids[0]}"; pids=("${pids[@]:1}"); fi
  fi
done
stb="$out/obj/stb_image_impl.o"
if [[ ! -f "$stb" ]]; then
  echo "compile stb_image (Debian's copy)"
  $cc $flags -w -c "$root/tests/fuzz/stb_image_impl.c" -o "$stb"
fi
for pid in "${pids[@]}"; do wait "$pid"; done
for target in obj image heightmap md2 crowd_xml editor_scene sound; do
  echo "link fuzz-$target"
  $cxx -std=c++17 -O1 -g $sanitize -fsanitize=fuzzer "$root/tests/fuzz/fuzz_$target.cpp" -I"$root/framework/include" \
       "${objects[@]}" "$stb" -lpugixml -lstb -o "$out/fuzz-$target"
done
echo "fuzzers in $out: fuzz-obj fuzz-image fuzz-heightmap fuzz-md2 fuzz-crowd_xml fuzz-editor_scene fuzz-sound"
