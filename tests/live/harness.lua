-- Drives a live session from a test: starts `shadenet [--window] --watch scenario.lua` with the
-- loop's test hooks (SHADENET_LIVE_SNAPSHOT: one EXR per redrawn frame; SHADENET_LIVE_EXIT_AFTER:
-- a time limit), feeds its console through a pipe, rewrites its files and waits for its frames.
-- The window tests run under xvfb-run, so a child started with `window = true` opens its window
-- on the same display.
local sn = require "shadenet"
local ffi = require "ffi"
pcall(ffi.cdef, "int usleep(unsigned int usec);")

local H = {}

function H.sleep(s) ffi.C.usleep(math.floor(s * 1e6)) end

function H.exists(path)
  local f = io.open(path, "rb")
  if f then f:close() end
  return f ~= nil
end

function H.read(path)
  local f = assert(io.open(path, "rb"), "cannot read " .. path)
  local s = f:read("*a")
  f:close()
  return s
end

-- Saves the way most editors do: a new file renamed over the old one.
function H.write(path, text)
  local f = assert(io.open(path .. ".tmp", "wb"))
  f:write(text)
  f:close()
  assert(os.rename(path .. ".tmp", path))
end

-- A live test's folder made afresh with the scenario script (tests/live/scenario.lua, through
-- `edit` when given) and the shader it includes: the script's path and its text.
function H.scenario(dir, edit)
  os.execute(("rm -rf %q && mkdir -p %q && cp tests/live/tint.frag %q/"):format(dir, dir, dir))
  local text = H.read("tests/live/scenario.lua")
  if edit then text = edit(text) end
  H.write(dir .. "/scenario.lua", text)
  return dir .. "/scenario.lua", text
end

-- Saves in place (truncate and write), the other way editors save.
function H.write_in_place(path, text)
  local f = assert(io.open(path, "wb"))
  f:write(text)
  f:close()
end

-- The shadenet binary running this test.
H.shadenet = arg and arg[-1] or "shadenet"

local Session = {}
Session.__index = Session

-- H.start{ dir = "out/live_tests/x", script = path, window = true, size = "160x120",
--          limit = 30 (seconds: the child's SHADENET_LIVE_EXIT_AFTER), args = {...},
--          shown = true (also save what is shown, overlays included: SHADENET_LIVE_SHOWN),
--          sigint = true (Ctrl-C as a terminal's: SIGINT not ignored, though a shell that
--          started this test in the background ignores it for its children) } -> session
function H.start(o)
  os.execute(("rm -rf %q %q %q %q && mkdir -p %q %q"):format(o.dir .. "/frames", o.dir .. "/shown", o.dir .. "/pid",
                                                             o.dir .. "/log.txt", o.dir .. "/frames", o.dir .. "/shown"))
  local s = setmetatable({ dir = o.dir, log_path = o.dir .. "/log.txt", started = sn.clock() }, Session)
  local cmd = ("echo $$ > %q; exec env %sSHADENET_LIVE_SNAPSHOT=%q SHADENET_LIVE_SHOWN=%q SHADENET_LIVE_EXIT_AFTER=%d "
               .. "%q %s --size %s --watch %q %s > %q 2>&1")
    :format(o.dir .. "/pid", o.sigint and "--default-signal=INT " or "", o.dir .. "/frames/frame-%d.exr",
            o.shown and o.dir .. "/shown/shown-%d.exr" or "",
            o.limit or 30, H.shadenet,
            o.window == false and "" or "--window", o.size or "160x120", o.script,
            table.concat(o.args or {}, " "), s.log_path)
  s.pipe = assert(io.popen("sh -c '" .. cmd:gsub("'", "'\\''") .. "'", "w"))
  for _ = 1, 250 do
    s.pid = H.exists(o.dir .. "/pid") and tonumber(H.read(o.dir .. "/pid"))
    if s.pid then break end
    H.sleep(0.02)
  end
  assert(s.pid, "the live session did not start")
  return s
end

function Session:log() return H.exists(self.log_path) and H.read(self.log_path) or "" end

function Session:fail(msg)
  error(("%s\n--- session log (%s) ---\n%s"):format(msg, self.log_path, self:log()), 2)
end

-- One console line, as typed.
function Session:send(line)
  self.pipe:write(line, "\n")
  self.pipe:flush()
end

function Session:frame_path(n) return ("%s/frames/frame-%d.exr"):format(self.dir, n) end

-- The number of the newest frame saved so far (0 = none).
function Session:frames()
  local n = self.seen or 0
  while H.exists(self:frame_path(n + 1)) do n = n + 1 end
  self.seen = n
  return n
end

-- Waits until frame n exists; returns the seconds waited. Fails after `timeout`.
function Session:wait_frame(n, timeout)
  local t0 = sn.clock()
  while self:frames() < n do
    if sn.clock() - t0 > (timeout or 20) then self:fail(("frame %d did not come within %gs"):format(n, timeout or 20)) end
    H.sleep(0.02)
  end
  return sn.clock() - t0
end

-- Waits until every console line sent so far has run and drawn its frame; returns the number
-- of the newest frame. (A line that runs without error redraws once, after the lines read with it.)
function Session:settle()
  self.marks = (self.marks or 0) + 1
  self:send(('print("SETTLE %d " .. sn.live.frames())'):format(self.marks))
  local before = tonumber(self:wait_log(("SETTLE %d (%%d+)"):format(self.marks)))
  self:wait_frame(before + 1)
  return before + 1
end

-- Waits until the log matches a Lua pattern; returns the captures (or the match).
function Session:wait_log(pattern, timeout)
  local t0 = sn.clock()
  while true do
    local r = { self:log():match(pattern) }
    if #r > 0 then return unpack(r) end
    if sn.clock() - t0 > (timeout or 20) then self:fail(("the log never matched %q"):format(pattern)) end
    H.sleep(0.02)
  end
end

function Session:image(n) return sn.image.load(self:frame_path(n)) end

-- What was shown (overlays included), for sessions started with shown = true: the newest
-- picture saved so far and its number (0, nil when none).
function Session:shown()
  local n = self.shown_seen or 0
  while H.exists(("%s/shown/shown-%d.exr"):format(self.dir, n + 1)) do n = n + 1 end
  self.shown_seen = n
  if n == 0 then return 0, nil end
  return n, sn.image.load(("%s/shown/shown-%d.exr"):format(self.dir, n))
end

-- Waits until a picture newer than number `after` is shown; returns its number and image.
function Session:wait_shown(after, timeout)
  local t0 = sn.clock()
  while true do
    local n = self:shown()
    if n > after then
      H.sleep(0.05)  -- the file is written whole (renamed into place), but give the loop a moment
      return self:shown()
    end
    if sn.clock() - t0 > (timeout or 20) then self:fail(("no picture shown after %d within %gs"):format(after, timeout or 20)) end
    H.sleep(0.02)
  end
end

-- CPU seconds (user + system) the session's process has used so far.
function Session:cpu_seconds()
  local stat = H.read(("/proc/%d/stat"):format(self.pid))
  local after = stat:match("%) (.*)$")  -- the command name may hold spaces; fields follow its ')'
  local fields = {}
  for f in after:gmatch("%S+") do fields[#fields + 1] = f end
  local ticks = tonumber(fields[12]) + tonumber(fields[13])  -- utime, stime (fields 14, 15 of stat)
  local p = io.popen("getconf CLK_TCK")
  local hz = tonumber(p:read("*l")) or 100
  p:close()
  return ticks / hz
end

-- Ends the session through its console and waits for the process to exit.
function Session:stop()
  self:send("sn.live.quit()")
  self.pipe:close()  -- waits for the process (LuaJIT does not report its status)
  return not H.exists(("/proc/%d/stat"):format(self.pid))
end

-- A process on a pseudo-terminal, as a user at a terminal runs it (the console's line editing
-- works only there): H.tty{ "cmd", "arg", ... } -> t with t:type(bytes), t:wait(plain text,
-- timeout) -> output so far, t:output(), t:exited(timeout) -> whether it ended, t:close()
-- (waits for the process to exit).
function H.tty(argv)
  pcall(ffi.cdef, [[
    int forkpty(int* amaster, char* name, void* termp, void* winp);
    int execvp(const char* file, char* const argv[]);
    void _exit(int status);
    long read(int fd, void* buf, size_t n);
    long write(int fd, const void* buf, size_t n);
    int close(int fd);
    struct sn_pollfd { int fd; short events; short revents; };
    int poll(struct sn_pollfd* fds, unsigned long n, int timeout);
    int waitpid(int pid, int* status, int options);
  ]])
  local cargv = ffi.new("char*[?]", #argv + 1)
  local keep = {}
  for i, a in ipairs(argv) do
    keep[i] = ffi.new("char[?]", #a + 1, a)
    cargv[i - 1] = keep[i]
  end
  local master = ffi.new("int[1]")
  local pid = ffi.C.forkpty(master, nil, nil, nil)
  assert(pid >= 0, "forkpty failed")
  if pid == 0 then
    ffi.C.execvp(cargv[0], cargv)
    ffi.C._exit(127)
  end
  local t = { fd = master[0], pid = pid, out = "" }
  local buf = ffi.new("char[4096]")
  function t:pump(ms)
    local p = ffi.new("struct sn_pollfd[1]", { { self.fd, 1, 0 } })
    while ffi.C.poll(p, 1, ms or 0) > 0 do
      local n = ffi.C.read(self.fd, buf, 4096)
      if n <= 0 then return false end
      self.out = self.out .. ffi.string(buf, n)
      ms = 0
    end
    return true
  end
  function t:output() self:pump() return self.out end
  function t:type(bytes)
    ffi.C.write(self.fd, bytes, #bytes)
    H.sleep(0.05)
  end
  function t:wait(text, timeout, from)
    local t0 = sn.clock()
    while not self.out:find(text, from or 1, true) do
      if not self:pump(50) or sn.clock() - t0 > (timeout or 20) then
        error(("the terminal never showed %q; it shows:\n%s"):format(text, self.out), 2)
      end
    end
    return self.out
  end
  -- True when the process has ended within `timeout` seconds (it is then reaped).
  function t:exited(timeout)
    if self.reaped then return true end
    local status = ffi.new("int[1]")
    local t0 = sn.clock()
    repeat  -- reading keeps the child from blocking on a full terminal
      self:pump(25)
      if ffi.C.waitpid(self.pid, status, 1) == self.pid then  -- WNOHANG
        self.reaped = true
        return true
      end
    until sn.clock() - t0 > (timeout or 10)
    return false
  end
  function t:close()
    self:exited(10)
    ffi.C.close(self.fd)
  end
  return t
end

-- Images equal in every channel of every pixel.
function H.same(a, b)
  local w, h = a:size()
  local w2, h2 = b:size()
  if w ~= w2 or h ~= h2 then return false end
  return sn.image.mse(a, b) == 0
end

-- Runs a script headless (EGL, no window), as a researcher reproducing a figure would; the
-- script must print `marker` when it succeeded. Returns its output.
function H.run_headless(script, marker)
  local cmd = ("%q %q 2>&1"):format(H.shadenet, script)
  local p = io.popen(cmd)
  local out = p:read("*a")
  p:close()
  assert(out:find(marker, 1, true), "headless run failed: " .. cmd .. "\n" .. out)
  return out
end

-- Real input for the window (X11's XTest, as a user's mouse and keyboard): H.x11() -> input
-- with :move(x, y), :key("3" [, "Shift_L"]), :drag(button, x0, y0, x1, y1); coordinates on the screen.
-- Without a window manager a new window sits at the screen's top-left corner.
function H.x11()
  pcall(ffi.cdef, [[
    typedef struct _XDisplay Display;
    Display* XOpenDisplay(const char* name);
    int XCloseDisplay(Display* d);
    int XSync(Display* d, int discard);
    unsigned long XStringToKeysym(const char* name);
    unsigned char XKeysymToKeycode(Display* d, unsigned long keysym);
    int XTestFakeKeyEvent(Display* d, unsigned int keycode, int is_press, unsigned long delay);
    int XTestFakeButtonEvent(Display* d, unsigned int button, int is_press, unsigned long delay);
    int XTestFakeMotionEvent(Display* d, int screen, int x, int y, unsigned long delay);
    unsigned long XDefaultRootWindow(Display* d);
    int XQueryTree(Display* d, unsigned long w, unsigned long* root, unsigned long* parent, unsigned long** children,
                   unsigned int* n);
    int XFree(void* p);
    unsigned long XInternAtom(Display* d, const char* name, int only_if_exists);
    typedef struct { int type; unsigned long serial; int send_event; Display* display; unsigned long window;
                     unsigned long message_type; int format; long l[5]; } XClientMessageEvent;
    typedef union { int type; XClientMessageEvent xclient; long pad[24]; } XEvent;
    int XSendEvent(Display* d, unsigned long w, int propagate, long mask, XEvent* e);
  ]])
  local X11, Xtst = ffi.load("X11"), ffi.load("Xtst.so.6")
  local d = X11.XOpenDisplay(nil)
  assert(d ~= nil, "no X display (run under xvfb-run)")
  local input = {}
  function input:move(x, y)
    Xtst.XTestFakeMotionEvent(d, -1, x, y, 0)
    X11.XSync(d, 0)
  end
  function input:key(name, modifier)  -- modifier: a key held meanwhile ("Shift_L")
    local code = X11.XKeysymToKeycode(d, X11.XStringToKeysym(name))
    assert(code ~= 0, "no key " .. name)
    local mod = modifier and X11.XKeysymToKeycode(d, X11.XStringToKeysym(modifier))
    if mod then Xtst.XTestFakeKeyEvent(d, mod, 1, 0) end
    Xtst.XTestFakeKeyEvent(d, code, 1, 0)
    Xtst.XTestFakeKeyEvent(d, code, 0, 0)
    if mod then Xtst.XTestFakeKeyEvent(d, mod, 0, 0) end
    X11.XSync(d, 0)
  end
  function input:drag(button, x0, y0, x1, y1, steps)
    self:move(x0, y0)
    Xtst.XTestFakeButtonEvent(d, button, 1, 0)
    X11.XSync(d, 0)
    steps = steps or 8
    for i = 1, steps do
      H.sleep(0.01)
      self:move(math.floor(x0 + (x1 - x0) * i / steps), math.floor(y0 + (y1 - y0) * i / steps))
    end
    Xtst.XTestFakeButtonEvent(d, button, 0, 0)
    X11.XSync(d, 0)
  end
  -- What a window manager's close button sends (there is none under Xvfb): WM_DELETE_WINDOW to
  -- every top-level window.
  function input:close_window()
    local root, parent, children, n = ffi.new("unsigned long[1]"), ffi.new("unsigned long[1]"),
                                      ffi.new("unsigned long*[1]"), ffi.new("unsigned int[1]")
    X11.XQueryTree(d, X11.XDefaultRootWindow(d), root, parent, children, n)
    local e = ffi.new("XEvent")
    e.xclient.type = 33  -- ClientMessage
    e.xclient.message_type = X11.XInternAtom(d, "WM_PROTOCOLS", 0)
    e.xclient.format = 32
    e.xclient.l[0] = X11.XInternAtom(d, "WM_DELETE_WINDOW", 0)
    for i = 0, n[0] - 1 do
      e.xclient.window = children[0][i]
      X11.XSendEvent(d, children[0][i], 0, 0, e)
    end
    if children[0] ~= nil then X11.XFree(children[0]) end
    X11.XSync(d, 0)
  end
  function input:close() X11.XCloseDisplay(d) end
  return input
end

-- The title of the session's window as X knows it (xwininfo), or nil.
function H.window_title(match)
  local p = io.popen("xwininfo -root -tree 2>/dev/null")
  local tree = p:read("*a")
  p:close()
  for title in tree:gmatch('"([^"\n]*)"') do
    if title:find(match, 1, true) then return title end
  end
  return nil
end

return H
