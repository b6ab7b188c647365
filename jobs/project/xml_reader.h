// Reading project XML with errors users can act on: every bad value names the file, line,
// element and attribute and says what was expected; attributes and child elements that nobody
// asked for become warnings naming their line. Built on tinyxml2 (line numbers from GetLineNum).
#pragma once

#include <tinyxml2.h>

#include <filesystem>
#include <initializer_list>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace polarform {

// A parsed XML document; throws InputError naming the file and line on malformed XML.
class XmlDocument {
 public:
  explicit XmlDocument(const std::filesystem::path& file);
  // From text (file is used in messages only).
  XmlDocument(const std::string& text, std::string file);
  const tinyxml2::XMLElement* root() const { return doc_->RootElement(); }
  const std::string& file() const { return file_; }

 private:
  std::unique_ptr<tinyxml2::XMLDocument> doc_;
  std::string file_;
};

// Typed access to one element's attributes and children. Every accessor marks what it read;
// warnings() lists everything left unread.
class XmlElementReader {
 public:
  XmlElementReader(const tinyxml2::XMLElement* element, std::string file);

  const tinyxml2::XMLElement* element() const { return e_; }
  std::string where() const;  // "file:line: <name>"
  bool has(const char* name) const;

  // A finite number; with a default when absent (or empty), else required.
  double number(const char* name) const;
  double number(const char* name, double fallback) const;
  std::optional<double> optional_number(const char* name) const;
  // A number that must be > 0 (or >= 0 when allow_zero).
  double positive(const char* name, bool allow_zero = false) const;
  double positive(const char* name, double fallback, bool allow_zero = false) const;
  int integer(const char* name, int fallback) const;
  // One of the allowed words.
  std::string choice(const char* name, std::initializer_list<const char*> allowed) const;
  std::string choice(const char* name, std::initializer_list<const char*> allowed,
                     const char* fallback) const;
  std::string text(const char* name, const char* fallback) const;
  // A comma-separated list of numbers ("3,3").
  std::vector<double> numbers(const char* name, std::size_t count) const;

  // Child elements by name, in document order (each marked as read).
  std::vector<const tinyxml2::XMLElement*> children(const char* name) const;
  const tinyxml2::XMLElement* child(const char* name) const;  // the first, or null

  // "file:line: unknown attribute 'x' on <cam>" for every attribute and child left unread.
  std::vector<std::string> warnings() const;

  [[noreturn]] void fail(const char* attribute, const std::string& expected) const;

 private:
  const char* raw(const char* name) const;

  const tinyxml2::XMLElement* e_;
  std::string file_;
  mutable std::set<std::string> read_attributes_;
  mutable std::set<const tinyxml2::XMLElement*> read_children_;
};

}  // namespace polarform
