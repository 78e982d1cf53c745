-- sn.dataset.concat, ds:subset, ds:split, ds:export and sn.dataset.load end to end: rows land
-- where the docs say, seeds decide, files come back bit for bit, and mistakes are clear errors.
local sn = require "shadenet"

local scene = sn.scene { mesh = "meshes/cloth.glb", size = { 96, 96 }, views = { count = 3 } }
local phong = sn.lighting.phong {}
local a = scene:dataset { target = phong, samples = 3000, seed = 1 }
local b = scene:dataset { target = phong, samples = 2000, seed = 2 }

local function row_text(ds, set, i)
  local x, y = ds:row(set, i)
  return table.concat(x, ",") .. "|" .. table.concat(y, ",")
end
local function all_rows(ds)
  local t, v = ds:counts()
  local out = {}
  for i = 1, t do out[#out + 1] = "t" .. row_text(ds, "train", i) end
  for i = 1, v do out[#out + 1] = "v" .. row_text(ds, "val", i) end
  return out
end
local function same(d1, d2)
  local r1, r2 = all_rows(d1), all_rows(d2)
  if #r1 ~= #r2 then return false end
  for i = 1, #r1 do if r1[i] ~= r2[i] then return false end end
  return d1:color() == d2:color() and table.concat(d1:input_names(), ",") == table.concat(d2:input_names(), ",")
end
local function fails(pattern, f, ...)
  local ok, err = pcall(f, ...)
  assert(not ok, "expected an error matching " .. pattern)
  assert(tostring(err):find(pattern, 1, true), "error '" .. tostring(err) .. "' lacks '" .. pattern .. "'")
end

-- concat: a's training rows, b's training rows; then the validation rows likewise.
local c = sn.dataset.concat { a, b }
assert(tostring(c) == "Dataset(6 -> 3 rgb, 4000 train / 1000 val)", tostring(c))
assert(row_text(c, "train", 1) == row_text(a, "train", 1))
assert(row_text(c, "train", 2400) == row_text(a, "train", 2400))
assert(row_text(c, "train", 2401) == row_text(b, "train", 1))
assert(row_text(c, "val", 601) == row_text(b, "val", 1))
assert(row_text(c, "val", 1000) == row_text(b, "val", 400))
assert(tostring(sn.dataset.concat { a }) == tostring(a))

local hsv = scene:dataset { target = phong, samples = 500, color = "hsv" }
fails("sn.dataset.concat: dataset 2 has colour space hsv, dataset 1 has rgb", sn.dataset.concat, { a, hsv })
local uv = sn.scene { mesh = "meshes/cloth.glb", size = { 32, 32 } }:dataset { target = phong, inputs = { "normal", "uv" }, samples = 100 }
fails("sn.dataset.concat: dataset 3 has 5 inputs, dataset 1 has 6", sn.dataset.concat, { a, b, uv })
fails("sn.dataset.concat: the list is empty", sn.dataset.concat, {})
fails("sn.dataset.concat: item 2 is a number, Dataset expected", sn.dataset.concat, { a, 3 })
fails("sn.dataset.concat: a list expected, got a table with the key 'seed'", sn.dataset.concat, { a, b, seed = 1 })
fails("sn.dataset.concat: a list of Datasets expected ({a, b, ...}), got Dataset", sn.dataset.concat, a)

-- subset: the first rows without a seed, a seeded choice with one; each set in proportion.
local first = c:subset { count = 100 }
assert(tostring(first) == "Dataset(6 -> 3 rgb, 80 train / 20 val)", tostring(first))
assert(row_text(first, "train", 80) == row_text(c, "train", 80))
assert(row_text(first, "val", 20) == row_text(c, "val", 20))
local s1, s1b, s2 = c:subset { fraction = 0.1, seed = 5 }, c:subset { fraction = 0.1, seed = 5 }, c:subset { fraction = 0.1, seed = 6 }
assert(tostring(s1) == "Dataset(6 -> 3 rgb, 400 train / 100 val)", tostring(s1))
assert(same(s1, s1b), "the same seed chooses the same rows")
assert(not same(s1, s2), "another seed chooses other rows")
assert(row_text(s1, "train", 1) ~= row_text(c, "train", 1) or row_text(s1, "train", 2) ~= row_text(c, "train", 2))

-- where: rows whose normal.x lies in [-1, 0.4] (and no others), before count.
local low = c:subset { where = { input = "normal", axis = "x", min = -1, max = 0.4 } }
local lt, lv = low:counts()
local expect = 0
for _, set in ipairs { "train", "val" } do
  local n = set == "train" and 4000 or 1000
  for i = 1, n do
    local x = c:row(set, i)
    if x[1] >= -1 and x[1] <= 0.4 then expect = expect + 1 end
  end
end
assert(lt + lv == expect and lt > 0 and lv > 0 and expect < 5000, ("where kept %d + %d of %d"):format(lt, lv, expect))
for i = 1, lt do
  local x = low:row("train", i)
  assert(x[1] >= -1 and x[1] <= 0.4, "row " .. i .. " normal.x " .. x[1])
end
local view_z = c:subset { where = { input = "view", axis = 3, min = 0.5 }, count = 10, seed = 1 }
assert(select(1, view_z:counts()) + select(2, view_z:counts()) == 10)
for i = 1, 8 do assert(view_z:row("train", i)[6] >= 0.5) end

fails("dataset:subset: where: no input 'uv' (the dataset's inputs: normal, view)", c.subset, c, { where = { input = "uv", axis = "u", min = 0 } })
fails("unknown axis 'w' (valid: x, y, z, u, v or a 1-based index)", c.subset, c, { where = { input = "normal", axis = "w", min = 0 } })
fails("dataset:subset: where: input 'normal' has 3 components (x, y, z or 1..3), not component 4", c.subset, c,
      { where = { input = "normal", axis = 4, min = 0 } })
fails("dataset:subset: where: min 1 is above max 0", c.subset, c, { where = { input = "normal", axis = "x", min = 1, max = 0 } })
fails("dataset:subset: where keeps no training rows", c.subset, c, { where = { input = "normal", axis = "x", min = 5 } })
fails("dataset:subset option 'seed' chooses the rows of count or fraction", c.subset, c, { seed = 1 })
fails("dataset:subset: give count, fraction or where", c.subset, c, {})
fails("dataset:subset: count 1 cannot keep a row in both", c.subset, c, { count = 1 })
fails("dataset:subset: unknown option 'rows'", c.subset, c, { rows = 3 })

-- split: training then validation rows pooled and dealt anew.
local r = c:split { split = 0.5, seed = 3 }
assert(tostring(r) == "Dataset(6 -> 3 rgb, 2500 train / 2500 val)", tostring(r))
assert(same(r, c:split { split = 0.5, seed = 3 }) and not same(r, c:split { split = 0.5, seed = 4 }))
local pool, dealt = {}, {}
for _, t in ipairs(all_rows(c)) do pool[t:sub(2)] = (pool[t:sub(2)] or 0) + 1 end
for _, t in ipairs(all_rows(r)) do dealt[t:sub(2)] = (dealt[t:sub(2)] or 0) + 1 end
for k, n in pairs(pool) do assert(dealt[k] == n, "split lost or duplicated a row") end
assert(tostring(c:split()) == "Dataset(6 -> 3 rgb, 4000 train / 1000 val)")
fails("dataset:split: split must lie strictly between 0 and 1 (the training share), got 1", c.split, c, { split = 1 })

-- export / load: NumPy arrays with a sidecar, and CSV; each comes back bit for bit.
local dir = sn.fs.tempdir("test_dataset_algebra")
local path = c:export(dir .. "/cloth")
assert(path == dir .. "/cloth.json", path)
local back = sn.dataset.load(path)
assert(same(c, back), "npy round trip")
assert(same(c, sn.dataset.load(dir .. "/cloth")))  -- no extension: the sidecar
local small = s1:subset { count = 50 }
assert(small:export(dir .. "/small.csv") == dir .. "/small.csv")
assert(same(small, sn.dataset.load(dir .. "/small.csv")), "csv round trip")
local f = assert(io.open(dir .. "/small.csv"))
assert(f:read("*l") == "normal_x,normal_y,normal_z,view_x,view_y,view_z,r,g,b,set")
f:close()
local h = hsv:subset { count = 20 }
h:export(dir .. "/hsv.csv")
assert(sn.dataset.load(dir .. "/hsv.csv"):color() == "hsv" and same(h, sn.dataset.load(dir .. "/hsv.csv")))
local uvs = uv:subset { count = 20 }
uvs:export(dir .. "/uv")
assert(same(uvs, sn.dataset.load(dir .. "/uv.json")))

fails("sn.dataset.load: cannot read dataset '" .. dir .. "/none.json': no such file", sn.dataset.load, dir .. "/none.json")
fails("unknown dataset file type '.npy'", sn.dataset.load, dir .. "/cloth.inputs.npy")
local w = assert(io.open(dir .. "/broken.csv", "w"))
w:write("x1,r,g,b,set\n1,2,3,4,train\n1,2,3\n")
w:close()
fails("sn.dataset.load: " .. dir .. "/broken.csv:3: 3 columns, the header has 5", sn.dataset.load, dir .. "/broken.csv")
fails("dataset:export: cannot write dataset '" .. dir .. "/broken.csv/x.inputs.npy': cannot create folder", c.export, c,
      dir .. "/broken.csv/x.json")

for _, name in ipairs { "cloth.json", "cloth.inputs.npy", "cloth.targets.npy", "small.csv", "hsv.csv", "uv.json",
                        "uv.inputs.npy", "uv.targets.npy", "broken.csv" } do
  assert(os.remove(dir .. "/" .. name), name)
end
assert(os.remove(dir))
print("dataset algebra ok")
