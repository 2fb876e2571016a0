#include "JsonWriter.hpp"

#include "Utf8.hpp"

#include <stoa/core/Assert.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace stoa::grader {

std::string jsonQuote(std::string_view text) {
    std::string quoted;
    quoted.reserve(text.size() + 2);
    quoted += '"';
    for (std::size_t i = 0; i < text.size();) {
        unsigned char c = static_cast<unsigned char>(text[i]);
        if (c >= 0x80) {
            std::size_t length = utf8SequenceLength(text, i);
            if (length == 0) {
                quoted += "\xEF\xBF\xBD"; // U+FFFD, the replacement character
                ++i;
            } else {
                quoted.append(text.substr(i, length));
                i += length;
            }
            continue;
        }
        switch (c) {
        case '"': quoted += "\\\""; break;
        case '\\': quoted += "\\\\"; break;
        case '\n': quoted += "\\n"; break;
        case '\r': quoted += "\\r"; break;
        case '\t': quoted += "\\t"; break;
        case '\b': quoted += "\\b"; break;
        case '\f': quoted += "\\f"; break;
        default:
            if (c < 0x20) {
                char escape[8];
                std::snprintf(escape, sizeof escape, "\\u%04x", c);
                quoted += escape;
            } else {
                quoted += static_cast<char>(c);
            }
        }
        ++i;
    }
    quoted += '"';
    return quoted;
}

void JsonWriter::newline() {
    m_text += '\n';
    m_text.append(2 * m_levels.size(), ' ');
}

void JsonWriter::beforeValue() {
    if (m_levels.empty()) {
        STOA_ASSERT(!m_rootWritten, "JsonWriter: the document already has its top-level value; "
                                    "put further values inside an array or object.");
        m_rootWritten = true;
        return;
    }
    Level& level = m_levels.back();
    if (level.isObject) {
        STOA_ASSERT(level.keyWritten, "JsonWriter: a value inside an object needs a key; call key() first.");
        level.keyWritten = false;
        return;
    }
    if (level.members++ > 0) m_text += ',';
    newline();
}

JsonWriter& JsonWriter::open(char bracket, bool isObject) {
    beforeValue();
    m_text += bracket;
    m_levels.push_back(Level{isObject, 0, false});
    return *this;
}

JsonWriter& JsonWriter::close(char bracket, bool isObject) {
    STOA_ASSERT(!m_levels.empty() && m_levels.back().isObject == isObject,
                "JsonWriter: endObject()/endArray() does not match the open beginObject()/beginArray().");
    STOA_ASSERT(!m_levels.back().keyWritten, "JsonWriter: a key has no value; call value() before endObject().");
    bool empty = m_levels.back().members == 0;
    m_levels.pop_back();
    if (!empty) newline();
    m_text += bracket;
    return *this;
}

JsonWriter& JsonWriter::beginObject() { return open('{', true); }
JsonWriter& JsonWriter::endObject() { return close('}', true); }
JsonWriter& JsonWriter::beginArray() { return open('[', false); }
JsonWriter& JsonWriter::endArray() { return close(']', false); }

JsonWriter& JsonWriter::key(std::string_view name) {
    STOA_ASSERT(!m_levels.empty() && m_levels.back().isObject, "JsonWriter::key(): keys belong inside an object; "
                                                               "call beginObject() first.");
    Level& level = m_levels.back();
    STOA_ASSERT(!level.keyWritten, "JsonWriter::key(): the previous key has no value yet.");
    if (level.members++ > 0) m_text += ',';
    newline();
    m_text += jsonQuote(name);
    m_text += ": ";
    level.keyWritten = true;
    return *this;
}

JsonWriter& JsonWriter::value(std::string_view text) {
    beforeValue();
    m_text += jsonQuote(text);
    return *this;
}

JsonWriter& JsonWriter::value(double number) {
    if (!std::isfinite(number)) return null();
    beforeValue();
    // Whole numbers as integers ("10", not "1e+01"); others as the shortest
    // of %.1g..%.17g that reads back as the same double.
    char text[40];
    if (number == std::floor(number) && std::fabs(number) < 1e15) {
        std::snprintf(text, sizeof text, "%.0f", number);
        m_text += std::strcmp(text, "-0") == 0 ? "0" : text;
        return *this;
    }
    for (int precision = 1; precision <= 17; ++precision) {
        std::snprintf(text, sizeof text, "%.*g", precision, number);
        if (std::strtod(text, nullptr) == number) break;
    }
    m_text += text;
    return *this;
}

JsonWriter& JsonWriter::value(int number) {
    beforeValue();
    m_text += std::to_string(number);
    return *this;
}

JsonWriter& JsonWriter::value(bool flag) {
    beforeValue();
    m_text += flag ? "true" : "false";
    return *this;
}

JsonWriter& JsonWriter::null() {
    beforeValue();
    m_text += "null";
    return *this;
}

const std::string& JsonWriter::text() const {
    STOA_ASSERT(m_levels.empty(), "JsonWriter::text(): an object or array is still open; "
                                  "close it with endObject()/endArray() first.");
    return m_text;
}

} // namespace stoa::grader
