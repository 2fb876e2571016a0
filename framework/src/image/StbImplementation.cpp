// The code of the stb headers Stoa uses, compiled into stoa_core where stb
// comes as headers only (vcpkg, Homebrew, or -DSTOA_STB_FROM_HEADERS=ON).
// Debian's libstb holds this code already, and the build links that instead
// (framework/cmake/StoaDependencies.cmake).

#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>

// Without STB_VORBIS_HEADER_ONLY the file holds its code.
#if __has_include(<stb_vorbis.h>)
#include <stb_vorbis.h>
#else
#include <stb_vorbis.c>
#endif
