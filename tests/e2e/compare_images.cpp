// compare_images ACTUAL.png REFERENCE.png: exit 0 when the two images match
// within the grader's default tolerance, 1 when they differ, 2 on bad input.
// The end-to-end tests use it to check the window against the headless render.

#include <stoa/core/InputError.hpp>
#include <stoa/image/ImageCompare.hpp>

#include <cstdio>

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: compare_images ACTUAL.png REFERENCE.png\n");
        return 2;
    }
    try {
        const stoa::Image actual = stoa::Image::load(argv[1]);
        const stoa::Image reference = stoa::Image::load(argv[2]);
        const stoa::CompareResult result = stoa::compareImages(actual, reference);
        std::printf("%s: %s\n", result.passed ? "match" : "DIFFERENT", result.summary.c_str());
        return result.passed ? 0 : 1;
    } catch (const stoa::InputError& error) {
        std::fprintf(stderr, "compare_images: %s\n", error.what());
        return 2;
    }
}
