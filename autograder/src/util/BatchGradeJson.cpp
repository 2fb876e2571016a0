#include "BatchGradeJson.hpp"

#include "JsonWriter.hpp"

#include <stoa/core/Assert.hpp>
#include <stoa/core/InputError.hpp>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace stoa::grader {

JsonValue JsonValue::boolean(bool flag) {
    JsonValue value;
    value.m_type = Type::Boolean;
    value.m_boolean = flag;
    return value;
}

JsonValue JsonValue::number(double number) {
    JsonValue value;
    value.m_type = Type::Number;
    value.m_number = number;
    return value;
}

JsonValue JsonValue::string(std::string text) {
    JsonValue value;
    value.m_type = Type::String;
    value.m_string = std::move(text);
    return value;
}

JsonValue JsonValue::array() {
    JsonValue value;
    value.m_type = Type::Array;
    return value;
}

JsonValue JsonValue::object() {
    JsonValue value;
    value.m_type = Type::Object;
    return value;
}

const JsonValue* JsonValue::find(const std::string& name) const {
    for (const auto& member : m_members)
        if (member.first == name) return &member.second;
    return nullptr;
}

void JsonValue::push(JsonValue value) {
    STOA_ASSERT(m_type == Type::Array, "JsonValue::push(): not an array; make it with JsonValue::array()");
    m_items.push_back(std::move(value));
}

void JsonValue::set(const std::string& name, JsonValue value) {
    STOA_ASSERT(m_type == Type::Object, "JsonValue::set(): not an object; make it with JsonValue::object()");
    for (auto& member : m_members)
        if (member.first == name) {
            member.second = std::move(value);
            return;
        }
    m_members.emplace_back(name, std::move(value));
}

namespace {

void write(JsonWriter& json, const JsonValue& value) {
    switch (value.type()) {
    case JsonValue::Type::Null: json.null(); break;
    case JsonValue::Type::Boolean: json.value(value.asBoolean()); break;
    case JsonValue::Type::Number: json.value(value.asNumber()); break;
    case JsonValue::Type::String: json.value(value.asString()); break;
    case JsonValue::Type::Array:
        json.beginArray();
        for (const JsonValue& item : value.items()) write(json, item);
        json.endArray();
        break;
    case JsonValue::Type::Object:
        json.beginObject();
        for (const auto& member : value.members()) {
            json.key(member.first);
            write(json, member.second);
        }
        json.endObject();
        break;
    }
}

// Recursive descent over the text; `m_at` is the next character.
class Parser {
public:
    Parser(const std::string& text, const std::string& fileName) : m_text(text), m_fileName(fileName) {}

    JsonValue document() {
        JsonValue value = parseValue(0);
        skipSpace();
        if (m_at != m_text.size()) fail("unexpected text after the document");
        return value;
    }

private:
    [[noreturn]] void fail(const std::string& what) const {
        int line = 1;
        for (std::size_t i = 0; i < m_at && i < m_text.size(); ++i)
            if (m_text[i] == '\n') ++line;
        throw InputError(m_fileName, line, "invalid JSON: " + what);
    }

    void skipSpace() {
        while (m_at < m_text.size() && (m_text[m_at] == ' ' || m_text[m_at] == '\t' || m_text[m_at] == '\n' ||
                                         m_text[m_at] == '\r'))
            ++m_at;
    }

    bool consume(const char* word) {
        std::string_view expected(word);
        if (m_text.compare(m_at, expected.size(), expected) != 0) return false;
        m_at += expected.size();
        return true;
    }

    JsonValue parseValue(int depth) {
        if (depth > 64) fail("nested deeper than 64 levels");
        skipSpace();
        if (m_at >= m_text.size()) fail("expected a value, found the end of the text");
        char c = m_text[m_at];
        if (c == '{') return parseObject(depth);
        if (c == '[') return parseArray(depth);
        if (c == '"') return JsonValue::string(parseString());
        if (consume("true")) return JsonValue::boolean(true);
        if (consume("false")) return JsonValue::boolean(false);
        if (consume("null")) return JsonValue();
        if (c == '-' || (c >= '0' && c <= '9')) return parseNumber();
        fail(std::string("unexpected character '") + c + "'");
    }

    JsonValue parseObject(int depth) {
        JsonValue object = JsonValue::object();
        ++m_at;   // '{'
        skipSpace();
        if (m_at < m_text.size() && m_text[m_at] == '}') {
            ++m_at;
            return object;
        }
        while (true) {
            skipSpace();
            if (m_at >= m_text.size() || m_text[m_at] != '"') fail("expected a member name in quotes");
            std::string name = parseString();
            skipSpace();
            if (m_at >= m_text.size() || m_text[m_at] != ':') fail("expected ':' after \"" + name + "\"");
            ++m_at;
            object.set(name, parseValue(depth + 1));
            skipSpace();
            if (m_at < m_text.size() && m_text[m_at] == ',') {
                ++m_at;
                continue;
            }
            if (m_at < m_text.size() && m_text[m_at] == '}') {
                ++m_at;
                return object;
            }
            fail("expected ',' or '}' in an object");
        }
    }

    JsonValue parseArray(int depth) {
        JsonValue array = JsonValue::array();
        ++m_at;   // '['
        skipSpace();
        if (m_at < m_text.size() && m_text[m_at] == ']') {
            ++m_at;
            return array;
        }
        while (true) {
            array.push(parseValue(depth + 1));
            skipSpace();
            if (m_at < m_text.size() && m_text[m_at] == ',') {
                ++m_at;
                continue;
            }
            if (m_at < m_text.size() && m_text[m_at] == ']') {
                ++m_at;
                return array;
            }
            fail("expected ',' or ']' in an array");
        }
    }

    JsonValue parseNumber() {
        const char* begin = m_text.c_str() + m_at;
        char* end = nullptr;
        double value = std::strtod(begin, &end);
        if (end == begin) fail("malformed number");
        m_at += static_cast<std::size_t>(end - begin);
        return JsonValue::number(value);
    }

    void appendUtf8(std::string& out, unsigned code) {
        if (code < 0x80) {
            out += static_cast<char>(code);
        } else if (code < 0x800) {
            out += static_cast<char>(0xC0 | (code >> 6));
            out += static_cast<char>(0x80 | (code & 0x3F));
        } else if (code < 0x10000) {
            out += static_cast<char>(0xE0 | (code >> 12));
            out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (code & 0x3F));
        } else {
            out += static_cast<char>(0xF0 | (code >> 18));
            out += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
            out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (code & 0x3F));
        }
    }

    unsigned parseHex4() {
        if (m_at + 4 > m_text.size()) fail("\\u needs four hex digits");
        unsigned code = 0;
        for (int i = 0; i < 4; ++i) {
            char c = m_text[m_at++];
            code <<= 4;
            if (c >= '0' && c <= '9') code |= static_cast<unsigned>(c - '0');
            else if (c >= 'a' && c <= 'f') code |= static_cast<unsigned>(c - 'a' + 10);
            else if (c >= 'A' && c <= 'F') code |= static_cast<unsigned>(c - 'A' + 10);
            else fail("\\u needs four hex digits");
        }
        return code;
    }

    std::string parseString() {
        ++m_at;   // '"'
        std::string out;
        while (true) {
            if (m_at >= m_text.size()) fail("unterminated string");
            char c = m_text[m_at++];
            if (c == '"') return out;
            if (static_cast<unsigned char>(c) < 0x20) fail("control character in a string");
            if (c != '\\') {
                out += c;
                continue;
            }
            if (m_at >= m_text.size()) fail("unterminated string");
            char escape = m_text[m_at++];
            switch (escape) {
            case '"': out += '"'; break;
            case '\\': out += '\\'; break;
            case '/': out += '/'; break;
            case 'b': out += '\b'; break;
            case 'f': out += '\f'; break;
            case 'n': out += '\n'; break;
            case 'r': out += '\r'; break;
            case 't': out += '\t'; break;
            case 'u': {
                unsigned code = parseHex4();
                if (code >= 0xD800 && code < 0xDC00 && m_text.compare(m_at, 2, "\\u") == 0) {
                    m_at += 2;
                    unsigned low = parseHex4();
                    code = 0x10000 + ((code - 0xD800) << 10) + (low - 0xDC00);
                }
                appendUtf8(out, code);
                break;
            }
            default: fail(std::string("unknown escape '\\") + escape + "'");
            }
        }
    }

    const std::string& m_text;
    const std::string& m_fileName;
    std::size_t m_at = 0;
};

} // namespace

std::string JsonValue::dump() const {
    JsonWriter json;
    write(json, *this);
    return json.text();
}

JsonValue parseJson(const std::string& text, const std::string& fileName) {
    return Parser(text, fileName).document();
}

JsonValue readJsonFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path.string(), 0, "cannot read the file");
    std::ostringstream text;
    text << in.rdbuf();
    return parseJson(text.str(), path.string());
}

} // namespace stoa::grader
