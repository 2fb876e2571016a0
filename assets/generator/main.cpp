// stoa-generate-assets: writes the Acropolis scene's meshes, materials and
// textures (assets/README.md lists them).
//
//   stoa-generate-assets OUTPUT_DIR                     every committed file
//   stoa-generate-assets --dense-statue N OUTPUT_DIR    only statue_dense.obj, about N triangles
//   stoa-generate-assets --sky OUTPUT_DIR               the sky's six cube-map faces (assets/sky/)
//   stoa-generate-assets --characters OUTPUT_DIR        lab 10's MD2 characters and skins (assets/crowds/)
//   stoa-generate-assets --sounds OUTPUT_DIR            the Ogg Vorbis sounds (assets/sounds/)

#include "Acropolis.hpp"
#include "Characters.hpp"
#include "Sky.hpp"
#include "Sounds.hpp"

#include <stoa/core/InputError.hpp>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

namespace {

int usage() {
    std::fprintf(stderr,
                 "usage: stoa-generate-assets OUTPUT_DIR\n"
                 "       stoa-generate-assets --dense-statue TRIANGLES OUTPUT_DIR\n"
                 "       stoa-generate-assets --sky OUTPUT_DIR\n"
                 "       stoa-generate-assets --characters OUTPUT_DIR\n"
                 "       stoa-generate-assets --sounds OUTPUT_DIR\n"
                 "Writes the Acropolis scene (assets/acropolis/ is its committed output), or only a\n"
                 "statue with about TRIANGLES triangles as OUTPUT_DIR/statue_dense.obj, or the sky's\n"
                 "six cube-map faces (assets/sky/ is their committed output), or lab 10's three MD2\n"
                 "characters with their skins (assets/crowds/ is their committed output), or the\n"
                 "footstep, spark and wind sounds as Ogg Vorbis (assets/sounds/ is their committed output).\n");
    return 2;
}

} // namespace

int main(int argc, char** argv) {
    try {
        if (argc == 2 && argv[1][0] != '-') {
            stoa::assets::generateAcropolis(argv[1]);
            std::printf("wrote %zu files to %s\n", stoa::assets::acropolisFileNames().size(), argv[1]);
            return 0;
        }
        if (argc == 3 && std::string(argv[1]) == "--sky") {
            stoa::assets::generateSky(argv[2]);
            std::printf("wrote %zu files to %s\n", stoa::assets::skyFileNames().size(), argv[2]);
            return 0;
        }
        if (argc == 3 && std::string(argv[1]) == "--characters") {
            stoa::assets::generateCharacters(argv[2]);
            std::printf("wrote %zu files to %s\n", stoa::assets::characterFileNames().size(), argv[2]);
            return 0;
        }
        if (argc == 3 && std::string(argv[1]) == "--sounds") {
            stoa::assets::generateSounds(argv[2]);
            std::printf("wrote %zu files to %s\n", stoa::assets::soundFileNames().size(), argv[2]);
            return 0;
        }
        if (argc == 4 && std::string(argv[1]) == "--dense-statue") {
            char* end = nullptr;
            const long triangles = std::strtol(argv[2], &end, 10);
            if (*end != '\0' || triangles < 16 || triangles > 100000000) {
                std::fprintf(stderr, "stoa-generate-assets: --dense-statue wants a triangle count from 16 to 100000000, got '%s'\n", argv[2]);
                return 2;
            }
            const auto path = stoa::assets::generateDenseStatue(argv[3], static_cast<int>(triangles));
            std::printf("wrote %s\n", path.c_str());
            return 0;
        }
        return usage();
    } catch (const std::exception& error) {
        std::fprintf(stderr, "stoa-generate-assets: %s\n", error.what());
        return 1;
    }
}
