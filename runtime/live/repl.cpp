#include "live/repl.h"

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <utility>

#include <editline/readline.h>

#include "io/atomic_write.h"
#include "io/read_file.h"
#include "io/temp_dir.h"

namespace sn::live {

namespace {
StdinReader* g_editing = nullptr;  // libedit's line callback takes no user data

// Saves the history whole or not at all: libedit writes a file in place, and a full disk left
// the history cut mid-line. It writes into a private scratch folder instead; what it wrote is
// kept only when it holds every entry (its header and one ended line each), and goes to its place
// as every file shadenet writes does (io::write_file_atomic: a fresh temporary, permissions kept,
// flushed, renamed). A failure leaves the old file and says so once.
void save_history(const std::string& path) {
  static bool warned = false;
  std::string why;
  try {
    const io::TempDir scratch("history");
    const std::string written = scratch.path() + "/history";
    if (write_history(written.c_str()) != 0) throw std::runtime_error("libedit could not write it");
    const std::string bytes = io::read_file(written, "history");
    const auto lines = std::count(bytes.begin(), bytes.end(), '\n');
    if (bytes.empty() || bytes.back() != '\n' || lines != history_length + 1)
      throw std::runtime_error("libedit wrote it short (a full disk?)");
    io::write_file_atomic(path, bytes, "the console history");
    return;
  } catch (const std::exception& e) {
    why = e.what();
  }
  if (!warned) std::fprintf(stderr, "\n[live] cannot save the console history to %s (%s); the old file stays\n", path.c_str(), why.c_str());
  warned = true;
}
}  // namespace

std::string StdinReader::history_path() {
  if (const char* p = getenv("SHADENET_HISTORY")) return p;
  if (const char* state = getenv("XDG_STATE_HOME"); state && *state) {
    std::error_code ec;
    std::filesystem::create_directories(std::string(state) + "/shadenet", ec);
    return std::string(state) + "/shadenet/history";
  }
  const char* home = getenv("HOME");
  return home && *home ? std::string(home) + "/.shadenet_history" : "";
}

StdinReader::StdinReader(std::function<void()> wake) : wake_(std::move(wake)) {
  editing_ = isatty(0) && isatty(1) && !g_editing;
  if (editing_) {
    g_editing = this;
    history_ = history_path();
    using_history();
    stifle_history(1000);
    if (!history_.empty()) read_history(history_.c_str());
    for (int i = 0; i < history_length; ++i)
      if (HIST_ENTRY* h = history_get(history_base + i); h && h->line) longest_ = std::max(longest_, std::strlen(h->line));
  }
  if (pipe2(control_, O_CLOEXEC) != 0) control_[0] = control_[1] = -1;
  thread_ = std::thread([this] { run(); });
}

StdinReader::~StdinReader() {
  char q = 'q';
  if (control_[1] >= 0) (void)!write(control_[1], &q, 1);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    ready_ = false;  // a thread waiting for the loop to take what it saw stops waiting
  }
  consumed_.notify_one();
  thread_.join();
  if (control_[0] >= 0) close(control_[0]), close(control_[1]);
  if (editing_) {
    if (line_open_) rl_callback_handler_remove();  // the terminal goes back to its own mode
    g_editing = nullptr;
  }
}

void StdinReader::prompt(const char* text) {
  if (!editing_) {
    if (interactive()) fputs(text, stdout), fflush(stdout);
    return;
  }
  if (line_open_) return;
  fflush(stdout);
  // Shows the prompt; libedit then reads the line a character at a time (edit()).
  rl_callback_handler_install(text, [](char* line) {
    StdinReader* self = g_editing;
    if (!self) return free(line);
    self->line_open_ = false;  // libedit left its reading mode: no character is fed until the next prompt
    std::lock_guard<std::mutex> lock(self->mutex_);
    if (!line) {  // Ctrl-D on an empty line: the loop asks before it ends the session
      self->ctrl_d_ = true;
      return;
    }
    std::string s = line;
    free(line);
    self->longest_ = std::max(self->longest_, s.size());
    if (s.find_first_not_of(" \t") != std::string::npos) {
      add_history(s.c_str());
      if (!self->history_.empty()) save_history(self->history_);
    }
    self->lines_.push_back(std::move(s));
  });
  line_open_ = true;
  std::lock_guard<std::mutex> lock(mutex_);
  if (ready_) wake_();  // characters typed while the last line ran
}

// libedit 3.1 (Debian 12's) points rl_line_buffer at the buffer its line is converted into, once,
// and after each character writes the line's end there (rl_line_buffer[rl_end] = 0); a line past
// 1,020 bytes moves that buffer, and the write went to freed memory: a pasted long line crashed
// the session ("malloc(): invalid next size"). It points at a buffer of ours instead, kept longer
// than any line one character can make: the line so far plus the longest it may recall or yank.
void StdinReader::hold_line_buffer() {
  const std::size_t need = 2 * (std::size_t(std::max(rl_end, 0)) + longest_) + 4096;
  if (line_buffer_.size() < need) line_buffer_.assign(need, '\0');
  rl_line_buffer = line_buffer_.data();
}

void StdinReader::edit() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!ready_ || !line_open_) return;  // nothing typed, or no line being edited yet
  }
  bool hangup = false;
  for (;;) {  // every character already typed, never waiting for more
    pollfd fd = {0, POLLIN, 0};
    if (!line_open_ || poll(&fd, 1, 0) <= 0) break;
    if (!(fd.revents & POLLIN)) {
      hangup = fd.revents & (POLLHUP | POLLERR | POLLNVAL);
      break;
    }
    hold_line_buffer();
    rl_callback_read_char();
    longest_ = std::max(longest_, std::size_t(std::max(rl_end, 0)));
  }
  std::lock_guard<std::mutex> lock(mutex_);
  if (hangup) eof_ = true;
  ready_ = false;
  consumed_.notify_one();
}

bool StdinReader::interactive() { return isatty(0); }

bool StdinReader::take(std::string& line) {
  if (editing_) edit();
  std::lock_guard<std::mutex> lock(mutex_);
  if (lines_.empty()) return false;
  line = std::move(lines_.front());
  lines_.pop_front();
  return true;
}

bool StdinReader::take_ctrl_d() {
  if (editing_) edit();
  std::lock_guard<std::mutex> lock(mutex_);
  return std::exchange(ctrl_d_, false);
}

bool StdinReader::at_end() {
  std::lock_guard<std::mutex> lock(mutex_);
  return eof_ && lines_.empty();
}

void StdinReader::run() {
  std::string partial;
  char buf[4096];
  auto finish = [&] {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!partial.empty()) lines_.push_back(partial);
    eof_ = true;
  };
  for (;;) {
    // poll, not a blocking read: the destructor must be able to stop the thread.
    pollfd fds[2] = {{0, POLLIN, 0}, {control_[0], POLLIN, 0}};
    if (poll(fds, control_[0] >= 0 ? 2 : 1, -1) < 0) {
      if (errno == EINTR) continue;
      return finish(), wake_();
    }
    if (fds[1].revents) return;
    if (fds[0].revents & POLLNVAL) return finish(), wake_();
    if (editing_) {  // the loop's thread feeds the characters to libedit; wait until it has
      std::unique_lock<std::mutex> lock(mutex_);
      ready_ = true;
      lock.unlock();
      wake_();
      lock.lock();
      consumed_.wait(lock, [&] { return !ready_ || eof_; });
      if (eof_) return;
      continue;
    }
    ssize_t n = read(0, buf, sizeof buf);
    if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
    // At a terminal a read of nothing is Ctrl-D (a hang-up reads as an error, or ends the process);
    // elsewhere it is the end of the input.
    if (n == 0 && interactive() && !(fds[0].revents & POLLHUP)) {
      if (!partial.empty()) {  // Ctrl-D after text ends that line, as a terminal does
        std::lock_guard<std::mutex> lock(mutex_);
        lines_.push_back(std::move(partial));
        partial.clear();
      } else {
        std::lock_guard<std::mutex> lock(mutex_);
        ctrl_d_ = true;
      }
      wake_();
      continue;
    }
    if (n <= 0) return finish(), wake_();
    partial.append(buf, size_t(n));
    bool any = false;
    for (size_t nl; (nl = partial.find('\n')) != std::string::npos;) {
      std::string line = partial.substr(0, nl);
      if (!line.empty() && line.back() == '\r') line.pop_back();
      partial.erase(0, nl + 1);
      std::lock_guard<std::mutex> lock(mutex_);
      lines_.push_back(std::move(line));
      any = true;
    }
    if (any) wake_();
  }
}

namespace {

int traceback(lua_State* L) {
  const char* msg = lua_tostring(L, 1);
  if (!msg) msg = lua_pushfstring(L, "(error object is a %s value)", luaL_typename(L, 1));
  luaL_traceback(L, L, msg, 1);
  return 1;
}

// A chunk that failed to compile only because it ended too early (an open `function`, `do`, ...).
bool incomplete(lua_State* L) {
  size_t len = 0;
  const char* msg = lua_tolstring(L, -1, &len);
  const char* eof = "'<eof>'";
  return msg && len >= strlen(eof) && strcmp(msg + len - strlen(eof), eof) == 0;
}

}  // namespace

bool Console::execute(const std::string& line, bool* ok) {
  if (ok) *ok = false;
  printed_values_ = false;
  // "=expr" is "return expr", as in the lua interpreter.
  buffer_ += buffer_.empty() ? (line.rfind('=', 0) == 0 ? "return " + line.substr(1) : line) : "\n" + line;
  int base = lua_gettop(L_);
  // As the lua interpreter does: try the line as an expression first so its values print. It
  // is an argument, not `return <line>`, so a call is no tail call and its errors keep stdin:LINE.
  // The closing bracket on the same line, so that a call's error names the line it is on (on a
  // line of its own it named the next); on the next line only where a comment ends the chunk.
  static const std::string pack = "local function pack(...) return {n = select('#', ...), ...} end return pack(";
  bool expression = true;
  std::string ret = pack + buffer_ + ")";
  int status = luaL_loadbuffer(L_, ret.data(), ret.size(), "=stdin");
  if (status != 0) {
    lua_pop(L_, 1);
    ret = pack + buffer_ + "\n)";
    status = luaL_loadbuffer(L_, ret.data(), ret.size(), "=stdin");
  }
  if (status != 0) {
    lua_pop(L_, 1);
    expression = false;
    if (luaL_loadbuffer(L_, buffer_.data(), buffer_.size(), "=stdin") != 0) {
      if (incomplete(L_)) {
        lua_pop(L_, 1);
        return false;
      }
      fprintf(stderr, "%s\n", lua_tostring(L_, -1));
      lua_settop(L_, base);
      buffer_.clear();
      return true;
    }
  }
  buffer_.clear();
  if (prepare_ && prepare_(L_)) lua_setfenv(L_, -2);
  lua_pushcfunction(L_, traceback);
  lua_insert(L_, -2);
  if (lua_pcall(L_, 0, LUA_MULTRET, base + 1) != 0) {
    fprintf(stderr, "%s\n", lua_tostring(L_, -1));
    lua_settop(L_, base);
    return true;
  }
  if (ok) *ok = true;
  // print(...) of the values, through the script's own `print`: an expression's (packed in one
  // table), or a statement's `return` (on the stack above the traceback function).
  int first = base + 2, n = lua_gettop(L_) - base - 1;
  if (expression) {
    lua_getfield(L_, first, "n");
    n = int(lua_tointeger(L_, -1));
    lua_pop(L_, 1);
    for (int i = 1; i <= n; ++i) lua_rawgeti(L_, first, i);
    first = lua_gettop(L_) - n + 1;
  }
  printed_values_ = n > 0;
  if (n > 0) {
    lua_getglobal(L_, "print");
    lua_insert(L_, first);
    if (lua_pcall(L_, n, 0, 0) != 0) fprintf(stderr, "%s\n", lua_tostring(L_, -1));
  }
  fflush(stdout);
  lua_settop(L_, base);
  return true;
}

}  // namespace sn::live
