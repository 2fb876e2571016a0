/* The fuzzers compile Debian's stb_image (libstb-dev) with the sanitizers, so
   that undefined behaviour inside it is found too. Stoa itself links libstb. */
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image.h>
#include <stb_image_write.h>
