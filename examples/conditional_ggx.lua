-- One network for a whole family of materials (the thesis' future work, chapter 5: "introduce the
-- attributes into inputs"): GGX gold over roughness 0.1-0.8, the roughness an input of the
-- network. The dataset draws each row's roughness at random in the range (scene:dataset{vary});
-- rendering passes the roughness as a value (a uniform), so the same trained network draws any
-- roughness in the range -- from a script, or from the live REPL with net:set_input.
--   build/shadenet examples/conditional_ggx.lua [OUT_DIR]        (default results/conditional_ggx)
-- Writes OUT_DIR/conditional_ggx.png (the model | the network | |error| at five roughnesses, on a
-- mesh it never saw), OUT_DIR/table.md (image MSE beside a network trained for each roughness
-- alone) and OUT_DIR/conditional_ggx.snmlp (the network, its condition and range included).
local sn = require "shadenet"

local out = arg and arg[1] or "results/conditional_ggx"
local t0 = sn.clock()
sn.fs.mkdir(out)

-- The cloth in 5 poses from three heights (the experiments' default data, smaller images).
local poses = { {}, { rotate = { 60, 1, 0, 0 } }, { rotate = { -60, 1, 0, 0 } },
                { rotate = { 60, 0, 0, 1 } }, { rotate = { -60, 0, 0, 1 } } }
local cloth = sn.scene { mesh = "meshes/cloth.glb", size = { 320, 240 }, poses = poses,
                         views = { { count = 4, elevation = -30 }, { count = 4, elevation = 20 },
                                   { count = 4, elevation = 60 } } }
local gold = sn.lighting.ggx {}
local hidden = { 16, 16, 16, 16, 16, 16 }
local recipe = { epochs = 20, batch = 8, adam = { lr = 0.00025, beta1 = 0.8, beta2 = 0.9 }, seed = 1, keep = "best" }
local function train(data, inputs)
  local net = sn.mlp { inputs = inputs, hidden = hidden, outputs = 3, seed = 1 }
  recipe.nets, recipe.data = { net }, data
  return net, sn.train(recipe)[1]
end

-- 1. The conditioned network: normal, view and roughness in; 64,149 rows, each its own roughness.
local data = cloth:dataset { target = gold, vary = { roughness = { 0.1, 0.8 } },
                             inputs = { "normal", "view", "roughness" }, seed = 1 }
local net, run = train(data, 7)
print(string.format("conditioned %s: best validation MSE %.3g over roughness 0.1-0.8 (%.1f s)", tostring(net),
                    run.best_val_mse, run.wall_time))
net:save(out .. "/conditional_ggx.snmlp")

-- 2. Five roughnesses on a mesh none of the networks saw, beside a network trained on that
--    roughness alone (same size, same rows, same recipe).
local blob = sn.scene { mesh = "meshes/test_blob.glb", size = { 200, 200 }, views = { count = 3, elevation = 25 } }
local panels, truths, mines, heats, rows = {}, {}, {}, {}, {}
local roughnesses = { 0.1, 0.275, 0.45, 0.625, 0.8 }
for k, r in ipairs(roughnesses) do
  local model = gold:with { roughness = r }
  local truth = blob:render(model, { view = 2 })
  local mine = sn.image.clamp(blob:render(net, { view = 2, values = { roughness = r } }))
  local alone = train(cloth:dataset { target = model, inputs = { "normal", "view" }, seed = 1 }, 6)
  local theirs = sn.image.clamp(blob:render(alone, { view = 2 }))
  rows[k] = { r = r, mse = sn.image.mse(truth, mine, { channels = 3, mask = truth }),
              alone = sn.image.mse(truth, theirs, { channels = 3, mask = truth }) }
  truths[k], mines[k] = truth, mine
  heats[k] = sn.image.heatmap(sn.image.diff(truth, mine), { mask = truth, max = 0.2, label = "|error|" })
  print(string.format("roughness %.3f: image MSE %.3g (a network for this roughness alone: %.3g)", r, rows[k].mse,
                      rows[k].alone))
end
for k, r in ipairs(roughnesses) do panels[#panels + 1] = { image = truths[k], caption = "roughness " .. r } end
for k in ipairs(roughnesses) do panels[#panels + 1] = { image = mines[k], caption = string.format("MSE %.2g", rows[k].mse) } end
for k in ipairs(roughnesses) do panels[#panels + 1] = { image = heats[k], caption = "" } end
sn.image.grid { panels = panels, columns = #roughnesses, row_labels = { "GGX", "one network", "|error|" },
                title = "One network for GGX gold at every roughness 0.1-0.8 (test blob, not trained on)" }
  :save(out .. "/conditional_ggx.png")

-- 3. The table.
local md = { "## One network over GGX roughness 0.1-0.8 (examples/conditional_ggx.lua)\n\n" }
md[#md + 1] = (string.format("%s, inputs normal, view, roughness; trained on the cloth in 5 poses x 3 rings (64,149 rows, "
                      .. "each its own roughness), best validation MSE %.3g. Image MSE on the test blob (not trained "
                      .. "on), beside a network of the same size trained on one roughness alone.\n\n",
                      tostring(net), run.best_val_mse))
md[#md + 1] = "| roughness | image MSE, one network for all | image MSE, a network for this roughness |\n|---:|---:|---:|\n"
for _, row in ipairs(rows) do md[#md + 1] = string.format("| %.3f | %.3g | %.3g |\n", row.r, row.mse, row.alone) end
sn.fs.write(out .. "/table.md", table.concat(md))  -- whole or not at all
print(string.format("wrote %s/conditional_ggx.png, table.md, conditional_ggx.snmlp (%.0f s)", out, sn.clock() - t0))
