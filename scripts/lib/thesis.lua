-- The thesis' own numbers (chapter 4), printed beside ours. Copied from
-- ../shared/THESIS_TABLES.md, which transcribes seed/000_be08f75db6e91dbd.txt. Their setup: 64,149
-- covered pixels of a clothing mesh, 4:1 random split, inputs world normal + view direction,
-- outputs RGB, tanh, Adam(0.00025, 0.8, 0.9), batch 8, 20 epochs, minimum validation MSE over
-- the epochs, median of 10 runs; GTX 1060 6 GB, i7-7700HQ.
local thesis = {}

local sizes = { 2, 4, 6, 8, 10, 12 }

local function grid(rows)
  local t = {}
  for i, layers in ipairs(sizes) do
    t[layers] = {}
    for j, width in ipairs(sizes) do t[layers][width] = rows[i][j] end
  end
  return t
end

thesis.sizes = sizes

-- Table 4.1: Phong, val MSE [hidden layers][width]. The printed table has "0.00351" at 8 x 12 and
-- "0.00042" at 12 x 8; read as 0.000351 and 0.000420 (the neighbours make the typo plain).
thesis.table_4_1 = grid {
  { 0.002158, 0.000736, 0.000713, 0.000569, 0.000696, 0.000565 },
  { 0.001785, 0.000693, 0.000472, 0.000428, 0.000395, 0.000380 },
  { 0.002558, 0.000657, 0.000502, 0.000512, 0.000383, 0.000353 },
  { 0.001992, 0.000497, 0.000509, 0.000476, 0.000356, 0.000351 },
  { 0.002526, 0.000480, 0.000534, 0.000460, 0.000347, 0.000325 },
  { 0.002595, 0.000571, 0.000467, 0.000420, 0.000352, 0.000367 },
}

-- Table 4.2: GGX BRDF (metal), val MSE [hidden layers][width].
thesis.table_4_2 = grid {
  { 0.008342, 0.007557, 0.004520, 0.003851, 0.003769, 0.004038 },
  { 0.005567, 0.003634, 0.001836, 0.002153, 0.000945, 0.000457 },
  { 0.004549, 0.003171, 0.002882, 0.001214, 0.000467, 0.000376 },
  { 0.004451, 0.002962, 0.003205, 0.001141, 0.000467, 0.000194 },
  { 0.005627, 0.003138, 0.002678, 0.000909, 0.000365, 0.000259 },
  { 0.006864, 0.003725, 0.001571, 0.000843, 0.000256, 0.000235 },
}

-- Table 4.3: GGX, 8 hidden layers. "6 -> 13": 6 neurons on the input side, 13 on the output
-- side, 4 + 4 layers.
thesis.table_4_3 = { ["6 fixed"] = 0.000623, ["13 fixed"] = 0.000134, ["6 -> 13"] = 0.000218, ["13 -> 6"] = 0.000106 }

-- Figure 4.11 (GGX, 8 x 8, lr 0.00003, 800 epochs): sigmoid and ReLU stall at the all-zeros
-- output's MSE on their data; the ordering tanh < leaky 0.2 < leaky 0.1 < leaky 0.05 < relu = sigmoid.
thesis.fig_4_11 = { stall_mse = 0.28633, order = { "tanh", "leaky_relu 0.2", "leaky_relu 0.1", "leaky_relu 0.05" } }

-- Table 4.4: GGX, 8 hidden layers, val MSE [colour space][width]; RGB printed only at width 8.
thesis.table_4_4 = {
  rgb = { [8] = 0.001483 },
  hsv = { [4] = 0.001760, [8] = 0.000563, [16] = 0.000171 },
  cie = { [4] = 0.001312, [8] = 0.000474, [16] = 0.000161 },
}

-- Section 4.5: textured Phong from normal + view; texture from object position + UV.
thesis.sec_4_5 = { textured_phong = 0.000169, texture_from_position_uv = 0.000504 }

-- Table 4.5: training time per batch (ms), GGX, width 8 [hidden layers][device][batch].
thesis.batches = { 1, 4, 8, 16, 32, 64, 128 }
local function by_batch(v)
  local t = {}
  for i, b in ipairs(thesis.batches) do t[b] = v[i] end
  return t
end
thesis.table_4_5 = {
  [4] = { cpu = by_batch { 0.032, 0.059, 0.112, 0.186, 0.461, 0.649, 1.166 },
          gpu = by_batch { 0.381, 0.434, 0.437, 0.450, 0.444, 0.446, 0.449 } },
  [8] = { cpu = by_batch { 0.059, 0.130, 0.238, 0.312, 0.604, 1.156, 3.377 },
          gpu = by_batch { 0.476, 0.475, 0.461, 0.464, 0.471, 0.472, 0.484 } },
  [16] = { cpu = by_batch { 0.075, 0.188, 0.318, 0.647, 1.129, 2.681, 4.660 },
           gpu = by_batch { 0.888, 0.896, 0.900, 0.903, 0.922, 0.920, 0.930 } },
}

-- Table 4.6: rendering time per frame (ms) ["LxW"][image size]; Table 4.7: ns per fragment.
thesis.table_4_6 = {
  ["4x4"] = { ["640x480"] = 0.879, ["1280x720"] = 1.697, ["1920x1080"] = 2.177 },
  ["8x8"] = { ["640x480"] = 4.263, ["1280x720"] = 8.241, ["1920x1080"] = 10.067 },
  ["12x12"] = { ["640x480"] = 12.754, ["1280x720"] = 24.002, ["1920x1080"] = 29.653 },
  ["16x16"] = { ["640x480"] = 29.117, ["1280x720"] = 52.655, ["1920x1080"] = 66.710 },
}
thesis.table_4_7 = { ["4x4"] = 15.8, ["8x8"] = 79.3, ["12x12"] = 237.3, ["16x16"] = 538.9 }

-- Samples in every quantitative experiment of the thesis.
thesis.samples = 64149

return thesis
