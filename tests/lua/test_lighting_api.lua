-- sn.lighting and sn.color from Lua: constructors and their parameters, the CPU twin
-- (model:shade) against the GPU (model:evaluate), copies with changed parameters, colour
-- conversions both ways.
local sn = require "shadenet"

local function near(a, b, tol, what)
  assert(math.abs(a - b) <= tol, string.format("%s: %.9g vs %.9g (tolerance %g)", what, a, b, tol))
end

-- Every model by name, defaults readable through :params().
local names = sn.lighting.models()
assert(#names == 5 and names[1] == "phong" and names[3] == "ggx", "models: " .. table.concat(names, ", "))
for _, name in ipairs(names) do
  local m = sn.lighting[name] {}
  assert(m:name() == name, "name of " .. name)
  assert(tostring(m):match("^" .. name .. "%("), "tostring: " .. tostring(m))
end

local gold = sn.lighting.ggx { roughness = 0.25, f0 = { 1.0, 0.71, 0.29 } }
local p = gold:params()
assert(p.roughness == 0.25 and p.f0[2] == 0.71 and p.diffuse[1] == 0, "ggx params")
local toon = sn.lighting.toon3 { thresholds = { 0.1, 0.2, 0.3, 0.4 } }
assert(#toon:params().thresholds == 4 and toon:params().thresholds[4] == 0.4, "toon3 thresholds")
assert(sn.lighting.phong { specular = 0.25 }:params().specular[3] == 0.25, "a number is a grey")

-- :with copies, changing only what it is given; equality compares parameters.
local rough = gold:with { roughness = 0.8 }
assert(rough:params().roughness == 0.8 and rough:params().f0[3] == 0.29, "with keeps the rest")
assert(gold:params().roughness == 0.25, "with leaves the original")
assert(gold == sn.lighting.ggx { roughness = 0.25 }, "equal parameters compare equal")
assert(gold ~= rough, "different parameters differ")
assert(sn.lighting.new("ggx", { roughness = 0.25 }) == gold, "sn.lighting.new by name")

-- Attributes a model reads from the G-buffer.
assert(#gold:attributes() == 2 and gold:attributes()[1] == "normal", "ggx reads normal, view")
local tex = sn.lighting.textured_phong {}:attributes()
assert(tex[3] == "base_color", "textured models read base_color")

-- The twin: Phong facing the light and the eye is C_p + W (then clamped to 1).
local phong = sn.lighting.phong { color = { 0.2, 0.4, 0.6 }, ambient = 0.3, specular = 0.1, shininess = 7 }
local up = { dir = { 0, 1, 0 } }
local raw = phong:shade { normal = { 0, 1, 0 }, view = { 0, 1, 0 }, light = up, raw = true }
near(raw[1], 0.3, 1e-12, "phong r") near(raw[2], 0.5, 1e-12, "phong g") near(raw[3], 0.7, 1e-12, "phong b")
local lit = sn.lighting.phong { specular = 1 }:shade { normal = { 0, 1, 0 }, view = { 0, 1, 0 }, light = up }
assert(lit[1] == 1, "recorded values clamp to 1, got " .. lit[1])
local bound = gold:bound(up)
assert(bound[1] > 1e3, "GGX's analytic bound is large at small roughness")

-- GPU against the twin on a few hundred directions.
local n, v, normals, views = 400, {}, {}, {}
for i = 1, n do
  local a, b = i * 2.399963, (i % 37) / 37 * math.pi
  normals[i] = { math.cos(a) * math.sin(b), math.cos(b), math.sin(a) * math.sin(b) }
  views[i] = { math.sin(3 * a), 0.5 + 0.5 * math.cos(a), math.cos(3 * a) }
end
local function vec4s(list)
  local out = {}
  for i, p in ipairs(list) do out[i] = { p[1], p[2], p[3], 0 } end
  return out
end
local nb, vb = sn.buffer { type = "vec4", data = vec4s(normals) }, sn.buffer { type = "vec4", data = vec4s(views) }
local out = sn.buffer { type = "vec4", size = n }
local light = { dir = { 0.3, 0.9, 0.2 }, color = { 1, 0.8, 0.6 } }
for _, m in ipairs { gold, phong, toon, sn.lighting.blinn_phong {} } do
  m:evaluate { normals = nb, views = vb, targets = out, light = light }
  local gpu = out:download()
  for i = 1, n do
    local t = m:shade { normal = normals[i], view = views[i], light = light }
    for c = 1, 3 do near(gpu[i][c], t[c], 1e-5, m:name() .. " sample " .. i) end
  end
end

-- Targets in another colour space: the GPU encodes what the twin encodes.
gold:evaluate { normals = nb, views = vb, targets = out, light = light, color = "cie_lab" }
local lab = out:download()
for i = 1, n, 17 do
  local t = sn.color.encode("cie", gold:shade { normal = normals[i], view = views[i], light = light })
  for c = 1, 3 do near(lab[i][c], t[c], 1e-5, "cie_lab target " .. i) end
end

-- Colours: known values and round trips; GPU conversion against the twin.
local hsv = sn.color.encode("hsv", { 1, 1, 0 })
near(hsv[1], 1 / 6, 1e-12, "yellow hue") near(hsv[2], 1, 0, "yellow saturation")
local white = sn.color.encode("cie_lab", { 1, 1, 1 })
near(white[1], 1, 1e-9, "white L*/100") near(white[2], 128 / 255, 1e-9, "white a*")
local xyz = sn.color.encode("cie_xyz", { 1, 0, 0 })
near(xyz[1], 0.4124564, 1e-12, "red X")
for _, space in ipairs { "rgb", "hsv", "cie", "cie_xyz", "cie_lab" } do
  local c = { 0.2, 0.7, 0.4 }
  local back = sn.color.decode(space, sn.color.encode(space, c))
  for k = 1, 3 do near(back[k], c[k], 1e-12, space .. " round trip") end
end
local colors = {}
for i = 1, 300 do colors[i] = { (i * 0.37) % 1, (i * 0.71) % 1, (i * 0.13) % 1 } end
local cin, cout = sn.buffer { type = "vec4", data = vec4s(colors) }, sn.buffer { type = "vec4", size = 300 }
sn.color.convert { input = cin, output = cout, space = "hsv" }
local enc = cout:download()
for i = 1, 300, 7 do
  local t = sn.color.encode("hsv", colors[i])
  local dh = math.abs(enc[i][1] - t[1])
  assert(math.min(dh, 1 - dh) < 1e-5 and math.abs(enc[i][3] - t[3]) < 1e-5, "GPU hsv " .. i)
end

-- A quick stress run from Lua: zeros for GGX at roughness 0.
local r = sn.lighting.stress(sn.lighting.ggx { roughness = 0 })
assert(r.samples > 30000 and r.failures == 0, "stress failures: " .. r.failures)
print("ok")
