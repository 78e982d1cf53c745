// Whole-file writes (io/atomic_write.h): through a symbolic link the file the link points to gets
// the bytes and the link stays a link (renamed over, the link became a file of its own and the
// file it named kept the old bytes: a net:save to a link "saved" nothing a reader of it sees);
// what is not a regular file (a FIFO, a device, a pipe behind /dev/stdout) is written into, never
// replaced; the temporary file is never a planted link, fits beside any legal name, and the old
// file's permissions carry over.
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
#include "message_of.h"

namespace sn::io {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(f), {});
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

// A FIFO, a pipe or socket reached through /dev/fd or through a link to /proc/self/fd/N
// (sn.fs.write("/dev/stdout") with stdout a pipe), a character device: the bytes go into them and
// they stay what they were. They were replaced by regular files (the tester's /dev/null became one).
TEST(AtomicWrite, StreamsAndDevicesAreWrittenInto) {
  const TempDir dir("test_atomic_write");
  const fs::path fifo = fs::path(dir.path()) / "fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);  // so that the writer's open does not wait
  ASSERT_GE(reader, 0);
  write_file_atomic(fifo.string(), "through a fifo");
  EXPECT_EQ(drain(reader), "through a fifo");
  EXPECT_TRUE(S_ISFIFO(mode_of(fifo)));
  write_files_atomic({{fifo.string(), "and together"}, {(fs::path(dir.path()) / "beside.txt").string(), "a file"}});
  EXPECT_EQ(drain(reader), "and together");
  EXPECT_TRUE(S_ISFIFO(mode_of(fifo)));
  EXPECT_EQ(read(fs::path(dir.path()) / "beside.txt"), "a file");
  ::close(reader);

  int pipe_fds[2];
  ASSERT_EQ(::pipe2(pipe_fds, O_NONBLOCK | O_CLOEXEC), 0);
  const std::string fd_path = "/dev/fd/" + std::to_string(pipe_fds[1]);
  write_file_atomic(fd_path, "through /dev/fd");
  EXPECT_EQ(drain(pipe_fds[0]), "through /dev/fd");
  const fs::path link = fs::path(dir.path()) / "out";
  fs::create_symlink("/proc/self/fd/" + std::to_string(pipe_fds[1]), link);  // its target reads "pipe:[N]"
  write_file_atomic(link.string(), "through a link");
  EXPECT_EQ(drain(pipe_fds[0]), "through a link");
  EXPECT_TRUE(fs::is_symlink(link));
  ::close(pipe_fds[0]);
  ::close(pipe_fds[1]);
  int sockets[2];  // stdout may be a socket (a service's log): no path opens one, its descriptor writes
  ASSERT_EQ(::socketpair(AF_UNIX, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0, sockets), 0);
  write_file_atomic("/dev/fd/" + std::to_string(sockets[1]), "through a socket");
  EXPECT_EQ(drain(sockets[0]), "through a socket");
  ::close(sockets[0]);
  ::close(sockets[1]);

  // A copy of /dev/null, made here (never the machine's own: the old code replaced it).
  const fs::path null = fs::path(dir.path()) / "null";
  if (::mknod(null.c_str(), S_IFCHR | 0666, makedev(1, 3)) == 0 && ::access(null.c_str(), W_OK) == 0) {
    const fs::path to_null = fs::path(dir.path()) / "to_null";
    fs::create_symlink("null", to_null);
    write_file_atomic(null.string(), "gone");
    write_file_atomic(to_null.string(), "gone too");
    EXPECT_TRUE(S_ISCHR(mode_of(null)));
    EXPECT_TRUE(fs::is_symlink(to_null));
  } else {
    std::fprintf(stderr, "(no character device made here: %s; that part skipped)\n", std::strerror(errno));
  }

  // A folder and a socket cannot be written; each stays.
  EXPECT_EQ(message_of([&] { write_file_atomic(dir.path(), "x"); }), "cannot write file '" + dir.path() + "': it is a directory");
  const fs::path sock = fs::path(dir.path()) / "sock";
  const int s = ::socket(AF_UNIX, SOCK_STREAM, 0);
  sockaddr_un addr{};
  addr.sun_family = AF_UNIX;
  ASSERT_LT(sock.string().size(), sizeof addr.sun_path);
  std::strcpy(addr.sun_path, sock.c_str());
  ASSERT_EQ(::bind(s, reinterpret_cast<const sockaddr*>(&addr), sizeof addr), 0);
  EXPECT_EQ(message_of([&] { write_file_atomic(sock.string(), "x"); }),
            "cannot write file '" + sock.string() + "': No such device or address (a socket is not opened as a file)");
  EXPECT_TRUE(S_ISSOCK(mode_of(sock)));
  ::close(s);
}

// A file reached through /proc/self/fd/N or /dev/fd/N (/dev/stdout sent to a file: `shadenet
// x.lua > log`) is one this process has open: written through that descriptor, where it stands,
// as print() writes. Replaced, the process went on writing into a file no longer in any folder;
// opened anew, the bytes would go over what was printed.
TEST(AtomicWrite, OurOwnOpenFileIsWrittenWhereItStands) {
  const TempDir dir("test_atomic_write");
  const fs::path log = fs::path(dir.path()) / "log.txt";
  const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);  // as a shell's '>'
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::write(fd, "printed\n", 8), 8);
  write_file_atomic("/proc/self/fd/" + std::to_string(fd), "written\n");
  write_files_atomic({{"/dev/fd/" + std::to_string(fd), "again\n"}});
  ASSERT_EQ(::write(fd, "printed\n", 8), 8);
  struct stat st {};
  ASSERT_EQ(::fstat(fd, &st), 0);
  EXPECT_EQ(st.st_nlink, 1u);  // still the file in the folder
  EXPECT_EQ(read(log), "printed\nwritten\nagain\nprinted\n");
  ::close(fd);
}

// A dangling link: the write makes the file it names (relative to the link's folder, its folders
// too) and the link stays; a chain of links is followed, a loop is an error. The link was
// replaced by a plain file.
TEST(AtomicWrite, ADanglingLinkGetsItsTarget) {
  const TempDir dir("test_atomic_write");
  const fs::path base(dir.path());
  fs::create_directories(base / "a");
  fs::create_symlink(fs::path("..") / "b" / "new.txt", base / "a" / "link");
  fs::create_symlink(fs::path("a") / "link", base / "chain");
  write_file_atomic((base / "a" / "link").string(), "first");
  EXPECT_TRUE(fs::is_symlink(base / "a" / "link"));
  EXPECT_EQ(read(base / "b" / "new.txt"), "first");
  fs::remove(base / "b" / "new.txt");
  write_files_atomic({{(base / "chain").string(), "second"}});
  EXPECT_TRUE(fs::is_symlink(base / "chain"));
  EXPECT_TRUE(fs::is_symlink(base / "a" / "link"));
  EXPECT_EQ(read(base / "b" / "new.txt"), "second");
  fs::create_symlink("loop2", base / "loop1");
  fs::create_symlink("loop1", base / "loop2");
  EXPECT_EQ(message_of([&] { write_file_atomic((base / "loop1").string(), "x"); }),
            "cannot write file '" + (base / "loop1").string() + "': more than 40 symbolic links in a row (a loop?)");
  EXPECT_TRUE(fs::is_symlink(base / "loop1"));
}

// A rename that fails (here: a folder put in the second file's place once the temporaries are
// written) leaves the files before it new and the rest old, and no temporary; what before_renames
// removed (a dataset's old sidecar) stays removed.
TEST(AtomicWrite, ARenameThatFailsLeavesTheRestOld) {
  const TempDir dir("test_atomic_write");
  const fs::path base(dir.path()), a = base / "a", b = base / "b", side = base / "side";
  for (const auto& p : {a, side}) std::ofstream(p) << "old";
  EXPECT_EQ(message_of([&] {
              write_files_atomic({{a.string(), "new"}, {b.string(), "new"}, {side.string(), "new"}}, "file", [&] {
                fs::remove(side);
                fs::create_directories(b / "x");
              });
            }),
            "cannot write file '" + b.string() + "': Is a directory");
  EXPECT_EQ(read(a), "new");
  EXPECT_FALSE(fs::exists(side));
  for (const auto& e : fs::directory_iterator(base)) EXPECT_NE(e.path().filename().string()[0], '.') << e.path();
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
