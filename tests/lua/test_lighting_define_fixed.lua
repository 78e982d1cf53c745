-- sn.lighting.define fixes a model's GLSL when it is defined, #included files and all: editing
-- those files afterwards changes nothing already defined (renders, datasets, evaluate, the key,
-- check), a later syntax error in them breaks none of its renders, and defining the model again
-- is how a new version comes in. GLSL given as a string #includes files beside the defining
-- script, as a file's #includes are beside the file.
local sn = require "shadenet"

local dir = "out/lighting_define_fixed"
os.execute(("rm -rf %q && mkdir -p %q"):format(dir, dir))
local function write(name, text)
  local f = assert(io.open(dir .. "/" .. name, "w"))
  f:write(text)
  f:close()
end
local function near(a, b, what) assert(math.abs(a - b) < 1e-5, ("%s: %.7g vs %.7g"):format(what, a, b)) end

-- A model in m.glsl, which #includes scale.glsl beside it; the script that defines it sits there
-- too (define looks for the file beside its caller).
write("scale.glsl", "float fixed_scale() { return 1.0; }\n")
local lambert = "vec3 shade(Surface s, Params p) { return vec3(p.a * fixed_scale() * max(dot(s.n, s.l), 0.0)); }\n"
write("m.glsl", '#include "scale.glsl"\n' .. lambert)
local function define_script(k)
  return ([[
local sn = require "shadenet"
local m = sn.lighting.define { name = "fixed_m", params = { a = { default = 0.5, range = { 0, 1 } } }, glsl = "m.glsl",
  twin = function(s, p) local d = %s * p.a * math.max(sn.vec3.dot(s.n, s.l), 0); return { d, d, d } end }
return m
]]):format(k)
end
write("define.lua", define_script(1))
local M = dofile(dir .. "/define.lua")
local key = sn.lighting.key("fixed_m")

local scene = sn.scene { mesh = sn.mesh.sphere {}, size = { 48, 48 }, views = { count = 1 } }
local light = scene:light()
local up = sn.buffer { type = "vec4", data = { { 0, 1, 0, 0 } } }
local function gpu(model, color)
  local out = sn.buffer { type = "vec4", size = 1 }
  model:evaluate { normals = up, views = up, targets = out, raw = true, light = light, color = color }
  return out:get(1)[1]
end
local lit = 0.5 * light.dir[2] / sn.vec3.length(light.dir)  -- a * n.l at the normal (0, 1, 0)
near(gpu(M), lit, "the model as defined")
local centre = scene:render(M):get(24, 24)

-- Both files edited: a green constant, a doubled scale. Nothing defined before changes.
write("m.glsl", '#include "scale.glsl"\nvec3 shade(Surface s, Params p) { return vec3(0.0, 1.0, 0.0); }\n')
write("scale.glsl", "float fixed_scale() { return 2.0; }\n")
near(gpu(M), lit, "evaluate after the files changed")
near(gpu(M, "hsv"), sn.color.encode("hsv", { lit, lit, lit })[3], "a program built after the edit (hsv)")
local again = scene:render(M):get(24, 24)  -- (every render assembles its program's source anew)
assert(again[1] == centre[1] and again[2] == centre[2], "a render after the files changed: grey, not their green")
assert(sn.lighting.key("fixed_m") == key, "the key is the definition's, not the files' of today")
local data = scene:dataset { target = M:with { a = 0.7 }, samples = 200 }
local x, y = data:row("train", 1)
local twin = M:with { a = 0.7 }:shade { normal = { x[1], x[2], x[3] }, view = { x[4], x[5], x[6] }, light = light }
near(y[1], twin[1], "a dataset's target after the files changed")
assert(sn.lighting.check(M).max_difference < 1e-5, "check holds the defined GLSL to its twin")

-- A syntax error in either file breaks none of it.
write("m.glsl", '#include "scale.glsl"\nvec3 shade(Surface s, Params p) { return vec3(1.0) }\n')
write("scale.glsl", "float fixed_scale() { return 2.0 }\n")
near(gpu(M, "cie_xyz"), sn.color.encode("cie_xyz", { lit, lit, lit })[2], "a program built while the files are broken")
assert(scene:render(M, { size = { 32, 32 } }):get(16, 16)[1] > 0, "a render while the files are broken")
-- Defining it again reads the files anew: the error names the file and line.
local ok, err = pcall(dofile, dir .. "/define.lua")
assert(not ok and err:find(dir .. "/scale.glsl:1: error", 1, true), err)
write("scale.glsl", "float fixed_scale() { return 2.0; }\n")
ok, err = pcall(dofile, dir .. "/define.lua")
assert(not ok and err:find(dir .. "/m.glsl:2: error", 1, true), err)
write("m.glsl", '#include "scale.glsl"\n' .. lambert)

-- Fixed, with the scale 2 and a twin that says so: the new definition shades twice as bright, the
-- value made before keeps its own.
write("define2.lua", define_script(2))
local M2 = dofile(dir .. "/define2.lua")
near(gpu(M2), 2 * lit, "the new definition")
near(gpu(M), lit, "the value made before the new definition")
assert(sn.lighting.key("fixed_m") ~= key, "a new definition, a new key")
assert(M ~= M2, "two definitions of one name are two models")

-- GLSL as a string: its #include is looked up beside the defining script, then in shaders/.
write("inline.lua", [[
local sn = require "shadenet"
local m = sn.lighting.define { name = "fixed_inline",
  glsl = '#include "scale.glsl"\n#include "lighting/common.glsl"\nvec3 shade(Surface s, Params p) { return vec3(fixed_scale() * max(clamp_dot(s.n, s.l), 0.0)); }',
  twin = function(s) local d = 2 * math.max(sn.vec3.dot(s.n, s.l), 0); return { d, d, d } end }
return m
]])
local inline = dofile(dir .. "/inline.lua")
near(gpu(inline), 4 * lit, "an inline GLSL's #include beside its script")
write("missing.lua", [[
local sn = require "shadenet"
sn.lighting.define { name = "fixed_missing", twin = function() return { 0, 0, 0 } end,
  glsl = '#include "nowhere.glsl"\nvec3 shade(Surface s, Params p) { return vec3(0.0); }' }
]])
ok, err = pcall(dofile, dir .. "/missing.lua")
assert(not ok and err:find('missing.lua:2 (glsl of fixed_missing):1: cannot find #include "nowhere.glsl" (looked in ' ..
                           dir .. '/, shaders/include/ and shaders/)', 1, true), err)
print("ok")
