#pragma once
// A small JSON writer: objects, arrays, strings, numbers, booleans, indented
// two spaces. Strings are escaped for JSON and made valid UTF-8 (a lab
// program's output may hold any bytes), so the result always parses.
//
//   JsonWriter json;
//   json.beginObject().key("score").value(7.5).key("tests").beginArray().endArray().endObject();
//   std::string text = json.text();

#include <string>
#include <string_view>
#include <vector>

namespace stoa::grader {

/// `text` as a quoted JSON string: '"', '\\' and control characters escaped,
/// bytes that are not valid UTF-8 replaced by U+FFFD.
std::string jsonQuote(std::string_view text);

class JsonWriter {
public:
    JsonWriter& beginObject();
    JsonWriter& endObject();
    JsonWriter& beginArray();
    JsonWriter& endArray();
    /// The next member's name; only inside an object, and each key takes one value.
    JsonWriter& key(std::string_view name);
    JsonWriter& value(std::string_view text);
    JsonWriter& value(const char* text) { return value(std::string_view(text)); }
    JsonWriter& value(const std::string& text) { return value(std::string_view(text)); }
    /// Finite numbers as the shortest decimal that reads back the same; NaN and infinities as null.
    JsonWriter& value(double number);
    JsonWriter& value(int number);
    JsonWriter& value(bool flag);
    JsonWriter& null();

    /// The document; every object and array must be closed.
    const std::string& text() const;

private:
    struct Level {
        bool isObject = false;
        int members = 0;
        bool keyWritten = false;
    };
    void beforeValue();
    void newline();
    JsonWriter& open(char bracket, bool isObject);
    JsonWriter& close(char bracket, bool isObject);

    std::string m_text;
    std::vector<Level> m_levels;
    bool m_rootWritten = false;
};

} // namespace stoa::grader
