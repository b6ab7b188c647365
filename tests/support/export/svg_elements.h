// Reading polarform's SVG back in tests: elements by class, and path data as pixel points.
#pragma once

#include <tinyxml2.h>

#include <functional>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "export/polyline_path.h"

namespace polarform::test {

using tinyxml2::XMLElement;

// All elements below root (inclusive) whose class list contains cls.
inline std::vector<const XMLElement*> by_class(const XMLElement* root, const std::string& cls) {
  std::vector<const XMLElement*> found;
  std::function<void(const XMLElement*)> visit = [&](const XMLElement* e) {
    if (const char* c = e->Attribute("class")) {
      std::istringstream words(c);
      for (std::string w; words >> w;)
        if (w == cls) found.push_back(e);
    }
    for (const XMLElement* child = e->FirstChildElement(); child;
         child = child->NextSiblingElement())
      visit(child);
  };
  visit(root);
  return found;
}

// The subpaths of path data made of M and L commands with absolute coordinates (of a marker
// shape, its first point).
inline std::vector<Polyline> subpaths(const std::string& d) {
  std::vector<Polyline> pieces;
  static const std::regex command(R"(([ML])(-?[0-9.]+) (-?[0-9.]+))");
  for (auto it = std::sregex_iterator(d.begin(), d.end(), command); it != std::sregex_iterator();
       ++it) {
    if ((*it)[1] == "M") pieces.emplace_back();
    pieces.back().push_back({std::stod((*it)[2]), std::stod((*it)[3])});
  }
  return pieces;
}

}  // namespace polarform::test
