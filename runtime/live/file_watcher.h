// Watches files for saves on a thread of its own (inotify on their folders, so editors that
// save by writing a new file and renaming it are seen too). The thread only records which
// files changed and calls `wake`; every reload, Lua and GL call stays on the main thread.
#pragma once
#include <functional>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

namespace sn::live {

class FileWatcher {
 public:
  // Throws when inotify is unavailable. `wake` runs on the watcher thread.
  explicit FileWatcher(std::function<void()> wake);
  ~FileWatcher();  // stops and joins the thread
  FileWatcher(const FileWatcher&) = delete;
  FileWatcher& operator=(const FileWatcher&) = delete;

  // Replaces the set of watched files (made absolute; they need not exist yet). Every save after
  // it returns is seen: the watches are in place (a watch the thread added later missed a save
  // made in between, and a session stayed on its broken first run).
  void watch(const std::vector<std::string>& files);
  // The watched files written (closed after writing) or renamed into place since the last call.
  std::vector<std::string> take_changed();

 private:
  void run();

  std::function<void()> wake_;
  int inotify_ = -1, control_[2] = {-1, -1};
  std::mutex mutex_;
  std::set<std::string> files_, changed_;
  std::vector<std::pair<int, std::string>> watches_;  // inotify descriptor, folder (under mutex_)
  std::thread thread_;
};

}  // namespace sn::live
