-- Section 4.5 (figures 4.20, 4.21): where a fully connected network falls short. (a) Textured
-- Phong learned from normal + view alone: the texture is not a function of those inputs, so its
-- detail (zipper, cuffs, weave) is lost while the lighting is right. (b) The texture itself
-- learned from object position + UV (5 inputs): it comes out flat and blurry. Both fit with a
-- small validation MSE; the images, and a detail measure (gradient energy of the network's
-- image over the truth's), show what the MSE hides.
--   shadenet scripts/sec_4_5_textures.lua [--quick] [--shard i/n] [--out DIR] [--backend cpu|gl|auto]
package.path = (arg and arg[0] and arg[0]:match("^(.*)/[^/]*$") or ".") .. "/?.lua;" .. package.path
local sn = require "shadenet"
local exp = require "lib.experiment"
local thesis = require "lib.thesis"

local E = exp.start("sec_4_5_textures", arg)
local epochs = E:pick(10, exp.epochs)
-- The texture as a "lighting model": textured Phong with full ambient and no specular returns
-- the base colour unchanged.
local texture_only = { name = "textured_phong", params = { ambient = 1, specular = 0, color = { 1, 1, 1 } } }
local cases = {
  { id = "textured_phong-normal_view", label = "(a) textured Phong from normal + view",
    data = { model = "textured_phong", inputs = { "normal", "view" } }, thesis = thesis.sec_4_5.textured_phong },
  { id = "texture-position_uv", label = "(b) texture from position + UV",
    data = { model = texture_only, inputs = { "position", "uv" } }, thesis = thesis.sec_4_5.texture_from_position_uv },
}
local runs = {}
for _, c in ipairs(cases) do
  c.desc = E:data_desc(c.data)
  runs[#runs + 1] = exp.run { id = c.id, hidden = exp.rep(12, 8), seed = 1, epochs = epochs, data = c.desc, keep_params = true }
end
local records = E:sweep(runs)

-- Mean squared gradient (forward differences) of the luminance over pixels whose neighbours are
-- covered too: how much fine detail an image holds.
local function detail(img)
  local w, h = img:size()
  local sum, n = 0, 0
  local function lum(x, y)
    local p = img:get(x, y)
    return 0.2126 * p[1] + 0.7152 * p[2] + 0.0722 * p[3], p[4] > 0.5
  end
  for y = 1, h - 1 do
    for x = 1, w - 1 do
      local l, c = lum(x, y)
      local lx, cx = lum(x + 1, y)
      local ly, cy = lum(x, y + 1)
      if c and cx and cy then
        sum = sum + (lx - l) ^ 2 + (ly - l) ^ 2
        n = n + 1
      end
    end
  end
  return n > 0 and sum / n or 0
end

local size = E:pick({ 200, 150 }, { 480, 360 })
local scene = E:scene { mesh = exp.meshes.train, size = size, views = 8 }
local panels, row_labels, rows = {}, {}, {}
for _, c in ipairs(cases) do
  local rec = records[c.id]
  if rec then
    local model = exp.model(c.desc.model)
    local net = exp.net_from_record(rec)
    local full = E:time("render", scene.render, scene, model, { view = 1 })
    local box = exp.frame(full)
    local truth = exp.crop(full, box)
    local img = sn.image.clamp(exp.crop(E:time("render", scene.render, scene, net, { view = 1 }), box))
    local mse = sn.image.mse(truth, img, { channels = 3, mask = truth })
    local heat = sn.image.heatmap(sn.image.diff(truth, img), { mask = truth, label = "|error|" })
    panels[#panels + 1] = { image = truth, caption = "ground truth" }
    panels[#panels + 1] = { image = img, caption = string.format("network 8 x 12, MSE %.2e", mse) }
    panels[#panels + 1] = { image = heat, caption = "|error|" }
    row_labels[#row_labels + 1] = c.label
    local base = E:baseline(c.desc)
    local m = rec.result.best_val_mse
    rows[#rows + 1] = {
      case = c.label, inputs = table.concat(c.desc.inputs, " + "), val_mse = m, thesis_val_mse = c.thesis,
      ratio = m / c.thesis, constant_mse = base.constant, image_mse = mse,
      detail_kept = detail(img) / detail(truth),
    }
  end
end
if #panels > 0 then
  E:figure("figures/textures.png", sn.image.grid {
    panels = panels, columns = 3, row_labels = row_labels,
    title = "Section 4.5 — textures: what a fully connected network loses", caption_size = size[1] >= 300 and 14 or 11 })
end
E.R:table {
  title = "Section 4.5 — textured targets: validation MSE and how much detail survives",
  columns = {
    { key = "case", align = "left" }, { key = "inputs", align = "left" },
    { key = "val_mse", header = "min val MSE (ours)", format = "%.4g" },
    { key = "thesis_val_mse", header = "val MSE (thesis)", format = "%.4g" },
    { key = "ratio", header = "ours / thesis", format = "%.2f" },
    { key = "constant_mse", header = "constant predictor", format = "%.4g" },
    { key = "image_mse", header = "image MSE (view 1)", format = "%.4g" },
    { key = "detail_kept", header = "detail kept (gradient energy, network / truth)", format = "%.3f" },
  },
  rows = rows,
  notes = { string.format("Network 8 x 12, one seed, %s, tanh; training data: %s.", exp.recipe(epochs), E:data_note()),
            "No unseen-mesh error here: both targets are the cloth's own texture, which no other mesh carries, and "
            .. "position / UV inputs mean something else on every mesh." },
}
E:finish {
  records = records,
  config = { cases = cases, hidden = exp.rep(12, 8), epochs = epochs, batch = exp.batch, adam = exp.adam },
  summary = { rows = rows },
}
