#include "JsonDocument.hpp"

#include <stoa/core/InputError.hpp>
#include <stoa/core/InputFile.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <map>
#include <optional>

namespace stoa::json {

namespace {

// Where the parser is in the text. nlohmann's lexer takes one character at a
// time from its input iterator and calls the SAX handler as soon as it has
// read a token, having read at most one character past it (a number ends at
// the first character that is not part of it). So when a callback comes, the
// last character read that is not white space is the token's last one, and its
// line is the token's line: a JSON token never spans lines.
struct TextCursor {
    int line = 1;               // the line of the next character
    int tokenLine = 1;          // the line of the last character read that is not white space
    const char* tokenEnd = nullptr;   // that character
    bool afterReturn = false;   // the last character was a '\r': a '\n' now ends no new line

    // Lines end in LF, CR LF or a CR alone (old Mac files).
    void consume(const char* at) {
        if (*at == '\n') {
            if (!afterReturn) ++line;
        } else if (*at == '\r') {
            ++line;
        } else if (*at != ' ' && *at != '\t') {
            tokenLine = line;
            tokenEnd = at;
        }
        afterReturn = *at == '\r';
    }
};

/// The text's characters for nlohmann's iterator input adapter, each one
/// counted into a TextCursor as the parser steps past it.
class CountingIterator {
public:
    using iterator_category = std::input_iterator_tag;
    using value_type = char;
    using difference_type = std::ptrdiff_t;
    using pointer = const char*;
    using reference = const char&;

    CountingIterator(const char* at, TextCursor* cursor) : m_at(at), m_cursor(cursor) {}

    reference operator*() const { return *m_at; }
    CountingIterator& operator++() {
        m_cursor->consume(m_at);
        ++m_at;
        return *this;
    }
    CountingIterator operator++(int) {
        CountingIterator before = *this;
        ++*this;
        return before;
    }
    bool operator==(const CountingIterator& other) const { return m_at == other.m_at; }
    bool operator!=(const CountingIterator& other) const { return m_at != other.m_at; }

private:
    const char* m_at;
    TextCursor* m_cursor;
};

struct Failure {
    int line;
    std::string message;
};

bool startsWith(const std::string& text, const std::string& prefix) { return text.compare(0, prefix.size(), prefix) == 0; }

/// The part of `text` between `from` and `to` (or its end), or "" when `from` is not in it.
std::string between(const std::string& text, const std::string& from, const std::string& to) {
    const std::size_t start = text.find(from);
    if (start == std::string::npos) return "";
    const std::size_t begin = start + from.size();
    const std::size_t end = to.empty() ? std::string::npos : text.find(to, begin);
    return text.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
}

/// nlohmann's name of a token in "unexpected ..." as a reader says it.
std::string plainToken(const std::string& name) {
    if (name == "true literal") return "true";
    if (name == "false literal") return "false";
    if (name == "null literal") return "null";
    if (name == "string literal") return "a string";
    if (name == "number literal") return "a number";
    return name;   // "'{'", "':'", ...
}

/// The word of the text that starts at `at` (up to white space or JSON's punctuation), for messages.
std::string wordAt(const char* at, const char* end) {
    const char* stop = at;
    while (stop < end && stop - at < 24 && !std::strchr(" \t\r\n,:[]{}\"", *stop)) ++stop;
    return std::string(at, stop == at ? std::min(at + 1, end) : stop);
}

/// A lexer error ("invalid literal", "invalid string: ...") plainly. `token`
/// is what the lexer read of a number or string; `word` is the text from the
/// character it stopped at, which for an invalid literal is the bad token
/// (nlohmann's token text then holds what came before it).
std::string plainLexerError(const std::string& error, std::string token, const std::string& word) {
    if (startsWith(error, "invalid literal")) {
        if (startsWith(word, "/")) return "a comment: JSON has no comments";
        if (startsWith(word, "'")) return "a single quote: JSON strings and keys are written in double quotes (\"...\")";
        // The lexer stops inside a literal it took for true, false or null ("nan" stops at the
        // 'a'); its token text ends with what it read of it, the character it stopped at last,
        // and `word` starts at that character.
        std::string read = token.substr(0, token.find("<U+"));
        std::size_t start = read.size();
        while (start > 0 && (std::isalpha(static_cast<unsigned char>(read[start - 1])) || read[start - 1] == '-')) --start;
        read = read.substr(start);
        if (!read.empty()) read.pop_back();
        const std::string literal = read + word;
        std::string lower = literal;
        std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
        if (lower == "nan" || lower == "-nan" || lower == "inf" || lower == "-inf" || lower == "infinity" || lower == "-infinity")
            return "'" + quoteInput(literal, 24) + "' is not a number JSON can hold: JSON has no NaN or infinity; write a finite number";
        return "'" + quoteInput(literal, 24) +
               "' is not a JSON value (text and keys go in double quotes; true, false and null are lower case)";
    }
    // nlohmann writes a control character it read as <U+000A>: the token is what came before.
    token = token.substr(0, token.find("<U+"));
    // "-Infinity" and "-nan" stop as numbers, at the letter after the '-'.
    if (startsWith(error, "invalid number") && token.size() >= 2 && token[0] == '-' &&
        std::isalpha(static_cast<unsigned char>(token.back()))) {
        std::string lower = "-" + word;
        std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
        if (lower == "-nan" || lower == "-inf" || lower == "-infinity")
            return "'-" + quoteInput(word, 24) + "' is not a number JSON can hold: JSON has no NaN or infinity; write a finite number";
    }
    const std::string quoted = "'" + quoteInput(token, 24) + "'";
    if (startsWith(error, "invalid number"))
        return quoted + " is not a number (numbers are written like 2, -1.5, 0.25, 1e-3: no '+', no leading or trailing '.')";
    if (startsWith(error, "invalid string: control character U+000A"))
        return "a line break inside a string: a string ends on the line it starts (is its closing \" missing?)";
    if (startsWith(error, "invalid string: control character"))
        return "a control character inside a string: write it as an escape such as \\t or \\u0001";
    if (startsWith(error, "invalid string: missing closing quote"))
        return "the file ends inside a string: its closing \" is missing";
    if (startsWith(error, "invalid string: forbidden character after backslash"))
        return "an unknown escape in a string: after \\ come only \" \\ / b f n r t or u and 4 hex digits "
               "(a backslash itself is written \\\\)";
    if (startsWith(error, "invalid string: '\\u'") || startsWith(error, "invalid string: surrogate"))
        return "a bad \\u escape in a string: \\u takes 4 hex digits, and a surrogate pair both its halves";
    if (startsWith(error, "invalid string: ill-formed UTF-8"))
        return "bytes that are not UTF-8 text inside a string (save the file as UTF-8)";
    if (startsWith(error, "invalid BOM")) return "the file starts with a broken byte order mark";
    if (startsWith(error, "invalid comment")) return "a comment: JSON has no comments";
    return error;
}

/// Builds the tree from nlohmann's SAX events (the names and signatures are
/// nlohmann's SAX interface), each value stamped with the cursor's line.
class TreeBuilder {
public:
    TreeBuilder(const TextCursor& cursor, const char* textEnd, int maxNesting)
        : m_cursor(cursor), m_textEnd(textEnd), m_maxNesting(maxNesting) {}

    bool null() { return add(scalar(Value::Kind::Null)); }
    bool boolean(bool on) {
        Value value = scalar(Value::Kind::Boolean);
        value.boolean = on;
        return add(std::move(value));
    }
    bool number_integer(std::int64_t number) {
        Value value = scalar(Value::Kind::Number);
        value.whole = value.fitsInteger = true;
        value.integer = number;
        value.number = static_cast<float>(number);
        value.text = std::to_string(number);
        return add(std::move(value));
    }
    bool number_unsigned(std::uint64_t number) {
        Value value = scalar(Value::Kind::Number);
        value.whole = true;
        value.fitsInteger = number <= static_cast<std::uint64_t>(INT64_MAX);
        value.integer = value.fitsInteger ? static_cast<std::int64_t>(number) : 0;
        value.number = static_cast<float>(number);
        value.text = std::to_string(number);
        return add(std::move(value));
    }
    bool number_float(double number, const std::string& text) {
        Value value = scalar(Value::Kind::Number);
        value.text = text;
        // The float nearest to the text itself, not to the double nlohmann made
        // of it: rounding twice could miss by one float, and a scene file must
        // read back exactly what was saved.
        float nearest = 0.0f;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), nearest);
        (void)end;
        if (error == std::errc::result_out_of_range) {
            value.outOfRange = std::fabs(number) >= 1.0;
            nearest = value.outOfRange ? static_cast<float>(std::copysign(HUGE_VAL, number)) : 0.0f;
        } else if (error != std::errc()) {
            nearest = static_cast<float>(number);   // not expected: nlohmann has checked the syntax
        }
        value.number = nearest;
        // Written with '.' or an exponent: not whole, even when its value is (2.0, 1e3).
        value.whole = false;
        return add(std::move(value));
    }
    bool string(std::string& text) {
        Value value = scalar(Value::Kind::String);
        value.text = std::move(text);
        return add(std::move(value));
    }
    bool binary(nlohmann::json::binary_t&) { return fail(m_cursor.tokenLine, "binary data has no place in JSON text"); }

    bool start_object(std::size_t) { return open(Value::Kind::Object); }
    bool start_array(std::size_t) { return open(Value::Kind::Array); }
    bool key(std::string& key) {
        Open& object = m_open.back();
        const auto [first, inserted] = object.keyLines.emplace(key, m_cursor.tokenLine);
        if (!inserted) {
            return fail(m_cursor.tokenLine, "the key \"" + quoteInput(key) + "\" is written twice in this object (first on line " +
                                                std::to_string(first->second) + ")");
        }
        object.pendingKey = std::move(key);
        object.pendingKeyLine = m_cursor.tokenLine;
        object.awaitingValue = true;
        return true;
    }
    bool end_object() { return close(); }
    bool end_array() { return close(); }

    bool parse_error(std::size_t, const std::string& token, const nlohmann::json::exception& error) {
        return fail(m_cursor.tokenLine, plainSyntaxError(error, token));
    }

    const std::optional<Failure>& failure() const { return m_failure; }
    Value takeRoot() { return std::move(m_root); }

private:
    struct Open {
        Value value;
        std::string pendingKey;
        int pendingKeyLine = 0;
        bool awaitingValue = false;             // a key has been read, its value not yet
        std::map<std::string, int> keyLines;    // each key read in this object and its line
    };

    Value scalar(Value::Kind kind) const {
        Value value;
        value.kind = kind;
        value.line = m_cursor.tokenLine;
        return value;
    }

    bool fail(int line, std::string message) {
        if (!m_failure) m_failure = Failure{line, std::move(message)};
        return false;
    }

    bool open(Value::Kind kind) {
        if (static_cast<int>(m_open.size()) >= m_maxNesting) {
            return fail(m_cursor.tokenLine, "objects and arrays are nested more than " + std::to_string(m_maxNesting) +
                                                " deep here: a scene file never needs that");
        }
        Open next;
        next.value = scalar(kind);
        m_open.push_back(std::move(next));
        return true;
    }

    bool close() {
        Value value = std::move(m_open.back().value);
        m_open.pop_back();
        return add(std::move(value));
    }

    bool add(Value value) {
        m_lastValueLine = m_cursor.tokenLine;
        if (m_open.empty()) {
            m_root = std::move(value);
            m_rootEndLine = m_cursor.tokenLine;
            return true;
        }
        Open& parent = m_open.back();
        if (parent.value.kind == Value::Kind::Array) {
            parent.value.items.push_back(std::move(value));
        } else {
            parent.value.members.push_back(Member{std::move(parent.pendingKey), parent.pendingKeyLine, std::move(value)});
            parent.awaitingValue = false;
        }
        return true;
    }

    /// nlohmann's message ("[json.exception.parse_error.101] parse error at
    /// line 3, column 5: syntax error while parsing object - unexpected string
    /// literal; expected '}'") as a short plain one ("a missing ',' before a
    /// string (after the value that ends on line 2), or a missing '}'"), from
    /// its parts and what is open here.
    std::string plainSyntaxError(const nlohmann::json::exception& error, const std::string& token) const {
        const std::string what = error.what();
        if (error.id == 406) return "the number '" + quoteInput(token, 24) + "' is too large";
        const std::string detail = between(what, " - ", "");
        const std::string lexerError = between(detail, "", "; last read: '");
        if (detail.find("; last read: '") != std::string::npos) {
            const std::string word = m_cursor.tokenEnd ? wordAt(m_cursor.tokenEnd, m_textEnd) : std::string();
            return plainLexerError(lexerError, token, word);
        }

        const std::string found = between(detail, "unexpected ", ";");
        const std::string expected = between(detail, "; expected ", "");
        if (found == "end of input") {
            if (m_open.empty()) return "the file is empty: a scene file is one JSON object, { ... }";
            const char* kind = m_open.back().value.kind == Value::Kind::Object ? "object" : "array";
            return std::string("the file ends before the ") + kind + " that starts on line " +
                   std::to_string(m_open.back().value.line) + " is closed (a missing '" +
                   (m_open.back().value.kind == Value::Kind::Object ? "}" : "]") + "')";
        }
        if (expected == "end of input") {
            return "text after the end of the file's value, which ends on line " + std::to_string(m_rootEndLine) +
                   " (a file holds one JSON value)";
        }
        const bool inObject = !m_open.empty() && m_open.back().value.kind == Value::Kind::Object;
        const bool inArray = !m_open.empty() && m_open.back().value.kind == Value::Kind::Array;
        if (found == "'}'" && expected == "string literal")
            return "a ',' before '}': JSON allows no comma after an object's last member";
        if (found == "']'" && inArray) return "a ',' before ']': JSON allows no comma after an array's last item";
        if (inObject && m_open.back().awaitingValue && (found == "'}'" || found == "','"))
            return "no value after \"" + quoteInput(m_open.back().pendingKey) + "\":";
        const std::string after = " (after the value that ends on line " + std::to_string(m_lastValueLine) + ")";
        if (expected == "'}'") return "a missing ',' before " + plainToken(found) + after + ", or a missing '}'";
        if (expected == "']'") return "a missing ',' before " + plainToken(found) + after + ", or a missing ']'";
        if (expected == "':'") return "a missing ':' after the key (found " + plainToken(found) + ")";
        if (expected == "string literal")
            return "found " + plainToken(found) + " where a key in double quotes was expected";
        if (!found.empty() && !expected.empty()) {
            const std::string wanted = expected == "'[', '{', or a literal" ? "a value" : plainToken(expected);
            return "found " + plainToken(found) + " where " + wanted + " was expected";
        }
        // Not a message of nlohmann 3.11's: its text after "line L, column C: ".
        const std::size_t column = what.find(", column ");
        const std::size_t colon = column == std::string::npos ? std::string::npos : what.find(": ", column);
        return colon == std::string::npos ? what : what.substr(colon + 2);
    }

    const TextCursor& m_cursor;
    const char* m_textEnd;
    int m_maxNesting;
    std::vector<Open> m_open;
    Value m_root;
    int m_rootEndLine = 0;
    int m_lastValueLine = 0;                    // where the last value read ends
    std::optional<Failure> m_failure;
};

} // namespace

Value parse(const std::string& text, const std::string& fileForMessages, int maxNesting) {
    // nlohmann takes a NUL byte for the end of the text: whatever followed it would vanish unread.
    const std::size_t nul = text.find('\0');
    if (nul != std::string::npos) {
        const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(nul), '\n'));
        throw InputError(fileForMessages, line, "a NUL byte: a scene file is text (is this the right file?)");
    }
    const char* begin = text.data();
    TextCursor cursor;
    TreeBuilder builder(cursor, begin + text.size(), maxNesting);
    const bool parsed = nlohmann::json::sax_parse(CountingIterator(begin, &cursor),
                                                  CountingIterator(begin + text.size(), &cursor), &builder);
    if (!parsed) {
        const Failure failure = builder.failure() ? *builder.failure() : Failure{cursor.tokenLine, "not JSON"};
        throw InputError(fileForMessages, failure.line, failure.message);
    }
    return builder.takeRoot();
}

std::string describe(const Value& value) {
    switch (value.kind) {
    case Value::Kind::Null: return "null";
    case Value::Kind::Boolean: return value.boolean ? "true" : "false";
    case Value::Kind::Number: return "the number " + quoteInput(value.text, 24);
    case Value::Kind::String: return "the string \"" + quoteInput(value.text) + "\"";
    case Value::Kind::Object: return "an object";
    case Value::Kind::Array:
        return value.items.size() == 1 ? "an array of 1 value" : "an array of " + std::to_string(value.items.size()) + " values";
    }
    return "a value";
}

} // namespace stoa::json
