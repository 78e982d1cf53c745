-- `shadenet --watch` headless, the ways a live session used to lose the user (issue 14): a run
-- that starts with a syntax error, an empty or half-written save, a module required lazily by a
-- view that breaks and is fixed, the user's view mode across a light change, and a GLSL error
-- raised while the script builds a program, a save made while the first run runs. Each step
-- fails without its fix.
local sn = require "shadenet"
package.path = "tests/live/?.lua;" .. package.path
local H = require "harness"

local dir = "out/live_tests/watch"
os.execute(("rm -rf %q && mkdir -p %q"):format(dir, dir))
local script, module = dir .. "/s.lua", dir .. "/lazy_mod.lua"
H.write(dir .. "/tint.frag", H.read("tests/live/tint.frag"))
H.write(module, "return { tint = { 0.2, 0.6, 0.9 } }\n")

-- The script, version n: prints RUN n; its network view requires lazy_mod while drawing.
local function version(n, light, extra)
  return ([[
local sn = require "shadenet"
package.path = %q .. "/?.lua;" .. package.path
print("RUN %d")
%s
local sphere = sn.mesh.sphere { segments = 24, rings = 12 }
local program = sn.program { vertex = "mesh.vert", fragment = %q }
local function shade(view, tint)
  local t = sn.target { width = view.width, height = view.height }
  sn.draw { target = t, program = program, mesh = sphere, camera = view.camera, clear = { 0, 0, 0, 0 },
            uniforms = { u_tint = tint, u_light = view.light.dir } }
  return t
end
sn.live.show {
  network = function(view) return shade(view, require("lazy_mod").tint) end,
  truth = function(view) return shade(view, { 0.8, 0.5, 0.3 }) end,
  camera = sn.camera { eye = { 0.6, 0.8, 2.6 } },
  light = { dir = { %s } },
}
]]):format(dir, n, extra or "", dir .. "/tint.frag", light or "0.5, 0.7, 0.6")
end

local function count(text, pattern)
  local n = 0
  for _ in text:gmatch(pattern) do n = n + 1 end
  return n
end

-- 1. A session that starts with a syntax error reloads when the file is fixed.
H.write(script, "local x = = 1\n")
local s = H.start { dir = dir .. "/session", script = script, window = false, limit = 90 }
s:wait_log("%[live%] error: [^\n]*s%.lua:1: unexpected symbol")
H.write(script, version(1))
s:wait_log("RUN 1")
s:wait_frame(1)
print("1. started broken, fixed: reloaded")

local function status(field)
  s.asked = (s.asked or 0) + 1
  s:send(('print("STATUS %d [" .. sn.live.status().%s:gsub("\\n", " ") .. "]")'):format(s.asked, field))
  return s:wait_log(("STATUS %d %%[([^\n]*)%%]"):format(s.asked))
end

-- 2. An empty save is an error, not a good run; a save in two steps (truncate, then write) runs once.
local runs = count(s:log(), "%[live%] ran ")
H.write_in_place(script, "")
s:wait_log("s%.lua: the script is empty")
assert(count(s:log(), "%[live%] ran ") == runs, "an empty file counted as a good run")
assert(status("error"):find("the script is empty", 1, true), "the status shows the empty script")
H.write(script, version(2))
s:wait_log("RUN 2")
s:settle()
runs = count(s:log(), "%[live%] ran ")
local empties = count(s:log(), "the script is empty")
H.write_in_place(script, "")           -- an editor that truncates, then writes
H.write_in_place(script, version(3))
s:wait_log("RUN 3")
s:settle()
assert(count(s:log(), "%[live%] ran ") == runs + 1, "the half-written save ran: " .. s:log())
assert(count(s:log(), "the script is empty") == empties, "the truncated moment was reported as an empty script")
assert(status("error") == "", "the good save cleared the error")
print("2. empty save is an error; truncate-then-write ran once")

-- 3. A module the view requires while drawing, broken then fixed, stays watched.
H.write(module, "return { tint = = 1 }\n")
s:wait_log("lazy_mod%.lua:1:")
assert(status("error"):find("lazy_mod.lua:1:", 1, true), "the status shows the module's error")
local before = s:frames()
H.write(module, "return { tint = { 0.9, 0.1, 0.1 } }\n")
s:wait_frame(before + 1, 15)
local n = s:settle()
assert(status("error") == "", "the fixed module cleared the error")
local img = s:image(n)
local w, h = img:size()
local px = img:get(math.floor(w / 2), math.floor(h / 2))  -- the sphere's middle
assert(math.abs(px[1] / px[3] - 9) < 1e-3, ("the fixed module's tint is drawn: %g %g %g"):format(px[1], px[2], px[3]))
print("3. lazily required module broken then fixed: reloaded")

-- 4. The view mode the user picked survives a change of the script's light.
s:send("sn.live.set_view { mode = 'error' }")
s:settle()
H.write(script, version(4, "-0.5, 0.7, 0.6"))
s:wait_log("RUN 4")
s:settle()
s:send('print("MODE " .. sn.live.view().mode .. " " .. sn.live.view().light.dir[1])')
local mode, lx = s:wait_log("MODE (%a+) (%S+)")
assert(tonumber(lx) == -0.5, "the script's new light is used, got " .. lx)
assert(mode == "error", "the user's view mode was reset to " .. mode .. " by a light change")
print("4. view mode kept across a light change")

-- 5. A GLSL error raised while the script builds a program: the status names the shader's line.
H.write(dir .. "/bad.frag", "layout(location = 0) out vec4 o_color;\nvoid main() {\n  o_color = vec4(1.0) +;\n}\n")
H.write(script, version(5, nil, ('local bad = sn.program { vertex = "mesh.vert", fragment = %q }'):format(dir .. "/bad.frag")))
s:wait_log("bad%.frag:3:")
local title = status("title")
assert(title:find("^ERROR [^|]*bad%.frag:3:"), "the status names the shader's file:line first: " .. title)
print("5. GLSL error in a program the script builds: " .. title:match("^ERROR ([^|]*)"))
s:stop()

-- 6. A save that lands while the first run runs, before the file is watched: the session reloads
-- (it stayed on the first run, comparing the next saves with the saved text it never ran).
local own = dir .. "/own.lua"
H.write(own, ([[
local sn = require "shadenet"
print("RUN A")
local f = assert(io.open(%q, "w"))
f:write('local sn = require "shadenet"\nprint("RUN B")\n')
f:close()
]]):format(own))
local t = H.start { dir = dir .. "/session_own", script = own, window = false, limit = 60 }
t:wait_log("RUN B", 20)
assert(count(t:log(), "RUN A") == 1, "the first run ran once: " .. t:log())
t:stop()
print("6. a save during the first run is run")
