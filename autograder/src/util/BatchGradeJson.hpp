#pragma once
// A small JSON reader for the batch grader: it reads the results.json that
// stoa-grade writes for each student (to fill the gradebook) and writes it back
// with the tests a failed build adds. Numbers are doubles, objects keep their
// members in order. Not a general-purpose library: no streaming, no comments.

#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace stoa::grader {

class JsonValue {
public:
    enum class Type { Null, Boolean, Number, String, Array, Object };

    JsonValue() = default;
    static JsonValue boolean(bool flag);
    static JsonValue number(double value);
    static JsonValue string(std::string text);
    static JsonValue array();
    static JsonValue object();

    Type type() const { return m_type; }
    bool isObject() const { return m_type == Type::Object; }
    bool isArray() const { return m_type == Type::Array; }

    double asNumber(double fallback = 0.0) const { return m_type == Type::Number ? m_number : fallback; }
    const std::string& asString() const { return m_string; }   // "" unless a string
    bool asBoolean() const { return m_type == Type::Boolean && m_boolean; }

    /// The elements of an array (empty for anything else).
    const std::vector<JsonValue>& items() const { return m_items; }
    /// The members of an object, in document order (empty for anything else).
    const std::vector<std::pair<std::string, JsonValue>>& members() const { return m_members; }
    /// The member `name` of an object; nullptr when absent or not an object.
    const JsonValue* find(const std::string& name) const;

    /// Appends to an array (STOA_ASSERT that it is one).
    void push(JsonValue value);
    /// Sets an object's member, replacing one of the same name (STOA_ASSERT that it is an object).
    void set(const std::string& name, JsonValue value);

    /// The document as indented JSON text.
    std::string dump() const;

private:
    Type m_type = Type::Null;
    bool m_boolean = false;
    double m_number = 0.0;
    std::string m_string;
    std::vector<JsonValue> m_items;
    std::vector<std::pair<std::string, JsonValue>> m_members;
};

/// Parses `text`; throws InputError naming `fileName`, the line and what was expected.
JsonValue parseJson(const std::string& text, const std::string& fileName = "<json>");

/// Reads and parses a file; throws InputError when it cannot be read or parsed.
JsonValue readJsonFile(const std::filesystem::path& path);

} // namespace stoa::grader
