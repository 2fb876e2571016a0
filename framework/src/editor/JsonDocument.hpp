#pragma once
// JSON text as a tree in which every value and every key knows its line, for
// a loader whose errors name the line of the offending value (the scene files,
// EditorSceneFile.cpp). nlohmann-json does the parsing through its SAX
// interface; it reports no positions, so JsonDocument.cpp feeds it the text
// through an iterator that counts lines as nlohmann reads them.
//
// Not a general JSON library: it holds what a loader checks (each number as
// the float it reads as, plus whether it was written as a whole number),
// keeps an object's members in file order and refuses a key written twice.

#include <cstdint>
#include <string>
#include <vector>

namespace stoa::json {

struct Member;

struct Value {
    enum class Kind { Null, Boolean, Number, String, Object, Array };

    Kind kind = Kind::Null;
    int line = 0;                 // 1-based, where the value starts
    bool boolean = false;
    // A number: the float nearest to it as written (a number too small for a
    // float reads as 0), and for a whole number written without '.' or
    // exponent, the integer itself when it fits.
    float number = 0.0f;
    bool outOfRange = false;      // larger than a float can hold (about 3.4e38); `number` is then infinite
    bool whole = false;           // written as a whole number (no '.', no exponent)
    bool fitsInteger = false;     // whole, and within std::int64_t
    std::int64_t integer = 0;
    std::string text;             // a string's text, or a number as written (for messages)
    std::vector<Member> members;  // an object's, in file order; keys unique
    std::vector<Value> items;     // an array's
};

struct Member {
    std::string key;
    int line = 0;                 // the key's line
    Value value;
};

/// The value `text` holds. Throws InputError(fileForMessages, line, ...) with a
/// short plain message when `text` is not one JSON value (a syntax error, a
/// key written twice in one object, objects and arrays nested deeper than
/// `maxNesting`, a NUL byte). A UTF-8 byte order mark at the start is skipped.
Value parse(const std::string& text, const std::string& fileForMessages, int maxNesting);

/// "a string", "a number", "true", "an object", "an array of 2 values", ... for "found ..." in messages.
std::string describe(const Value& value);

} // namespace stoa::json
