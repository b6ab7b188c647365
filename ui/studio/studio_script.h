// The --script of polarform-studio: actions run in order on the live app, through the same code as
// its menus, shortcuts and window events, each followed by frames until the computations settle.
// One action per line; '#' starts a comment; arguments are separated by blanks and a path with
// blanks is written in double quotes. Relative paths are resolved against the script's folder.
//
//   open PATH              File ▸ Open (a project or a point cloud)
//   drop PATH…             files dropped on the window
//   template KIND NAME     File ▸ New from template (KIND cam or vessel, NAME as in examples/)
//   workspace KIND         switch to the cam, study, vessel or fit workspace
//   edit                   the workspace's scripted edit, as one undoable step (cam and vessel:
//                          the --bench-frames edit; fit: a coarser net, fitted again)
//   undo / redo            Edit ▸ Undo / Redo
//   save                   File ▸ Save (the document must have a file)
//   save-as PATH           File ▸ Save as
//   export TAG PATH        File ▸ Export; TAG names the item (all, iges, step, dxf, x3d, csv,
//                          study)
//   screenshot PATH        the window as it is now, to a PNG
//   numbers [LABEL]        print the workspace's key numbers under "LABEL:" (default "numbers:")
#pragma once

#include <filesystem>
#include <istream>
#include <string>
#include <vector>

namespace polarform::studio {

enum class ScriptVerb {
  open,
  drop,
  new_from_template,
  workspace,
  edit,
  undo,
  redo,
  save,
  save_as,
  export_file,
  screenshot,
  numbers
};

struct ScriptAction {
  ScriptVerb verb = ScriptVerb::numbers;
  std::vector<std::string> arguments;  // paths resolved against the script's folder
  int line = 0;
  std::string text;  // the line as written, without comment and outer blanks
};

// Parses a whole script before anything runs. Throws InputError "FILE:LINE: …" for an unknown
// action, a wrong number of arguments, an unknown workspace or an unterminated quote.
std::vector<ScriptAction> parse_script(std::istream& in, const std::filesystem::path& file);

// Reads and parses `file`; InputError also when it cannot be read.
std::vector<ScriptAction> read_script(const std::filesystem::path& file);

}  // namespace polarform::studio
