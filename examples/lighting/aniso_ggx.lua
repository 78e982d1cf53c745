-- Anisotropic GGX as a lighting model defined in Lua + GLSL (no C++): highlights stretched along
-- the surface's tangent, as on brushed metal. It reads the G-buffer's "tangent" (the glTF
-- TANGENT attribute, else generated from the UVs: runtime/scene/tangents.h), so its networks
-- take the tangent as an input too. The GLSL is aniso_ggx.glsl beside this file.
--   build/shadenet examples/lighting/aniso_ggx.lua [OUT_DIR]     (default results/lighting)
-- `require` it (package.path holding examples/lighting/) to get the model without the demo.
local sn = require "shadenet"
local v3 = sn.vec3

local PI, MIN_ALPHA, MIN_LENGTH2, MIN_DENOMINATOR = math.pi, 1e-3, 1e-30, 1e-30

-- The twins of perpendicular() and aniso_tangent() in the GLSL.
local function perpendicular(n, x)
  local r = v3.sub(x, v3.scale(n, v3.dot(n, x)))
  local r2 = v3.dot(r, r)
  return r2 > 1e-6 and v3.scale(r, 1 / math.sqrt(r2)) or { 0, 0, 0 }
end
local function aniso_tangent(n, t)
  local u = perpendicular(n, t)
  if v3.dot(u, u) < 0.5 then u = perpendicular(n, { 1, 0, 0 }) end
  if v3.dot(u, u) < 0.5 then u = perpendicular(n, { 0, 0, 1 }) end
  return u
end

local function fresnel_schlick(f0, vh)
  local m = 1 - v3.clamp(vh, 0, 1)
  local m5 = (m * m) * (m * m) * m
  return { f0[1] + (1 - f0[1]) * m5, f0[2] + (1 - f0[2]) * m5, f0[3] + (1 - f0[3]) * m5 }
end

local function alphas(p)
  return math.max(p.roughness_x ^ 2, MIN_ALPHA), math.max(p.roughness_y ^ 2, MIN_ALPHA)
end

local aniso_ggx = sn.lighting.define {
  name = "aniso_ggx",
  params = {
    roughness_x = { default = 0.3, range = { 0, 1 }, doc = "perceptual roughness along the tangent (alpha_x = r^2)" },
    roughness_y = { default = 0.7, range = { 0, 1 }, doc = "perceptual roughness along the bitangent" },
    f0 = { type = "rgb", default = { 0.95, 0.93, 0.88 }, range = { 0, 1 }, doc = "F0 (silver by default)" },
    diffuse = { type = "rgb", default = 0, range = { 0, 1 }, doc = "Lambertian albedo; 0 for metals" },
    ambient = { type = "rgb", default = 0.1, range = { 0, 1000 }, doc = "ambient light, reflected with diffuse + f0" },
  },
  attributes = { "tangent" },
  glsl = "aniso_ggx.glsl",
  twin = function(s, p)
    local n, v, l = s.n, s.v, s.l
    local out = v3.mul(p.ambient, v3.add(p.diffuse, p.f0))
    local nl = v3.clamp(v3.dot(n, l), -1, 1)
    if not (nl > 0) then return out end
    local brdf = v3.scale(p.diffuse, nl)
    local nv = v3.clamp(v3.dot(n, v), -1, 1)
    local lv = v3.add(l, v)
    if nv > 0 and v3.dot(lv, lv) > MIN_LENGTH2 then
      local ax, ay = alphas(p)
      local t = aniso_tangent(n, s.tangent)
      local b = v3.cross(n, t)
      local h = v3.normalize(lv)
      local ht, hb, hn = v3.dot(h, t) / ax, v3.dot(h, b) / ay, v3.dot(h, n)
      local d = ht * ht + hb * hb + hn * hn
      local dist = 1 / (PI * ax * ay * math.max(d * d, MIN_DENOMINATOR))
      local vt, vb, lt, lb = ax * v3.dot(v, t), ay * v3.dot(v, b), ax * v3.dot(l, t), ay * v3.dot(l, b)
      local vis = 0.5 * nl / math.max(nl * math.sqrt(nv * nv + vt * vt + vb * vb)
                                      + nv * math.sqrt(nl * nl + lt * lt + lb * lb), MIN_DENOMINATOR)
      brdf = v3.add(brdf, v3.scale(fresnel_schlick(p.f0, v3.dot(v, h)), PI * dist * vis))
    end
    return v3.add(out, v3.mul(s.light_color, brdf))
  end,
  -- pi D <= 1 / (ax ay), V n.l <= 1 / (2 min(ax, ay)), F <= 1.
  bound = function(p, light)
    local ax, ay = alphas(p)
    local lobe = 0.5 / (ax * ay * math.min(ax, ay))
    local out = {}
    for c = 1, 3 do
      out[c] = p.ambient[c] * (p.diffuse[c] + p.f0[c]) + light.color[c] * (p.diffuse[c] + lobe)
    end
    return out
  end,
}

local this = debug.getinfo(1, "S").source:sub(2)
if not (arg and arg[0] == this) then return aniso_ggx end

package.path = this:match("^(.*)/[^/]*$") .. "/?.lua;" .. package.path
require("demo").run(aniso_ggx, { out = arg[1] or "results/lighting", name = "aniso_ggx",
                                 inputs = { "normal", "view", "tangent" },
                                 title = "anisotropic GGX, roughness 0.3 x 0.7" })
