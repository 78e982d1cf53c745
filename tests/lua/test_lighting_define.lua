-- sn.lighting.define: a model written in Lua + GLSL goes everywhere a built-in goes (by name,
-- :with, :shade through its twin, :evaluate on the GPU, check, stress, scene:render,
-- scene:dataset with a cache keyed by its GLSL), and the shipped plug-in models hold to their
-- twins and to an independent oracle.
local sn = require "shadenet"
local v3 = sn.vec3

local function near(a, b, tol, what)
  assert(math.abs(a - b) <= tol, string.format("%s: %.9g vs %.9g (tolerance %g)", what, a, b, tol))
end

-- Minnaert's limb darkening, I = albedo (n.l)^k (n.v)^(k - 1), as a string of GLSL.
local function minnaert_glsl(k_expr)
  return [[
vec3 shade(Surface s, Params p) {
  float nl = max(dot(s.n, s.l), 0.0), nv = max(dot(s.n, s.v), 0.0);
  if (!(nl > 0.0 && nv > 0.0)) return vec3(0.0);
  return s.light_color * p.albedo * pow(nl, ]] .. k_expr .. [[) * pow(nv, p.k - 1.0);
}
]]
end
local function minnaert_twin(s, p)
  local nl, nv = math.max(v3.dot(s.n, s.l), 0), math.max(v3.dot(s.n, s.v), 0)
  if not (nl > 0 and nv > 0) then return { 0, 0, 0 } end
  return v3.scale(v3.mul(s.light_color, p.albedo), nl ^ p.k * nv ^ (p.k - 1))
end
local function define_minnaert(k_expr)
  return sn.lighting.define {
    name = "minnaert",
    params = { k = { default = 1.2, range = { 1, 2 } }, albedo = { type = "rgb", default = 0.7, range = { 0, 1 } } },
    glsl = minnaert_glsl(k_expr),
    twin = minnaert_twin,
  }
end

local m = define_minnaert("p.k")
assert(m:name() == "minnaert" and tostring(m) == "minnaert(albedo={0.7, 0.7, 0.7}, k=1.2)", tostring(m))
local names = sn.lighting.models()
assert(names[#names] == "minnaert", "defined models are listed after the built-ins")
assert(sn.lighting.new("minnaert", { k = 1.5 }):params().k == 1.5, "sn.lighting.new finds a defined model")
assert(sn.lighting.minnaert { k = 1.5 } == m:with { k = 1.5 }, "sn.lighting.NAME and :with agree")
local ok, err = pcall(function() return m:with { k = 3 } end)
assert(not ok and err:find("parameter 'k'") and err:find("must lie in %[1, 2%]"), err)

-- The twin is what :shade computes: k = 1.5 at n.l = 0.6, n.v = 0.8.
local l = { dir = { 0, 1, 0 } }
local n = { 0.8, 0.6, 0 }
local c = m:with { k = 1.5 }:shade { normal = { 0, 1, 0 }, view = { 0.6, 0.8, 0 }, light = { dir = n }, raw = true }
near(c[1], 0.7 * 0.6 ^ 1.5 * 0.8 ^ 0.5, 1e-12, "minnaert twin")

-- The GPU agrees with the twin on a few hundred directions (model:evaluate).
local count, normals, views = 300, {}, {}
for i = 1, count do
  local a, b = i * 2.399963, (i % 29) / 29 * math.pi
  normals[i] = { math.cos(a) * math.sin(b), math.cos(b), math.sin(a) * math.sin(b) }
  views[i] = { math.sin(3 * a), 0.5 + 0.5 * math.cos(a), math.cos(3 * a) }
end
local function vec4s(list)
  local o = {}
  for i, p in ipairs(list) do o[i] = { p[1], p[2], p[3], 0 } end
  return o
end
local nb, vb = sn.buffer { type = "vec4", data = vec4s(normals) }, sn.buffer { type = "vec4", data = vec4s(views) }
local out = sn.buffer { type = "vec4", size = count }
local k15 = m:with { k = 1.5 }
k15:evaluate { normals = nb, views = vb, targets = out, light = l, raw = true }
local worst = 0
for i = 1, count do
  local t = k15:shade { normal = normals[i], view = views[i], light = l, raw = true }
  local g = out:get(i)
  for ch = 1, 3 do worst = math.max(worst, math.abs(g[ch] - t[ch])) end
end
assert(worst < 1e-5, "minnaert GPU vs twin: " .. worst)

-- check and stress run on it like on a built-in.
local chk = sn.lighting.check(k15)
assert(chk.compared > 20000 and chk.max_difference < 1e-4, "check: " .. chk.max_difference)
local st = sn.lighting.stress(k15)
assert(st.failures == 0 and st.samples > 30000, "stress failures " .. st.failures)

-- A scene renders it and builds datasets from it; the cache key holds the GLSL, so a changed
-- definition (same name, same parameters) builds a new dataset and an unchanged one does not.
local scene = sn.scene { mesh = sn.mesh.sphere {}, size = { 64, 48 }, views = { count = 2, elevation = 20 } }
local img = scene:render(m)
local w, h = img:size()
local centre = img:get(math.floor(w / 2) + 1, math.floor(h / 2) + 1)
assert(centre[4] == 1 and centre[1] > 0.1, "the sphere is drawn")
sn.dataset_cache_clear()
local d1 = scene:dataset { target = m, samples = 1000 }
local builds = sn.dataset_stats().builds
scene:dataset { target = m, samples = 1000 }
assert(sn.dataset_stats().builds == builds, "same definition: a cache hit")
local m2 = define_minnaert("p.k + 0.0")  -- the same function, different source text
local d2 = scene:dataset { target = m2, samples = 1000 }
assert(sn.dataset_stats().builds == builds + 1, "changed GLSL: a new dataset")
assert(d1:counts() == d2:counts(), "same pixels")

-- A model defined inside a coroutine that has ended: its twin runs on the thread that calls it.
local co = coroutine.create(function()
  return sn.lighting.define { name = "lambert_co", glsl = "vec3 shade(Surface s, Params p) { return vec3(max(dot(s.n, s.l), 0.0)); }",
                              twin = function(s) local k = math.max(v3.dot(s.n, s.l), 0) return { k, k, k } end }
end)
local _, lambert_co = coroutine.resume(co)
assert(coroutine.status(co) == "dead")
co = nil
collectgarbage()
collectgarbage()
assert(sn.lighting.check(lambert_co).max_difference < 1e-5, "a twin defined in a finished coroutine")

-- Every built-in holds to its C++ twin through the same check (measured: 2e-8 toon3 .. 6e-6 ggx).
for _, name in ipairs { "phong", "blinn_phong", "ggx", "toon3", "textured_phong" } do
  local r = sn.lighting.check(sn.lighting[name] {})
  assert(r.compared > 40000 and r.max_difference < 2e-5, name .. ": GPU vs twin " .. r.max_difference)
end

-- The shipped plug-in models: GPU within a float shader's reach of the twin everywhere the
-- check looks, no NaN/Inf/negative anywhere in the stress grid, and an oracle that is not the
-- twin: Oren-Nayar with sigma = 0 is Lambert, i.e. Phong without its specular term.
package.path = "examples/lighting/?.lua;" .. package.path
local on = require "oren_nayar"
for _, model in ipairs { on, on:with { sigma = 0 }, on:with { sigma = 1.5707963, ambient = 0 } } do
  local r = sn.lighting.check(model)
  assert(r.max_difference < 2e-5, tostring(model) .. ": GPU vs twin " .. r.max_difference)
  assert(sn.lighting.stress(model).failures == 0, tostring(model) .. ": stress")
end
local lambert = sn.lighting.phong { color = { 0.8, 0.8, 0.8 }, ambient = 0.1, specular = 0 }
local flat = on:with { sigma = 0 }
for i = 1, 50 do
  local nn, vv = normals[i], views[i]
  local a = flat:shade { normal = nn, view = vv, light = { dir = { 0.5, 0.7, 0.6 } } }
  local b = lambert:shade { normal = nn, view = vv, light = { dir = { 0.5, 0.7, 0.6 } } }
  near(a[1], b[1], 1e-12, "oren_nayar sigma 0 = Lambert")
end
-- Rough surfaces look flatter: at sigma = 0.5 and grazing light seen from the light's side,
-- Oren-Nayar is brighter than Lambert's cosine (the backscatter the model is known for).
local rough = on:shade { normal = { 0, 1, 0 }, view = { 0.8, 0.6, 0 }, light = { dir = { 0.8, 0.6, 0 } }, raw = true }
local lam = lambert:shade { normal = { 0, 1, 0 }, view = { 0.8, 0.6, 0 }, light = { dir = { 0.8, 0.6, 0 } }, raw = true }
assert(rough[1] > lam[1] * 1.1, string.format("backscatter: %.4f vs Lambert %.4f", rough[1], lam[1]))

-- Anisotropic GGX reads the tangent: with equal roughnesses it is the built-in GGX, on the twin
-- (against the C++ twin) and on the GPU (against the built-in's shader); unequal, its highlight
-- depends on the tangent's direction.
local aniso = require "aniso_ggx"
-- Float's reach: 1.5e-5 at the defaults, 1.4e-4 at roughness 0 (alpha = 1e-3, a needle lobe).
for _, case in ipairs { { aniso, 3e-5 }, { aniso:with { roughness_x = 0.05, roughness_y = 1 }, 1e-4 },
                        { aniso:with { roughness_x = 0 }, 3e-4 } } do
  local model = case[1]
  local r = sn.lighting.check(model)
  assert(r.max_difference < case[2], tostring(model) .. ": GPU vs twin " .. r.max_difference)
  assert(sn.lighting.stress(model).failures == 0, tostring(model) .. ": stress")
end
assert(aniso:attributes()[3] == "tangent", "aniso_ggx reads the tangent")
local iso = aniso:with { roughness_x = 0.4, roughness_y = 0.4 }
local ggx = sn.lighting.ggx { roughness = 0.4, f0 = { 0.95, 0.93, 0.88 }, diffuse = 0, ambient = 0.1 }
local tangents = {}
for i = 1, count do
  local t = v3.cross(normals[i], { 0.3, 0.9, -0.2 })
  tangents[i] = { t[1], t[2], t[3] }
end
local worst_twin = 0
for i = 1, count do
  local a = iso:shade { normal = normals[i], view = views[i], tangent = tangents[i], light = l, raw = true }
  local b = ggx:shade { normal = normals[i], view = views[i], light = l, raw = true }
  for ch = 1, 3 do worst_twin = math.max(worst_twin, math.abs(a[ch] - b[ch]) / math.max(1, math.abs(b[ch]))) end
end
assert(worst_twin < 1e-12, "isotropic aniso_ggx twin vs ggx twin: " .. worst_twin)
local tb = sn.buffer { type = "vec4", data = vec4s(tangents) }
local out_iso, out_ggx = sn.buffer { type = "vec4", size = count }, sn.buffer { type = "vec4", size = count }
iso:evaluate { normals = nb, views = vb, tangents = tb, targets = out_iso, light = l, raw = true }
ggx:evaluate { normals = nb, views = vb, targets = out_ggx, light = l, raw = true }
local worst_gpu = 0
for i = 1, count do
  local a, b = out_iso:get(i), out_ggx:get(i)
  for ch = 1, 3 do worst_gpu = math.max(worst_gpu, math.abs(a[ch] - b[ch]) / math.max(1, math.abs(b[ch]))) end
end
assert(worst_gpu < 1e-4, "isotropic aniso_ggx shader vs ggx shader: " .. worst_gpu)
ok, err = pcall(function() aniso:evaluate { normals = nb, views = vb, targets = out_iso } end)
assert(not ok and err:find("reads 'tangent': give tangents = Buffer"), err)
-- Stretched: turning the tangent by 90 degrees about the normal changes the highlight.
local up = { 0, 1, 0 }
local half = v3.normalize(v3.add({ 0.3, 1, 0 }, { -0.1, 1, 0.25 }))
local function at(t)
  return aniso:shade { normal = up, view = { -0.1, 1, 0.25 }, tangent = t, light = { dir = { 0.3, 1, 0 } }, raw = true }[1]
end
assert(at { 1, 0, 0 } > 1.5 * at { 0, 0, 1 } or at { 0, 0, 1 } > 1.5 * at { 1, 0, 0 },
       string.format("the tangent turns the lobe: %.4f vs %.4f (h = %.2f, %.2f, %.2f)", at { 1, 0, 0 }, at { 0, 0, 1 },
                     half[1], half[2], half[3]))

-- Datasets and renders take the tangent from the G-buffer.
local tangent_data = scene:dataset { target = aniso, inputs = { "normal", "view", "tangent" }, samples = 1000 }
assert(tangent_data:inputs() == 9, "normal + view + tangent = 9 inputs")
local img_a = scene:render(aniso)
assert(img_a:get(math.floor(w / 2) + 1, math.floor(h / 2) + 1)[4] == 1, "aniso_ggx renders")
print("ok")
