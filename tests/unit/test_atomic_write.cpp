// Whole-file writes (io/atomic_write.h) through a symbolic link: the file the link points to gets
// the bytes and the link stays a link (renamed over, the link became a file of its own and the
// file it named kept the old bytes: a net:save to a link "saved" nothing a reader of it sees).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "io/atomic_write.h"
#include "io/temp_dir.h"

namespace sn::io {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(f), {});
}

TEST(AtomicWrite, ThroughASymbolicLink) {
  const TempDir dir("test_atomic_write");
  const fs::path real = fs::path(dir.path()) / "sub" / "real.txt", link = fs::path(dir.path()) / "link.txt";
  fs::create_directories(real.parent_path());
  write_file_atomic(real.string(), "old");
  fs::create_symlink(fs::path("sub") / "real.txt", link);  // relative, as users make them
  write_file_atomic(link.string(), "new");
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(read(real), "new");
  write_files_atomic({{link.string(), "both"}, {(fs::path(dir.path()) / "other.txt").string(), "x"}});
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(read(real), "both");
  // The link and its target named together are one file, listed twice.
  EXPECT_THROW(write_files_atomic({{link.string(), "a"}, {real.string(), "b"}}), std::invalid_argument);
  EXPECT_EQ(read(real), "both");
}

}  // namespace
}  // namespace sn::io
