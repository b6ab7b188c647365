// A minimal streaming writer for SVG markup: elements with escaped attribute values, pixel
// coordinates rounded to 0.01 px, and escaped text content. Output is deterministic and
// locale-independent; the plot code (export/plot_panel, export/plot_legend) draws through it.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace polarform {

class SvgWriter {
 public:
  // Starts an element: "<name". Follow with attr() calls and one of empty(), text() or open().
  SvgWriter& begin(std::string_view name);
  SvgWriter& attr(std::string_view name, std::string_view value);
  SvgWriter& attr(std::string_view name, double pixels);  // rounded to 0.01, trailing zeros cut

  void empty();                         // "/>"
  void text(std::string_view content);  // ">content</name>", content escaped
  void open();                          // ">"; children follow until close()
  void close();                         // "</name>" of the innermost open element

  const std::string& str() const { return out_; }

 private:
  std::string out_;
  std::string pending_;                     // name of the element being started
  std::vector<std::string> open_elements_;  // innermost last
};

// Pixel coordinate as written into SVG: rounded to 0.01 px, trailing zeros cut.
std::string svg_number(double pixels);

}  // namespace polarform
