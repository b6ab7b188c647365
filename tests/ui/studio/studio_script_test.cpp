// The --script parser of polarform-studio: every action read with its arguments, comments, blank
// lines and quoted paths, relative paths resolved against the script's folder, and a table of bad
// lines refused with "FILE:LINE: …" before anything runs.
#include "ui/studio/studio_script.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "src/error.h"

namespace polarform::studio {
namespace {

const std::filesystem::path kScript = "/work/jobs/session.txt";

std::vector<ScriptAction> parse(const std::string& text) {
  std::istringstream in(text);
  return parse_script(in, kScript);
}

TEST(StudioScript, ReadsEveryAction) {
  const auto actions = parse(R"(# set up
open cams/roller.xml
drop /data/a.xyz "/data/b c.ply"
template cam roller
workspace vessel
edit
undo
redo
save
save-as "out/my cam.xml"   # a path with a blank
export iges /abs/profile.igs
screenshot shot.png
numbers after-edit
numbers
)");
  ASSERT_EQ(actions.size(), 13u);
  const std::vector<ScriptVerb> verbs = {
      ScriptVerb::open,       ScriptVerb::drop,        ScriptVerb::new_from_template,
      ScriptVerb::workspace,  ScriptVerb::edit,        ScriptVerb::undo,
      ScriptVerb::redo,       ScriptVerb::save,        ScriptVerb::save_as,
      ScriptVerb::export_file, ScriptVerb::screenshot, ScriptVerb::numbers,
      ScriptVerb::numbers};
  for (std::size_t i = 0; i < verbs.size(); ++i) EXPECT_EQ(actions[i].verb, verbs[i]) << i;
  EXPECT_EQ(actions[0].line, 2);
  EXPECT_EQ(actions[0].arguments, std::vector<std::string>{"/work/jobs/cams/roller.xml"});
  EXPECT_EQ(actions[1].arguments, (std::vector<std::string>{"/data/a.xyz", "/data/b c.ply"}));
  EXPECT_EQ(actions[2].arguments, (std::vector<std::string>{"cam", "roller"}));  // not paths
  EXPECT_EQ(actions[3].arguments, std::vector<std::string>{"vessel"});
  EXPECT_TRUE(actions[4].arguments.empty());
  EXPECT_EQ(actions[8].arguments, std::vector<std::string>{"/work/jobs/out/my cam.xml"});
  EXPECT_EQ(actions[8].text, "save-as \"out/my cam.xml\"");
  EXPECT_EQ(actions[9].arguments, (std::vector<std::string>{"iges", "/abs/profile.igs"}));
  EXPECT_EQ(actions[10].arguments, std::vector<std::string>{"/work/jobs/shot.png"});
  EXPECT_EQ(actions[11].arguments, std::vector<std::string>{"after-edit"});
  EXPECT_TRUE(actions[12].arguments.empty());
  EXPECT_EQ(actions[12].line, 14);
}

TEST(StudioScript, EmptyScriptsHaveNoActions) {
  EXPECT_TRUE(parse("").empty());
  EXPECT_TRUE(parse("\n  \n# only a comment\n\t\r\n").empty());
}

TEST(StudioScript, RefusesBadLinesNamingFileAndLine) {
  struct Case {
    std::string text, message;
  };
  const Case cases[] = {
      {"frobnicate", ":1: unknown action 'frobnicate' (known: open, drop,"},
      {"numbers\nOpen x.xml", ":2: unknown action 'Open'"},
      {"open", ":1: open takes 1 argument(s), got 0 (usage: open PATH)"},
      {"open a.xml b.xml", ":1: open takes 1 argument(s), got 2"},
      {"drop", ":1: drop takes at least 1 argument(s), got 0"},
      {"edit 3", ":1: edit takes 0 argument(s), got 1"},
      {"undo now", ":1: undo takes 0 argument(s), got 1"},
      {"export iges", ":1: export takes 2 argument(s), got 1 (usage: export TAG PATH)"},
      {"numbers a b", ":1: numbers takes 0 to 1 argument(s), got 2"},
      {"workspace cams", ":1: unknown workspace 'cams'"},
      {"template fit sphere", ":1: templates are cam or vessel designs, not 'fit'"},
      {"template cam", ":1: template takes 2 argument(s), got 1"},
      {"save-as \"out/x.xml", ":1: unterminated quote"},
      {"save-as \"\"", ":1: an empty argument"},
      {"\n\n# fine so far\nscreenshot", ":4: screenshot takes 1 argument(s), got 0"},
  };
  for (const Case& c : cases) {
    try {
      parse(c.text);
      ADD_FAILURE() << "accepted: " << c.text;
    } catch (const InputError& e) {
      EXPECT_THAT(e.what(), testing::HasSubstr(kScript.string() + c.message)) << c.text;
    }
  }
}

TEST(StudioScript, UnreadableFileIsAnInputError) {
  EXPECT_THROW(read_script("/no/such/script.txt"), InputError);
}

}  // namespace
}  // namespace polarform::studio
