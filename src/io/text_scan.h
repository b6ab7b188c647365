// Text scanning shared by the point-cloud readers: a line cursor over an in-memory file, blank-
// separated tokens, and locale-independent number parsing with std::from_chars. Everything works
// on [begin, end) ranges, never past them, so a truncated or corrupted file cannot be overread.
#pragma once

#include <charconv>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace polarform::io_detail {

inline bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

inline const char* skip_blanks(const char* p, const char* end) {
  while (p < end && is_blank(*p)) ++p;
  return p;
}

inline std::string_view trim(std::string_view s) {
  while (!s.empty() && is_blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_blank(s.back())) s.remove_suffix(1);
  return s;
}

// The line without a '#' comment and surrounding blanks.
inline std::string_view strip_comment(std::string_view line) {
  const std::size_t hash = line.find('#');
  return trim(hash == std::string_view::npos ? line : line.substr(0, hash));
}

// Removes and returns the next blank-separated token of `rest` (empty when none is left).
inline std::string_view next_token(std::string_view& rest) {
  std::size_t b = 0;
  while (b < rest.size() && is_blank(rest[b])) ++b;
  std::size_t e = b;
  while (e < rest.size() && !is_blank(rest[e])) ++e;
  const std::string_view token = rest.substr(b, e - b);
  rest.remove_prefix(e);
  return token;
}

// Parses a double at p (an optional leading '+' is accepted, as scanners write it); returns the
// end of the number, or nullptr if there is none or it is out of range. NaN and Inf parse.
inline const char* parse_double_prefix(const char* p, const char* end, double& value) {
  if (p < end && *p == '+' && end - p > 1 && p[1] != '-' && p[1] != '+') ++p;
  const auto [next, ec] = std::from_chars(p, end, value);
  return ec == std::errc() ? next : nullptr;
}

// True if the whole token is one number.
inline bool parse_double(std::string_view token, double& value) {
  const char* end = token.data() + token.size();
  return !token.empty() && parse_double_prefix(token.data(), end, value) == end;
}

// True if the whole token is a non-negative decimal integer that fits.
inline bool parse_count(std::string_view token, std::uint64_t& value) {
  if (token.empty()) return false;
  const char* end = token.data() + token.size();
  const auto [next, ec] = std::from_chars(token.data(), end, value);
  return ec == std::errc() && next == end;
}

// A token quoted for an error message: at most 40 characters, unprintable bytes as \xNN.
inline std::string quoted(std::string_view token) {
  static constexpr char hex[] = "0123456789abcdef";
  std::string out(1, '\'');
  for (std::size_t i = 0; i < token.size() && i < 40; ++i) {
    const auto c = static_cast<unsigned char>(token[i]);
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  if (token.size() > 40) out += "...";
  return out += '\'';
}

// Parses the next n blank-separated numbers of `rest` into out; on failure `what` says what was
// expected. Tokens after the n-th are left in `rest`.
inline bool parse_coordinates(std::string_view& rest, double* out, int n, std::string& what) {
  for (int i = 0; i < n; ++i) {
    const std::string_view token = next_token(rest);
    if (token.empty()) {
      what = "expected " + std::to_string(n) + " coordinates, found " + std::to_string(i);
      return false;
    }
    if (!parse_double(token, out[i])) {
      what = "invalid number " + quoted(token) + ": expected a decimal number";
      return false;
    }
  }
  return true;
}

// Walks an in-memory text line by line ('\n' terminated; a trailing '\r' stays on the line and
// counts as a blank). Line numbers are 1-based.
class LineCursor {
 public:
  explicit LineCursor(std::string_view text, std::size_t offset = 0, std::size_t line = 0)
      : text_(text), offset_(offset), line_(line) {}

  // The next line, or false at the end of the text.
  bool next(std::string_view& line) {
    if (offset_ >= text_.size()) return false;
    const char* begin = text_.data() + offset_;
    const std::size_t left = text_.size() - offset_;
    const auto* newline = static_cast<const char*>(std::memchr(begin, '\n', left));
    const std::size_t length = newline ? static_cast<std::size_t>(newline - begin) : left;
    line = std::string_view(begin, length);
    offset_ += newline ? length + 1 : length;
    ++line_;
    return true;
  }

  // Number of the line last returned by next().
  std::size_t line_number() const { return line_; }
  // Byte offset just past the line last returned by next().
  std::size_t offset() const { return offset_; }

 private:
  std::string_view text_;
  std::size_t offset_;
  std::size_t line_;
};

// Number of lines in the text: an upper bound on the records of a line-based format.
inline std::size_t count_lines(std::string_view text) {
  std::size_t lines = 0;
  for (const char *p = text.data(), *end = p + text.size(); p < end; ++lines) {
    const auto* newline = static_cast<const char*>(std::memchr(p, '\n', end - p));
    p = newline ? newline + 1 : end;
  }
  return lines;
}

// Number of lines whose first token is `keyword` (e.g. "v" in OBJ, "vertex" in ASCII STL).
inline std::size_t count_keyword_lines(std::string_view text, std::string_view keyword) {
  std::size_t count = 0;
  LineCursor lines(text);
  for (std::string_view line; lines.next(line);) {
    const char* p = skip_blanks(line.data(), line.data() + line.size());
    const std::string_view rest(p, line.data() + line.size() - p);
    if (rest.starts_with(keyword) &&
        (rest.size() == keyword.size() || is_blank(rest[keyword.size()])))
      ++count;
  }
  return count;
}

}  // namespace polarform::io_detail
