-- shadenet's first job: teach two tiny networks to shade like the Phong and the GGX lighting
-- models, then compare them with the models on the mesh they learned from and on five meshes
-- they never saw. Run from the repository root:
--   build/shadenet examples/quickstart.lua [OUT_DIR]      (default results/quickstart)
-- It writes OUT_DIR/quickstart.png (per model: truth, network and error on every mesh),
-- OUT_DIR/coverage.png (what the training rows cover) and OUT_DIR/table.md, and prints where they are. 3-6 s on a 2-core machine without a GPU.
local sn = require "shadenet"

local out = arg and arg[1] or "results/quickstart"
local t_start = sn.clock()

-- 1. Training data that covers the directions a mesh can face. A network learns the rows it
--    sees: the hanging cloth alone has no normal pointing further up than y = 0.40, so trained
--    on it a network never sees the highlight most other meshes have. Tilting the cloth by
--    +-60 degrees about x and about z (5 poses), each seen from three heights (rings of 8 views at
--    -30, 20 and 60 degrees), covers the sphere of normals and the views around them.
local poses = { {}, { rotate = { 60, 1, 0, 0 } }, { rotate = { -60, 1, 0, 0 } },
                { rotate = { 60, 0, 0, 1 } }, { rotate = { -60, 0, 0, 1 } } }
local cloth = sn.scene { mesh = "meshes/cloth.glb", size = { 640, 480 }, poses = poses,
                         views = { { count = 8, elevation = -30 }, { count = 8, elevation = 20 },
                                   { count = 8, elevation = 60 } } }

-- 2. Meshes to look at: the cloth (upright) and five meshes no network trains on, each from
--    three elevations (-30, 20 and 60 degrees; one camera per ring).
local rings = { { count = 3, elevation = -30 }, { count = 3, elevation = 20 }, { count = 3, elevation = 60 } }
local views = { 1, 5, 9 }
local meshes = {
  { label = "cloth (trained on)", mesh = "meshes/cloth.glb" },
  { label = "test blob", mesh = "meshes/test_blob.glb" },
  { label = "Duck", mesh = "../shared/meshes/Duck.gltf" },
  { label = "Box", mesh = "../shared/meshes/Box.gltf" },
  { label = "sphere", mesh = sn.mesh.sphere {} },
  { label = "torus", mesh = sn.mesh.torus {} },
}
for _, m in ipairs(meshes) do m.scene = sn.scene { mesh = m.mesh, size = { 240, 180 }, views = rings } end

-- 3. What to learn: two lighting models and a network for each.
local cases = {
  { name = "Phong", model = sn.lighting.phong {}, hidden = { 16, 16, 16, 16, 16, 16 } },
  { name = "GGX", model = sn.lighting.ggx {}, hidden = { 16, 16, 16, 16, 16, 16 } },
}

-- The brightest covered pixel's luminance: a highlight the network misses lowers it.
local function peak(img)
  local w, h = img:size()
  local best = 0
  for y = 1, h do
    for x = 1, w do
      local p = img:get(x, y)
      if p[4] > 0.5 then best = math.max(best, 0.2126 * p[1] + 0.7152 * p[2] + 0.0722 * p[3]) end
    end
  end
  return best
end

local panels, row_labels, rows = {}, {}, {}
for _, c in ipairs(cases) do
  -- 4. A dataset: world normal + view direction -> the model's RGB at 64,149 covered pixels,
  --    split 4:1 into training and validation rows.
  local data = cloth:dataset { inputs = { "normal", "view" }, target = c.model, seed = 1 }
  if c == cases[1] then
    -- What the rows cover (ds:coverage): the share of the sphere of normals and of the view
    -- hemisphere they fill, and how much of the test blob lies outside; drawn as a figure.
    sn.fs.mkdir(out)
    local cov = data:coverage { against = meshes[2].scene, figure = out .. "/coverage.png",
                                title = "training rows (cloth, 5 poses x 3 rings) against the test blob" }
    print(string.format("coverage: %.0f%% of the normal sphere, %.0f%% of the view hemisphere; %.1f%% of the test "
                        .. "blob's pixels fall outside (normals y %.2f..%.2f)", 100 * cov.normal.fraction,
                        100 * cov.view.fraction, 100 * cov.outside.either, cov.normal.y_min, cov.normal.y_max))
  end
  local net = sn.mlp { inputs = 6, hidden = c.hidden, outputs = 3, activation = "tanh", seed = 1 }

  -- 5. Train with the thesis' settings: 20 epochs, minibatches of 8, Adam(0.00025, 0.8, 0.9).
  --    keep = "best" leaves the network with the weights of its best validation epoch.
  local r = sn.train { nets = { net }, data = data, epochs = 20, batch = 8,
                       adam = { lr = 0.00025, beta1 = 0.8, beta2 = 0.9 }, seed = 1, keep = "best" }
  local result = r[1]
  if sn.interrupted() then  -- Ctrl-C: a half-trained network is no result to show
    print(string.format("quickstart: stopped by Ctrl-C while training the %s network; "
                        .. "quickstart.png and table.md not written", c.name))
    os.exit(130)
  end
  print(string.format("%-5s %s: best validation MSE %.3g at epoch %d, trained in %.1f s on %s",
                      c.name, tostring(net), result.best_val_mse, result.best_epoch, result.wall_time, result.backend))

  -- 6. Render the model and the network on every mesh; measure image MSE and SSIM over the
  --    covered pixels of each view, the network's image clamped to [0, 1] as a display shows it.
  local row = { name = c.name, net = tostring(net), val_mse = result.best_val_mse, seconds = result.wall_time,
                meshes = {} }
  local truths, mines, heats = {}, {}, {}
  for k, m in ipairs(meshes) do
    local mse, ssim = 0, 0
    for _, v in ipairs(views) do
      local truth = m.scene:render(c.model, { view = v })
      local mine = sn.image.clamp(m.scene:render(net, { view = v }))
      mse = mse + sn.image.mse(truth, mine, { channels = 3, mask = truth }) / #views
      ssim = ssim + sn.image.ssim(truth, mine, { channels = 3, mask = truth }) / #views
      if v == views[2] then
        -- The figure shows the middle elevation, cropped to the mesh.
        local x, y, w, h = sn.image.covered_box(truth)
        truths[k], mines[k] = sn.image.crop(truth, x, y, w, h), sn.image.crop(mine, x, y, w, h)
        heats[k] = sn.image.heatmap(sn.image.diff(truths[k], mines[k]), { mask = truths[k], max = 0.2, label = "|error|" })
      end
    end
    row.meshes[k] = { mse = mse, ssim = ssim, peak = peak(mines[k]) / peak(truths[k]) }
    if k > 1 then
      row.unseen_mse = (row.unseen_mse or 0) + mse / (#meshes - 1)
      row.unseen_ssim = (row.unseen_ssim or 0) + ssim / (#meshes - 1)
    end
  end
  for k, m in ipairs(meshes) do panels[#panels + 1] = { image = truths[k], caption = m.label } end
  for k in ipairs(meshes) do
    panels[#panels + 1] = { image = mines[k], caption = string.format("MSE %.2g, SSIM %.2f, peak %.2f", row.meshes[k].mse,
                                                                          row.meshes[k].ssim, row.meshes[k].peak) }
  end
  for k in ipairs(meshes) do panels[#panels + 1] = { image = heats[k], caption = "" } end
  for _, what in ipairs { "the model", "network", "|error|" } do row_labels[#row_labels + 1] = c.name .. ": " .. what end
  print(string.format("%-5s image MSE on the cloth %.3g; on the 5 unseen meshes %.3g (%.1fx), SSIM %.3f", c.name,
                      row.meshes[1].mse, row.unseen_mse, row.unseen_mse / row.meshes[1].mse, row.unseen_ssim))
  rows[#rows + 1] = row
end

-- 7. The figure and a small table.
sn.fs.mkdir(out)
local figure = sn.image.grid { panels = panels, columns = #meshes, row_labels = row_labels,
                               title = "shadenet quickstart: networks trained on the posed cloth, shown on meshes they never saw" }
figure:save(out .. "/quickstart.png")

local head = "| model | network | validation MSE |"
local rule = "|---|---|---:|"
for _, m in ipairs(meshes) do
  head = head .. " " .. m.label .. ": image MSE / SSIM / peak |"
  rule = rule .. "---:|"
end
local lines = { head .. " unseen meshes: mean image MSE / SSIM | unseen / cloth MSE | training time (s) |",
                rule .. "---:|---:|---:|" }
for _, r in ipairs(rows) do
  local cells = { r.name, r.net, string.format("%.3g", r.val_mse) }
  for _, m in ipairs(r.meshes) do cells[#cells + 1] = string.format("%.3g / %.3f / %.2f", m.mse, m.ssim, m.peak) end
  cells[#cells + 1] = string.format("%.3g / %.3f", r.unseen_mse, r.unseen_ssim)
  cells[#cells + 1] = string.format("%.1f", r.unseen_mse / r.meshes[1].mse)
  cells[#cells + 1] = string.format("%.1f", r.seconds)
  lines[#lines + 1] = "| " .. table.concat(cells, " | ") .. " |"
end
lines[#lines + 1] = ""
lines[#lines + 1] = "Image MSE and SSIM over covered pixels, mean of 3 views per mesh (elevations -30, 20, 60 degrees). "
  .. "Peak: the brightest covered pixel's luminance in the network's image over the model's, in the middle view "
  .. "(below 1 where a highlight is missing or dimmed)."
-- sn.fs.write: a temporary file, every write checked, renamed: never a half-written table.
sn.fs.write(out .. "/table.md", table.concat(lines, "\n") .. "\n")

print(string.format("wrote %s/quickstart.png, %s/coverage.png and %s/table.md in %.0f s", out, out, out,
                    sn.clock() - t_start))
