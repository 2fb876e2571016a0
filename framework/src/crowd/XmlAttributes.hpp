#pragma once
// Reading an element of a crowd world's XML with every check the format makes:
// the attributes it may carry, its child elements, and numbers, whole numbers
// and "x z" pairs within their ranges. Each failure throws InputError with the
// file and line of the element (XmlFile::fail).

#include "XmlFile.hpp"

#include <glm/vec2.hpp>

#include <pugixml.hpp>

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace stoa::xml {

/// Throws unless every attribute of `node` is one of `allowed`, each once.
void checkAttributes(const XmlFile& file, pugi::xml_node node, std::initializer_list<const char*> allowed);

/// The element children of `node`; text other than white space is an error.
std::vector<pugi::xml_node> childElements(const XmlFile& file, pugi::xml_node node);

/// An element that may hold nothing, with the attributes it may carry.
void checkLeaf(const XmlFile& file, pugi::xml_node node, std::initializer_list<const char*> allowed);

/// The attribute's text; a missing or empty attribute is an error.
std::string requiredText(const XmlFile& file, pugi::xml_node node, const char* name);

/// The attribute's text, or `fallback` when the attribute is missing; an empty one is an error.
std::string optionalText(const XmlFile& file, pugi::xml_node node, const char* name, const std::string& fallback);

/// The whole of `text` as a number a float holds, or nothing: not "", "1.5m", "nan" or
/// "inf", not past a float's range ("1e39") and not so close to 0 that a float loses it
/// ("1e-60"); 0 itself is a number. The locale plays no part.
std::optional<double> parseNumber(std::string_view text);

/// The ranges a number attribute may be checked against.
enum class Range {
    NonNegative,   ///< 0 or more
    Positive,      ///< greater than 0 and at most 100000
    UnitInterval,  ///< between 0 and 1
    Step,          ///< a time step, from 0.001 to 1 seconds
    Metres,        ///< a place or a height, from -100000 to 100000
};

/// The attribute as a float in `range`; a missing attribute is `fallback`, or an error without one.
float number(const XmlFile& file, pugi::xml_node node, const char* name, std::optional<float> fallback, Range range);

/// The attribute as a whole number in [least, most]; a missing attribute is `fallback`, or an error without one.
std::int64_t wholeNumber(const XmlFile& file, pugi::xml_node node, const char* name, std::optional<std::int64_t> fallback,
                         std::int64_t least, std::int64_t most);

/// The attribute as "x z", two numbers in Range::Metres separated by white space; `fallback` when missing.
glm::vec2 coordinates(const XmlFile& file, pugi::xml_node node, const char* name, glm::vec2 fallback);

} // namespace stoa::xml
