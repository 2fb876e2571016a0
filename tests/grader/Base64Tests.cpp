// Base64 for the HTML report's data URIs, and the escaping of report text.

#include "catch.hpp"

#include "Base64.hpp"
#include "Escape.hpp"

#include "TempFolder.hpp"

using namespace stoa::grader;

TEST_CASE("base64Encode matches RFC 4648's test vectors", "[grader][report][base64]") {
    // RFC 4648, section 10.
    CHECK(base64Encode(std::string("")) == "");
    CHECK(base64Encode(std::string("f")) == "Zg==");
    CHECK(base64Encode(std::string("fo")) == "Zm8=");
    CHECK(base64Encode(std::string("foo")) == "Zm9v");
    CHECK(base64Encode(std::string("foob")) == "Zm9vYg==");
    CHECK(base64Encode(std::string("fooba")) == "Zm9vYmE=");
    CHECK(base64Encode(std::string("foobar")) == "Zm9vYmFy");
}

TEST_CASE("base64Encode uses the whole alphabet and handles every byte value", "[grader][report][base64]") {
    const std::uint8_t high[] = {0xFB, 0xFF, 0xBF};   // 111110 111111 111110 111111
    CHECK(base64Encode(high, 3) == "+/+/");
    const std::uint8_t zeros[] = {0, 0, 0, 0};
    CHECK(base64Encode(zeros, 4) == "AAAAAA==");
    std::string all;
    for (int i = 0; i < 256; ++i) all += static_cast<char>(i);
    std::string text = base64Encode(all);
    CHECK(text.size() == (256 + 2) / 3 * 4);
    CHECK(text.rfind("AAECAwQF", 0) == 0);                  // bytes 0..5
    CHECK(text.substr(text.size() - 8) == "/P3+/w==");      // bytes 252..254, then 255 alone, padded
    CHECK(text.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/=") ==
          std::string::npos);
}

TEST_CASE("fileDataUri embeds a file and gives nothing for a missing one", "[grader][report][base64]") {
    stoa::test::TempFolder folder("base64");
    std::filesystem::path file = folder.write("tiny.png", "abc");
    CHECK(fileDataUri(file) == "data:image/png;base64,YWJj");
    CHECK(fileDataUri(file, "text/plain") == "data:text/plain;base64,YWJj");
    CHECK(fileDataUri(folder / "missing.png").empty());
    CHECK(fileDataUri("").empty());
    CHECK(fileDataUri(folder.write("empty.png", "")).empty());
}

TEST_CASE("htmlEscape and xmlEscape escape markup and clean what XML cannot carry", "[grader][report][escape]") {
    CHECK(htmlEscape("a < b && c > \"d\" 'e'") == "a &lt; b &amp;&amp; c &gt; &quot;d&quot; &#39;e&#39;");
    CHECK(xmlEscape("<x a='1'>") == "&lt;x a=&apos;1&apos;&gt;");
    CHECK(xmlEscape("tab\tnew\nline\r") == "tab\tnew\nline\r");
    // Control characters and invalid UTF-8 become U+FFFD; valid UTF-8 stays.
    const std::string replacement = "\xEF\xBF\xBD";
    CHECK(xmlEscape(std::string("bell\a esc\x1b[0m nul") + '\0') ==
          "bell" + replacement + " esc" + replacement + "[0m nul" + replacement);
    CHECK(sanitizedText("caf\xC3\xA9 \xE2\x9C\x93") == "caf\xC3\xA9 \xE2\x9C\x93");
    CHECK(sanitizedText("\xFF\xC3") == replacement + replacement);
    CHECK(sanitizedText("\xC0\xAF") == replacement + replacement);      // overlong '/'
    CHECK(sanitizedText("\xED\xA0\x80") == replacement + replacement + replacement);   // a surrogate
    CHECK(sanitizedText("\xEF\xBF\xBE") == replacement + replacement + replacement);   // U+FFFE
}
