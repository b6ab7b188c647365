// Escaping of user text (labels, titles, table cells) for XML and HTML output: markup characters
// become entities, and control characters that XML 1.0 forbids become U+FFFD, so any string
// yields a well-formed document.
#pragma once

#include <string>
#include <string_view>

namespace polarform {

// text with & < > " ' replaced by entities and tab, LF, CR by character references (so that they
// survive attribute-value normalisation); safe in element content and in attribute values.
std::string xml_escape(std::string_view text);

}  // namespace polarform
