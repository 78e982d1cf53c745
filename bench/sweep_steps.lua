-- The steps of Table 4.1's sweep outside the training, each as the table runs it: building its
-- dataset (the posed cloth, 120 views of 640 x 480, 64,149 rows; a new seed per repeat, so the
-- cache builds anew) and scoring networks of its 36 shapes on the unseen meshes (15 views of
-- 160 x 120, `sn.render_errors` through E:unseen_errors; untrained networks cost what trained
-- ones do).
--
--   shadenet bench/sweep_steps.lua [repeats] [seeds]
--     repeats: timings per step; the median is printed (default 5)
--     seeds:   networks per shape scored in one call (default 3: 108 networks; the table's 10: 360)
--
-- Run from the repository root (the unseen meshes' paths are relative to it). Times are
-- sn.clock() (wall clock) around one call; "load" is the 1-minute load average before the
-- step's first run. Ctrl-C stops it after the call in flight (that step is not printed), removes
-- its scratch folder and exits 130.
local sn = require "shadenet"
package.path = (arg[0]:match("^(.*)/[^/]*$") or ".") .. "/?.lua;" .. package.path
local B = require "common"
local exp = require "lib.experiment"
local thesis = require "lib.thesis"

local o = B.args("bench/sweep_steps.lua", { { "repeats", "5", B.whole(1) }, { "seeds", "3", B.whole(1) } })
local repeats, seeds = o.repeats, o.seeds
-- Before the scratch folder exists: SIGINT's default action would end the process before the
-- Lua state closes, and the folder (the experiment's records) would stay in TMPDIR.
B.catch_interrupt()
local out = sn.fs.tempdir("sweep_steps")
local E = exp.start("sweep_steps", { "--out", out })
B.stop_if_interrupted()
local desc = E:data_desc { model = "phong" }
local scene = E:scene(desc.scene)
local nets = {}
for s = 1, seeds do
  for _, layers in ipairs(thesis.sizes) do
    for _, width in ipairs(thesis.sizes) do
      nets[#nets + 1] = sn.mlp { inputs = desc.inputs, hidden = exp.rep(width, layers), seed = s }
    end
  end
end
B.stop_if_interrupted()
E:unseen_errors(nets, desc)  -- the unseen scenes, their G-buffers and truths: built once, as in the table
B.stop_if_interrupted()

local function bench(name, f)
  local load = B.load()
  local times = {}
  for i = 1, repeats do
    collectgarbage()
    local t0 = sn.clock()
    f(i)
    times[i] = sn.clock() - t0
    B.stop_if_interrupted("the step '" .. name .. "'")
  end
  local lo, hi = math.min(unpack(times)), math.max(unpack(times))
  print(("%-44s %9.3f %9.3f %9.3f %6s"):format(name, B.median(times), lo, hi, load))
end

print(("%-44s %9s %9s %9s %6s"):format("step (" .. repeats .. " repeats)", "median s", "min s", "max s", "load"))
bench("dataset (64,149 rows of 120 views)", function(i)
  scene:dataset { inputs = desc.inputs, target = exp.model(desc.model), color = desc.color, samples = desc.samples,
                  split = desc.split, seed = 1000 + i }
end)
bench(("unseen-mesh errors (%d networks x 15 views)"):format(#nets), function() E:unseen_errors(nets, desc) end)
