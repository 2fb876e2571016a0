#pragma once
// What the crowd XML tests share: a small valid world to add to, and the check
// that a set of files is refused at a given file and line with a given message.

#include "catch.hpp"
#include "TempFolder.hpp"

#include <stoa/core/InputError.hpp>
#include <stoa/crowd/CrowdXml.hpp>

#include <map>
#include <string>

namespace stoa::test {

inline bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

/// The 1-based line of `text` where `marker` first appears.
inline int lineOf(const std::string& text, const std::string& marker) {
    const std::size_t at = text.find(marker);
    REQUIRE(at != std::string::npos);
    int line = 1;
    for (std::size_t i = 0; i < at; ++i) line += text[i] == '\n';
    return line;
}

/// Writes `files` (name -> text) to a fresh folder and loads its "world.xml",
/// expecting an InputError at `file`:(line of `marker` in that file) whose
/// message holds `message`.
inline void expectError(const std::map<std::string, std::string>& files, const std::string& file, const std::string& marker,
                 const std::string& message) {
    TempFolder folder("crowd-xml");
    for (const auto& [name, text] : files) folder.write(name, text);
    const int line = lineOf(files.at(file), marker);
    try {
        (void)loadCrowdWorld(folder / "world.xml");
    } catch (const InputError& error) {
        INFO(error.what());
        CHECK(error.file() == (folder / file).string());
        CHECK(error.line() == line);
        CHECK(contains(error.message(), message));
        return;
    }
    FAIL("loadCrowdWorld did not throw; expected " << file << ":" << line << ": ..." << message);
}

/// A small valid world with `inside` added before its <spawn>.
inline std::string world(const std::string& inside) {
    return "<world>\n"
           "  <ground collision=\"c.png\"/>\n"
           "  <type name=\"walker\" model=\"w.md2\" skin=\"w.png\" behaviour=\"walk\"/>\n"
           "  <behaviour name=\"walk\" kind=\"fsm\">\n"
           "    <state name=\"go\"><wander/></state>\n"
           "  </behaviour>\n" +
           inside +
           "  <spawn type=\"walker\" count=\"3\" x=\"0\" z=\"0\"/>\n"
           "</world>\n";
}

} // namespace stoa::test
