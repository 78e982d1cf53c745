-- The edges of sn.lighting.define, check and stress that a new model runs into: a check that
-- compares nothing is an error, not a pass; the twin sees the attributes the GPU sees; any
-- parameter name that is not a GLSL word works everywhere; names that could not work are refused
-- when the model is defined, saying why.
local sn = require "shadenet"

local function fails(pattern, fn, ...)
  local ok, err = pcall(fn, ...)
  assert(not ok, "expected an error matching '" .. pattern .. "'")
  assert(tostring(err):find(pattern, 1, true), "error: " .. tostring(err) .. "\nexpected: " .. pattern)
end

local function twin_of(k) return function() return { k, k, k } end end

-- 1. A wrong twin is found with the default lights; a lights argument that lists no light (a
--    single light's table, an empty list) is an error, since it would compare nothing. (define
--    holds the twin at the defaults, k = 1, where k and k^3 agree; check finds it at k = 2.)
local wrong = sn.lighting.define {
  name = "edges_wrong_twin", params = { k = { default = 1, range = { 1, 2 } } },
  glsl = "vec3 shade(Surface s, Params p) { return vec3(p.k * max(dot(s.n, s.l), 0.0)); }",
  twin = function(s, p) local d = p.k ^ 3 * math.max(sn.vec3.dot(s.n, s.l), 0); return { d, d, d } end,
}
assert(sn.lighting.check(wrong).max_difference < 1e-5, "right at the defaults")
wrong = wrong:with { k = 2 }
local c = sn.lighting.check(wrong)
assert(c.compared > 0 and c.max_difference > 0.5, "the wrong twin is found: " .. c.max_difference)
fails("got a table with the key 'light'", sn.lighting.check, wrong, { light = { dir = { 1, 0, 0 } } })
fails("got an empty list", sn.lighting.check, wrong, {})
fails("got an empty list", sn.lighting.stress, wrong, {})
fails("got a table with the key 'dir'", sn.lighting.stress, wrong, { dir = { 0, 1, 0 } })
local one = sn.lighting.check(wrong, { { dir = { 0, 1, 0 } } })
assert(one.compared > 0 and one.max_difference > 0.5, "one light in a list is compared")

-- 2. An attribute the model does not declare reaches the GPU as its default (base_color 1), and
--    the twin gets the same: a right twin reading it matches.
local base = sn.lighting.define {
  name = "edges_undeclared_base", params = {},
  glsl = "vec3 shade(Surface s, Params p) { return s.base_color * 0.5; }",
  twin = function(s) return { s.base_color[1] * 0.5, s.base_color[2] * 0.5, s.base_color[3] * 0.5 } end,
}
assert(sn.lighting.check(base).max_difference < 1e-6, "undeclared base_color: " .. sn.lighting.check(base).max_difference)
assert(sn.lighting.stress(base).failures == 0, "stress of the undeclared base_color model")
-- Declared, the twin sees the grid's colours, and the check still matches.
local declared = sn.lighting.define {
  name = "edges_declared_base", params = {}, attributes = { "base_color" },
  glsl = "vec3 shade(Surface s, Params p) { return s.base_color * 0.5; }",
  twin = function(s) return { s.base_color[1] * 0.5, s.base_color[2] * 0.5, s.base_color[3] * 0.5 } end,
}
assert(sn.lighting.check(declared).max_difference < 1e-6, "declared base_color")

-- 3. Parameters named like the uniforms and attributes of the shaders that include a model
--    (view, position, count) render, evaluate and build datasets like any other name.
local glow = sn.lighting.define {
  name = "edges_glow", attributes = { "position" },
  params = {
    view = { type = "rgb", default = { 0, 1, 0 }, range = { -10, 10 } },
    position = { default = 0.5, range = { 0, 1 } },
    count = { default = 2, range = { 0, 4 } },
  },
  glsl = [[vec3 shade(Surface s, Params p) {
  return vec3(p.position * p.count * max(dot(s.n, normalize(p.view)), 0.0) + 0.0 * s.position.x);
}]],
  twin = function(s, p)
    local k = p.position * p.count * math.max(sn.vec3.dot(s.n, sn.vec3.normalize(p.view)), 0)
    return { k, k, k }
  end,
}
assert(sn.lighting.check(glow).max_difference < 1e-5, "parameters named view, position, count")
local scene = sn.scene { mesh = sn.mesh.sphere {}, size = { 48, 48 }, views = { count = 1 } }
local img = scene:render(glow:with { count = 1 }, { view = 1 })
local g = scene:gbuffer { view = 1, attributes = { "normal" } }
local n = g:read("normal"):get(24, 24)
local expect = 0.5 * math.max(n[2] / math.sqrt(n[1] ^ 2 + n[2] ^ 2 + n[3] ^ 2), 0)
assert(math.abs(img:get(24, 24)[1] - expect) < 1e-4, ("render: %g against %g"):format(img:get(24, 24)[1], expect))
assert(scene:dataset { target = glow, samples = 200 }:counts() > 0, "a dataset of the model")

-- 4. Refused when defined, naming the reason: a parameter named by a GLSL keyword or type, a
--    model named like one of sn.lighting's functions, GLSL whose only shade() is commented out.
local function define(name, params, glsl)
  return sn.lighting.define { name = name, params = params, twin = twin_of(1),
                              glsl = glsl or "vec3 shade(Surface s, Params p) { return vec3(1.0); }" }
end
for _, word in ipairs { "in", "out", "vec3", "float", "sampler2D", "mat3x4", "class", "dvec2" } do
  fails("parameter '" .. word .. "': the name is a GLSL keyword or type", define, "edges_kw",
        { [word] = { default = 1, range = { 0, 2 } } })
end
for _, fn in ipairs { "stress", "check", "define", "new", "models", "stress_cases" } do
  fails("the name is taken by the function sn.lighting." .. fn, define, fn, {})
end
fails("must define vec3 shade(Surface s, Params p)", define, "edges_commented", {},
      "// vec3 shade(Surface s, Params p) { return vec3(1.0); }\n/* vec3 shade(Surface s, Params p) */\nvec3 f() { return vec3(1.0); }")
-- A name that only contains a keyword is fine.
assert(define("edges_fine", { input_gain = { default = 1, range = { 0, 2 } }, vec3ish = { default = 1, range = { 0, 2 } } }))

-- 5. A model whose GLSL gives NaN or Inf somewhere (its twin too: define holds the two to each
--    other, the stress test to finite values): a dataset of it is an error naming the first such
--    sample, not a dataset of clamped made-up targets (sqrt of a negative cosine stored as 0, 1/0 as 1).
local nanny = sn.lighting.define {
  name = "edges_nanny", params = {},
  glsl = "vec3 shade(Surface s, Params p) { float d = dot(s.n, s.l); return vec3(sqrt(d), 0.5, d < 0.0 ? 1.0 / 0.0 : 0.0); }",
  twin = function(s) local d = sn.vec3.dot(s.n, s.l); return { math.sqrt(d), 0.5, d < 0 and math.huge or 0 } end,
}
fails("lighting model 'edges_nanny' gave NaN or infinite radiance for ", function()
  return scene:dataset { target = nanny, samples = 300 }
end)
fails("(the first: normal (", sn.dataset.sample, { target = nanny, n = 1000, seed = 1 })
-- A finite model's datasets are unchanged by the check.
assert(scene:dataset { target = glow, samples = 300 }:counts() > 0)

-- 6. A name defined again with other GLSL is another model; again with the same GLSL (a script
--    re-run in live mode), the same one.
local function constant(k)
  return sn.lighting.define { name = "edges_constant", params = {},
                              glsl = ("vec3 shade(Surface s, Params p) { return vec3(%.1f); }"):format(k),
                              twin = twin_of(k) }
end
local first, second, again = constant(0.2), constant(0.7), constant(0.7)
assert(first ~= second and second == again and first == first, "equality follows the definition")
print("ok")
