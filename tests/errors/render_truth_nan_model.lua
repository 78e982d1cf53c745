-- expect: render_truth_nan_model\.lua:8: lighting model badsqrt gives a NaN or infinite radiance at [0-9]+ covered pixels \(the first at \([0-9]+, [0-9]+\)\); its shade must be finite for every input
-- A model whose GLSL gives NaN (sqrt of a negative n.l) drew those pixels black in a truth render.
local sn = require "shadenet"
sn.lighting.define { name = "badsqrt", params = { a = { default = 1, range = { 0, 2 } } },
  glsl = "vec3 shade(Surface s, Params p) { return vec3(p.a * sqrt(dot(s.n, s.l))); }",
  twin = function(s, p) local d = p.a * math.sqrt(sn.vec3.dot(s.n, s.l)); return { d, d, d } end }
local scene = sn.scene { mesh = sn.mesh.sphere {}, size = { 32, 32 }, views = { count = 1 } }
local img = scene:render(sn.lighting.badsqrt {})
