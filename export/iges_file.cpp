#include "export/iges_file.h"

#include <cstdio>

#include "src/error.h"

namespace polarform {

namespace {

// Columns 73-80: section letter and right-justified 7-digit sequence number.
std::string sequence(char section, int number) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%c%07d", section, number);
  return buf;
}

std::string pad(std::string s, std::size_t width) {
  s.resize(width, ' ');
  return s;
}

// Packs delimiter-terminated tokens into lines of `width` columns; a token is split only when it
// is longer than a whole line (a long Hollerith string).
std::vector<std::string> pack(const std::vector<std::string>& tokens, std::size_t width) {
  std::vector<std::string> lines(1);
  for (const std::string& token : tokens) {
    if (lines.back().size() + token.size() > width && !lines.back().empty()) lines.emplace_back();
    std::size_t at = 0;
    while (token.size() - at > width - lines.back().size()) {
      const std::size_t take = width - lines.back().size();
      lines.back() += token.substr(at, take);
      at += take;
      lines.emplace_back();
    }
    lines.back() += token.substr(at);
  }
  return lines;
}

// Tokens "a," "b," ... "z;" from parameters a..z.
std::vector<std::string> delimited(const std::vector<std::string>& params) {
  std::vector<std::string> tokens;
  for (std::size_t i = 0; i < params.size(); ++i)
    tokens.push_back(params[i] + (i + 1 == params.size() ? ';' : ','));
  return tokens;
}

std::string right(const std::string& s, int width) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%*s", width, s.c_str());
  return buf;
}

std::string right(int value, int width) { return right(std::to_string(value), width); }

}  // namespace

std::string iges_string(const std::string& text, const std::string& field) {
  for (unsigned char c : text)
    if (c < 32 || c > 126)
      throw InputError("IGES " + field + " '" + text +
                       "': only printable ASCII characters can be written");
  if (text.empty()) return "";  // the default (empty) value
  return std::to_string(text.size()) + "H" + text;
}

std::string iges_file(const std::string& start_text, const std::vector<std::string>& global_params,
                      const std::vector<IgesEntity>& entities) {
  std::string out;
  auto emit = [&out](const std::string& data72, char section, int number) {
    out += pad(data72, 72) + sequence(section, number) + '\n';
  };

  // IGES 5.3 Start section: free text, at least one line.
  iges_string(start_text, "start section text");
  int s = 0;
  for (std::size_t at = 0; at < start_text.size() || s == 0; at += 72)
    emit(start_text.substr(at, 72), 'S', ++s);

  // IGES 5.3 Global section: parameter and record delimiters first.
  std::vector<std::string> globals = {"1H,", "1H;"};
  globals.insert(globals.end(), global_params.begin(), global_params.end());
  int g = 0;
  for (const std::string& line : pack(delimited(globals), 72)) emit(line, 'G', ++g);

  // IGES 5.3 Parameter Data section: columns 1-64 data, 65-72 the owning DE pointer.
  std::vector<std::string> p_lines;
  std::vector<int> p_start, p_count;
  for (std::size_t i = 0; i < entities.size(); ++i) {
    const IgesEntity& e = entities[i];
    std::vector<std::string> params = {std::to_string(e.type)};
    params.insert(params.end(), e.params.begin(), e.params.end());
    if (e.name_property_de != 0) {  // no associativities, one property pointer
      params.insert(params.end(), {"0", "1", std::to_string(e.name_property_de)});
    }
    const std::vector<std::string> lines = pack(delimited(params), 64);
    p_start.push_back(static_cast<int>(p_lines.size()) + 1);
    p_count.push_back(static_cast<int>(lines.size()));
    const int de = iges_de_pointer(static_cast<int>(i));
    for (const std::string& line : lines) p_lines.push_back(pad(line, 64) + right(de, 8));
  }

  // IGES 5.3 Directory Entry section: two lines of ten 8-column fields per entity.
  int d = 0;
  for (std::size_t i = 0; i < entities.size(); ++i) {
    const IgesEntity& e = entities[i];
    if (e.label.size() > 8 || e.status.size() != 8)
      throw InputError("IGES entity " + std::to_string(e.type) + ": label '" + e.label +
                       "' longer than 8 characters or malformed status '" + e.status + "'");
    emit(right(e.type, 8) + right(p_start[i], 8) + right(0, 8) + right(0, 8) + right(0, 8) +
             right(0, 8) + right(0, 8) + right(0, 8) + e.status,
         'D', ++d);
    emit(right(e.type, 8) + right(0, 8) + right(0, 8) + right(p_count[i], 8) + right(e.form, 8) +
             std::string(16, ' ') + right(e.label, 8) + right(0, 8),
         'D', ++d);
  }

  int p = 0;
  for (const std::string& line : p_lines) emit(line, 'P', ++p);

  // IGES 5.3 Terminate section: line counts of the four sections.
  emit(sequence('S', s) + sequence('G', g) + sequence('D', d) + sequence('P', p), 'T', 1);
  return out;
}

}  // namespace polarform
