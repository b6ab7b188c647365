// Atomic output: a failing writer leaves the previous file intact and no temporary behind.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "export/atomic_file.h"
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
  const fs::path dir = fs::temp_directory_path() / "polarform_atomic_test";
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

}  // namespace
}  // namespace polarform
