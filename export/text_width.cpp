#include "export/text_width.h"

#include <cstdint>

namespace polarform {

namespace {

// Advance width in em of one code point; DejaVu Sans values rounded up per character class.
double advance(std::uint32_t c) {
  if (c < 0x80) {
    const char ascii = static_cast<char>(c);
    const auto among = [ascii](std::string_view set) {
      return set.find(ascii) != std::string_view::npos;
    };
    if (among(" .,:;!|'ijlI")) return 0.32;
    if (among("-()[]/ftr")) return 0.42;
    if (among("mwMW%")) return 0.98;
    if (c >= 'A' && c <= 'Z') return 0.74;
    if (c >= 'a' && c <= 'z') return 0.62;
    return 0.66;  // digits (0.636 em, rounded up for hinting) and the rest
  }
  if (c == 0x00B2 || c == 0x00B3 || c == 0x00B9 || (c >= 0x2070 && c <= 0x207F)) return 0.42;
  if (c == 0x2212 || c == 0x00D7) return 0.84;  // minus sign, multiplication sign
  return 0.72;
}

}  // namespace

double text_width(std::string_view utf8, double font_size) {
  double em = 0;
  for (std::size_t i = 0; i < utf8.size();) {
    const auto lead = static_cast<unsigned char>(utf8[i]);
    const std::size_t length = lead < 0x80    ? 1
                               : lead >= 0xF0 ? 4
                               : lead >= 0xE0 ? 3
                               : lead >= 0xC0 ? 2
                                              : 1;
    std::uint32_t c = length == 1 ? lead : lead & (0x7F >> length);
    for (std::size_t k = 1; k < length && i + k < utf8.size(); ++k)
      c = (c << 6) | (static_cast<unsigned char>(utf8[i + k]) & 0x3F);
    em += advance(c);
    i += length;
  }
  return em * font_size;
}

}  // namespace polarform
