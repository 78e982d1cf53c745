-- sn.render_errors scores many networks over many views at once, on every thread: each number
-- must be the one net:render, sn.image.clamp, sn.image.mse and sn.image.ssim give one at a time
-- (to the bit), for the cpu kernels and for a network only the fragment shader can draw, with
-- its NaN or infinite pixels counted (such a render is not scored: NaN, whichever backend drew
-- it); bad arguments are errors that say what is wrong.
local sn = require "shadenet"
local expect = require "expect"

local phong = sn.lighting.phong {}
local blob = sn.scene { mesh = "meshes/test_blob.glb", size = { 120, 90 }, views = { count = 3, elevation = 20 } }
local sphere = sn.scene { mesh = sn.mesh.sphere {}, size = { 80, 60 }, views = { count = 2, elevation = -20 } }
local views = {}
for v = 1, 3 do
  views[#views + 1] = { gbuffer = blob:gbuffer { view = v, attributes = { "normal", "view" } }, truth = blob:render(phong, { view = v }) }
end
views[#views + 1] = { gbuffer = sphere:gbuffer { view = 2, attributes = { "view", "normal" } }, truth = sphere:render(phong, { view = 2 }) }

-- softsign written with a loop, which the cpu backend does not translate: a network for the fragment shader
sn.activation.define { name = "softsign_e", glsl = "vec4 s = x; for (int i = 0; i < 1; i++) s = s / (1.0 + abs(s)); return s;",
                       grad = "1.0 / ((1.0 + abs(x)) * (1.0 + abs(x)))",
                       lua = function(x) return x / (1 + math.abs(x)) end,
                       lua_grad = function(x) return 1 / (1 + math.abs(x)) ^ 2 end }
local attrs = { "normal", "view" }
local nets = {
  sn.mlp { inputs = attrs, hidden = { 8, 8 }, outputs = 3, seed = 1 },
  sn.mlp { inputs = attrs, hidden = { 12, 12, 12 }, outputs = 3, seed = 2, color = "hsv" },
  sn.mlp { inputs = { "view", "normal" }, hidden = { 4 }, outputs = 3, seed = 3, activation = "relu" },
  sn.mlp { inputs = attrs, hidden = { 8 }, outputs = 3, seed = 4, activation = "softsign_e" },  -- gl only
  sn.mlp { inputs = attrs, hidden = { 6 }, outputs = 3, seed = 5, output_activation = "exponential" },
  -- nets[1]'s inputs encoded: the same G-buffer reads, other first-layer inputs
  sn.mlp { inputs = attrs, hidden = { 8, 8 }, outputs = 3, seed = 6, encoding = { view = { "frequency", bands = 2 } } },
}
nets[5].layers[2].bias = { 0, 200, 0 }  -- exp(200) overflows: infinite green on every covered pixel

local errors = sn.render_errors { nets = nets, views = views, nonfinite = "ignore" }
assert(#errors == #nets)
local backends, distinct = {}, {}
for i, net in ipairs(nets) do
  assert(#errors[i] == #views)
  for k, v in ipairs(views) do
    local mine = sn.image.clamp(net:render(v.gbuffer, { nonfinite = "ignore" }))
    local info = sn.render_info()
    backends[info.backend] = true
    local mse = sn.image.mse(v.truth, mine, { channels = 3, mask = v.truth })
    local ssim = sn.image.ssim(v.truth, mine, { channels = 3, mask = v.truth })
    local e = errors[i][k]
    if info.nonfinite > 0 then  -- not scored: clamped, an infinity would pass as a plausible 1
      assert(e.mse ~= e.mse and e.ssim ~= e.ssim and e.nonfinite == info.nonfinite and mse == mse,
             ("net %d view %d: %g %g %d pixels"):format(i, k, e.mse, e.ssim, e.nonfinite))
    else
      assert(e.mse == mse and e.ssim == ssim and e.nonfinite == info.nonfinite,
             ("net %d view %d: mse %.17g ssim %.17g nonfinite %d, one at a time %.17g %.17g %d"):format(
               i, k, e.mse, e.ssim, e.nonfinite, mse, ssim, info.nonfinite))
      distinct[("%.17g"):format(e.mse)] = true
    end
  end
end
assert(backends.gl, "the softsign network drew with the fragment shader")
local count = 0
for _ in pairs(distinct) do count = count + 1 end
assert(count == (#nets - 1) * #views, "every network and view has an error of its own (but nets[5]'s, NaN)")
assert(errors[5][1].nonfinite > 100 and errors[1][1].nonfinite == 0, "infinite pixels counted")
expect.fails(function()
  sn.render_errors { nets = { nets[5] }, views = views, nonfinite = "error" }
end, "pixels are NaN or infinite")
-- A network whose render is NaN (inf - inf) cannot be scored: its pairs are NaN with the pixels
-- counted, and the networks beside it in the batch are scored as alone.
local nan_net = sn.mlp { inputs = attrs, hidden = { 2 }, outputs = 3, activation = "relu" }
nan_net.layers[1].weight = { { 3e38, 3e38, 3e38, 3e38, 3e38, 3e38 }, { 3e38, 3e38, 3e38, 3e38, 3e38, 3e38 } }
nan_net.layers[2].weight = { { 1, -1 }, { 1, -1 }, { 1, -1 } }
local with_nan = sn.render_errors { nets = { nets[1], nan_net }, views = views, nonfinite = "ignore" }
local nan_views = 0
for k = 1, #views do
  assert(with_nan[1][k].mse == errors[1][k].mse and with_nan[1][k].ssim == errors[1][k].ssim, "view " .. k)
  local e = with_nan[2][k]
  if e.mse ~= e.mse then
    nan_views = nan_views + 1
    assert(e.ssim ~= e.ssim and e.nonfinite > 0, ("NaN network, view %d: %g %g %d"):format(k, e.mse, e.ssim, e.nonfinite))
  end
end
assert(nan_views >= 3, "the blob's views are NaN: " .. nan_views)
expect.fails(function()
  sn.render_errors { nets = { nets[1], nan_net }, views = views, nonfinite = "error" }
end, "pixels are NaN or infinite")
-- One network as itself, an empty list of views
assert(sn.render_errors { nets = nets[1], views = { views[2] } }[1][1].mse == errors[1][2].mse)
assert(#sn.render_errors { nets = nets, views = {} }[1] == 0)

expect.fails(function()
  sn.render_errors { nets = nets, views = { { gbuffer = views[1].gbuffer, truth = views[4].truth } } }
end, "view 1's truth is 80x60x4; RGBA of the G-buffer's 120x90 expected")
expect.fails(function()
  sn.render_errors { nets = { nets[1], "net" }, views = views }
end, "'nets': element 2 is string, not an Mlp")
expect.fails(function()
  sn.render_errors { nets = nets, views = { { gbuffer = views[1].gbuffer } } }
end, "element 1: 'truth' must be an Image, got nil")
-- Two copies of a conditioned network, each rendering at its own value: the inputs differ only
-- in that value, and each pair's error is the one its own render gives.
local sphere_ggx = sphere:dataset { target = sn.lighting.ggx {}, vary = { roughness = { 0.1, 0.8 } },
                                    inputs = { "normal", "view", "roughness" }, samples = 2000 }
local twins = {}
for t = 1, 2 do
  twins[t] = sn.mlp { inputs = 7, hidden = { 8 }, seed = 7 }
  sn.train { nets = { twins[t] }, data = sphere_ggx, epochs = 1, batch = 8 }
end
twins[1]:set_input("roughness", 0.2)
twins[2]:set_input("roughness", 0.7)
local sphere_view = { gbuffer = sphere:gbuffer { view = 1, attributes = { "normal", "view" } },
                      truth = sphere:render(sn.lighting.ggx {}, { view = 1 }) }
local e3 = sn.render_errors { nets = twins, views = { sphere_view } }
for t = 1, 2 do
  local mine = sn.image.clamp(twins[t]:render(sphere_view.gbuffer))
  assert(e3[t][1].mse == sn.image.mse(sphere_view.truth, mine, { channels = 3, mask = sphere_view.truth }))
end
assert(e3[1][1].mse ~= e3[2][1].mse, "the condition's value reaches the render")

local positional = sn.mlp { inputs = { "position", "normal" }, hidden = { 4 }, outputs = 3, seed = 6 }
expect.fails(function()
  sn.render_errors { nets = { positional }, views = views }
end, "position")
print("ok")
