-- A lighting model defined in a 29-line script (examples/lighting/live_model.lua) runs live:
-- `shadenet --watch` draws its truth; saving its GLSL file re-runs the script, which redefines the
-- model and redraws with the new shader, while the network trained under sn.keep is kept. A GLSL
-- its twin no longer matches, or one that does not compile, is an error shown once, and the last
-- good model keeps drawing (it holds the GLSL it was defined with).
local sn = require "shadenet"
package.path = "tests/live/?.lua;" .. package.path
local H = require "harness"

local dir = "out/live_tests/lighting_model"
os.execute(("rm -rf %q && mkdir -p %q"):format(dir, dir))
local script = H.read("examples/lighting/live_model.lua")
script = script:gsub('mode = "side"', 'mode = "truth"') .. '\nprint("RUN")\n'
H.write(dir .. "/live_model.lua", script)
H.write(dir .. "/minnaert.glsl", H.read("examples/lighting/minnaert.glsl"))

local s = H.start { dir = dir .. "/session", script = dir .. "/live_model.lua", window = false, limit = 60 }
s:wait_frame(1)
local first = s:image(1)
local w, h = first:size()
local function centre(img) return img:get(math.floor(w / 2) + 1, math.floor(h / 2) + 1) end
local c1 = centre(first)
assert(c1[4] == 1 and c1[1] > 0.05 and math.abs(c1[1] - c1[3]) < 1e-6, "a grey Minnaert truth at the centre")

-- Tint the shader and save it the way editors do: its twin no longer matches, which the re-run
-- says, and the untinted model stays.
local glsl = H.read(dir .. "/minnaert.glsl"):gsub("return s%.light_color %* p%.albedo", "return vec3(1.0, 0.6, 0.3) * s.light_color * p.albedo")
H.write(dir .. "/minnaert.glsl", glsl)
s:wait_log("sn%.lighting%.define 'minnaert': its GLSL gives")
local c = centre(s:image(s:settle()))
assert(c[1] == c1[1] and c[3] == c1[3], "the last good model is drawn")
-- Tint the twin too: the new model is drawn.
local tinted, a, b
tinted, a = script:gsub("local k = nl %^ p%.k %* nv %^ %(p%.k %- 1%)", "local k = nl ^ p.k * nv ^ (p.k - 1)\n    k = { k, 0.6 * k, 0.3 * k }")
tinted, b = tinted:gsub("s%.light_color%[(%d)%] %* p%.albedo%[%d%] %* k", "s.light_color[%1] * p.albedo[%1] * k[%1]")
assert(a == 1 and b == 3, "the twin is tinted as the GLSL is")
H.write(dir .. "/live_model.lua", tinted)
s:wait_log("RUN\n.*RUN")
local n = s:settle()
local c2 = centre(s:image(n))
assert(math.abs(c2[1] - c1[1]) < 1e-5 and math.abs(c2[3] - 0.3 * c1[3]) < 1e-5,
       ("the edited shader is drawn: red %.4f -> %.4f, blue %.4f -> %.4f"):format(c1[1], c2[1], c1[3], c2[3]))
local log = s:log()
local _, trained = log:gsub("trained mlp", "")
assert(trained == 1, "the network was trained once and kept across the re-runs:\n" .. log)

-- A GLSL error on save keeps the last good model on screen and names the file and line, once:
-- the model on screen holds its own GLSL, so its frames do not compile the broken file again.
local before = #s:log()
H.write(dir .. "/minnaert.glsl", glsl:gsub("pow%(nl, p%.k%)", "pow(nl, p.kk)"))
s:wait_log("minnaert%.glsl:%d+")
local c3 = centre(s:image(s:settle()))
assert(c3[1] == c2[1] and c3[3] == c2[3], "the last good model is drawn")
local _, errors = s:log():sub(before + 1):gsub("GLSL compile error", "")
assert(errors == 1, "the error is reported once:\n" .. s:log():sub(before + 1))
s:stop()

-- A conditioned network's roughness changes from the console: the next frame shows it, with no
-- retraining.
H.write(dir .. "/conditioned.lua", [[
local sn = require "shadenet"
local scene = sn.scene { mesh = sn.mesh.sphere {}, size = { 64, 64 }, views = { count = 4 } }
local net = sn.keep("conditioned", function()
  local data = scene:dataset { target = sn.lighting.ggx {}, vary = { roughness = { 0.1, 0.8 } },
                               inputs = { "normal", "view", "roughness" }, samples = 3000 }
  local net = sn.mlp { inputs = 7, hidden = { 12, 12 }, seed = 1 }
  sn.train { nets = { net }, data = data, epochs = 3, batch = 8 }
  print("trained conditioned")
  return net
end)
sn.live.show { scene = scene, network = net, mode = "network" }
]])
local c = H.start { dir = dir .. "/conditioned_session", script = dir .. "/conditioned.lua", window = false, limit = 60 }
c:wait_frame(1)
local before = c:image(c:settle())
c:send('net:set_input("roughness", 0.75)')
local after = c:image(c:settle())
assert(sn.image.mse(before, after, { channels = 3 }) > 1e-6, "the new roughness is drawn")
local _, trained = c:log():gsub("trained conditioned", "")
assert(trained == 1, "no retraining:\n" .. c:log())
c:stop()
print("ok")
