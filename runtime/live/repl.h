// The console of live mode: lines from stdin go into a queue (the loop is woken by `wake`); the
// main loop takes them and runs each in the script's Lua state, printing results as the
// standalone lua interpreter does. A line that ends inside a statement waits for the next.
//
// At a terminal the line is edited with libedit (BSD licence, readline's API: arrows, Ctrl-A/E,
// history search) and the history is kept across sessions in a file (history_path()). The
// reader thread then only watches stdin and wakes the loop; libedit runs on the loop's thread,
// so editing, prompts and the loop's own output never race. A pipe (the tests) is read as plain
// lines by the thread.
#pragma once
#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

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
  // True once per Ctrl-D on an empty line at a terminal: the console goes on reading (the loop
  // decides whether the session ends).
  bool take_ctrl_d();
  static bool interactive();  // stdin is a terminal (prompts are printed only then)
  // At a terminal: shows `text` and lets the user edit the next line (nothing otherwise).
  void prompt(const char* text);

  // The history file: $SHADENET_HISTORY (empty: none), else $XDG_STATE_HOME/shadenet/history,
  // else ~/.shadenet_history.
  static std::string history_path();

 private:
  void run();
  void edit();  // feeds the typed characters to libedit (loop thread)
  void hold_line_buffer();  // before each character fed to libedit: see repl.cpp
  std::function<void()> wake_;
  bool editing_ = false;  // a terminal: libedit reads, the thread only polls
  bool ready_ = false;    // (editing) stdin has characters the loop has not fed to libedit yet
  bool line_open_ = false;  // (editing) a prompt is shown and libedit is reading its line
  std::condition_variable consumed_;
  std::string history_;
  std::vector<char> line_buffer_;  // (editing) what libedit's rl_line_buffer points to
  std::size_t longest_ = 0;        // (editing) the longest line of the history or edited so far
  int control_[2] = {-1, -1};
  std::mutex mutex_;
  std::deque<std::string> lines_;
  bool eof_ = false;
  bool ctrl_d_ = false;
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
  // The last chunk was an expression whose values were printed (a query such as
  // `net:trained_steps()`), not a statement that may have changed something.
  bool printed_values() const { return printed_values_; }
  const char* prompt() const { return continuing() ? ">> " : "> "; }

 private:
  lua_State* L_;
  std::function<bool(lua_State*)> prepare_;
  std::string buffer_;
  bool printed_values_ = false;
};

}  // namespace sn::live
