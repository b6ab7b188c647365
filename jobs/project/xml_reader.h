// Reading project XML with errors users can act on: every bad value names the file, line,
// element and attribute and says what was expected; attributes and child elements that nobody
// asked for are refused with the names that are known (or, leniently, become warnings). Built on
// tinyxml2 (line numbers from GetLineNum).
#pragma once

#include <tinyxml2.h>

#include <filesystem>
#include <initializer_list>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "jobs/project/unknown_names.h"

namespace polarform {

// An attribute or element nobody read: "file:line: unknown attribute 'x' on <cam>" and the names
// the reader knows there, "a, b".
struct UnknownName {
  std::string what;
  std::string known;
};

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
  bool has(const char* name) const;  // present and not empty; marks the name as known

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
  // A comma-separated list of numbers of any length ("0,0,0,0.5,1,1,1"), at least one.
  std::vector<double> number_list(const char* name) const;

  // Child elements by name, in document order (each marked as read, the name as known).
  std::vector<const tinyxml2::XMLElement*> children(const char* name) const;
  const tinyxml2::XMLElement* child(const char* name) const;  // the first, or null

  // Appends every attribute and child element left unread, with the names this reader asked for.
  void collect_unknown_names(std::vector<UnknownName>& unknown) const;

  [[noreturn]] void fail(const char* attribute, const std::string& expected) const;

 private:
  const char* raw(const char* name) const;

  const tinyxml2::XMLElement* e_;
  std::string file_;
  mutable std::set<std::string> read_attributes_;
  mutable std::set<std::string> asked_children_;
  mutable std::set<const tinyxml2::XMLElement*> read_children_;
};

// The root's `version`: 1 is read; a newer one only leniently, with a warning.
void check_project_version(const XmlElementReader& root, UnknownNames policy,
                           std::vector<std::string>& warnings);

// The project's length unit: units="mm|inch" on the root or on the design element (`design`, the
// same if given on both), as millimetres per unit: 1 or 25.4. Every length of the file is in it.
double read_length_unit(const XmlElementReader& root, const XmlElementReader& design);

// Settles the unknown names a reader collected: throws one InputError listing them all (refuse)
// or appends "… ignored (known here: …)" to warnings (warn).
void settle_unknown_names(const std::vector<UnknownName>& unknown, UnknownNames policy,
                          std::vector<std::string>& warnings);

}  // namespace polarform
