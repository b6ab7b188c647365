#include "src/io/csv_text.h"

#include <fstream>
#include <sstream>

#include "src/error.h"
#include "src/io/text_scan.h"

namespace polarform {

std::string read_text_file(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string() + ": cannot open file");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string_view> comma_fields(std::string_view line) {
  std::vector<std::string_view> out;
  while (true) {
    const std::size_t c = line.find(',');
    out.push_back(io_detail::trim(line.substr(0, c)));
    if (c == std::string_view::npos) return out;
    line.remove_prefix(c + 1);
  }
}

void for_each_data_line(std::string_view text, const std::string& name,
                        const std::function<void(std::string_view, const std::string&)>& on_line) {
  std::size_t line_no = 0;
  while (!text.empty()) {
    const std::size_t nl = text.find('\n');
    std::string_view line = text.substr(0, nl);
    text.remove_prefix(nl == std::string_view::npos ? text.size() : nl + 1);
    ++line_no;
    if (line_no == 1 && line.starts_with("\xEF\xBB\xBF")) line.remove_prefix(3);
    line = io_detail::strip_comment(line);
    if (!line.empty()) on_line(line, name + ":" + std::to_string(line_no) + ": ");
  }
}

}  // namespace polarform
