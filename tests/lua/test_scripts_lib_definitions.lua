-- A run's config carries the keys of the user definitions it uses (a lighting model, an
-- activation, an encoding: their GLSL hashed; an encoding's options, output counts and twin too),
-- so a sweep retrains a run whose definition changed under the same name: it reused the old
-- records. Built-ins add nothing (older configs stay).
package.path = "scripts/?.lua;" .. package.path
local sn = require "shadenet"
local exp = require "lib.experiment"
local json = require "lib.json"

local E = exp.start("definitions", { "--quick", "--out", sn.fs.tempdir("test_scripts_lib_definitions") })

local function define_snake(a)
  sn.activation.define { name = "snake_t", glsl = ("z + sin(%g * z) * sin(%g * z) / %g"):format(a, a, a),
                         grad = ("1.0 + sin(2.0 * %g * z)"):format(a),
                         lua = function(z) return z + math.sin(a * z) ^ 2 / a end,
                         lua_grad = function(z) return 1 + math.sin(2 * a * z) end }
end
local function define_model(w)
  sn.lighting.define { name = "lambert_t", params = { k = { default = 1, range = { 0, 10 } } },
                       glsl = ("vec3 shade(Surface s, Params p) { return s.light_color * p.k * max((dot(s.n, s.l) + %g) / %g, 0.0); }")
                         :format(w, 1 + w),
                       twin = function(s, p)
                         return sn.vec3.scale(s.light_color, p.k * math.max((sn.vec3.dot(s.n, s.l) + w) / (1 + w), 0))
                       end }
end

local function config()
  local desc = E:data_desc { model = "lambert_t" }
  return exp.run { id = "r", hidden = { 4 }, seed = 1, activation = "snake_t", data = desc }.config
end

define_snake(1)
define_model(0.25)
local a = config()
assert(a.definitions and a.definitions["activation snake_t"], "the activation's key: " .. json.encode(a))
assert(a.data.truth_definition, "the model's key")
define_snake(2)
local b = config()
assert(b.definitions["activation snake_t"] ~= a.definitions["activation snake_t"], "a redefined activation, a new key")
assert(b.data.truth_definition == a.data.truth_definition, "the model as it was")
define_model(0.5)
assert(config().data.truth_definition ~= a.data.truth_definition, "a redefined model, a new key")
-- The key covers what the shaders read: a file the GLSL #includes, and the attributes.
local dir = sn.fs.tempdir("definitions_include")
sn.fs.write(dir .. "/gain.glsl", "float gain() { return 0.5; }\n")
sn.fs.write(dir .. "/model.glsl", '#include "gain.glsl"\nvec3 shade(Surface s, Params p) { return vec3(gain()); }\n')
local gain = 0.5
local function define_included(attributes)
  sn.lighting.define { name = "included_t", glsl = dir .. "/model.glsl", attributes = attributes,
                       twin = function() return { gain, gain, gain } end }
  return sn.lighting.key("included_t")
end
local k1 = define_included()
sn.fs.write(dir .. "/gain.glsl", "float gain() { return 0.9; }\n")
gain = 0.9
local k2 = define_included()
assert(k2 ~= k1, "an included file changed, a new key")
assert(define_included { "uv" } ~= k2, "other attributes, a new key")
assert(define_included() == k2, "the same files and attributes, the same key")
-- An encoding's key covers all a network sees, not its GLSL and count alone (a sweep reused its
-- runs after include_input's default changed): include_input and its default, the output counts,
-- and the twin the cpu backend encodes with, down to a value it closes over. It is the same in
-- every process (a child script, run twice), and the same for the same definition.
local C = require "script_check"
local child = C.child("definitions_encoding", [[
local sn = require "shadenet"
local KEEP, SCALE, CLAMP = os.getenv("KEEP") ~= "0", tonumber(os.getenv("SCALE") or "1"), os.getenv("CLAMP") == "1"
local count = os.getenv("OUTPUTS") == "reordered" and function(w, n, keep) return w * n + (keep and w or 0) end
                                                     or function(w, n, keep) return (keep and w or 0) + w * n end
local twin = CLAMP and function(x, n, keep)
  local out = {}
  if keep then for c = 1, #x do out[#out + 1] = x[c] end end
  for c = 1, #x do for k = 1, n do out[#out + 1] = math.min(x[c], 1e4) * k * SCALE end end
  return out
end or function(x, n, keep)
  local out = {}
  if keep then for c = 1, #x do out[#out + 1] = x[c] end end
  for c = 1, #x do for k = 1, n do out[#out + 1] = x[c] * k * SCALE end end
  return out
end
sn.encoding.define { name = "ramp_t", count = { "bands", min = 1, max = 3, default = 2 }, include_input = KEEP,
                     outputs = count, lua = twin,
                     glsl = "int m = keep ? w : 0; if (j < m) return x[j]; int c = (j - m) / n; return x[c] * float(j - m - c * n + 1);" }
print("key " .. sn.encoding.key("ramp_t"))
]])
local function enc_key(env)
  local out = C.ok(child, {}, env)
  return assert(out:match("key (%x+)"), out)
end
local k_base = enc_key {}
assert(enc_key {} == k_base, "the same definition in another process, the same key")
assert(enc_key { OUTPUTS = "reordered" } == k_base, "outputs written otherwise, the same counts: the same key")
assert(enc_key { KEEP = "0" } ~= k_base, "include_input's default changed, a new key")
assert(enc_key { SCALE = "1.0000001" } ~= k_base, "a value the twin closes over changed, a new key")
assert(enc_key { CLAMP = "1" } ~= k_base, "the twin's code changed (beyond where the GLSL is compared), a new key")
-- A run's config records it.
loadfile(child)()
local enc_run = exp.run { id = "r", hidden = { 4 }, seed = 1, data = E:data_desc { model = "phong" },
                          encoding = { normal = "ramp_t" } }.config
assert(enc_run.definitions["encoding ramp_t"] == k_base, json.encode(enc_run.definitions))
-- A mesh file rewritten under the same path: another mesh_key, so its runs are trained again.
local mesh_path = dir .. "/mesh.glb"
sn.mesh.sphere {}:save(mesh_path)
local before = E:data_desc { model = "phong", mesh = mesh_path }
sn.mesh.torus {}:save(mesh_path)
package.loaded["lib.experiment"] = nil  -- a new process: the key is read once per process
local E2 = require("lib.experiment").start("definitions", { "--quick", "--out", sn.fs.tempdir("test_scripts_lib_definitions") })
local after = E2:data_desc { model = "phong", mesh = mesh_path }
assert(before.mesh_key and after.mesh_key and before.mesh_key ~= after.mesh_key, json.encode { before.mesh_key, after.mesh_key })
-- Only built-ins: no keys, the config as before.
local builtin = exp.run { id = "r", hidden = { 4 }, seed = 1, data = E:data_desc { model = "phong" } }.config
assert(builtin.definitions == nil and builtin.data.truth_definition == nil, json.encode(builtin))
-- A model given as { name, params } or as a Lighting value, and a mesh as a value, as the docs
-- allow (the first failed inside the library, the others could not be turned into JSON keys).
local positional = E:data_desc { model = { "lambert_t", { k = 2 } } }
assert(positional.truth:find("k=2", 1, true), positional.truth)
local value = E:data_desc { model = sn.lighting.ggx { roughness = 0.3 } }
assert(value.model.name == "ggx" and value.truth == tostring(sn.lighting.ggx { roughness = 0.3 }), json.encode(value))
local sphere = sn.mesh.sphere {}
local s1 = E:scene { mesh = sphere, size = { 8, 8 }, views = 1 }
assert(E:scene { mesh = sphere, size = { 8, 8 }, views = 1 } == s1, "a mesh value's scene is cached")
assert(E:scene { mesh = sn.mesh.sphere {}, size = { 8, 8 }, views = 1 } ~= s1, "another mesh value, another scene")
print("ok")
