#include "live/file_watcher.h"

#include <fcntl.h>
#include <poll.h>
#include <sys/inotify.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace fs = std::filesystem;

namespace sn::live {

namespace {
std::string normal_absolute(const std::string& p) {
  std::error_code ec;
  fs::path a = fs::weakly_canonical(fs::absolute(p), ec);  // follows symlinks: the real file is watched
  if (ec) a = fs::absolute(p).lexically_normal();
  return a.string();
}
}  // namespace

FileWatcher::FileWatcher(std::function<void()> wake) : wake_(std::move(wake)) {
  inotify_ = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
  if (inotify_ < 0) throw std::runtime_error(std::string("--watch: inotify unavailable: ") + strerror(errno));
  if (pipe2(control_, O_NONBLOCK | O_CLOEXEC) != 0) {
    close(inotify_);
    throw std::runtime_error(std::string("--watch: pipe: ") + strerror(errno));
  }
  thread_ = std::thread([this] { run(); });
}

FileWatcher::~FileWatcher() {
  char q = 'q';
  (void)!write(control_[1], &q, 1);
  thread_.join();
  close(inotify_);
  close(control_[0]);
  close(control_[1]);
}

// One inotify watch per folder of a watched file, added here on the caller's thread.
void FileWatcher::watch(const std::vector<std::string>& files) {
  std::lock_guard<std::mutex> lock(mutex_);
  files_.clear();
  std::set<std::string> wanted;
  for (const auto& f : files) {
    std::string a = normal_absolute(f);
    files_.insert(a);
    wanted.insert(fs::path(a).parent_path().string());
  }
  for (auto it = watches_.begin(); it != watches_.end();) {
    if (!wanted.count(it->second)) {
      inotify_rm_watch(inotify_, it->first);
      it = watches_.erase(it);
    } else {
      wanted.erase(it->second);
      ++it;
    }
  }
  for (const auto& folder : wanted) {
    int wd = inotify_add_watch(inotify_, folder.c_str(), IN_CLOSE_WRITE | IN_MOVED_TO);
    if (wd >= 0) watches_.emplace_back(wd, folder);  // a folder that does not exist yet is skipped
  }
}

std::vector<std::string> FileWatcher::take_changed() {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<std::string> out(changed_.begin(), changed_.end());
  changed_.clear();
  return out;
}

void FileWatcher::run() {
  alignas(inotify_event) char buf[16384];
  for (;;) {
    pollfd fds[2] = {{control_[0], POLLIN, 0}, {inotify_, POLLIN, 0}};
    if (poll(fds, 2, -1) < 0) {
      if (errno == EINTR) continue;
      return;
    }
    if (fds[0].revents) return;  // the destructor's 'q'
    if (!(fds[1].revents & POLLIN)) continue;
    bool any = false;
    ssize_t n;
    while ((n = read(inotify_, buf, sizeof buf)) > 0) {
      for (char* p = buf; p < buf + n;) {
        auto* ev = reinterpret_cast<inotify_event*>(p);
        p += sizeof(inotify_event) + ev->len;
        if (!ev->len) continue;
        std::lock_guard<std::mutex> lock(mutex_);
        for (const auto& [wd, folder] : watches_) {
          if (wd != ev->wd) continue;
          std::string path = (fs::path(folder) / ev->name).string();
          if (files_.count(path)) changed_.insert(path), any = true;
        }
      }
    }
    if (any) wake_();
  }
}

}  // namespace sn::live
