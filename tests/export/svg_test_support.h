// Helpers shared by the plot tests: parse SVG text with tinyxml2, find elements by class, read
// path data back into pixel points and tick labels back into numbers.
#pragma once

#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <cmath>
#include <cstdlib>
#include <functional>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "export/nice_ticks.h"
#include "export/polyline_path.h"
#include "tests/support/export/svg_elements.h"

namespace polarform::test {

inline PixelRect area_of(const XMLElement* rect) {
  const double x = rect->DoubleAttribute("x"), y = rect->DoubleAttribute("y");
  return {x, y, x + rect->DoubleAttribute("width"), y + rect->DoubleAttribute("height")};
}

// A tick label as a number: "−0.5", "100", "10⁻³", "2×10⁻⁷"; a factor "×10⁶" multiplies.
inline double label_value(std::string label, const std::string& factor = {}) {
  const auto replace_all = [](std::string& s, const std::string& from, const std::string& to) {
    for (std::size_t at; (at = s.find(from)) != std::string::npos;) s.replace(at, from.size(), to);
  };
  const char* supers[] = {"\u2070", "\u00B9", "\u00B2", "\u00B3", "\u2074",
                          "\u2075", "\u2076", "\u2077", "\u2078", "\u2079"};
  const auto power = [&](std::string s) {  // "×10⁻³" or "10⁻³" -> 1e-3
    replace_all(s, "\u00D7", "");
    replace_all(s, "\u207B", "-");
    for (int d = 0; d < 10; ++d) replace_all(s, supers[d], std::to_string(d));
    return std::stod("1e" + s.substr(2));
  };
  replace_all(label, "\u2212", "-");
  const double scale = factor.empty() ? 1.0 : power(factor);
  const std::size_t times = label.find("\u00D7");
  if (times != std::string::npos)
    return std::stod(label.substr(0, times)) * power(label.substr(times)) * scale;
  if (label.rfind("10", 0) == 0 && label.size() > 2 &&
      !std::isdigit(static_cast<unsigned char>(label[2])) && label[2] != '.')
    return power(label) * scale;
  return std::stod(label) * scale;
}

struct ParsedSvg {
  tinyxml2::XMLDocument doc;
  explicit ParsedSvg(const std::string& text) {
    EXPECT_EQ(doc.Parse(text.c_str(), text.size()), tinyxml2::XML_SUCCESS) << doc.ErrorStr();
  }
  const XMLElement* root() const { return doc.RootElement(); }
  std::vector<const XMLElement*> all(const std::string& cls) const { return by_class(root(), cls); }
};

}  // namespace polarform::test
