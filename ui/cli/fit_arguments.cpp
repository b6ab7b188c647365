#include "ui/cli/fit_arguments.h"

#include <charconv>
#include <cmath>
#include <sstream>

#include "src/error.h"

namespace polarform {

namespace {

std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> out;
  std::string field;
  std::istringstream in(text);
  while (std::getline(in, field, ',')) out.push_back(field);
  if (!text.empty() && text.back() == ',') out.emplace_back();
  return out;
}

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t") - a + 1);
}

std::string count_text(int lo, int hi) {
  return lo == hi ? std::to_string(lo) : std::to_string(lo) + " to " + std::to_string(hi);
}

}  // namespace

std::vector<double> parse_numbers(const std::string& option, const std::string& text, int min_count,
                                  int max_count) {
  const std::vector<std::string> fields = split(text);
  const std::string expected = count_text(min_count, max_count) + " comma-separated numbers";
  if (static_cast<int>(fields.size()) < min_count || static_cast<int>(fields.size()) > max_count)
    throw InputError(option + " '" + text + "': expected " + expected);
  std::vector<double> out;
  for (const std::string& raw : fields) {
    const std::string f = trim(raw);
    double v = 0.0;
    const auto [end, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
    if (f.empty() || ec != std::errc() || end != f.data() + f.size() || !std::isfinite(v))
      throw InputError(option + " '" + text + "': '" + f + "' is not a finite number; expected " +
                       expected);
    out.push_back(v);
  }
  return out;
}

std::pair<int, int> parse_int_pair(const std::string& option, const std::string& text, int lo,
                                   int hi) {
  const std::string expected = "one or two comma-separated integers from " + std::to_string(lo) +
                               " to " + std::to_string(hi);
  const std::vector<std::string> fields = split(text);
  if (fields.empty() || fields.size() > 2)
    throw InputError(option + " '" + text + "': expected " + expected);
  int v[2] = {0, 0};
  for (std::size_t i = 0; i < fields.size(); ++i) {
    const std::string f = trim(fields[i]);
    const auto [end, ec] = std::from_chars(f.data(), f.data() + f.size(), v[i]);
    if (f.empty() || ec != std::errc() || end != f.data() + f.size() || v[i] < lo || v[i] > hi)
      throw InputError(option + " '" + text + "': expected " + expected);
  }
  return {v[0], fields.size() == 2 ? v[1] : v[0]};
}

int parse_choice(const std::string& option, const std::string& text,
                 const std::vector<std::string>& choices) {
  for (std::size_t i = 0; i < choices.size(); ++i)
    if (choices[i] == text) return static_cast<int>(i);
  std::string list;
  for (std::size_t i = 0; i < choices.size(); ++i)
    list += (i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + choices[i];
  throw InputError(option + " '" + text + "': expected " + list);
}

}  // namespace polarform
