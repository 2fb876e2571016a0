#include "XmlFile.hpp"

#include "XmlText.hpp"

#include <stoa/core/InputError.hpp>
#include <stoa/core/InputFile.hpp>

#include <algorithm>

namespace stoa::xml {

XmlFile::XmlFile(std::string text, const std::filesystem::path& name)
    : m_name(name.string()), m_folder(name.parent_path()), m_text(std::move(text)) {
    checkXmlText(m_text, m_name);
    m_lineStarts.push_back(0);
    for (std::size_t i = 0; i < m_text.size(); ++i) {
        const bool lineFeed = m_text[i] == '\n';
        const bool loneReturn = m_text[i] == '\r' && (i + 1 == m_text.size() || m_text[i + 1] != '\n');
        if (lineFeed || loneReturn) m_lineStarts.push_back(i + 1);
    }
    // encoding_utf8: pugixml converts nothing, so its offsets are offsets into m_text.
    // parse_default expands only XML's five built-in entities and character references;
    // it reads no DOCTYPE, so it never expands an entity the file defines or fetches one.
    const pugi::xml_parse_result result =
        m_document.load_buffer(m_text.data(), m_text.size(), pugi::parse_default, pugi::encoding_utf8);
    if (!result) {
        throw InputError(m_name, lineOfOffset(result.offset), std::string("malformed XML: ") + result.description());
    }
}

int XmlFile::line(pugi::xml_node node) const {
    int line = lineOfOffset(node.offset_debug());
    if (node.type() == pugi::node_pcdata && line > 0) {
        // Line ends in a value are single '\n's (parse_eol), so counting them counts lines.
        for (const char* c = node.value(); *c == ' ' || *c == '\t' || *c == '\n' || *c == '\r'; ++c) line += *c == '\n';
    }
    return line;
}

void XmlFile::fail(pugi::xml_node node, const std::string& message) const {
    throw InputError(m_name, line(node), message);
}

int XmlFile::lineOfOffset(std::ptrdiff_t offset) const {
    if (offset < 0) return 0;
    const auto after = std::upper_bound(m_lineStarts.begin(), m_lineStarts.end(), static_cast<std::size_t>(offset));
    return static_cast<int>(after - m_lineStarts.begin());
}

std::string tag(pugi::xml_node node) { return "<" + quoteInput(node.name()) + ">"; }

} // namespace stoa::xml
