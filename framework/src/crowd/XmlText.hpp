#pragma once
// What text a crowd world's XML file may hold, checked before pugixml parses
// it: UTF-8 (a byte-order mark allowed), never UTF-16, and only the entity
// references XML itself defines. pugixml would keep an unknown `&name;` as
// those characters, cut a name at `&#0;` and write `&#x110000;` as bytes that
// are not UTF-8; each of those is an error here, with its line.

#include <string>

namespace stoa {

/// Throws InputError(name, line, ...) for UTF-16 text, bytes that are not
/// UTF-8, or an entity reference other than &amp; &lt; &gt; &quot; &apos; and
/// a character reference to a character XML allows (&#9;, &#x263A;; not &#0;,
/// not past U+10FFFF). Comments, CDATA sections, processing instructions and a
/// DOCTYPE are skipped, as the parser skips them.
void checkXmlText(const std::string& text, const std::string& name);

} // namespace stoa
