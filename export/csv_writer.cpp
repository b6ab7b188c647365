#include "export/csv_writer.h"

#include "export/atomic_file.h"
#include "src/error.h"
#include "src/number_text.h"

namespace polarform {

CsvWriter::CsvWriter(std::vector<std::string> headers_with_units)
    : columns_(headers_with_units.size()) {
  if (headers_with_units.empty())
    throw InputError("CsvWriter: headers must name at least one column");
  for (std::size_t i = 0; i < columns_; ++i) {
    if (headers_with_units[i].empty())
      throw InputError("CsvWriter: header " + std::to_string(i + 1) +
                       " is empty; expected a name "
                       "with units such as \"theta [deg]\"");
    text_.append(i == 0 ? "" : ",").append(csv_field(headers_with_units[i]));
  }
  text_.append("\n");
}

void CsvWriter::row(std::span<const double> values) {
  if (values.size() != columns_)
    throw InputError("CsvWriter: row " + std::to_string(rows_ + 1) + " has " +
                     std::to_string(values.size()) + " values; expected " +
                     std::to_string(columns_) + ", one per header");
  for (std::size_t i = 0; i < values.size(); ++i)
    text_.append(i == 0 ? "" : ",").append(format_round_trip(values[i]));
  text_.append("\n");
  ++rows_;
}

void CsvWriter::row(std::initializer_list<double> values) {
  row(std::span<const double>(values.begin(), values.size()));
}

void CsvWriter::save(const std::filesystem::path& path) const {
  write_file_atomically(path, text_);
}

std::string csv_field(const std::string& text) {
  const bool quote = text.find_first_of(",\"\r\n") != std::string::npos ||
                     (!text.empty() && (text.front() == ' ' || text.back() == ' '));
  if (!quote) return text;
  std::string out = "\"";
  for (const char c : text) out.append(c == '"' ? "\"\"" : std::string(1, c));
  return out + "\"";
}

}  // namespace polarform
