// Atomic result files: the content arrives whole, parents are created, no temporary is left,
// and an impossible path fails with its name.
#include "core/file_io.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.h"

namespace rearm {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(FileIo, WritesAndReplacesAtomically) {
  const fs::path dir = fs::temp_directory_path() / "rearm_file_io_test" / "a" / "b";
  fs::remove_all(dir.parent_path().parent_path());
  const fs::path file = dir / "out.json";
  write_file_atomically(file.string(), "first");
  EXPECT_EQ(read(file), "first");
  write_file_atomically(file.string(), std::string("second\0x", 8));
  EXPECT_EQ(read(file), std::string("second\0x", 8));
  EXPECT_FALSE(fs::exists(file.string() + ".tmp"));
  fs::remove_all(dir.parent_path().parent_path());
}

TEST(FileIo, ImpossiblePathNamesIt) {
  const fs::path blocker = fs::temp_directory_path() / "rearm_file_io_blocker";
  { std::ofstream(blocker) << "x"; }
  try {
    write_file_atomically((blocker / "sub" / "f.json").string(), "x");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("rearm_file_io_blocker"), std::string::npos) << e.what();
  }
  fs::remove(blocker);
}

}  // namespace
}  // namespace rearm
