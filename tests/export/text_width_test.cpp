// Text width estimates: per-class advances and UTF-8 decoding of the symbols in tick labels.
#include <gtest/gtest.h>

#include "export/text_width.h"

namespace polarform {
namespace {

TEST(TextWidth, SumsAdvancesOfDecodedCodePoints) {
  EXPECT_DOUBLE_EQ(text_width("", 12), 0);
  EXPECT_DOUBLE_EQ(text_width("10", 10), 2 * 6.6);
  EXPECT_DOUBLE_EQ(text_width("0.5", 10), 6.6 + 3.2 + 6.6);
  // U+2212 minus (3 bytes), U+207B and U+2076 superscripts, U+00D7 times (2 bytes each or 3).
  EXPECT_DOUBLE_EQ(text_width("\u22125", 10), 8.4 + 6.6);
  EXPECT_DOUBLE_EQ(text_width("2\u00D710\u207B\u2076", 10), 6.6 + 8.4 + 2 * 6.6 + 2 * 4.2);
  EXPECT_DOUBLE_EQ(text_width("\u03B8", 10), 7.2);  // other non-ASCII: Greek theta
  EXPECT_GT(text_width("mmm", 12), text_width("iii", 12) * 2.5);
}

}  // namespace
}  // namespace polarform
