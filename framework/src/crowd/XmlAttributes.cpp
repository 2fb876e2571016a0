#include "XmlAttributes.hpp"

#include <stoa/core/InputFile.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <system_error>

namespace stoa::xml {

namespace {

std::string attributeText(pugi::xml_attribute attribute) {
    return std::string(attribute.name()) + "=\"" + quoteInput(attribute.value()) + "\"";
}

/// What the text of a number attribute holds.
enum class NumberText { Number, NotANumber, TooLarge, TooSmall };

/// Reads the whole of `text` as a number a float can hold: not "", "1.5m", "nan" or "inf"
/// (NotANumber), not past a float's range ("1e39": TooLarge), and not so close to 0 that a
/// float loses it or its precision ("1e-60", "1e-45": TooSmall); 0 itself is a number.
/// std::from_chars ignores the locale, unlike strtod.
NumberText readNumber(std::string_view text, double& value) {
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    value = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || end != text.data() + text.size()) return NumberText::NotANumber;
    if (error == std::errc::result_out_of_range) {
        // from_chars leaves `value` alone then: the digits tell which way it overflowed.
        const std::size_t exponent = text.find_first_of("eE");
        const bool negativeExponent = exponent != std::string_view::npos && exponent + 1 < text.size() && text[exponent + 1] == '-';
        return negativeExponent ? NumberText::TooSmall : NumberText::TooLarge;
    }
    if (error != std::errc() || !std::isfinite(value)) return NumberText::NotANumber;
    if (std::abs(value) > std::numeric_limits<float>::max()) return NumberText::TooLarge;
    if (value != 0.0 && std::abs(value) < std::numeric_limits<float>::min()) return NumberText::TooSmall;
    return NumberText::Number;
}

/// The problem with the number attribute's text, as a message, or "" when it is a
/// number (then in `value`).
std::string numberProblem(pugi::xml_attribute attribute, const std::string& where, double& value) {
    switch (readNumber(attribute.value(), value)) {
    case NumberText::Number: return "";
    case NumberText::NotANumber: return "the attribute " + attributeText(attribute) + " on " + where + " is not a number";
    case NumberText::TooLarge:
        return "the attribute " + attributeText(attribute) + " on " + where + " is too large for a float (at most 3.4e38)";
    case NumberText::TooSmall:
        return "the attribute " + attributeText(attribute) + " on " + where +
               " is too close to 0 for a float (the smallest it keeps exactly is 1.2e-38); write 0 or a larger number";
    }
    return "";
}

/// How far from the origin a place or a height may be: 100 km, so that every
/// difference of two of them is a float with room for centimetres to spare.
constexpr double kMaxMetres = 100000.0;

bool inRange(double value, Range range) {
    switch (range) {
    case Range::NonNegative: return value >= 0.0;
    case Range::Positive: return value > 0.0 && value <= kMaxMetres;
    case Range::UnitInterval: return value >= 0.0 && value <= 1.0;
    case Range::Step: return value >= 0.001 && value <= 1.0;
    case Range::Metres: return std::abs(value) <= kMaxMetres;
    }
    return false;
}

const char* describe(Range range) {
    switch (range) {
    case Range::NonNegative: return "0 or more";
    case Range::Positive: return "greater than 0 and at most 100000";
    case Range::UnitInterval: return "between 0 and 1";
    case Range::Step: return "from 0.001 to 1 (seconds)";
    case Range::Metres: return "from -100000 to 100000 (metres)";
    }
    return "";
}

} // namespace

/// Throws unless every attribute of `node` is one of `allowed`, each once.
void checkAttributes(const XmlFile& file, pugi::xml_node node, std::initializer_list<const char*> allowed) {
    for (pugi::xml_attribute attribute = node.first_attribute(); attribute; attribute = attribute.next_attribute()) {
        const std::string name = attribute.name();
        const bool known = std::any_of(allowed.begin(), allowed.end(), [&](const char* a) { return name == a; });
        if (!known) {
            std::string expected;
            for (const char* a : allowed) expected += (expected.empty() ? "" : ", ") + std::string(a);
            file.fail(node, "unknown attribute '" + quoteInput(name) + "' on " + tag(node) +
                                (expected.empty() ? "; it takes no attributes" : "; expected one of: " + expected));
        }
        for (pugi::xml_attribute later = attribute.next_attribute(); later; later = later.next_attribute()) {
            if (name == later.name()) file.fail(node, "the attribute '" + quoteInput(name) + "' appears twice on " + tag(node));
        }
    }
}

/// The element children of `node`; text other than white space is an error.
std::vector<pugi::xml_node> childElements(const XmlFile& file, pugi::xml_node node) {
    std::vector<pugi::xml_node> children;
    for (pugi::xml_node child : node.children()) {
        if (child.type() == pugi::node_element) {
            children.push_back(child);
        } else if (child.type() == pugi::node_pcdata || child.type() == pugi::node_cdata) {
            const std::string text = child.value();
            const std::size_t start = std::min(text.find_first_not_of(" \t\r\n"), text.size());
            const std::size_t end = text.find_last_not_of(" \t\r\n") + 1;
            file.fail(child, "unexpected text '" + quoteInput(text.substr(start, end > start ? end - start : 0)) + "' in " + tag(node) +
                                 "; the format keeps everything in attributes");
        }
    }
    return children;
}

/// An element that may hold nothing, with the attributes it may carry.
void checkLeaf(const XmlFile& file, pugi::xml_node node, std::initializer_list<const char*> allowed) {
    checkAttributes(file, node, allowed);
    const std::vector<pugi::xml_node> children = childElements(file, node);
    if (!children.empty()) file.fail(children[0], tag(node) + " holds no elements; found " + tag(children[0]));
}

/// The attribute's text; a missing or empty attribute is an error.
std::string requiredText(const XmlFile& file, pugi::xml_node node, const char* name) {
    const pugi::xml_attribute attribute = node.attribute(name);
    if (!attribute) file.fail(node, "missing attribute '" + std::string(name) + "' on " + tag(node));
    if (*attribute.value() == '\0') file.fail(node, "the attribute '" + std::string(name) + "' on " + tag(node) + " is empty");
    return attribute.value();
}

std::string optionalText(const XmlFile& file, pugi::xml_node node, const char* name, const std::string& fallback) {
    return node.attribute(name) ? requiredText(file, node, name) : fallback;
}

std::optional<double> parseNumber(std::string_view text) {
    double value = 0.0;
    if (readNumber(text, value) != NumberText::Number) return std::nullopt;
    return value;
}

float number(const XmlFile& file, pugi::xml_node node, const char* name, std::optional<float> fallback, Range range) {
    const pugi::xml_attribute attribute = node.attribute(name);
    if (!attribute) {
        if (fallback) return *fallback;
        file.fail(node, "missing attribute '" + std::string(name) + "' on " + tag(node));
    }
    double value = 0.0;
    if (const std::string problem = numberProblem(attribute, tag(node), value); !problem.empty()) file.fail(node, problem);
    const float kept = static_cast<float>(value);
    if (!inRange(kept, range)) {
        file.fail(node, "the attribute " + attributeText(attribute) + " on " + tag(node) + " is out of range: it must be " +
                            describe(range));
    }
    return kept;
}

/// A whole number in [least, most].
std::int64_t wholeNumber(const XmlFile& file, pugi::xml_node node, const char* name, std::optional<std::int64_t> fallback,
                         std::int64_t least, std::int64_t most) {
    const pugi::xml_attribute attribute = node.attribute(name);
    if (!attribute) {
        if (fallback) return *fallback;
        file.fail(node, "missing attribute '" + std::string(name) + "' on " + tag(node));
    }
    std::string_view text = attribute.value();
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    std::int64_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    const bool whole = !text.empty() && end == text.data() + text.size();
    if (error == std::errc() && !whole && parseNumber(attribute.value())) {
        file.fail(node, "the attribute " + attributeText(attribute) + " on " + tag(node) + " is not a whole number");
    }
    if (error == std::errc::invalid_argument || !whole) {
        file.fail(node, "the attribute " + attributeText(attribute) + " on " + tag(node) + " is not a number");
    }
    if (error == std::errc::result_out_of_range || value < least || value > most) {
        file.fail(node, "the attribute " + attributeText(attribute) + " on " + tag(node) + " is out of range: it must be " +
                            std::to_string(least) + " to " + std::to_string(most));
    }
    return value;
}

/// "x z": two finite numbers separated by white space.
glm::vec2 coordinates(const XmlFile& file, pugi::xml_node node, const char* name, glm::vec2 fallback) {
    const pugi::xml_attribute attribute = node.attribute(name);
    if (!attribute) return fallback;
    std::vector<std::string_view> words;
    const std::string_view text = attribute.value();
    for (std::size_t at = 0; at < text.size();) {
        const std::size_t start = text.find_first_not_of(" \t\r\n", at);
        if (start == std::string_view::npos) break;
        const std::size_t end = std::min(text.find_first_of(" \t\r\n", start), text.size());
        words.push_back(text.substr(start, end - start));
        at = end;
    }
    std::optional<double> x, z;
    if (words.size() == 2) x = parseNumber(words[0]), z = parseNumber(words[1]);
    if (!x || !z) {
        file.fail(node, "the attribute " + attributeText(attribute) + " on " + tag(node) +
                            " is not a pair of numbers \"x z\" (metres)");
    }
    if (!inRange(*x, Range::Metres) || !inRange(*z, Range::Metres)) {
        file.fail(node, "the attribute " + attributeText(attribute) + " on " + tag(node) + " is out of range: x and z must be " +
                            describe(Range::Metres));
    }
    return {static_cast<float>(*x), static_cast<float>(*z)};
}

} // namespace stoa::xml
