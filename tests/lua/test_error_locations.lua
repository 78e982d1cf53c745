-- Errors name the script's line and what went wrong, never a runtime file's line, a segfault or
-- a silent nil: obj.release with a '.', a lighting twin that shades its own model, buf:ffi,
-- scene:render and the live API with released objects, sn.near's arguments, names read from
-- sn's tables (sn.image.mes), and sn.record's counts and sizes.
local sn = require "shadenet"
local expect = require "expect"
local fails = expect.fails_here

-- ---- :release() checks its object (b.release(io.stdout) freed a FILE* as a Buffer) ----
local b = sn.buffer { size = 4 }
fails(function() b.release(io.stdout) end, "Buffer:release: Buffer expected, got FILE* (call it with ':', obj:release())")
fails(function() b.release() end, "Buffer:release: Buffer expected, got no value")
local t = sn.target { width = 2, height = 2 }
fails(function() b.release(t) end, "Buffer:release: Buffer expected, got Target")
io.stdout:write("")  -- still a file
assert(tostring(t) ~= "Target (released)" and b:get(1) == 0, "nothing was released")
b:release()
b:release()  -- twice is fine
fails(function() local v = b:get(1); return v end, "this Buffer was released")
getmetatable(t).__gc(io.stdout)  -- __gc too checks what it frees
assert(tostring(t):find("Target"), "the target lives")

-- ---- a twin that calls its own model's shade: an error, not ~7000 C frames and a segfault ----
local v3 = sn.vec3
local model
local depth, twin_line = 0, nil
model = sn.lighting.define {
  name = "locations_recur", params = { k = { default = 0.9, range = { 0, 1 } } },
  glsl = "vec3 shade(Surface s, Params p) { return s.light_color * p.k * max(dot(s.n, s.l), 0.0); }",
  twin = function(s, p)
    depth = depth + 1
    if model then
      twin_line = debug.getinfo(1, "l").currentline + 1
      local c = model:shade { normal = s.n, view = s.v }  -- the line the error names
      return c
    end
    return v3.scale(s.light_color, p.k * math.max(v3.dot(s.n, s.l), 0))
  end,
}
depth = 0
fails(function() local c = model:shade { normal = { 0, 1, 0 }, view = { 0, 1, 0 } }; return c end,
      "lighting model 'locations_recur': its twin: more than 100 nested calls from Lua into shadenet and back")
assert(depth == 100, "stopped at the limit, not at the C stack's end: " .. depth)
local ok, err = pcall(function() local c = model:shade { normal = { 0, 1, 0 }, view = { 0, 1, 0 } }; return c end)
local here = debug.getinfo(1, "S").short_src  -- as error positions name this file
assert(#err < 400 and err:sub(1, #here + #tostring(twin_line) + 3) == here .. ":" .. twin_line .. ": ",
       "one message, at the twin's line: " .. err)
-- The counter is back at 0: a twin that calls another model nests once and works.
local phong = sn.lighting.phong {}
local outer = sn.lighting.define {
  name = "locations_outer", params = {},
  glsl = "vec3 shade(Surface s, Params p) { return vec3(0.5); }",
  twin = function(s)
    phong:shade { normal = s.n, view = s.v }  -- another model's twin, nested once
    return { 0.5, 0.5, 0.5 }
  end,
}
assert(outer:shade { normal = { 0, 1, 0 }, view = { 0, 1, 0 } }[1] > 0, "one level of nesting works")

-- ---- buf:ffi ----
local f = sn.buffer { size = 4 }
fails(function() local p = f:ffi("float"); return p end,
      "buf:ffi: ctype 'float': cannot convert 'void *' to 'float' (a pointer type expected, such as \"float*\")")
fails(function() local p = f:ffi("nosuchtype*"); return p end, "buf:ffi: ctype 'nosuchtype*'")
assert(f:ffi("float*")[0] == 0, "a pointer type maps")
f:release()
fails(function() local p = f:ffi(); return p end, "buf:ffi: this Buffer was released")

-- ---- scene:render with released objects ----
local function new_scene()
  local s = sn.scene { mesh = sn.mesh.sphere { segments = 8, rings = 4 }, size = { 8, 8 }, views = { count = 1 } }
  return s
end
local scene = new_scene()
local gone = sn.lighting.phong {}
gone:release()
fails(function() local img = scene:render(gone); return img end, "scene:render: this Lighting was released")
local net = sn.mlp { inputs = { "normal", "view" }, hidden = { 4 } }
net:release()
fails(function() local img = scene:render(net); return img end, "scene:render: this Mlp was released")
local released = new_scene()
released:release()
fails(function() local img = released:render(phong); return img end, "scene:render: this Scene was released")
assert(scene:render(phong), "a live scene renders")

-- ---- the live API ----
sn.live.show { truth = function() local tt = sn.target { width = 8, height = 8 } tt:clear { 1, 1, 1, 1 } return tt end, size = { 8, 8 } }
fails(function() local p = sn.live.screenshot("shot.xyz"); return p end,
      "sn.live.screenshot: cannot save 'shot.xyz': unknown image extension '.xyz'")
fails(function() local p = sn.live.screenshot(5); return p end, "sn.live.screenshot: path must be a string, got number")
local out = sn.fs.tempdir("locations")
local function record(o)
  o.dir = o.dir or out .. "/r"
  local d, frames = sn.record(o)
  return d, frames
end
fails(function() local d = record { orbit = { count = 1.5 } }; return d end,
      "sn.record: orbit.count must be a whole number in 1..100000, got 1.5")
fails(function() local d = record { orbit = { count = -3 } }; return d end, "got -3")
fails(function() local d = record { orbit = { count = 2 ^ 31 } }; return d end, "got 2147483648")
fails(function() local d = record { sweep = { set = function() end, count = 0 / 0 } }; return d end,
      "sn.record: sweep.count must be a whole number in 1..100000, got nan")
fails(function() local d = record { sweep = { set = function() end, from = 1 / 0 } }; return d end,
      "sn.record: sweep.from must be a finite number, got inf")
fails(function() local d = record { orbit = { count = 1, elevation = 90 } }; return d end,
      "sn.record: orbit.elevation must be a number of degrees in (-90, 90), got 90")
fails(function() local d = record { orbit = { count = 1, distance = 0 } }; return d end,
      "sn.record: orbit.distance must be a finite number > 0, got 0")
fails(function() local d = record { orbit = { count = 1 }, width = 0 } return d end,
      "sn.record: width must be a whole number in 1..16384, got 0")
fails(function() local d = record { orbit = { count = 1 }, height = 2.5 } return d end, "sn.record: height must be")
assert(not sn.fs.exists(out .. "/r"), "no folder for a refused recording")
local dir, frames = record { orbit = { count = 2 } }
assert(#frames == 2 and sn.fs.exists(dir), "two frames")

local live_scene = new_scene()
sn.live.show { truth = phong, scene = live_scene }
live_scene:release()
for name, call in pairs {
  render = function() local r = sn.live.render { mode = "truth" }; return r end,
  probe = function() local r = sn.live.probe(1, 1); return r end,
  screenshot = function() local r = sn.live.screenshot(out .. "/s.png"); return r end,
  record = function() local r = record { orbit = { count = 1 }, dir = out .. "/r2" }; return r end,
} do
  local ok2, e = pcall(call)
  assert(not ok2 and e:sub(1, #here + 1) == here .. ":" and e:find("^:%d+: sn%.", #here + 1) and
         e:find("scene:render: this Scene was released", 1, true) and not e:find("runtime/", 1, true),
         name .. ": " .. tostring(e))
end

-- ---- sn.near checks its arguments ----
fails(function() local r = sn.near(5, { "a" }); return r end, "sn.near: argument 1 (the name): string expected, got number")
fails(function() local r = sn.near("a", "abc"); return r end,
      "sn.near: argument 2 (the names): a list of strings expected, got string")
fails(function() local r = sn.near("a", { "b", 3 }); return r end, "sn.near: argument 2 (the names): element 2 is a number, not a string")
assert(sn.near("sampels", { "samples", "seed" })[1] == "samples", "sn.near still finds")

-- ---- names read from sn's tables: near names, as the module gives them ----
fails(function() local r = sn.image.mes; return r end, "sn.image.mes is not part of shadenet (did you mean sn.image.mse?)")
fails(function() local m = sn.mesh.shpere {}; return m end, "sn.mesh.shpere is not part of shadenet (did you mean sn.mesh.sphere?)")
fails(function() local r = sn.fs.exist; return r end, "sn.fs.exist is not part of shadenet (did you mean sn.fs.exists?)")
fails(function() local r = sn.image.train; return r end, "sn.image.train is not part of shadenet (did you mean sn.train?)")
fails(function() local r = sn.mesh.mse; return r end, "(did you mean sn.image.mse?)")
fails(function() local r = sn.live.nothing_like_it; return r end, "sn.live.nothing_like_it is not part of shadenet (the API: docs/lua-api.md)")
fails(function() local r = sn.tain; return r end, "sn.tain is not part of shadenet (did you mean sn.train?)")
fails(function() local r = sn.mse; return r end, "(did you mean sn.image.mse?)")
-- Every plain table of the module is strict; rawget still probes quietly, non-string keys read nil.
for k, v in pairs(sn) do
  if type(v) == "table" then
    assert(getmetatable(v) and getmetatable(v).__index, "sn." .. k .. " has an __index")
    if k ~= "lighting" then
      assert(not pcall(function() local r = v.no_such_name_here; return r end), "sn." .. k .. " is strict")
    end
  end
end
assert(rawget(sn.image, "mes") == nil and rawget(sn.live, "_tick") == nil and sn.image[1] == nil, "quiet probes")
sn.image.added_later = 1  -- fields added later read as usual
assert(sn.image.added_later == 1)
sn.image.added_later = nil

print("error locations: ok")
