-- Oren-Nayar diffuse reflection as a lighting model defined in Lua + GLSL (no C++): the GLSL is
-- oren_nayar.glsl beside this file, the twin below computes the same in double precision.
-- Run it to check the shader against the twin, stress it, train a network and write
-- results/lighting/oren_nayar.png (truth | network | error on meshes the network never saw):
--   build/shadenet examples/lighting/oren_nayar.lua [OUT_DIR]
-- `require` it (package.path holding examples/lighting/) to get the model without the demo.
local sn = require "shadenet"
local v3 = sn.vec3

local oren_nayar = sn.lighting.define {
  name = "oren_nayar",
  params = {
    sigma = { default = 0.5, range = { 0, 1.5707963 }, doc = "slope deviation of the V-cavities (radians)" },
    albedo = { type = "rgb", default = { 0.8, 0.8, 0.8 }, range = { 0, 1 }, doc = "reflectance at normal incidence" },
    ambient = { default = 0.1, range = { 0, 1 }, doc = "d, the ambient share, as in Phong" },
  },
  glsl = "oren_nayar.glsl",
  twin = function(s, p)
    local nl, nv = v3.clamp(v3.dot(s.n, s.l), -1, 1), v3.clamp(v3.dot(s.n, s.v), -1, 1)
    local s2 = p.sigma * p.sigma
    local a, b = 1 - 0.5 * s2 / (s2 + 0.33), 0.45 * s2 / (s2 + 0.09)
    local rough = 0
    if nl > 0 and nv > 0 then
      local cos_phi = math.max(v3.dot(v3.normalize(v3.sub(s.l, v3.scale(s.n, nl))),
                                      v3.normalize(v3.sub(s.v, v3.scale(s.n, nv)))), 0)
      local sin_i, sin_r = v3.length(v3.cross(s.n, s.l)), v3.length(v3.cross(s.n, s.v))
      local sin_alpha = nl < nv and sin_i or sin_r
      local tan_beta = nl < nv and sin_r / nv or sin_i / nl
      rough = b * cos_phi * sin_alpha * tan_beta
    end
    local k = p.ambient + (1 - p.ambient) * math.max(nl, 0) * (a + rough)
    return v3.scale(v3.mul(s.light_color, p.albedo), k)
  end,
}

local this = debug.getinfo(1, "S").source:sub(2)
if not (arg and arg[0] == this) then return oren_nayar end

package.path = this:match("^(.*)/[^/]*$") .. "/?.lua;" .. package.path
require("demo").run(oren_nayar:with { sigma = 0.6 }, { out = arg[1] or "results/lighting", name = "oren_nayar",
                                                 title = "Oren-Nayar, sigma 0.6" })
