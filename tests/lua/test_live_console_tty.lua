-- The console at a terminal (a pseudo-terminal here): lines are edited (the up arrow recalls the
-- last line, backspace deletes, the edited line runs), the history is saved to its file and the
-- next session recalls the last session's lines; Ctrl-D on an empty line ends the session, asking
-- first when console edits would be lost (Ctrl-D again within 3 s ends it; it ended at once, edits
-- and all); Ctrl-C stops a line that never ends; lines of thousands of characters are typed and
-- recalled like short ones.
-- (Piped stdin, no terminal: tests/window/test_live_repl.lua and the other live tests.)
local sn = require "shadenet"
package.path = "tests/live/?.lua;" .. package.path
local H = require "harness"

local dir = "out/live_tests/console_tty"
os.execute(("rm -rf %q && mkdir -p %q"):format(dir, dir))
local script, history = dir .. "/main.lua", dir .. "/history"
H.write(script, 'local sn = require "shadenet"\nprint("READY")\n')
local function session()
  return H.tty { "env", "SHADENET_HISTORY=" .. history, "SHADENET_LIVE_EXIT_AFTER=60", H.shadenet, "--watch", script }
end
local UP, BACKSPACE, CTRL_D = "\27[A", "\127", "\4"
local ASK = "press Ctrl-D again (or Q) to quit"
-- Ends a session that has console edits: the first Ctrl-D asks, the second ends it.
local function quit(t)
  local from = #t:output() + 1
  t:type(CTRL_D)
  t:wait(ASK, nil, from)
  assert(not t:exited(0.3), "the first Ctrl-D after an edit does not end the session")
  t:type(CTRL_D)
  assert(t:exited(5), "the second Ctrl-D ends it")
  t:close()
end

-- Without console edits Ctrl-D ends the session at once.
local t0 = session()
t0:wait("READY")
t0:wait("> ")
t0:type("40 + 2\r")  -- a query, not an edit
t0:wait("42")
t0:type(CTRL_D)
assert(t0:exited(5), "Ctrl-D with no console edit ends the session at once")
assert(not t0:output():find(ASK, 1, true), "nothing was asked")
t0:close()

-- Ctrl-C at the terminal stops a line that never ends; the console goes on (it ended the process).
local tc = session()
tc:wait("READY")
tc:wait("> ")
tc:type("while true do end\r")
H.sleep(0.5)
tc:type("\3")
tc:wait("stdin:1: interrupted by the user (Ctrl-C)")
tc:type('print("AFTER=" .. 6 * 7)\r')
tc:wait("AFTER=42")
quit(tc)

local t = session()
t:wait("READY")
t:wait("> ")
t:type("v = 40 + 1\r")
t:type(UP .. BACKSPACE .. "2\r")  -- recalls "v = 40 + 1", deletes the 1, types 2: v = 40 + 2
t:type('print("V=" .. v)\r')
local out = t:wait("V=42")
quit(t)
assert(not out:find("V=41", 1, true), "the edited line ran, not the recalled one")
-- libedit's format: a header line, then one line each with spaces as \040 (vis(3) encoding)
local saved = H.read(history):gsub("\\(%d%d%d)", function(o) return string.char(tonumber(o, 8)) end)
assert(saved:find("v = 40 + 2", 1, true) and saved:find('print("V=" .. v)', 1, true),
       "the history file holds the session's lines:\n" .. saved)

-- A new session recalls the last one's lines: up twice is "v = 40 + 2" (before the print).
local t2 = session()
t2:wait("READY")
t2:wait("> ")
t2:type(UP .. UP .. "\r")
t2:type(UP .. UP .. "\r")  -- now the print line again
local out2 = t2:wait("V=42")
quit(t2)
assert(select(2, out2:gsub("V=42", "")) >= 1, "the recalled lines ran")
-- Lines past libedit's 1,020-byte conversion buffer (a pasted table of weights): its readline
-- layer wrote their end into freed memory, and the session died ("malloc(): invalid next size").
-- Typed a piece at a time (a terminal's input queue holds 4 KB), then recalled from the history.
local t3 = session()
t3:wait("READY")
t3:wait("> ")
local function type_long(text)
  for at = 1, #text, 1000 do t3:type(text:sub(at, at + 999)) end
end
for n = 1, 3 do
  type_long('s = "' .. ("w"):rep(3000 * n) .. '"\r')
  t3:type('print("LEN=" .. #s)\r')
  t3:wait("LEN=" .. 3000 * n)
end
t3:type('s = ""\r')
local before = #t3:output()
t3:type(UP .. UP .. UP .. "\r")  -- the longest line, recalled
t3:type('print("LEN=" .. #s)\r')
t3:wait("LEN=9000", nil, before)
quit(t3)
-- On a full disk the history file stays as it was (libedit wrote it in place and left it cut
-- mid-line), and the session says so once. Needs root for the tmpfs; skipped elsewhere.
local full = "/tmp/shadenet_history_full_" .. tostring(os.time()) .. "_" .. tostring(math.random(1, 1e6))
os.execute(("mkdir -p %q"):format(full))
local mounted = os.execute(("mount -t tmpfs -o size=64k tmpfs %q 2>/dev/null"):format(full))
if mounted == 0 or mounted == true then
  local kept = H.read(history)
  H.write(full .. "/history", kept)
  local f = assert(io.open(full .. "/filler", "wb"))
  f:write(("f"):rep(64 * 1024))  -- fills the rest (the write stops when the disk is full)
  f:close()
  local t4 = H.tty { "env", "SHADENET_HISTORY=" .. full .. "/history", "SHADENET_LIVE_EXIT_AFTER=60", H.shadenet, "--watch", script }
  t4:wait("READY")
  t4:wait("> ")
  t4:type('print("FULL=" .. 6 * 7)\r')
  local out4 = t4:wait("FULL=42")
  quit(t4)
  local after = H.read(full .. "/history")
  local left = io.popen(("ls -a %q"):format(full)):read("*a")
  os.execute(("umount %q; rmdir %q"):format(full, full))
  assert(after == kept, "the old history stays whole on a full disk:\n" .. after)
  assert(out4:find("cannot save the console history to " .. full .. "/history (", 1, true) and
         out4:find("No space left on device); the old file stays", 1, true), out4)
  assert(not left:find(".tmp", 1, true), "no temporary left: " .. left)
else
  os.execute(("rmdir %q"):format(full))
  print("full-disk history: SKIPPED (cannot mount a tmpfs here: not root?)")
end
print(("console at a terminal: the edited line ran (V=42), history in %s recalled by the next session"):format(history))
