#pragma once
// One XML file of a crowd world, parsed and kept with its text, so that every
// error names the file and the line of the element it is about.

#include <pugixml.hpp>

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace stoa::xml {

/// One parsed XML file, kept with its text so that an element's byte offset
/// (pugixml's offset_debug()) becomes a 1-based line.
class XmlFile {
public:
    /// Checks `text` (checkXmlText) and parses it; throws InputError with the
    /// line for text that is not well-formed XML. `name` is the file named in
    /// errors and its folder the one relative paths in the file are resolved against.
    XmlFile(std::string text, const std::filesystem::path& name);

    const std::string& name() const { return m_name; }
    const std::filesystem::path& folder() const { return m_folder; }
    const pugi::xml_document& document() const { return m_document; }

    /// The line of an element's name, or of the first character of text that is not white space.
    int line(pugi::xml_node node) const;

    /// Throws InputError naming this file and the line of `node`.
    [[noreturn]] void fail(pugi::xml_node node, const std::string& message) const;

private:
    int lineOfOffset(std::ptrdiff_t offset) const;

    std::string m_name;
    std::filesystem::path m_folder;
    std::string m_text;
    std::vector<std::size_t> m_lineStarts;  // byte offset of each line's first byte
    pugi::xml_document m_document;
};

/// "<name>", for messages.
std::string tag(pugi::xml_node node);

} // namespace stoa::xml
