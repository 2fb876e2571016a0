#include "ImageFile.hpp"

#include <stoa/core/InputError.hpp>

#include <array>
#include <string>
#include <vector>

// stb_image decodes a JPG whose entropy-coded data ends early (a truncated
// file, or a header patched to a larger size) by padding the missing bits
// with zeros, and reports success: the picture is garbage. This walk counts
// what the data really holds. For a sequential (baseline) JPG it decodes every
// Huffman code of every block, without dequantising or transforming anything
// (it costs a small part of a real decode, and stops as soon as the data does);
// for a progressive one it checks that the scans end at an end-of-image marker
// and hold at least one bit per block.

namespace stoa::detail {

namespace {

struct HuffmanTable {
    bool defined = false;
    std::array<int, 18> maxCode{};  // the largest code of each length, -1 when none
    std::array<int, 17> minCode{};
    std::array<int, 17> firstValue{};
    std::array<std::uint8_t, 256> values{};
};

struct Component {
    int id = 0, h = 1, v = 1;
    int dcTable = 0, acTable = 0;
};

class JpegWalk {
public:
    JpegWalk(const std::uint8_t* bytes, std::size_t size, const std::string& name)
        : m_bytes(bytes), m_size(size), m_name(name) {}

    void run();

private:
    [[noreturn]] void fail(const std::string& message) const { throw InputError(m_name, 0, message); }
    std::uint32_t big(std::size_t at) const { return (std::uint32_t(m_bytes[at]) << 8) | m_bytes[at + 1]; }

    void readHuffmanTables(std::size_t at, std::size_t end);
    void readFrame(std::size_t at, std::size_t end, bool progressive);
    std::size_t walkScan(std::size_t at, std::size_t end);
    std::vector<Component> scanComponents(std::size_t at, std::size_t end) const;
    long long unitCount(std::vector<Component>& scan) const;
    void skipBlock(const Component& component, long long mcu, long long mcus);
    [[noreturn]] void ranOut(long long mcu, long long mcus) const;
    std::size_t nextMarker(std::size_t at, unsigned long long* dataBytes) const;

    // The bit reader of a sequential scan.
    int bit();
    int decode(const HuffmanTable& table);
    bool skipBits(int count);

    const std::uint8_t* m_bytes;
    std::size_t m_size;
    const std::string& m_name;

    HuffmanTable m_dc[4], m_ac[4];
    std::vector<Component> m_components;
    int m_width = 0, m_height = 0, m_maxH = 1, m_maxV = 1;
    bool m_frame = false, m_progressive = false;
    unsigned m_restartInterval = 0;
    unsigned long long m_progressiveBytes = 0;
    int m_scans = 0;

    std::size_t m_at = 0;
    std::uint32_t m_accumulator = 0;
    int m_bitsLeft = 0;
};

void JpegWalk::readHuffmanTables(std::size_t at, std::size_t end) {
    while (at < end) {
        const int tableClass = m_bytes[at] >> 4, index = m_bytes[at] & 15;
        if (tableClass > 1 || index > 3) fail("the JPG is damaged: a Huffman table has class " +
                                              std::to_string(tableClass) + " and index " + std::to_string(index));
        if (end - at < 17) fail("the JPG is damaged: a Huffman table is cut short");
        HuffmanTable& table = tableClass == 0 ? m_dc[index] : m_ac[index];
        table = HuffmanTable();
        int count = 0, code = 0;
        for (int length = 1; length <= 16; ++length) {
            const int codes = m_bytes[at + std::size_t(length)];
            table.firstValue[length] = count;
            table.minCode[length] = code;
            code += codes;
            count += codes;
            if (code > (1 << length)) fail("the JPG is damaged: a Huffman table has more codes than fit");
            table.maxCode[length] = codes ? code - 1 : -1;
            code <<= 1;
        }
        if (count > 256 || end - at - 17 < std::size_t(count)) fail("the JPG is damaged: a Huffman table is cut short");
        for (int i = 0; i < count; ++i) table.values[std::size_t(i)] = m_bytes[at + 17 + std::size_t(i)];
        table.defined = true;
        at += 17 + std::size_t(count);
    }
}

void JpegWalk::readFrame(std::size_t at, std::size_t end, bool progressive) {
    if (m_frame) fail("the JPG has two frame headers (SOF)");
    if (end - at < 6) fail("the JPG's frame header is too short");
    m_height = static_cast<int>(big(at + 1));
    m_width = static_cast<int>(big(at + 3));
    const int count = m_bytes[at + 5];
    if (count != 1 && count != 3 && count != 4) {
        fail("the JPG has " + std::to_string(count) + " colour components; Stoa reads 1 (grey), 3 and 4");
    }
    if (end - at < 6 + 3 * std::size_t(count)) fail("the JPG's frame header is too short");
    for (int i = 0; i < count; ++i) {
        Component component;
        component.id = m_bytes[at + 6 + 3 * std::size_t(i)];
        component.h = m_bytes[at + 7 + 3 * std::size_t(i)] >> 4;
        component.v = m_bytes[at + 7 + 3 * std::size_t(i)] & 15;
        if (component.h < 1 || component.h > 4 || component.v < 1 || component.v > 4) {
            fail("the JPG is damaged: a component has sampling factors " + std::to_string(component.h) + "x" +
                 std::to_string(component.v) + " (1 to 4 allowed)");
        }
        for (const Component& other : m_components) {
            if (other.id == component.id) {
                fail("the JPG's frame header names component " + std::to_string(component.id) + " twice");
            }
        }
        m_maxH = std::max(m_maxH, component.h);
        m_maxV = std::max(m_maxV, component.v);
        m_components.push_back(component);
    }
    m_frame = true;
    m_progressive = progressive;
}

int JpegWalk::bit() {
    if (m_bitsLeft == 0) {
        if (m_at >= m_size) return -1;
        const std::uint8_t byte = m_bytes[m_at];
        if (byte == 0xff) {
            if (m_at + 1 >= m_size || m_bytes[m_at + 1] != 0) return -1;  // a marker: the scan's data ends
            m_at += 2;
        } else {
            ++m_at;
        }
        m_accumulator = byte;
        m_bitsLeft = 8;
    }
    --m_bitsLeft;
    return static_cast<int>((m_accumulator >> m_bitsLeft) & 1u);
}

/// The next symbol, -1 when the data ends, -2 for a code the table lacks.
int JpegWalk::decode(const HuffmanTable& table) {
    int code = 0;
    for (int length = 1; length <= 16; ++length) {
        const int next = bit();
        if (next < 0) return -1;
        code = (code << 1) | next;
        if (code <= table.maxCode[std::size_t(length)]) {
            return table.values[std::size_t(table.firstValue[std::size_t(length)] + code -
                                            table.minCode[std::size_t(length)]) & 255u];
        }
    }
    return -2;
}

bool JpegWalk::skipBits(int count) {
    for (int i = 0; i < count; ++i) {
        if (bit() < 0) return false;
    }
    return true;
}

/// The offset of the next marker at or after `at` that is not a restart
/// marker; `dataBytes` (when given) grows by the bytes passed over.
std::size_t JpegWalk::nextMarker(std::size_t at, unsigned long long* dataBytes) const {
    const std::size_t start = at;
    while (at + 1 < m_size) {
        if (m_bytes[at] == 0xff) {
            const std::uint8_t next = m_bytes[at + 1];
            if (next != 0 && next != 0xff && !(next >= 0xd0 && next <= 0xd7)) break;
        }
        ++at;
    }
    if (dataBytes) *dataBytes += at - start;
    return at;
}

/// The components a scan header names, with the Huffman tables it picks for each.
std::vector<Component> JpegWalk::scanComponents(std::size_t at, std::size_t end) const {
    if (!m_frame) fail("the JPG has image data (SOS) before its frame header (SOF)");
    if (end - at < 1) fail("the JPG's scan header is too short");
    const std::size_t count = m_bytes[at];
    if (count < 1 || count > 4 || end - at < 1 + 2 * count + 3) fail("the JPG's scan header is damaged");
    std::vector<Component> scan;
    for (std::size_t i = 0; i < count; ++i) {
        const int id = m_bytes[at + 1 + 2 * i];
        const Component* found = nullptr;
        for (const Component& component : m_components) {
            if (component.id == id) found = &component;
        }
        if (!found) fail("the JPG's scan names component " + std::to_string(id) + ", which its frame lacks");
        // stb_image keeps one Huffman table choice per component, so a
        // component named twice would be decoded with other tables than
        // these; the standard does not allow it.
        for (const Component& earlier : scan) {
            if (earlier.id == id) fail("the JPG's scan names component " + std::to_string(id) + " twice");
        }
        Component component = *found;
        component.dcTable = m_bytes[at + 2 + 2 * i] >> 4;
        component.acTable = m_bytes[at + 2 + 2 * i] & 15;
        if (component.dcTable > 3 || component.acTable > 3) fail("the JPG's scan names a Huffman table past 3");
        scan.push_back(component);
    }
    return scan;
}

/// How many units (MCUs) a baseline scan of `scan` codes; a non-interleaved
/// scan codes one block per unit, so its component's h and v become 1.
long long JpegWalk::unitCount(std::vector<Component>& scan) const {
    if (scan.size() == 1) {
        const Component& c = scan[0];
        const long long width = (static_cast<long long>(m_width) * c.h + m_maxH - 1) / m_maxH;
        const long long height = (static_cast<long long>(m_height) * c.v + m_maxV - 1) / m_maxV;
        scan[0].h = scan[0].v = 1;
        return ((width + 7) / 8) * ((height + 7) / 8);
    }
    return static_cast<long long>((m_width + 8 * m_maxH - 1) / (8 * m_maxH)) *
           ((m_height + 8 * m_maxV - 1) / (8 * m_maxV));
}

void JpegWalk::ranOut(long long mcu, long long mcus) const {
    fail("the JPG's image data ends after " + std::to_string(mcu) + " of the " + std::to_string(mcus) +
         " blocks (MCUs) its " + std::to_string(m_width) + "x" + std::to_string(m_height) +
         " header promises: the file is truncated, or its header was altered");
}

/// One 8x8 block's Huffman codes, read and skipped: its DC difference, then AC
/// run/size pairs up to the end of the block.
void JpegWalk::skipBlock(const Component& component, long long mcu, long long mcus) {
    const int dc = decode(m_dc[component.dcTable]);
    if (dc == -1) ranOut(mcu, mcus);
    if (dc < 0 || dc > 15) fail("the JPG's image data is damaged (an invalid Huffman code)");
    if (!skipBits(dc)) ranOut(mcu, mcus);
    for (int k = 1; k < 64;) {
        const int symbol = decode(m_ac[component.acTable]);
        if (symbol == -1) ranOut(mcu, mcus);
        if (symbol < 0) fail("the JPG's image data is damaged (an invalid Huffman code)");
        const int run = symbol >> 4, size = symbol & 15;
        if (size == 0) {
            if (run != 15) break;  // end of block
            k += 16;
            continue;
        }
        if (!skipBits(size)) ranOut(mcu, mcus);
        k += run + 1;
    }
}

std::size_t JpegWalk::walkScan(std::size_t at, std::size_t end) {
    ++m_scans;
    std::vector<Component> scan = scanComponents(at, end);
    if (m_progressive) return nextMarker(end, &m_progressiveBytes);

    for (const Component& component : scan) {
        if (!m_dc[component.dcTable].defined || !m_ac[component.acTable].defined) {
            fail("the JPG's scan uses a Huffman table it never defines");
        }
    }
    const long long mcus = unitCount(scan);
    m_at = end;
    m_bitsLeft = 0;
    for (long long mcu = 0; mcu < mcus; ++mcu) {
        if (m_restartInterval && mcu > 0 && mcu % m_restartInterval == 0) {
            m_bitsLeft = 0;
            if (m_at + 1 < m_size && m_bytes[m_at] == 0xff && m_bytes[m_at + 1] >= 0xd0 && m_bytes[m_at + 1] <= 0xd7) {
                m_at += 2;
            }
        }
        for (const Component& component : scan)
            for (int block = 0; block < component.h * component.v; ++block) skipBlock(component, mcu, mcus);
    }
    return nextMarker(m_at, nullptr);
}

void JpegWalk::run() {
    std::size_t at = 2;
    for (;;) {
        while (at + 1 < m_size && m_bytes[at] == 0xff && m_bytes[at + 1] == 0xff) ++at;
        if (at + 2 > m_size) {
            fail("the JPG is truncated: it ends at byte " + std::to_string(m_size) +
                 " without its end-of-image marker");
        }
        if (m_bytes[at] != 0xff) fail("the JPG is damaged: no marker at byte " + std::to_string(at));
        const int marker = m_bytes[at + 1];
        at += 2;
        if (marker == 0xd9) break;                                   // end of image
        if (marker == 0x01 || (marker >= 0xd0 && marker <= 0xd7)) continue;  // no length
        if (at + 2 > m_size) fail("the JPG is truncated: it ends inside a marker");
        const std::size_t length = big(at);
        if (length < 2 || length > m_size - at) {
            fail("the JPG is truncated: a segment at byte " + std::to_string(at - 2) + " claims " +
                 std::to_string(length) + " bytes, but the file ends at byte " + std::to_string(m_size));
        }
        const std::size_t end = at + length;
        switch (marker) {
        case 0xc4: readHuffmanTables(at + 2, end); break;
        case 0xc0:
        case 0xc1:
        case 0xc2: readFrame(at + 2, end, marker == 0xc2); break;
        case 0xdd:
            if (length != 4) fail("the JPG's restart interval segment is damaged");
            m_restartInterval = big(at + 2);
            break;
        case 0xda: at = walkScan(at + 2, end); continue;
        default: break;
        }
        at = end;
    }
    if (m_scans == 0) fail("the JPG has no image data (no scan before its end-of-image marker)");
    if (m_progressive) {
        unsigned long long blocks = 0;
        for (const Component& c : m_components) {
            const unsigned long long width = (static_cast<unsigned long long>(m_width) * c.h + m_maxH - 1) / m_maxH;
            const unsigned long long height = (static_cast<unsigned long long>(m_height) * c.v + m_maxV - 1) / m_maxV;
            blocks += ((width + 7) / 8) * ((height + 7) / 8);
        }
        if (m_progressiveBytes * 8 < blocks) {
            fail("the JPG's image data (" + std::to_string(m_progressiveBytes) + " bytes) is too small for the " +
                 std::to_string(blocks) + " blocks its " + std::to_string(m_width) + "x" +
                 std::to_string(m_height) + " header promises: the file is damaged or its header was altered");
        }
    }
}

} // namespace

void checkJpegData(const std::uint8_t* bytes, std::size_t size, const std::string& name) {
    JpegWalk(bytes, size, name).run();
}

} // namespace stoa::detail
