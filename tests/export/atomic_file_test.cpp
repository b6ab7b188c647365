// Atomic output: a failing writer leaves the previous file intact and no temporary behind; a job's
// outputs are one transaction — a folder either gets every new file or stays exactly as it was,
// whichever step fails (a writer, a directory in the way of a target, a rename), and nothing
// hidden is left behind.
#include "export/atomic_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "src/error.h"

namespace polarform {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(AtomicFile, ReplacesOnSuccessKeepsOldOnFailure) {
  const fs::path dir =
      fs::temp_directory_path() / ("polarform_atomic_test_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path file = dir / "out.txt";
  write_file_atomically(file, "first");
  EXPECT_EQ(read(file), "first");
  EXPECT_THROW(write_file_atomically(file,
                                     [](std::ostream& out) {
                                       out << "partial";
                                       throw InputError("writer failed");
                                     }),
               InputError);
  EXPECT_EQ(read(file), "first");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}), 1);
  write_file_atomically(file, [](std::ostream& out) { out << 0.1; });
  EXPECT_EQ(read(file), "0.1");
  EXPECT_THROW(write_file_atomically(dir / "missing" / "x.txt", "x"), InputError);
  fs::remove_all(dir);
}

// Every file of a folder (hidden ones included) with its content; a sub-folder as "<dir>".
std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> out;
  for (const auto& e : fs::directory_iterator(dir))
    out[e.path().filename().string()] = fs::is_directory(e) ? "<dir>" : read(e.path());
  return out;
}

class OutputTransactionTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("polarform_transaction_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    write_files_atomically(dir_, {{"a.txt", "old a"}, {"c.txt", "old c"}, {"keep.txt", "mine"}});
    before_ = snapshot(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
  std::map<std::string, std::string> before_;
};

TEST_F(OutputTransactionTest, CommitReplacesAndAddsAndLeavesNothingHidden) {
  OutputTransaction t(dir_);
  t.add("a.txt", "new a");
  t.add("b.txt", [](std::ostream& out) { out << 0.25; });
  t.add("c.txt", "new c");
  EXPECT_EQ(snapshot(dir_).size(), 6u);  // three temporaries beside the old files
  t.commit();
  EXPECT_EQ(snapshot(dir_),
            (std::map<std::string, std::string>{
                {"a.txt", "new a"}, {"b.txt", "0.25"}, {"c.txt", "new c"}, {"keep.txt", "mine"}}));
}

TEST_F(OutputTransactionTest, DirectoryInTheWayChangesNothing) {
  fs::create_directory(dir_ / "b.txt");
  before_ = snapshot(dir_);
  OutputTransaction t(dir_);
  t.add("a.txt", "new a");
  t.add("b.txt", "new b");
  t.add("c.txt", "new c");
  try {
    t.commit();
    FAIL() << "committed over a directory";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("b.txt"), std::string::npos) << e.what();
  }
  EXPECT_EQ(snapshot(dir_), before_);
}

// A rename that fails after others succeeded (here: the last file's temporary has gone) undoes
// the ones before it: the replaced files come back, the new ones go.
TEST_F(OutputTransactionTest, FailureInTheMiddleOfTheRenamesRestoresTheFolder) {
  OutputTransaction t(dir_);
  t.add("a.txt", "new a");
  t.add("b.txt", "new b");
  t.add("c.txt", "new c");
  for (const auto& e : fs::directory_iterator(dir_))
    if (e.path().filename().string().rfind(".c.txt.tmp", 0) == 0) fs::remove(e.path());
  EXPECT_THROW(t.commit(), InputError);
  EXPECT_EQ(snapshot(dir_), before_);
}

TEST_F(OutputTransactionTest, AFailingWriterOrNoCommitChangesNothing) {
  {
    OutputTransaction t(dir_);
    t.add("a.txt", "new a");
    EXPECT_THROW(t.add("c.txt",
                       [](std::ostream& out) {
                         out << "partial";
                         throw InputError("disk full");
                       }),
                 InputError);
  }  // not committed
  EXPECT_EQ(snapshot(dir_), before_);
  // A folder the transaction made goes again; a file in the way of the folder is named.
  const fs::path fresh = dir_ / "fresh";
  {
    OutputTransaction t(fresh);
    t.add("x.txt", "x");
  }
  EXPECT_FALSE(fs::exists(fresh));
  try {
    OutputTransaction t(dir_ / "keep.txt");
    FAIL() << "a file taken for the output folder";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("a file of that name is in the way"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace polarform
