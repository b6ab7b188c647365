// A report's fields as "name=value" lines, one per scalar, for the studio's script mode and the
// tests that compare it with report.json: nested names joined by '.', array elements by their
// index ("arc_list.3.sweep_deg"); numbers as the shortest text that reads back exactly, texts on
// one line (backslashes and line breaks escaped as \\ and \n).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace polarform {

// Every scalar of `fields` as "<prefix><name>=<value>\n", in the fields' order.
std::string report_lines(const nlohmann::ordered_json& fields,
                         const std::string& prefix = "report.");

}  // namespace polarform
