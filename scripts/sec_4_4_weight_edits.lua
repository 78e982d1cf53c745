-- Section 4.4 (figures 4.13-4.19): a network fitted to three-colour toon shading (8 hidden layers
-- x 12, Adam lr 0.00025, batch 8; the thesis' 6 x 8 for figures 4.18 and 4.19), then edited by hand: the first layer (the normal inputs'
-- weights rotated, as if the surface -- and so the light -- turned), a middle layer (one unit
-- switched around) and the last layer (output rows swapped or scaled). Each edit is rendered on
-- the training mesh and on the test mesh, and measured against the unedited network: how much
-- the colours changed (which colours appear, wherever) and how much the shading pattern changed
-- (where the colour changes), which is the thesis' observation in numbers: first-layer edits
-- move highlights, last-layer edits recolour.
--   shadenet scripts/sec_4_4_weight_edits.lua [--quick] [--shard i/n] [--out DIR] [--backend cpu|gl|auto]
package.path = (arg and arg[0] and arg[0]:match("^(.*)/[^/]*$") or ".") .. "/?.lua;" .. package.path
local sn = require "shadenet"
local exp = require "lib.experiment"
local results = require "lib.results"

local E = exp.start("sec_4_4_weight_edits", arg)
local epochs = E:pick(10, exp.epochs)
local desc = E:data_desc { model = "toon3" }
-- The 8 x 12 network of figures 4.13-4.17, and the 6 x 8 one of figures 4.18 and 4.19.
local records = E:sweep { exp.run { id = "toon3-8x12", hidden = exp.rep(12, 8), seed = 1, epochs = epochs, data = desc,
                                    keep_params = true },
                          exp.run { id = "toon3-6x8", hidden = exp.rep(8, 6), seed = 1, epochs = epochs, data = desc,
                                    keep_params = true } }
local rec = records["toon3-8x12"]
if not rec then return E:finish { records = records } end
local fitted = exp.net_from_record(rec)
local L = #fitted.layers  -- weight layers: 8 hidden + output

-- Rotates the first layer's weights on the normal inputs (columns 1..3) so the network sees
-- every normal turned by `degrees` about `axis` ("x" or "y").
local function rotate_normals(net, axis, degrees)
  local a = math.rad(degrees)
  local c, s = math.cos(a), math.sin(a)
  local i, j = 1, 3  -- y axis: mixes normal x and z
  if axis == "x" then i, j = 2, 3 end
  local w = net.layers[1].weight
  for r = 1, #w do
    local wi, wj = w[r][i], w[r][j]
    w[r][i] = c * wi + s * wj
    w[r][j] = -s * wi + c * wj
  end
end
local function negate_unit(net, layer, unit)
  local w = net.layers[layer].weight
  for c = 1, #w[unit] do w[unit][c] = -w[unit][c] end
  net.layers[layer].bias[unit] = -net.layers[layer].bias[unit]
end
local function scale_unit(net, layer, unit, k)
  local w = net.layers[layer].weight
  for c = 1, #w[unit] do w[unit][c] = k * w[unit][c] end
  net.layers[layer].bias[unit] = k * net.layers[layer].bias[unit]
end
local function swap_outputs(net, a, b)
  local layer = net.layers[#net.layers]
  local ra, rb = layer.weight[a]:table(), layer.weight[b]:table()
  layer.weight[a], layer.weight[b] = rb, ra
  local ba, bb = layer.bias[a], layer.bias[b]
  layer.bias[a], layer.bias[b] = bb, ba
end

-- `caption`: what the figure says under each edit (short enough for a panel).
local edits = {
  { id = "first_rot_y", layer = "first", label = "first layer: normals turned 35° about y", caption = "layer 1: normals 35° about y",
    apply = function(n) rotate_normals(n, "y", 35) end },
  { id = "first_rot_x", layer = "first", label = "first layer: normals turned 25° about x", caption = "layer 1: normals 25° about x",
    apply = function(n) rotate_normals(n, "x", 25) end },
  { id = "middle_negate", layer = "middle", label = string.format("layer %d: unit 1 negated", math.floor(L / 2) + 1),
    caption = string.format("layer %d: unit 1 negated", math.floor(L / 2) + 1),
    apply = function(n) negate_unit(n, math.floor(L / 2) + 1, 1) end },
  { id = "middle_scale", layer = "middle", label = string.format("layer %d: unit 2 x 3", math.floor(L / 2) - 1),
    caption = string.format("layer %d: unit 2 x 3", math.floor(L / 2) - 1),
    apply = function(n) scale_unit(n, math.floor(L / 2) - 1, 2, 3) end },
  { id = "last_swap_rb", layer = "last", label = "last layer: red and blue rows swapped", caption = "last: red <-> blue rows",
    apply = function(n) swap_outputs(n, 1, 3) end },
  { id = "last_scale_g", layer = "last", label = "last layer: green row x 0.5", caption = "last: green row x 0.5",
    apply = function(n) scale_unit(n, L, 2, 0.5) end },
}
for _, e in ipairs(edits) do
  e.net = fitted:clone()
  e.apply(e.net)
end

-- Colour and pattern change of `b` against `a` over the pixels covered in both, each blind to
-- the other (per-pixel chromaticity counted moved bands as recolouring, and luminance correlation
-- a palette swap as a new pattern):
--   colour: which colours appear, wherever. The palette is the RGB cells (8 levels a channel,
--   of the display's gamma-encoded value, so dark shades are told apart) holding at least 0.5%
--   of the pixels; the change is the share of each image's pixels whose colour's cell is not in
--   the other's palette, the two averaged.
--   pattern: where the colour changes. 1 - the correlation of the two images' gradient
--   magnitudes (forward differences, summed over RGB): a band that moved moves its edges, a
--   recoloured band keeps them.
local function cell(p)
  local function level(v) return math.max(0, math.min(7, math.floor(math.max(v, 0) ^ (1 / 2.2) * 8))) end
  return level(p[1]), level(p[2]), level(p[3])
end
local function palette(img, covered)
  local count, n = {}, 0
  for _, xy in ipairs(covered) do
    local r, g, b = cell(img:get(xy[1], xy[2]))
    local k = r * 64 + g * 8 + b
    count[k], n = (count[k] or 0) + 1, n + 1
  end
  local set = {}
  for k, c in pairs(count) do if c >= 0.005 * n then set[k] = true end end
  return set
end
-- The share of `img`'s pixels whose colour's cell is not in `set`.
local function outside(img, covered, set)
  local out = 0
  for _, xy in ipairs(covered) do
    local r, g, b = cell(img:get(xy[1], xy[2]))
    if not set[r * 64 + g * 8 + b] then out = out + 1 end
  end
  return out / math.max(1, #covered)
end
local function gradient(img, x, y)
  local p, r, d = img:get(x, y), img:get(x + 1, y), img:get(x, y + 1)
  local g = 0
  for c = 1, 3 do g = g + math.abs(r[c] - p[c]) + math.abs(d[c] - p[c]) end
  return g
end
local function change(a, b)
  local w, h = a:size()
  local covered = {}
  for y = 1, h - 1 do
    for x = 1, w - 1 do
      local inside = true
      for _, q in ipairs { { x, y }, { x + 1, y }, { x, y + 1 } } do
        inside = inside and a:get(q[1], q[2])[4] > 0.5 and b:get(q[1], q[2])[4] > 0.5
      end
      if inside then covered[#covered + 1] = { x, y } end
    end
  end
  local colour = 0.5 * (outside(b, covered, palette(a, covered)) + outside(a, covered, palette(b, covered)))
  local n, sa, sb, saa, sbb, sab = #covered, 0, 0, 0, 0, 0
  for _, xy in ipairs(covered) do
    local ga, gb = gradient(a, xy[1], xy[2]), gradient(b, xy[1], xy[2])
    sa, sb, saa, sbb, sab = sa + ga, sb + gb, saa + ga * ga, sbb + gb * gb, sab + ga * gb
  end
  local cov = sab / n - (sa / n) * (sb / n)
  local va, vb = saa / n - (sa / n) ^ 2, sbb / n - (sb / n) ^ 2
  local corr = (va > 0 and vb > 0) and cov / math.sqrt(va * vb) or 1
  return colour, 1 - corr
end

local size = E:pick({ 200, 150 }, { 480, 360 })
local truth_model = exp.model("toon3")
-- The ground truth of one mesh view cropped to its frame, and a function rendering a network
-- there the same way (clamped to [0, 1], as a display shows it).
local function view_of(m)
  local scene = E:scene { mesh = m.mesh, size = size, views = 8 }
  local full = E:time("render", scene.render, scene, truth_model, { view = m.view })
  local box = exp.frame(full)
  return exp.crop(full, box), function(net)
    return sn.image.clamp(exp.crop(E:time("render", scene.render, scene, net, { view = m.view }), box))
  end
end
local meshes = { { mesh = exp.meshes.train, label = "training mesh", view = 1 },
                 { mesh = exp.meshes.test, label = "test mesh", view = 2 } }
local panels, row_labels, rows, panel_rows = {}, {}, {}, {}
for _, m in ipairs(meshes) do
  local truth, render = view_of(m)
  local base = render(fitted)
  local base_mse = sn.image.mse(truth, base, { channels = 3, mask = truth })
  panels[#panels + 1] = { image = truth, caption = "toon ground truth" }
  panels[#panels + 1] = { image = base, caption = string.format("fitted, MSE %.2e", base_mse) }
  panel_rows[#panel_rows + 1] = { mesh = m.label, view = m.view, panel = "fitted", mse = base_mse }
  for k, e in ipairs(edits) do
    local img = render(e.net)
    panels[#panels + 1] = { image = img, caption = string.format("(%s) %s", string.char(96 + k), e.caption) }
    local colour, pattern = change(base, img)
    rows[#rows + 1] = { mesh = m.label, edit = string.char(96 + k), layer = e.layer, description = e.label,
                        colour_change = colour, pattern_change = pattern }
    panel_rows[#panel_rows + 1] = { mesh = m.label, view = m.view, panel = "(" .. string.char(96 + k) .. ") " .. e.label,
                                    mse = sn.image.mse(truth, img, { channels = 3, mask = truth }),
                                    colour_change = colour, pattern_change = pattern }
  end
  row_labels[#row_labels + 1] = m.label
end
E:figure("figures/weight_edits.png", sn.image.grid {
  panels = panels, columns = #edits + 2, row_labels = row_labels,
  title = E:marked_title("Section 4.4 — a toon-shading network (8 x 12) edited by hand"),
  caption_size = size[1] >= 300 and 14 or 11 })
-- Each panel's MSE against the toon truth (an edit's too: how far it moved from the truth), and
-- an edit's change against the fitted network.
E.R:write("figures/weight_edits.csv", results.csv({ { key = "mesh" }, { key = "view" }, { key = "panel" }, { key = "mse" },
                                                    { key = "colour_change" }, { key = "pattern_change" } }, panel_rows))

-- Figure 4.17: stylised looks from hand edits of the 8 x 12 network, as the thesis shows three
-- (a watercolour-like shade, shades in different colours, strokes). Ours: (a) every middle layer's
-- weights perturbed by up to 25% (a fixed pseudo-random pattern), (b) the output colours cycled
-- (red takes green's row, green blue's, blue red's) with the shading kept, (c) the first layer's
-- weights on the normal inputs tripled, which sharpens the bands into strokes. Measured like the
-- edits above, against the fitted network.
local function perturb_middle(net, amount)
  local k = 0
  for l = 2, L - 1 do
    local w = net.layers[l].weight
    for r = 1, #w do
      for c = 1, #w[r] do
        k = k + 1
        w[r][c] = w[r][c] * (1 + amount * math.sin(12.9898 * k))  -- deterministic, no RNG state
      end
    end
  end
end
local function cycle_outputs(net)
  local layer = net.layers[#net.layers]
  local rows = { layer.weight[1]:table(), layer.weight[2]:table(), layer.weight[3]:table() }
  local bias = { layer.bias[1], layer.bias[2], layer.bias[3] }
  for c = 1, 3 do
    local from = c % 3 + 1
    layer.weight[c], layer.bias[c] = rows[from], bias[from]
  end
end
local function scale_normal_inputs(net, k)
  local w = net.layers[1].weight
  for r = 1, #w do
    for c = 1, 3 do w[r][c] = k * w[r][c] end
  end
end
local styles = {
  { id = "style_perturbed", caption = "middle layers perturbed 25%", apply = function(n) perturb_middle(n, 0.25) end },
  { id = "style_cycled", caption = "output colours cycled", apply = cycle_outputs },
  { id = "style_strokes", caption = "layer 1 normal weights x 3", apply = function(n) scale_normal_inputs(n, 3) end },
}
local style_rows = {}
do
  local p3, labels3 = {}, {}
  for _, st in ipairs(styles) do
    st.net = fitted:clone()
    st.apply(st.net)
  end
  for _, m in ipairs(meshes) do
    local truth, render = view_of(m)
    local base = render(fitted)
    p3[#p3 + 1] = { image = truth, caption = "toon ground truth" }
    p3[#p3 + 1] = { image = base, caption = "fitted 8 x 12" }
    for k, st in ipairs(styles) do
      local img = render(st.net)
      p3[#p3 + 1] = { image = img, caption = string.format("(%s) %s", string.char(96 + k), st.caption) }
      local colour, pattern = change(base, img)
      style_rows[#style_rows + 1] = { mesh = m.label, style = string.char(96 + k), description = st.caption,
                                      colour_change = colour, pattern_change = pattern }
    end
    labels3[#labels3 + 1] = m.label
  end
  E:figure("figures/fig_4_17_styles.png", sn.image.grid {
    panels = p3, columns = #styles + 2, row_labels = labels3, caption_size = size[1] >= 300 and 14 or 11,
    title = E:marked_title("Figure 4.17 — stylised looks from hand edits of the 8 x 12 toon network") })
  E.R:write("figures/fig_4_17_styles.csv", results.csv({ { key = "mesh" }, { key = "style" }, { key = "description" },
    { key = "colour_change" }, { key = "pattern_change" } }, style_rows))
end

-- Figures 4.18 and 4.19: the 6 x 8 network fitted (4.18) and edited (4.19: its last layer's red
-- and blue rows swapped, edit (e) above) on the training mesh and on the test mesh from three
-- views. The thesis' point: an edited network still acts as a lighting model on another mesh,
-- so its edit looks the same from every view (the colour change against the fitted network
-- stays alike and the pattern change stays near 0).
local small_rec = records["toon3-6x8"]
local small_rows = {}
if small_rec then
  local small = exp.net_from_record(small_rec)
  local edited = small:clone()
  swap_outputs(edited, 1, 3)
  local views = { { mesh = exp.meshes.train, label = "training mesh", view = 1 } }
  for _, v in ipairs { 2, 4, 6 } do views[#views + 1] = { mesh = exp.meshes.test, label = "test mesh", view = v } end
  local p2, labels2 = {}, {}
  for _, m in ipairs(views) do
    local truth, render = view_of(m)
    local fit, ed = render(small), render(edited)
    local mse = sn.image.mse(truth, fit, { channels = 3, mask = truth })
    local colour, pattern = change(fit, ed)
    p2[#p2 + 1] = { image = truth, caption = "toon ground truth" }
    p2[#p2 + 1] = { image = fit, caption = string.format("fitted 6 x 8, MSE %.2e", mse) }
    p2[#p2 + 1] = { image = ed, caption = "edited: red and blue rows swapped" }
    labels2[#labels2 + 1] = string.format("%s, view %d", m.label, m.view)
    small_rows[#small_rows + 1] = { mesh = m.label, view = m.view, fitted_mse = mse, colour_change = colour,
                                    pattern_change = pattern }
  end
  E:figure("figures/fig_4_18_4_19.png", sn.image.grid {
    panels = p2, columns = 3, row_labels = labels2, caption_size = size[1] >= 300 and 14 or 11,
    title = E:marked_title("Figures 4.18 and 4.19 — the 6 x 8 toon network, fitted and edited, on the training and a "
                           .. "different mesh") })
  E.R:write("figures/fig_4_18_4_19.csv", results.csv({ { key = "mesh" }, { key = "view" },
    { key = "fitted_mse" }, { key = "colour_change" }, { key = "pattern_change" } }, small_rows))
end

E.R:table {
  title = "Section 4.4 — what each edit changes, against the unedited network",
  columns = {
    { key = "mesh", align = "left" }, { key = "edit" }, { key = "layer", align = "left" },
    { key = "description", align = "left" },
    { key = "colour_change", header = "colour change (pixels whose colours the other lacks)", format = "%.4f" },
    { key = "pattern_change", header = "pattern change (1 - gradient correlation)", format = "%.4f" },
  },
  rows = rows,
  notes = {
    string.format("Fitted network: min val MSE %.6f after %s, tanh; training data: %s.",
                  rec.result.best_val_mse, exp.recipe(epochs), E:data_note()),
    string.format("Fitted network on the unseen meshes: image MSE %.4g, SSIM %.4f. %s", rec.result.unseen_mse or 0 / 0,
                  rec.result.unseen_ssim or 0 / 0, exp.unseen_note()),
    "Colour change: the share of pixels whose colour (an RGB cell, 8 levels a channel of the gamma-encoded value) "
      .. "the other rendering's palette (the cells holding 0.5% of its pixels or more) lacks, both ways averaged: "
      .. "which colours appear, wherever they lie. Pattern change: 1 - the correlation of the two renderings' "
      .. "gradient magnitudes: where the colour changes. Both over the pixels covered in both renderings.",
    "Figure 4.17 (figures/fig_4_17_styles.png and .csv): three stylised edits of the 8 x 12 network, measured the same way.",
    small_rec and string.format("Figures 4.18 and 4.19 (figures/fig_4_18_4_19.png and .csv): the thesis' 6 x 8 network, "
                                .. "min val MSE %.6f, fitted and with its red and blue output rows swapped, on the training "
                                .. "mesh (view 1) and the test mesh (views 2, 4, 6).", small_rec.result.best_val_mse) or nil,
  },
}
-- The edited networks, for a closer look (sn.load).
for _, e in ipairs(edits) do
  e.net:save(E.R:path("networks/" .. e.id .. ".mlp"))
  E.R.written[#E.R.written + 1] = "networks/" .. e.id .. ".mlp"
end
fitted:save(E.R:path("networks/fitted.mlp"))
E.R.written[#E.R.written + 1] = "networks/fitted.mlp"
E:finish {
  records = records,
  config = { model = "toon3", hidden = exp.rep(12, 8), epochs = epochs, batch = exp.batch, adam = exp.adam, data = desc,
             edits = (function() local t = {} for i, e in ipairs(edits) do t[i] = { id = e.id, label = e.label } end return t end)() },
  summary = { rows = rows, fitted_val_mse = rec.result.best_val_mse, fitted_unseen_mse = rec.result.unseen_mse,
              fitted_unseen_ssim = rec.result.unseen_ssim },
}
