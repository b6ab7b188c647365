#include "ui/studio/studio_script.h"

#include <fstream>
#include <limits>
#include <optional>
#include <string_view>

#include "src/error.h"
#include "ui/studio/workspace_kind.h"

namespace polarform::studio {
namespace {

constexpr int kMany = std::numeric_limits<int>::max();

// How an action is written: its name, how many arguments it takes, and which of them are paths
// (all from `first_path` on; -1 for none).
struct VerbSyntax {
  std::string_view name;
  ScriptVerb verb;
  int min_arguments, max_arguments;
  int first_path;
  std::string_view usage;
};

constexpr VerbSyntax kVerbs[] = {
    {"open", ScriptVerb::open, 1, 1, 0, "open PATH"},
    {"drop", ScriptVerb::drop, 1, kMany, 0, "drop PATH…"},
    {"template", ScriptVerb::new_from_template, 2, 2, -1, "template cam|vessel NAME"},
    {"workspace", ScriptVerb::workspace, 1, 1, -1, "workspace cam|study|vessel|fit"},
    {"edit", ScriptVerb::edit, 0, 0, -1, "edit"},
    {"undo", ScriptVerb::undo, 0, 0, -1, "undo"},
    {"redo", ScriptVerb::redo, 0, 0, -1, "redo"},
    {"save", ScriptVerb::save, 0, 0, -1, "save"},
    {"save-as", ScriptVerb::save_as, 1, 1, 0, "save-as PATH"},
    {"export", ScriptVerb::export_file, 2, 2, 1, "export TAG PATH"},
    {"screenshot", ScriptVerb::screenshot, 1, 1, 0, "screenshot PATH"},
    {"numbers", ScriptVerb::numbers, 0, 1, -1, "numbers [LABEL]"},
};

std::string known_actions() {
  std::string list;
  for (const VerbSyntax& v : kVerbs) list += (list.empty() ? "" : ", ") + std::string(v.name);
  return list;
}

std::string argument_count(const VerbSyntax& v) {
  const std::string min = std::to_string(v.min_arguments);
  if (v.max_arguments == kMany) return "at least " + min;
  if (v.max_arguments == v.min_arguments) return min;
  return min + " to " + std::to_string(v.max_arguments);
}

// The line without its comment, split at blanks; "…" groups a token with blanks.
std::vector<std::string> tokens(const std::string& line, const std::string& where) {
  std::vector<std::string> out;
  std::size_t i = 0;
  while (i < line.size()) {
    const char c = line[i];
    if (c == '#') break;
    if (c == ' ' || c == '\t' || c == '\r') {
      ++i;
      continue;
    }
    if (c == '"') {
      const std::size_t close = line.find('"', i + 1);
      if (close == std::string::npos) throw InputError(where + ": unterminated quote");
      out.push_back(line.substr(i + 1, close - i - 1));
      i = close + 1;
      continue;
    }
    const std::size_t end = line.find_first_of(" \t\r#\"", i);
    out.push_back(line.substr(i, end == std::string::npos ? std::string::npos : end - i));
    i = end == std::string::npos ? line.size() : end;
  }
  return out;
}

std::string trimmed(const std::string& line) {
  std::string s = line.substr(0, line.find('#'));
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

}  // namespace

std::vector<ScriptAction> parse_script(std::istream& in, const std::filesystem::path& file) {
  std::vector<ScriptAction> actions;
  const std::filesystem::path folder = file.parent_path();
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::string where = file.string() + ":" + std::to_string(number);
    std::vector<std::string> words = tokens(line, where);
    if (words.empty()) continue;
    const VerbSyntax* syntax = nullptr;
    for (const VerbSyntax& v : kVerbs)
      if (v.name == words.front()) syntax = &v;
    if (!syntax)
      throw InputError(where + ": unknown action '" + words.front() + "' (known: " +
                       known_actions() + ")");
    ScriptAction action{syntax->verb, {words.begin() + 1, words.end()}, number, trimmed(line)};
    const int count = static_cast<int>(action.arguments.size());
    if (count < syntax->min_arguments || count > syntax->max_arguments)
      throw InputError(where + ": " + std::string(syntax->name) + " takes " +
                       argument_count(*syntax) + " argument(s), got " + std::to_string(count) +
                       " (usage: " + std::string(syntax->usage) + ")");
    for (const std::string& a : action.arguments)
      if (a.empty()) throw InputError(where + ": an empty argument (\"\")");
    if (syntax->first_path >= 0)
      for (int k = syntax->first_path; k < count; ++k) {
        const std::filesystem::path p(action.arguments[k]);
        if (p.is_relative()) action.arguments[k] = (folder / p).lexically_normal().string();
      }
    const auto kind = syntax->verb == ScriptVerb::workspace ||
                              syntax->verb == ScriptVerb::new_from_template
                          ? parse_workspace(action.arguments.front())
                          : std::optional<WorkspaceKind>{};
    if (syntax->verb == ScriptVerb::workspace && !kind)
      throw InputError(where + ": unknown workspace '" + action.arguments.front() +
                       "' (cam, study, vessel or fit)");
    if (syntax->verb == ScriptVerb::new_from_template &&
        (!kind || (*kind != WorkspaceKind::cam && *kind != WorkspaceKind::vessel)))
      throw InputError(where + ": templates are cam or vessel designs, not '" +
                       action.arguments.front() + "'");
    actions.push_back(std::move(action));
  }
  return actions;
}

std::vector<ScriptAction> read_script(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw InputError(file.string() + ": cannot read the script");
  return parse_script(in, file);
}

}  // namespace polarform::studio
