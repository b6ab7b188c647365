#include "jobs/report/report_lines.h"

#include "jobs/report/report_number.h"
#include "src/number_text.h"

namespace polarform {

namespace {

// A text on one line: backslashes and line breaks escaped as \\ and \n.
std::string one_line(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '\\')
      out += "\\\\";
    else if (c == '\n')
      out += "\\n";
    else
      out += c;
  }
  return out;
}

void append(std::string& out, const nlohmann::ordered_json& value, const std::string& name) {
  if (value.is_object()) {
    for (const auto& [key, child] : value.items())
      append(out, child, name.empty() ? key : name + "." + key);
  } else if (value.is_array()) {
    for (std::size_t i = 0; i < value.size(); ++i)
      append(out, value[i], name + "." + std::to_string(i));
  } else {
    out += name + "=";
    if (value.is_number_float())
      out += format_round_trip(report_number(value.get<double>()));
    else if (value.is_string())
      out += one_line(value.get<std::string>());
    else
      out += value.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
    out += "\n";
  }
}

}  // namespace

std::string report_lines(const nlohmann::ordered_json& fields, const std::string& prefix) {
  std::string out;
  for (const auto& [key, value] : fields.items()) append(out, value, prefix + key);
  return out;
}

}  // namespace polarform
