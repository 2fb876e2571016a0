#include "ImageFile.hpp"

#include <stoa/core/InputError.hpp>

#include <cctype>
#include <cstring>
#include <cstdio>
#include <string>
#include <vector>

// Every check here runs before stb_image sees a byte. stb_image trusts sizes
// it reads (it allocates what a 54-byte BMP header asks for before it finds
// the pixels missing; it negates a BMP height of INT_MIN; its PNM header
// parser overflows on a long number) and it fills missing BMP, TGA and JPG
// data with zeros, so the sizes are checked against the limits and against
// what the file can hold first.

namespace stoa::detail {

namespace {

class Reader {
public:
    Reader(const std::uint8_t* bytes, std::size_t size, const std::string& name)
        : m_bytes(bytes), m_size(size), m_name(name) {}

    std::size_t size() const { return m_size; }
    bool has(std::size_t at, std::size_t count) const { return at <= m_size && count <= m_size - at; }
    std::uint8_t byte(std::size_t at) const { return m_bytes[at]; }
    std::uint32_t little(std::size_t at, int count) const {
        std::uint32_t value = 0;
        for (int i = count - 1; i >= 0; --i) value = (value << 8) | m_bytes[at + static_cast<std::size_t>(i)];
        return value;
    }
    std::uint32_t big(std::size_t at, int count) const {
        std::uint32_t value = 0;
        for (int i = 0; i < count; ++i) value = (value << 8) | m_bytes[at + static_cast<std::size_t>(i)];
        return value;
    }
    [[noreturn]] void fail(const std::string& message) const { throw InputError(m_name, 0, message); }

private:
    const std::uint8_t* m_bytes;
    std::size_t m_size;
    const std::string& m_name;
};

std::string dimensions(long long width, long long height) {
    return std::to_string(width) + "x" + std::to_string(height);
}

/// Width and height within the limits, or an InputError naming them.
/// (`bytesPerSample` 2 for a 16-bit image: it counts twice towards maxPixels, as stb_image holds
/// it at 16 bits before it converts.)
void checkSize(const Reader& in, const char* format, long long width, long long height, int bytesPerSample = 1) {
    if (width <= 0 || height <= 0) {
        in.fail(std::string("the ") + format + " header gives the size " + dimensions(width, height) +
                "; width and height must be at least 1");
    }
    if (width > Image::maxSide || height > Image::maxSide) {
        in.fail(std::string("the ") + format + " header gives the size " + dimensions(width, height) +
                ", past the limit of " + std::to_string(Image::maxSide) + " pixels per side");
    }
    if (width * height * bytesPerSample > Image::maxPixels) {
        char megapixels[32];
        std::snprintf(megapixels, sizeof megapixels, "%.1f", static_cast<double>(width * height) / (1024.0 * 1024.0));
        in.fail(std::string("the ") + format + " header gives the size " + dimensions(width, height) + " (" + megapixels +
                " megapixels" + (bytesPerSample > 1 ? ", at 16 bits a sample, which count twice" : "") +
                "), past the limit of " + std::to_string(Image::maxPixels / (1024 * 1024)) +
                " megapixels (4096 x 4096): scale it down");
    }
}

[[noreturn]] void truncated(const Reader& in, const char* format, long long width, long long height,
                            std::size_t needed) {
    in.fail(std::string("the file is truncated: its ") + format + " header promises " + dimensions(width, height) +
            " pixels, which need " + std::to_string(needed) + " bytes, but the file has " +
            std::to_string(in.size()));
}

ImageFileHeader checkPng(const Reader& in) {
    if (!in.has(8, 25) || in.big(8, 4) != 13 || in.big(12, 4) != 0x49484452u) {
        in.fail("the PNG is damaged or truncated: it does not start with an IHDR chunk of 13 bytes");
    }
    const std::uint32_t width = in.big(16, 4), height = in.big(20, 4);
    const int depth = in.byte(24), colourType = in.byte(25);
    checkSize(in, "PNG", width, height, depth == 16 ? 2 : 1);
    int samples = 0;
    switch (colourType) {
    case 0: samples = 1; break;
    case 2: samples = 3; break;
    case 3: samples = 1; break;
    case 4: samples = 2; break;
    case 6: samples = 4; break;
    default: in.fail("the PNG has colour type " + std::to_string(colourType) + "; PNG allows 0, 2, 3, 4 and 6");
    }
    const bool depthAllowed = depth == 8 || (depth == 16 && colourType != 3) ||
                              ((depth == 1 || depth == 2 || depth == 4) && (colourType == 0 || colourType == 3));
    if (!depthAllowed) {
        in.fail("the PNG has bit depth " + std::to_string(depth) + " with colour type " +
                std::to_string(colourType) + ", which PNG does not allow");
    }
    // Walk the chunks: every one complete, an IEND at the end.
    std::size_t at = 8;
    unsigned long long imageData = 0;
    bool ended = false;
    while (!ended) {
        if (!in.has(at, 8)) {
            in.fail("the PNG is truncated: it ends at byte " + std::to_string(in.size()) +
                    " without its IEND chunk");
        }
        const std::uint32_t length = in.big(at, 4);
        const std::uint32_t type = in.big(at + 4, 4);
        if (length > 0x7fffffffu || !in.has(at + 8, std::size_t(length) + 4)) {
            in.fail("the PNG is truncated: a chunk at byte " + std::to_string(at) + " claims " +
                    std::to_string(length) + " bytes, but the file ends at byte " + std::to_string(in.size()));
        }
        if (type == 0x49444154u) imageData += length;  // IDAT
        ended = type == 0x49454e44u;                     // IEND
        at += std::size_t(length) + 12;
    }
    if (imageData == 0) in.fail("the PNG has no image data (no IDAT chunk)");
    // Deflate packs at most 1032 bytes into one; a file that would need a
    // better ratio was patched or is damaged, and is refused before
    // stb_image allocates for the size it claims.
    const unsigned long long rowBytes = (static_cast<unsigned long long>(width) * samples * depth + 7) / 8 + 1;
    const unsigned long long raw = rowBytes * height;
    if (raw > imageData * 1032 + 1024) {
        in.fail("the PNG's image data (" + std::to_string(imageData) + " bytes) cannot hold " +
                dimensions(width, height) + " pixels even at deflate's best ratio; the file is damaged or its "
                "header was altered");
    }
    return {ImageFormat::Png, static_cast<int>(width), static_cast<int>(height), depth == 16 ? 16 : 8};
}

ImageFileHeader checkJpg(const Reader& in) {
    // The markers up to the first frame header (SOFn); checkJpegData() walks the rest.
    std::size_t at = 2;
    for (;;) {
        while (in.has(at, 1) && in.byte(at) == 0xff && in.has(at + 1, 1) && in.byte(at + 1) == 0xff) ++at;
        if (!in.has(at, 4)) in.fail("the JPG is truncated: it ends before its frame header (SOF)");
        if (in.byte(at) != 0xff) in.fail("the JPG is damaged: no marker at byte " + std::to_string(at));
        const int marker = in.byte(at + 1);
        const std::uint32_t length = in.big(at + 2, 2);
        if (length < 2 || !in.has(at + 2, length)) {
            in.fail("the JPG is truncated: a segment at byte " + std::to_string(at) + " claims " +
                    std::to_string(length) + " bytes, but the file ends at byte " + std::to_string(in.size()));
        }
        const bool frame = marker >= 0xc0 && marker <= 0xcf && marker != 0xc4 && marker != 0xc8 && marker != 0xcc;
        if (frame) {
            if (marker != 0xc0 && marker != 0xc1 && marker != 0xc2) {
                in.fail("the JPG uses a coding Stoa cannot read (lossless, hierarchical or arithmetic, SOF marker " +
                        std::to_string(marker - 0xc0) + "); save it as a baseline or progressive JPG");
            }
            if (length < 8) in.fail("the JPG's frame header is too short");
            const int precision = in.byte(at + 4);
            const std::uint32_t height = in.big(at + 5, 2), width = in.big(at + 7, 2);
            if (precision != 8) in.fail("the JPG has " + std::to_string(precision) + "-bit samples; only 8 bits are read");
            if (height == 0) in.fail("the JPG gives its height in a DNL marker, which Stoa does not read");
            checkSize(in, "JPG", width, height);
            return {ImageFormat::Jpg, static_cast<int>(width), static_cast<int>(height), 8};
        }
        if (marker == 0xda || marker == 0xd9) in.fail("the JPG has no frame header (SOF) before its image data");
        at += 2 + length;
    }
}

ImageFileHeader checkBmp(const Reader& in) {
    if (!in.has(0, 18)) in.fail("the BMP is truncated: its header needs at least 18 bytes, the file has " +
                                std::to_string(in.size()));
    const std::uint32_t headerSize = in.little(14, 4);
    if (headerSize != 12 && headerSize != 40 && headerSize != 56 && headerSize != 108 && headerSize != 124) {
        in.fail("the BMP has an info header of " + std::to_string(headerSize) +
                " bytes; Stoa reads 12 (OS/2), 40, 56, 108 and 124");
    }
    if (!in.has(14, headerSize)) {
        in.fail("the BMP is truncated: its info header needs " + std::to_string(14 + headerSize) +
                " bytes, the file has " + std::to_string(in.size()));
    }
    long long width = 0, height = 0;
    std::uint32_t bitsPerPixel = 0, compression = 0;
    if (headerSize == 12) {  // OS/2 1.x: 16-bit sizes, no compression
        width = in.little(18, 2);
        height = in.little(20, 2);
        bitsPerPixel = in.little(24, 2);
    } else {
        width = static_cast<std::int32_t>(in.little(18, 4));
        height = static_cast<std::int32_t>(in.little(22, 4));
        if (height < 0) height = -height;  // top-down rows; in long long, INT_MIN negates safely
        bitsPerPixel = in.little(28, 2);
        compression = in.little(30, 4);
    }
    checkSize(in, "BMP", width, height);
    if (bitsPerPixel != 1 && bitsPerPixel != 4 && bitsPerPixel != 8 && bitsPerPixel != 16 && bitsPerPixel != 24 &&
        bitsPerPixel != 32) {
        in.fail("the BMP has " + std::to_string(bitsPerPixel) + " bits per pixel; BMP allows 1, 4, 8, 16, 24 and 32");
    }
    if (compression == 1 || compression == 2) in.fail("the BMP is run-length encoded (RLE), which Stoa does not read");
    if (compression != 0 && compression != 3) {
        in.fail("the BMP uses compression " + std::to_string(compression) + "; Stoa reads uncompressed BMPs only");
    }
    const std::size_t dataOffset = in.little(10, 4);
    const unsigned long long rowBytes = (static_cast<unsigned long long>(width) * bitsPerPixel + 31) / 32 * 4;
    const unsigned long long needed = dataOffset + rowBytes * static_cast<unsigned long long>(height);
    if (needed > in.size()) truncated(in, "BMP", width, height, needed);
    return {ImageFormat::Bmp, static_cast<int>(width), static_cast<int>(height), 8};
}

/// TGA has no signature: a header is taken for TGA only when every field is
/// one TGA allows (a colour-map type of 0 or 1 alone tells it from every other
/// format Stoa knows).
bool looksLikeTga(const Reader& in) {
    if (!in.has(0, 18)) return false;
    const int colourMapType = in.byte(1), imageType = in.byte(2), bits = in.byte(16);
    if (colourMapType > 1) return false;
    const int base = imageType & ~8;
    if (imageType > 11 || base < 1 || base > 3) return false;
    if (base == 1) return colourMapType == 1 && (bits == 8 || bits == 16);
    if (base == 2) return bits == 15 || bits == 16 || bits == 24 || bits == 32;
    return bits == 8 || bits == 16;
}

ImageFileHeader checkTga(const Reader& in) {
    const long long width = in.little(12, 2), height = in.little(14, 2);
    checkSize(in, "TGA", width, height);
    const int imageType = in.byte(2);
    std::size_t colourMapBytes = 0;
    if (in.byte(1) == 1) {
        const int entryBits = in.byte(7);
        if (entryBits != 15 && entryBits != 16 && entryBits != 24 && entryBits != 32) {
            in.fail("the TGA's colour map has " + std::to_string(entryBits) + "-bit entries; TGA allows 15, 16, 24 and 32");
        }
        colourMapBytes = std::size_t(in.little(5, 2)) * std::size_t((entryBits + 7) / 8);
    }
    const std::size_t pixelBytes = (in.byte(16) + 7u) / 8u;
    std::size_t at = 18 + in.byte(0) + colourMapBytes;
    const unsigned long long pixels = static_cast<unsigned long long>(width) * height;
    if (imageType < 9) {
        const unsigned long long needed = at + pixels * pixelBytes;
        if (needed > in.size()) truncated(in, "TGA", width, height, needed);
    } else {
        // Walk the run-length packets: a header byte, then one pixel (a run) or n raw pixels.
        for (unsigned long long done = 0; done < pixels;) {
            if (at >= in.size()) {
                in.fail("the file is truncated: its TGA header promises " + dimensions(width, height) +
                        " pixels, but its run-length data ends after " + std::to_string(done));
            }
            const std::uint8_t header = in.byte(at++);
            const std::size_t count = (header & 0x7fu) + 1u;
            at += (header & 0x80u) ? pixelBytes : count * pixelBytes;
            done += count;
        }
        if (at > in.size()) {
            in.fail("the file is truncated: its TGA run-length data ends inside a packet");
        }
    }
    return {ImageFormat::Tga, static_cast<int>(width), static_cast<int>(height), 8};
}

/// A PNM header: magic, width, height and maxval, with '#' comments between.
struct PnmHeader {
    char kind = 0;  // '2', '3', '5' or '6'
    long long width = 0, height = 0, maxValue = 0;
    std::size_t dataStart = 0;  // the first byte after the single whitespace that ends the header
};

PnmHeader readPnmHeader(const Reader& in) {
    PnmHeader header;
    header.kind = static_cast<char>(in.byte(1));
    if (header.kind == '1' || header.kind == '4') {
        in.fail("the file is a PBM bitmap (P1/P4), which Stoa does not read; save it as a PGM (P2/P5)");
    }
    if (header.kind == '7') in.fail("the file is a PAM (P7), which Stoa does not read; save it as a PGM or PPM");
    std::size_t at = 2;
    long long* fields[3] = {&header.width, &header.height, &header.maxValue};
    const char* names[3] = {"width", "height", "maxval"};
    for (int field = 0; field < 3; ++field) {
        for (;;) {
            while (in.has(at, 1) && std::isspace(in.byte(at))) ++at;
            if (!in.has(at, 1) || in.byte(at) != '#') break;
            while (in.has(at, 1) && in.byte(at) != '\n' && in.byte(at) != '\r') ++at;
        }
        if (!in.has(at, 1)) in.fail(std::string("the PNM header ends before its ") + names[field]);
        if (in.byte(at) == '-') in.fail(std::string("the PNM header gives a negative ") + names[field]);
        if (!std::isdigit(in.byte(at))) {
            in.fail(std::string("the PNM header's ") + names[field] + " is not a number (found byte " +
                    std::to_string(in.byte(at)) + ")");
        }
        long long value = 0;
        while (in.has(at, 1) && std::isdigit(in.byte(at))) {
            value = value * 10 + (in.byte(at++) - '0');
            if (value > 1000000000000LL) {
                in.fail(std::string("the PNM header's ") + names[field] + " (" + std::to_string(value) +
                        "...) is far too large");
            }
        }
        *fields[field] = value;
        if (in.has(at, 1) && !std::isspace(in.byte(at))) {
            in.fail(std::string("the PNM header's ") + names[field] + " is followed by a byte that is not a space");
        }
    }
    header.dataStart = at + 1;
    return header;
}

ImageFileHeader checkPnm(const Reader& in) {
    const PnmHeader header = readPnmHeader(in);
    checkSize(in, "PNM", header.width, header.height, header.maxValue > 255 ? 2 : 1);
    if (header.maxValue < 1 || header.maxValue > 65535) {
        in.fail("the PNM header gives maxval " + std::to_string(header.maxValue) + "; it must be 1 to 65535");
    }
    const int channels = header.kind == '3' || header.kind == '6' ? 3 : 1;
    const unsigned long long samples = static_cast<unsigned long long>(header.width) * header.height * channels;
    if (header.kind == '5' || header.kind == '6') {
        const unsigned long long needed = header.dataStart + samples * (header.maxValue > 255 ? 2 : 1);
        if (needed > in.size()) truncated(in, "PNM", header.width, header.height, needed);
    } else if (samples > in.size() - std::min(in.size(), header.dataStart) + 1) {
        // Each ASCII sample takes at least a digit and a separator.
        in.fail("the file is truncated: its PNM header promises " + dimensions(header.width, header.height) +
                " pixels, more samples than the file's " + std::to_string(in.size()) + " bytes can hold");
    }
    return {ImageFormat::Pnm, static_cast<int>(header.width), static_cast<int>(header.height),
            header.maxValue > 255 ? 16 : 8};
}

bool startsWith(const Reader& in, const char* signature) {
    const std::size_t length = std::strlen(signature);
    if (!in.has(0, length)) return false;
    for (std::size_t i = 0; i < length; ++i) {
        if (in.byte(i) != static_cast<std::uint8_t>(signature[i])) return false;
    }
    return true;
}

} // namespace

ImageFileHeader checkImageFile(const std::uint8_t* bytes, std::size_t size, const std::string& name) {
    const Reader in(bytes, size, name);
    if (size == 0) in.fail("the file is empty");
    if (startsWith(in, "\x89PNG\r\n\x1a\n")) return checkPng(in);
    if (startsWith(in, "\xff\xd8\xff")) return checkJpg(in);
    if (startsWith(in, "BM")) return checkBmp(in);
    if (in.has(0, 2) && in.byte(0) == 'P' && in.byte(1) >= '1' && in.byte(1) <= '7') {
        if (in.byte(1) == '2' || in.byte(1) == '3' || in.byte(1) == '5' || in.byte(1) == '6') return checkPnm(in);
        readPnmHeader(in);  // throws for P1, P4, P7
    }
    const char* other = startsWith(in, "GIF8")         ? "a GIF"
                        : startsWith(in, "8BPS")       ? "a Photoshop (PSD) file"
                        : startsWith(in, "#?RADIANCE") ? "a Radiance HDR file"
                        : startsWith(in, "#?RGBE")     ? "a Radiance HDR file"
                        : startsWith(in, "RIFF")       ? "a RIFF file (WebP?)"
                        : startsWith(in, "\x89PNG")    ? "a damaged PNG (its signature is cut or altered)"
                                                       : nullptr;
    if (other) {
        in.fail(std::string("the file is ") + other + ", whatever its name says; Stoa reads PNG, JPG, BMP, TGA "
                "and PGM/PPM images only");
    }
    if (looksLikeTga(in)) return checkTga(in);
    in.fail("not a PNG, JPG, BMP, TGA or PGM/PPM image (the first bytes match none of them)");
}

namespace {

/// Calls store(i, value) for each of the `samples` samples after the header,
/// binary (P5, P6: one byte, or two big-endian bytes when maxval > 255) or text
/// (P2, P3); a value above maxval is clamped (binary) or refused (text).
template <typename Store>
void readPnmSamples(const Reader& in, const PnmHeader& header, std::size_t samples, Store&& store) {
    const unsigned long maxValue = static_cast<unsigned long>(header.maxValue);
    if (header.kind == '5' || header.kind == '6') {
        // checkImageFile() saw that they are all there.
        for (std::size_t i = 0; i < samples; ++i) {
            const std::size_t at = header.dataStart + (maxValue > 255 ? 2 * i : i);
            unsigned long value = maxValue > 255 ? (unsigned long)(in.byte(at) << 8 | in.byte(at + 1)) : in.byte(at);
            if (value > maxValue) value = maxValue;
            store(i, value);
        }
        return;
    }
    std::size_t at = header.dataStart - 1;  // ASCII samples may follow any whitespace
    for (std::size_t i = 0; i < samples; ++i) {
        for (;;) {
            while (in.has(at, 1) && std::isspace(in.byte(at))) ++at;
            if (!in.has(at, 1) || in.byte(at) != '#') break;
            while (in.has(at, 1) && in.byte(at) != '\n' && in.byte(at) != '\r') ++at;
        }
        if (!in.has(at, 1)) {
            in.fail("the file is truncated: its PNM header promises " + std::to_string(samples) + " samples, but it "
                    "holds " + std::to_string(i));
        }
        if (!std::isdigit(in.byte(at))) {
            in.fail("sample " + std::to_string(i + 1) + " of the PNM is not a number (found byte " +
                    std::to_string(in.byte(at)) + ")");
        }
        unsigned long value = 0;
        while (in.has(at, 1) && std::isdigit(in.byte(at))) {
            value = value * 10 + (in.byte(at++) - '0');
            if (value > maxValue) {
                in.fail("sample " + std::to_string(i + 1) + " of the PNM is larger than its maxval " +
                        std::to_string(maxValue));
            }
        }
        store(i, value);
    }
}

} // namespace

Image decodePnm(const std::uint8_t* bytes, std::size_t size, const std::string& name) {
    const Reader in(bytes, size, name);
    const PnmHeader header = readPnmHeader(in);
    const int channels = header.kind == '3' || header.kind == '6' ? 3 : 1;
    Image image(static_cast<int>(header.width), static_cast<int>(header.height), channels);
    const unsigned long maxValue = static_cast<unsigned long>(header.maxValue);
    std::uint8_t* out = image.data();
    readPnmSamples(in, header, image.sizeInBytes(), [&](std::size_t i, unsigned long value) {
        out[i] = static_cast<std::uint8_t>((value * 255 + maxValue / 2) / maxValue);
    });
    return image;
}

std::vector<float> decodePgmFractions(const std::uint8_t* bytes, std::size_t size, const std::string& name, int& width,
                                      int& height) {
    const Reader in(bytes, size, name);
    const PnmHeader header = readPnmHeader(in);
    if (header.kind == '3' || header.kind == '6') {
        in.fail("the file is a colour PPM; a height map at full precision must be grey (PGM, P2 or P5)");
    }
    width = static_cast<int>(header.width);
    height = static_cast<int>(header.height);
    std::vector<float> values(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
    const float maxValue = static_cast<float>(header.maxValue);
    readPnmSamples(in, header, values.size(),
                   [&](std::size_t i, unsigned long value) { values[i] = static_cast<float>(value) / maxValue; });
    return values;
}

} // namespace stoa::detail
