#pragma once
// The entry points the libFuzzer harnesses (fuzz_*.cpp, built by
// build-fuzzers.sh with clang) and the regression replay (replay.cpp, built
// by CMake and run by CTest) feed bytes to. Each returns true when the loader
// accepted the input and false when it threw InputError; anything else (a
// crash, another exception, a sanitizer report) is a finding.

#include <cstddef>
#include <cstdint>
#include <string>

namespace stoa::fuzz {

/// OBJ text; everything after the first line "#@mtl" is the text of every MTL
/// file an mtllib line names (the line itself is an OBJ comment).
bool obj(const std::uint8_t* data, std::size_t size);
/// Any image file (PNG, JPG, BMP, TGA, PGM/PPM, or anything else).
bool image(const std::uint8_t* data, std::size_t size);
/// The same bytes as a height map.
bool heightMap(const std::uint8_t* data, std::size_t size);
/// A Quake 2 MD2 model, stoa::decodeMd2.
bool md2(const std::uint8_t* data, std::size_t size);
/// A crowd world's XML, stoa::parseCrowdWorld, named fuzz.xml in a folder
/// that does not exist (so an <include> is refused, never read).
bool crowdXml(const std::uint8_t* data, std::size_t size);
/// An editor scene file's JSON, stoa::editorSceneFromJson; a scene it reads
/// must also save, and read back to the same text.
bool editorScene(const std::uint8_t* data, std::size_t size);

/// A sound file (Ogg Vorbis, WAV, or anything else), stoa::SoundClip::decode;
/// a clip it reads is mono or stereo, within the rate and length limits.
bool sound(const std::uint8_t* data, std::size_t size);

/// The separator line of obj() inputs.
inline const std::string mtlSeparator = "\n#@mtl\n";

} // namespace stoa::fuzz
