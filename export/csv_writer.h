// CSV tables of numbers for studies and analyses (SVAJ samples, conversion errors): a header row
// whose names carry units ("theta [deg]"), quoted per RFC 4180 where needed, then rows of doubles
// written as the shortest text that reads back exactly, independent of the locale. Lines end in
// '\n'; non-finite values are written as nan, inf, -inf.
#pragma once

#include <filesystem>
#include <initializer_list>
#include <span>
#include <string>
#include <vector>

namespace polarform {

class CsvWriter {
 public:
  // One non-empty header per column.
  explicit CsvWriter(std::vector<std::string> headers_with_units);

  // Appends a row; it must have one value per column.
  void row(std::span<const double> values);
  void row(std::initializer_list<double> values);

  std::size_t columns() const { return columns_; }
  std::size_t rows() const { return rows_; }

  std::string str() const { return text_; }
  // Writes str() to path atomically.
  void save(const std::filesystem::path& path) const;

 private:
  std::size_t columns_;
  std::size_t rows_ = 0;
  std::string text_;
};

// A CSV field as RFC 4180 wants it: quoted, with quotes doubled, if it holds a comma, a quote,
// a line break or leading/trailing space; unchanged otherwise.
std::string csv_field(const std::string& text);

}  // namespace polarform
