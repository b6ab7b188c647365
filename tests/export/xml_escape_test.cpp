// XML text for the writers (export/xml_escape.h): markup characters become entities, UTF-8 text
// passes unchanged, control characters that XML 1.0 forbids become U+FFFD.
#include "export/xml_escape.h"

#include <gtest/gtest.h>

#include <string>

namespace polarform {
namespace {

TEST(XmlEscape, MarkupAndControlCharacters) {
  EXPECT_EQ(xml_escape("a < b & c > \"d\" 'e'"), "a &lt; b &amp; c &gt; &quot;d&quot; &#39;e&#39;");
  EXPECT_EQ(xml_escape("θ [deg]"), "θ [deg]");
  EXPECT_EQ(xml_escape(std::string("a\x01"
                                   "b")),
            "a\xEF\xBF\xBD"
            "b");
  // Found by fuzzing: a raw CR in an attribute reads back as LF, so a saved project changed when
  // read again. Tab, LF and CR are written as character references, which readers keep.
  EXPECT_EQ(xml_escape("a\tb\nc\rd"), "a&#9;b&#10;c&#13;d");
}

}  // namespace
}  // namespace polarform
