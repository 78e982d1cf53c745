// The console of live mode: a thread reads lines from stdin into a queue (and calls `wake`);
// the main loop takes them and runs each in the script's Lua state, printing results as the
// standalone lua interpreter does. A line that ends inside a statement waits for the next.
#pragma once
#include <deque>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

#include <lua.hpp>

namespace sn::live {

class StdinReader {
 public:
  explicit StdinReader(std::function<void()> wake);  // starts reading fd 0
  ~StdinReader();  // stops and joins (does not close stdin)
  StdinReader(const StdinReader&) = delete;
  StdinReader& operator=(const StdinReader&) = delete;

  bool take(std::string& line);  // the next complete line, without its newline
  bool at_end();  // stdin was closed and every line was taken
  static bool interactive();  // stdin is a terminal (prompts are printed only then)

 private:
  void run();
  std::function<void()> wake_;
  int control_[2] = {-1, -1};
  std::mutex mutex_;
  std::deque<std::string> lines_;
  bool eof_ = false;
  std::thread thread_;
};

// Runs console lines in L. Accumulates lines while the chunk is incomplete (Lua reports
// "<eof>"); returns true when a chunk ran (successfully or not), false while it waits for more.
// Each chunk runs in the environment `prepare` leaves on the stack, if one is given (live mode:
// the globals plus the script's top-level locals).
class Console {
 public:
  explicit Console(lua_State* L, std::function<bool(lua_State*)> prepare = {}) : L_(L), prepare_(std::move(prepare)) {}
  // Returns false while the chunk is incomplete; `ok` tells whether a finished chunk ran without error.
  bool execute(const std::string& line, bool* ok = nullptr);
  bool continuing() const { return !buffer_.empty(); }
  void prompt() const;  // "> " or ">> " on a terminal, nothing otherwise

 private:
  lua_State* L_;
  std::function<bool(lua_State*)> prepare_;
  std::string buffer_;
};

}  // namespace sn::live
