// The JSON writer's escaping and layout, and Gradescope's results.json, read
// back with a small strict parser so the output is known to be valid JSON.

#include "catch.hpp"

#include "JsonWriter.hpp"
#include "Report.hpp"
#include "ResultsJson.hpp"
#include "TempFolder.hpp"

#include <stoa/core/InputError.hpp>

#include <map>
#include <memory>
#include <set>

using namespace stoa::grader;

namespace {

// A JSON value, just enough to check documents in tests.
struct Json {
    enum class Type { Null, Bool, Number, String, Array, Object } type = Type::Null;
    bool flag = false;
    double number = 0;
    std::string text;
    std::vector<Json> items;
    std::vector<std::pair<std::string, Json>> members;

    const Json& operator[](const std::string& key) const {
        for (const auto& member : members)
            if (member.first == key) return member.second;
        throw std::runtime_error("no key " + key);
    }
    bool has(const std::string& key) const {
        for (const auto& member : members)
            if (member.first == key) return true;
        return false;
    }
};

// Strict JSON (RFC 8259) parser; throws std::runtime_error on anything invalid.
class Parser {
public:
    explicit Parser(const std::string& text) : m_text(text) {}

    Json document() {
        Json value = parseValue();
        skipSpace();
        if (m_at != m_text.size()) fail("text after the document");
        return value;
    }

private:
    [[noreturn]] void fail(const std::string& what) {
        throw std::runtime_error("JSON: " + what + " at byte " + std::to_string(m_at));
    }
    void skipSpace() {
        while (m_at < m_text.size() && std::string(" \t\r\n").find(m_text[m_at]) != std::string::npos) ++m_at;
    }
    bool take(char c) {
        skipSpace();
        if (m_at < m_text.size() && m_text[m_at] == c) {
            ++m_at;
            return true;
        }
        return false;
    }
    void expect(char c) {
        if (!take(c)) fail(std::string("expected '") + c + "'");
    }
    bool takeWord(const char* word) {
        std::string w(word);
        if (m_text.compare(m_at, w.size(), w) != 0) return false;
        m_at += w.size();
        return true;
    }
    std::string parseString() {
        expect('"');
        std::string out;
        while (true) {
            if (m_at >= m_text.size()) fail("unterminated string");
            unsigned char c = static_cast<unsigned char>(m_text[m_at++]);
            if (c == '"') return out;
            if (c < 0x20) fail("raw control character in a string");
            if (c != '\\') {
                out += static_cast<char>(c);
                continue;
            }
            char escape = m_text.at(m_at++);
            switch (escape) {
            case '"': out += '"'; break;
            case '\\': out += '\\'; break;
            case '/': out += '/'; break;
            case 'n': out += '\n'; break;
            case 'r': out += '\r'; break;
            case 't': out += '\t'; break;
            case 'b': out += '\b'; break;
            case 'f': out += '\f'; break;
            case 'u': {
                unsigned code = std::stoul(m_text.substr(m_at, 4), nullptr, 16);
                m_at += 4;
                if (code >= 0x80) fail("test parser handles only ASCII \\u escapes");
                out += static_cast<char>(code);
                break;
            }
            default: fail("bad escape");
            }
        }
    }
    Json parseValue() {
        skipSpace();
        Json value;
        if (m_at >= m_text.size()) fail("missing value");
        char c = m_text[m_at];
        if (c == '{') {
            value.type = Json::Type::Object;
            ++m_at;
            if (take('}')) return value;
            do {
                skipSpace();
                std::string key = parseString();
                expect(':');
                value.members.emplace_back(key, parseValue());
            } while (take(','));
            expect('}');
        } else if (c == '[') {
            value.type = Json::Type::Array;
            ++m_at;
            if (take(']')) return value;
            do value.items.push_back(parseValue());
            while (take(','));
            expect(']');
        } else if (c == '"') {
            value.type = Json::Type::String;
            value.text = parseString();
        } else if (takeWord("true") || takeWord("false")) {
            value.type = Json::Type::Bool;
            value.flag = m_text[m_at - 1] == 'e' && m_text[m_at - 2] == 'u';
        } else if (takeWord("null")) {
            value.type = Json::Type::Null;
        } else {
            std::size_t begin = m_at;
            if (m_text[m_at] == '-') ++m_at;
            if (m_at >= m_text.size() || !std::isdigit(static_cast<unsigned char>(m_text[m_at]))) fail("bad value");
            if (m_text[m_at] == '0' && m_at + 1 < m_text.size() && std::isdigit(static_cast<unsigned char>(m_text[m_at + 1])))
                fail("leading zero");
            while (m_at < m_text.size() && std::string("0123456789.eE+-").find(m_text[m_at]) != std::string::npos) ++m_at;
            value.type = Json::Type::Number;
            value.number = std::stod(m_text.substr(begin, m_at - begin));
        }
        return value;
    }

    const std::string& m_text;
    std::size_t m_at = 0;
};

Json parse(const std::string& text) { return Parser(text).document(); }

GradeResult result(const std::string& lab, const std::string& name, GradeStatus status, double points,
                   double maxPoints, stoa::Visibility visibility = stoa::Visibility::Visible) {
    GradeResult r;
    r.lab = lab;
    r.caseName = name;
    r.status = status;
    r.points = points;
    r.maxPoints = maxPoints;
    r.visibility = visibility;
    return r;
}

} // namespace

TEST_CASE("jsonQuote escapes what JSON requires", "[grader][json]") {
    CHECK(jsonQuote("plain") == "\"plain\"");
    CHECK(jsonQuote("say \"hi\"") == "\"say \\\"hi\\\"\"");
    CHECK(jsonQuote("C:\\path") == "\"C:\\\\path\"");
    CHECK(jsonQuote("a\nb\tc\r") == "\"a\\nb\\tc\\r\"");
    CHECK(jsonQuote(std::string("\x01\x1f\b\f", 4)) == "\"\\u0001\\u001f\\b\\f\"");
    CHECK(jsonQuote(std::string("nul\0here", 8)) == "\"nul\\u0000here\"");
    CHECK(jsonQuote("/ and \x7f stay") == "\"/ and \x7f stay\"");
}

TEST_CASE("jsonQuote keeps valid UTF-8 and replaces invalid bytes", "[grader][json]") {
    CHECK(jsonQuote("caf\xC3\xA9 \xE2\x9C\x93 \xF0\x9F\x98\x80") == "\"caf\xC3\xA9 \xE2\x9C\x93 \xF0\x9F\x98\x80\"");
    const std::string replacement = "\xEF\xBF\xBD";
    CHECK(jsonQuote("bad \xFF byte") == "\"bad " + replacement + " byte\"");
    CHECK(jsonQuote("cut \xE2\x9C") == "\"cut " + replacement + replacement + "\"");
    CHECK(jsonQuote("overlong \xC0\xAF") == "\"overlong " + replacement + replacement + "\"");
    CHECK(jsonQuote("surrogate \xED\xA0\x80") == "\"surrogate " + replacement + replacement + replacement + "\"");
}

TEST_CASE("JsonWriter lays out nested values", "[grader][json]") {
    JsonWriter json;
    json.beginObject();
    json.key("score").value(7.5);
    json.key("whole").value(10.0);
    json.key("count").value(3);
    json.key("ok").value(true);
    json.key("none").null();
    json.key("empty").beginArray().endArray();
    json.key("tags").beginArray().value("a").value(std::string("b")).endArray();
    json.key("nested").beginObject().key("x").value(0.1).endObject();
    json.endObject();
    CHECK(json.text() ==
          "{\n"
          "  \"score\": 7.5,\n"
          "  \"whole\": 10,\n"
          "  \"count\": 3,\n"
          "  \"ok\": true,\n"
          "  \"none\": null,\n"
          "  \"empty\": [],\n"
          "  \"tags\": [\n"
          "    \"a\",\n"
          "    \"b\"\n"
          "  ],\n"
          "  \"nested\": {\n"
          "    \"x\": 0.1\n"
          "  }\n"
          "}");
    Json parsed = parse(json.text());
    CHECK(parsed["score"].number == 7.5);
    CHECK(parsed["nested"]["x"].number == 0.1);
}

TEST_CASE("JsonWriter writes non-finite numbers as null", "[grader][json]") {
    JsonWriter json;
    json.beginArray().value(std::nan("")).value(1.0 / 0.0).value(-2.25).endArray();
    Json parsed = parse(json.text());
    CHECK(parsed.items[0].type == Json::Type::Null);
    CHECK(parsed.items[1].type == Json::Type::Null);
    CHECK(parsed.items[2].number == -2.25);
}

TEST_CASE("results.json follows Gradescope's format", "[grader][json]") {
    std::vector<GradeResult> results = {
        result("01_transforms", "orbit_front", GradeStatus::Passed, 10, 10),
        result("01_transforms", "orbit_side", GradeStatus::Failed, 0, 5),
        result("01_transforms", "secret", GradeStatus::Passed, 2.5, 2.5, stoa::Visibility::Hidden),
        result("02_shading", "blinn", GradeStatus::NotAttempted, 0, 10),
    };
    results[1].reason = "3.2% pixels off (max 200, mean 4.1)";
    results[3].reason = "not implemented: shade()";
    results[3].programOutput = "loading \"scene\"\n\tstoa: not implemented: shade()\n\xFF";
    Totals totals = summarize(results);
    Json document = parse(resultsJson(results, totals, 12.3, "score: 12.5 / 27.5\n"));

    std::set<std::string> topKeys;
    for (const auto& member : document.members) topKeys.insert(member.first);
    CHECK(topKeys == std::set<std::string>{"score", "execution_time", "output", "visibility", "stdout_visibility",
                                           "tests"});
    CHECK(document["score"].number == 12.5);
    CHECK(document["execution_time"].number == 13);
    CHECK(document["output"].text == "score: 12.5 / 27.5\n");
    CHECK(document["visibility"].text == "visible");
    CHECK(document["stdout_visibility"].text == "hidden");

    const Json& tests = document["tests"];
    REQUIRE(tests.items.size() == 4);
    // The per-test keys of https://gradescope-autograders.readthedocs.io/en/latest/specs/ (there is no
    // per-test execution_time: the render time goes in extra_data).
    const std::set<std::string> documented = {"score", "max_score", "status", "name", "name_format", "number",
                                              "output", "output_format", "tags", "visibility", "extra_data"};
    for (const Json& test : tests.items)
        for (const auto& member : test.members) CHECK(documented.count(member.first) == 1);

    CHECK(tests.items[0]["name"].text == "01_transforms/orbit_front");
    CHECK(tests.items[0]["number"].text == "1.1");
    CHECK(tests.items[0]["status"].text == "passed");
    CHECK(tests.items[0]["score"].number == 10);
    CHECK(tests.items[0]["visibility"].text == "visible");
    CHECK(tests.items[1]["status"].text == "failed");
    CHECK(tests.items[1]["max_score"].number == 5);
    CHECK(tests.items[1]["output"].text.find("3.2% pixels off") != std::string::npos);
    CHECK(tests.items[2]["visibility"].text == "after_published");
    CHECK(tests.items[3]["number"].text == "2.1");
    CHECK(tests.items[3]["status"].text == "failed");
    CHECK(tests.items[3]["tags"].items[0].text == "02_shading");
    CHECK(tests.items[3]["output"].text.find("\tstoa: not implemented: shade()") != std::string::npos);
    CHECK_FALSE(tests.items[1]["extra_data"].has("hint_mistake"));
}

TEST_CASE("results.json carries a known-mistake hint in the case's output", "[grader][json][hint]") {
    std::vector<GradeResult> results = {result("02_shading", "sun", GradeStatus::Failed, 0, 5)};
    results[0].reason = "3.2% pixels off (max 200, mean 4.1)";
    results[0].hint = "Use the half vector.";
    results[0].hintDocs = "docs/labs/02_shading.md#the-half-vector";
    results[0].hintMistake = "no_half_vector";
    results[0].seconds = 0.5;
    Json document = parse(resultsJson(results, summarize(results), 1.0, ""));
    const Json& test = document["tests"].items.at(0);
    CHECK(test["output"].text.find("known mistake 'no_half_vector': Use the half vector.") != std::string::npos);
    CHECK(test["output"].text.find("Read docs/labs/02_shading.md#the-half-vector") != std::string::npos);
    CHECK(test["extra_data"]["hint_mistake"].text == "no_half_vector");
    CHECK(test["extra_data"]["hint_docs"].text == "docs/labs/02_shading.md#the-half-vector");
    CHECK(test["extra_data"]["render_seconds"].number == 0.5);
}

TEST_CASE("writeResultsJson writes the file and reports a folder it cannot write", "[grader][json]") {
    stoa::test::TempFolder folder;
    std::vector<GradeResult> results = {result("01_transforms", "a", GradeStatus::Passed, 1, 1)};
    std::filesystem::path path = folder.path() / "results" / "results.json";
    writeResultsJson(path, results, summarize(results), 1.0, "");
    std::ifstream file(path);
    std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    CHECK(parse(text)["score"].number == 1);

    folder.write("plain-file", "x");
    CHECK_THROWS_AS(writeResultsJson(folder.path() / "plain-file" / "results.json", results, summarize(results), 1.0, ""),
                    stoa::InputError);
}
