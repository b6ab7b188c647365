// The --script runner of the app shell (part of App, app.h): each parsed action is carried out
// through the code of the menus, shortcuts and window events it stands for, and the app renders
// until the background work has settled before the next one.
#include <algorithm>
#include <iostream>

#include "src/error.h"
#include "ui/studio/app.h"
#include "ui/studio/template_picker.h"

namespace polarform::studio {

int App::run_script() {
  std::vector<ScriptAction> script;
  try {
    script = read_script(*options_.script);
  } catch (const InputError& e) {
    std::cerr << "polarform-studio: " << e.what() << "\n";
    return 2;
  }
  settle();
  const std::size_t errors_before = log_.error_count();
  for (const ScriptAction& action : script) {
    std::cout << "script " << options_.script->filename().string() << ":" << action.line << ": "
              << action.text << "\n";
    run_action(action);
    if (!settle())
      log_.error("Script line " + std::to_string(action.line) +
                 ": the computations did not settle within 10 minutes");
  }
  std::cout << "errors: " << log_.error_count() << "\n";
  return log_.error_count() == errors_before ? 0 : 1;
}

void App::run_action(const ScriptAction& action) {
  const auto& args = action.arguments;
  const std::string where = "Script line " + std::to_string(action.line) + ": ";
  const std::string here = "the " + std::string(workspace_name(active_)) + " workspace";
  switch (action.verb) {
    case ScriptVerb::open:
      open_document(args[0]);
      break;
    case ScriptVerb::drop:
      window_->drop({args.begin(), args.end()});
      break;
    case ScriptVerb::new_from_template:
      open_template(*parse_workspace(args[0]), args[1], where);
      break;
    case ScriptVerb::workspace:
      if (const Workspace* w = workspace(*parse_workspace(args[0])))
        select_tab_ = active_ = w->kind();
      else
        log_.error(where + "the " + args[0] + " workspace is not part of this build");
      break;
    case ScriptVerb::edit:
      if (!active().scripted_edit()) log_.error(where + here + " has nothing a script can edit");
      break;
    case ScriptVerb::undo:
      if (active().can_undo())
        active().undo();
      else
        log_.error(where + "nothing to undo in " + here);
      break;
    case ScriptVerb::redo:
      if (active().can_redo())
        active().redo();
      else
        log_.error(where + "nothing to redo in " + here);
      break;
    case ScriptVerb::save:
      if (!active().can_save())
        log_.error(where + here + " has nothing to save");
      else if (active().document_path().empty())
        log_.error(where + active().document_name() + " has no file yet: use save-as PATH");
      else
        save(false);
      break;
    case ScriptVerb::save_as:
      if (!active().can_save())
        log_.error(where + here + " has nothing to save");
      else if (active().save(args[0]))
        state_.remember(args[0], active_);
      break;
    case ScriptVerb::export_file:
      export_by_tag(args[0], args[1], where);
      break;
    case ScriptVerb::screenshot:
      screenshot(args[0]);
      break;
    case ScriptVerb::numbers:
      std::cout << (args.empty() ? "numbers" : args[0]) << ":\n" << active().numbers();
      break;
  }
}

void App::open_template(WorkspaceKind kind, const std::string& name, const std::string& where) {
  const Workspace* w = workspace(kind);
  const auto templates = w ? list_templates(context_.examples / w->template_folder())
                           : std::vector<std::filesystem::path>{};
  const auto found = std::find_if(templates.begin(), templates.end(),
                                  [&](const auto& f) { return f.stem() == name; });
  if (found != templates.end()) return open_document(*found, true);
  std::string names;
  for (const auto& f : templates) names += " " + f.stem().string();
  log_.error(where + "no " + std::string(workspace_name(kind)) + " template '" + name +
             "' (templates:" + names + ")");
}

void App::export_by_tag(const std::string& tag, const std::filesystem::path& path,
                        const std::string& where) {
  const auto choices = active().export_choices();
  const auto choice = std::find_if(choices.begin(), choices.end(),
                                   [&](const ExportChoice& c) { return c.request.tag == tag; });
  if (choice == choices.end()) {
    std::string tags;
    for (const auto& c : choices) tags += " " + c.request.tag;
    log_.error(where + "the " + std::string(workspace_name(active_)) +
               " workspace has no export '" + tag + "' (exports:" + tags + ")");
  } else if (!choice->enabled) {
    log_.error(where + "export " + tag + " is not available now" +
               (choice->tooltip.empty() ? "" : ": " + choice->tooltip));
  } else {
    active().export_to(choice->request, path);
  }
}

}  // namespace polarform::studio
