// Issue 25: crowd worlds from an attacker or an unlucky user. Includes have a
// budget and stay in the world's folder tree, numbers are checked for the range
// they are used in, and the text is UTF-8 with XML's own entities only; each
// refusal names the file, the line and the problem.

#include "CrowdXmlFiles.hpp"

#include <stoa/core/InputError.hpp>
#include <stoa/crowd/CrowdXml.hpp>

#include <map>
#include <string>

using namespace stoa;
using namespace stoa::test;

TEST_CASE("Issue 25: includes stay in the world's folder, once each, within a budget", "[crowd][xml][issue25]") {
    const std::string agents = "agents.xml";
    SECTION("an include outside the world's folder") {
        expectError({{"world.xml", world("  <include file=\"/etc/passwd\"/>\n")}}, "world.xml", "/etc/passwd",
                    "<include> file=\"/etc/passwd\" lies outside the world's folder");
        expectError({{"world.xml", world("  <include file=\"../outside.xml\"/>\n")}}, "world.xml", "../outside.xml",
                    "lies outside the world's folder");
    }
    SECTION("an error in an included file says where it was included from") {
        TempFolder folder("crowd-xml");
        folder.write("world.xml", world("  <include file=\"a.xml\"/>\n"));
        folder.write("a.xml", "<agents>\n  <include file=\"b.xml\"/>\n</agents>\n");
        folder.write("b.xml", "<agents>\n\n  <type name=\"x\" model=\"m\" skin=\"s\" behaviour=\"walk\" speed=\"fast\"/>\n</agents>\n");
        try {
            (void)loadCrowdWorld(folder / "world.xml");
            FAIL("the world loaded");
        } catch (const InputError& error) {
            CHECK(error.file() == (folder / "b.xml").string());
            CHECK(error.line() == 3);
            CHECK(contains(error.message(), "is not a number (included from " + (folder / "a.xml").string() + ":2, from " +
                                                (folder / "world.xml").string() + ":7)"));
        }
    }
    SECTION("a file included twice") {
        expectError({{"world.xml", world("  <include file=\"agents.xml\"/>\n  <include file=\"./agents.xml\"/>\n")},
                     {agents, "<agents/>\n"}},
                    "world.xml", "./agents.xml", "<include> file=\"./agents.xml\" is included already, at ");
    }
    SECTION("too many includes: four files, each including the next many times, stop at the budget") {
        // Each file includes the next 1000 times (under the depth limit): a second include of one
        // file is refused at once, and more than maxIncludes different files are refused too.
        std::string many = "  <include file=\"b.xml\"/>\n";
        for (int i = 1; i < 1000; ++i) many += "  <include file=\"./b.xml\"/>\n";
        expectError({{"world.xml", world(many)}, {"b.xml", "<agents/>\n"}}, "world.xml", "./b.xml", "is included already");
        std::string distinct;
        std::map<std::string, std::string> files;
        for (int i = 0; i <= CrowdXmlLimits::maxIncludes; ++i) {
            distinct += "  <include file=\"f" + std::to_string(i) + ".xml\"/>\n";
            files["f" + std::to_string(i) + ".xml"] = "<agents/>\n";
        }
        files["world.xml"] = world(distinct);
        expectError(files, "world.xml", "<include file=\"f256.xml",
                    "more than " + std::to_string(CrowdXmlLimits::maxIncludes) + " <include> elements in one world");
    }
}

TEST_CASE("Issue 25: a crowd world's numbers are checked for the range they are used in", "[crowd][xml][issue25]") {
    const auto withType = [](const std::string& attributes) {
        return world("  <type name=\"t\" model=\"m\" skin=\"s\" behaviour=\"walk\" " + attributes + "/>\n");
    };
    SECTION("past a float's range: too large, not 'not a number'") {
        expectError({{"world.xml", withType("speed=\"1e39\"")}}, "world.xml", "speed=",
                    "speed=\"1e39\" on <type> is too large for a float (at most 3.4e38)");
    }
    SECTION("so close to 0 that a float loses it") {
        expectError({{"world.xml", withType("scale=\"1e-60\"")}}, "world.xml", "scale=",
                    "scale=\"1e-60\" on <type> is too close to 0 for a float");
        expectError({{"world.xml", withType("radius=\"1e-45\"")}}, "world.xml", "radius=", "is too close to 0 for a float");
    }
    SECTION("a step too small to simulate in any time") {
        const std::string text = world("");
        expectError({{"world.xml", "<world step=\"0.0001\">" + text.substr(text.find('>') + 1)}}, "world.xml", "<world",
                    "step=\"0.0001\" on <world> is out of range: it must be from 0.001 to 1 (seconds)");
    }
    SECTION("a speed a step would carry past any ground") {
        expectError({{"world.xml", withType("speed=\"3e38\"")}}, "world.xml", "speed=",
                    "is out of range: it must be greater than 0 and at most 100000");
    }
    SECTION("a ground whose extent or heights overflow") {
        const std::string text = world("");
        const std::string ground = "<ground collision=\"c.png\"/>";
        std::string huge = text;
        huge.replace(huge.find(ground), ground.size(), "<ground collision=\"c.png\" min=\"-3e38 -3e38\" max=\"3e38 3e38\"/>");
        expectError({{"world.xml", huge}}, "world.xml", "<ground", "x and z must be from -100000 to 100000 (metres)");
        std::string high = text;
        high.replace(high.find(ground), ground.size(), "<ground collision=\"c.png\" height-min=\"-3e38\" height-max=\"3e38\"/>");
        expectError({{"world.xml", high}}, "world.xml", "<ground", "must be from -100000 to 100000 (metres)");
    }
}

TEST_CASE("Issue 25: a crowd world's text is UTF-8 with XML's own entities only", "[crowd][xml][issue25]") {
    const auto named = [](const std::string& name) {
        return world("  <type name=\"" + name + "\" model=\"m\" skin=\"s\" behaviour=\"walk\"/>\n");
    };
    SECTION("an undefined entity is refused, not kept as its name") {
        expectError({{"world.xml", named("a&foo;b")}}, "world.xml", "&foo;", "the entity '&foo;' is not defined");
    }
    SECTION("&#0; would cut the name short") {
        expectError({{"world.xml", named("ab&#0;cd")}}, "world.xml", "&#0;", "'&#0;' refers to a character XML does not allow");
    }
    SECTION("a character reference past U+10FFFF would not be UTF-8") {
        expectError({{"world.xml", named("x&#x110000;")}}, "world.xml", "&#x110000;", "refers to a character XML does not allow");
    }
    SECTION("a lone & is an error that says to write &amp;") {
        expectError({{"world.xml", named("salt & pepper")}}, "world.xml", "& pepper", "write & as &amp;");
    }
    SECTION("a byte that is not UTF-8 (Latin-1) names its line") {
        expectError({{"world.xml", named("caf\xe9")}}, "world.xml", "caf", "the file is not UTF-8 here");
    }
    SECTION("UTF-16 says to save as UTF-8") {
        std::string utf16 = "\xff\xfe";
        for (char c : std::string("<world/>\n")) utf16 += std::string(1, c) + '\0';
        TempFolder folder("crowd-xml");
        folder.write("world.xml", utf16);
        try {
            (void)loadCrowdWorld(folder / "world.xml");
            FAIL("a UTF-16 world loaded");
        } catch (const InputError& error) {
            CHECK(contains(error.message(), "the file is UTF-16; save it as UTF-8"));
        }
    }
    SECTION("XML's own entities, character references and a & in a comment read as they should") {
        TempFolder folder("crowd-xml");
        folder.write("world.xml", "<!-- salt & pepper -->\n" + named("a&amp;b&#x263A;&#65;"));
        const CrowdWorld loaded = loadCrowdWorld(folder / "world.xml");
        REQUIRE(loaded.types.size() == 2);
        CHECK(loaded.types[1].name == "a&b\xe2\x98\xba" "A");
    }
}
