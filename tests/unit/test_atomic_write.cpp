// Whole-file writes (io/atomic_write.h): through a symbolic link the file the link points to gets
// the bytes and the link stays a link (renamed over, the link became a file of its own and the
// file it named kept the old bytes: a net:save to a link "saved" nothing a reader of it sees); the
// temporary file is never a planted link, fits beside any legal name, and the old file's
// permissions carry over.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

#include "io/atomic_write.h"
#include "io/temp_dir.h"

namespace sn::io {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(f), {});
}

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "(no error)";
}

// What a non-blocking read end holds now.
std::string drain(int fd) {
  std::string out;
  char b[256];
  for (ssize_t n; (n = ::read(fd, b, sizeof b)) > 0;) out.append(b, std::size_t(n));
  return out;
}

mode_t mode_of(const fs::path& p) {
  struct stat st {};
  EXPECT_EQ(::lstat(p.c_str(), &st), 0) << p;
  return st.st_mode;
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

// The temporary file is created, never opened through what is there: a link planted under the
// name the writer used to pick (".NAME.tmpPID") once took the bytes to the file it named.
TEST(AtomicWrite, APlantedLinkIsNotWrittenThrough) {
  const TempDir dir("test_atomic_write");
  const fs::path base(dir.path()), victim = base / "victim", target = base / "data.txt";
  std::ofstream(victim) << "untouched";
  fs::create_symlink(victim, base / (".data.txt.tmp" + std::to_string(::getpid())));
  write_file_atomic(target.string(), "new");
  EXPECT_EQ(read(victim), "untouched");
  EXPECT_TRUE(S_ISREG(mode_of(target)));
  EXPECT_EQ(read(target), "new");
}

// Names up to NAME_MAX (255 bytes) are written, UTF-8 ones too: the temporary's name is cut to fit
// (it was 5 + digits longer than the name: ENAMETOOLONG), and stays one that
// remove_stale_temporaries knows.
TEST(AtomicWrite, LongNamesFit) {
  const TempDir dir("test_atomic_write");
  const fs::path base(dir.path());
  std::string utf8 = "x";
  while (utf8.size() + 3 <= 251) utf8 += "\xc3\xa9";  // é, two bytes: a cut may fall inside one
  for (const std::string& name : {std::string(251, 'n') + ".txt", utf8 + ".txt", std::string(255, 'm')}) {
    ASSERT_LE(name.size(), 255u);
    write_file_atomic((base / name).string(), "long");
    EXPECT_EQ(read(base / name), "long");
  }
  std::vector<std::string> temps;
  write_files_atomic({{(base / (std::string(251, 'n') + ".txt")).string(), "together"}, {(base / utf8).string(), "too"}},
                     "file", [&] {
                       for (const auto& e : fs::directory_iterator(base))
                         if (e.path().filename().string()[0] == '.') temps.push_back(e.path().filename().string());
                     });
  EXPECT_EQ(read(base / (std::string(251, 'n') + ".txt")), "together");
  ASSERT_EQ(temps.size(), 2u);
  for (const auto& t : temps) {
    EXPECT_LE(t.size(), 255u) << t;
    std::ofstream(base / t) << "left by a killed writer";
  }
  EXPECT_EQ(remove_stale_temporaries(dir.path(), 0), 2);
}

// Overwriting keeps the file's permissions and, where the writer may, its owner (a private 0600
// checkpoint became 0644, world-readable); a new file gets 0666 less the umask, as other tools
// make them.
TEST(AtomicWrite, PermissionsCarryOver) {
  const TempDir dir("test_atomic_write");
  const fs::path base(dir.path()), secret = base / "secret.bin", shared = base / "shared.txt";
  std::ofstream(secret) << "old";
  fs::permissions(secret, fs::perms::owner_read | fs::perms::owner_write);
  write_file_atomic(secret.string(), "new");
  EXPECT_EQ(mode_of(secret) & 07777, 0600u);
  std::ofstream(shared) << "old";
  fs::permissions(shared, fs::perms(0664));
  write_files_atomic({{secret.string(), "newer"}, {shared.string(), "new"}});
  EXPECT_EQ(mode_of(secret) & 07777, 0600u);
  EXPECT_EQ(mode_of(shared) & 07777, 0664u);
  EXPECT_EQ(read(secret), "newer");
  const mode_t old_mask = ::umask(0);
  write_file_atomic((base / "fresh0").string(), "x");
  ::umask(027);
  write_file_atomic((base / "fresh027").string(), "x");
  ::umask(old_mask);
  EXPECT_EQ(mode_of(base / "fresh0") & 07777, 0666u);
  EXPECT_EQ(mode_of(base / "fresh027") & 07777, 0640u);
  if (::geteuid() == 0) {  // only root may give a file away
    ASSERT_EQ(::chown(shared.c_str(), 4242, 4343), 0);
    write_file_atomic(shared.string(), "newer");
    struct stat st {};
    ASSERT_EQ(::stat(shared.c_str(), &st), 0);
    EXPECT_EQ(st.st_uid, 4242u);
    EXPECT_EQ(st.st_gid, 4343u);
    EXPECT_EQ(st.st_mode & 07777, 0664u);
  }
}

}  // namespace
}  // namespace sn::io
