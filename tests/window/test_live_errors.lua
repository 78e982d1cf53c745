-- A broken save keeps the last good state: a syntax error, a runtime error (after a weight edit)
-- and a broken shader are each reported with file:line in the terminal and the window's status,
-- the picture stays what it was (the last good program keeps running), and the next good save
-- recovers.
local sn = require "shadenet"
package.path = "tests/live/?.lua;" .. package.path
local H = require "harness"

local dir = "out/live_tests/errors"
os.execute(("mkdir -p %q"):format(dir))
local template = H.read("tests/live/scenario.lua")
local shader = H.read("tests/live/tint.frag")
local script, frag = dir .. "/scenario.lua", dir .. "/tint.frag"
H.write(frag, shader)
H.write(script, template)

local s = H.start { dir = dir, script = script }
s:wait_frame(1)
local good = s:image(1)

local function status_error()
  s.asked = (s.asked or 0) + 1
  s:send(('print("STATUS %d [" .. sn.live.status().error:gsub("\\n", " ") .. "]")'):format(s.asked))
  return s:wait_log(("STATUS %d %%[([^\n]*)%%]"):format(s.asked))
end

-- A redraw now must show the good picture.
local function assert_still_good(what)
  s:send("sn.live.redraw()")
  local n = s:settle()
  assert(H.same(s:image(n), good), what .. ": the picture changed")
end

-- 1. Syntax error: nothing of the broken version runs.
local lines = {}
for l in template:gmatch("[^\n]*\n") do lines[#lines + 1] = l end
local edit_line
for i, l in ipairs(lines) do if l:find("%-%- EDITS") then edit_line = i end end
H.write(script, (template:gsub("%-%- EDITS\n", "net.layers[1].weight[1][1] = = 0.9\n")))
local where = s:wait_log("%[live%] error: ([^\n]*scenario%.lua:%d+):")
assert(where:match(":(%d+)$") == tostring(edit_line), "syntax error reported at " .. where .. ", expected line " .. edit_line)
assert(status_error():find("scenario.lua:" .. edit_line .. ":", 1, true), "the status shows the syntax error")
local title = H.window_title("ERROR ")
assert(title and title:find("scenario.lua:" .. edit_line .. ": unexpected symbol", 1, true),
       "the window's title shows the error: " .. tostring(title))
assert_still_good("syntax error")

-- 2. Runtime error after a weight edit: the edit is undone, the last good weights stay.
H.write(script, (template:gsub("%-%- EDITS\n", "net.layers[1].weight[1][1] = 0.9\nerror('broken on purpose')\n")))
s:wait_log("scenario%.lua:" .. (edit_line + 1) .. ": broken on purpose")
assert(status_error():find("scenario.lua:" .. (edit_line + 1) .. ": broken on purpose", 1, true))
assert_still_good("runtime error")

-- 3. Recovery: a good save clears the error.
H.write(script, template)
local n = s:settle()
assert(status_error() == "", "the error was cleared by the good save")

-- 4. A broken shader: reported with its file:line, the last good program keeps drawing.
H.write(frag, (shader:gsub("float lambert", "float lambert = ;\n  float lambert2")))
local msg = s:wait_log("%[live%] error: ([^\n]*tint%.frag:%d+: error[^\n]*)")
local frag_line = s:wait_log("(tint%.frag:%d+): error")
assert(frag_line == "tint.frag:8", "shader error at " .. frag_line .. ", expected tint.frag:8 (the broken statement)")
assert(status_error():find("tint.frag", 1, true), "the status names the shader")
title = H.window_title("ERROR ")
assert(title and title:find("tint.frag:8: error", 1, true), "the title shows the shader's file:line: " .. tostring(title))
assert_still_good("broken shader")
s:send("sn.live.set_view{ mode = 'side' }")  -- new views still render with the last good program
local side = s:settle()

-- 5. The fixed shader (now half as bright) is picked up by the next frame.
H.write(frag, (shader:gsub("u_tint %* lambert", "0.5 * u_tint * lambert")))
s:wait_frame(side + 1, 15)
local fixed = s:image(side + 1)
s:send("sn.live.set_view{ mode = 'network' }")
local half = s:image(s:settle())
assert(status_error() == "", "the shader error was cleared")
local x, y = 80, 60  -- the sphere's middle
local a, b = good:get(x, y), half:get(x, y)
for c = 1, 3 do
  assert(math.abs(b[c] - 0.5 * a[c]) < 1e-6, ("channel %d: %g is not half of %g"):format(c, b[c], a[c]))
end
local w = fixed:size()
assert(w == 160, "side by side is 2 x 2 panels of 80 pixels, got " .. w)
s:stop()
print("errors: syntax and runtime errors at scenario.lua:" .. edit_line .. "/" .. (edit_line + 1) ..
      ", shader error at " .. frag_line .. ", each kept the last good picture and recovered")
