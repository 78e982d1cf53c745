-- examples/quickstart.lua, the README's main job: it writes its figure and table, says where,
-- and its networks shade like the models on the mesh they learned from and on meshes they never saw.
local C = require "script_check"
local sn = require "shadenet"

local dir = C.tmpdir("quickstart")
local t0 = sn.clock()
local out = C.ok("examples/quickstart.lua", { dir })
local seconds = sn.clock() - t0
assert(seconds < 180, "the quickstart takes under 3 minutes, took " .. seconds)
assert(out:find("wrote " .. dir .. "/quickstart.png, " .. dir .. "/coverage.png and " .. dir .. "/table.md", 1, true),
       "it prints where it wrote:\n" .. out)
-- The posed cloth's rows cover most of the normal sphere; little of the test blob is outside.
local normals, views, outside = out:match("coverage: (%d+)%% of the normal sphere, (%d+)%% of the view hemisphere; ([%d.]+)%%")
assert(tonumber(normals) > 80 and tonumber(outside) < 5, "coverage line: " .. tostring(normals) .. " " .. tostring(outside))
assert(sn.image.load(dir .. "/coverage.png"), "the coverage figure")
local img = sn.image.load(dir .. "/quickstart.png")
local w, h = img:size()
assert(w > 1000 and h > 900, "6 meshes x 6 rows")
-- The table's targets: both networks shade the five unseen meshes within 10x of their error on
-- the cloth, and Phong's highlight is there on each (the network's brightest pixel at least 60% of
-- the model's; trained on the hanging cloth alone it had none).
local md = C.read(dir .. "/table.md")
local n = 0
for line in md:gmatch("[^\n]+") do
  local cells = {}
  for cell in line:gmatch("|([^|]*)") do cells[#cells + 1] = cell:match("^%s*(.-)%s*$") end
  if cells[2] and cells[2]:match("^mlp") then
    n = n + 1
    local name, val = cells[1], tonumber(cells[3])
    assert(C.finite(val) and val < 1e-3, name .. ": validation MSE " .. tostring(val))
    local cloth = tonumber(cells[4]:match("^(%S+)"))
    assert(C.finite(cloth) and cloth < 0.02, name .. ": image MSE on the cloth " .. tostring(cloth))
    for k = 5, 9 do
      local mse, ssim, peak = cells[k]:match("^(%S+) / (%S+) / (%S+)$")
      mse, ssim, peak = tonumber(mse), tonumber(ssim), tonumber(peak)
      assert(C.finite(mse) and mse < 0.05 and ssim > 0.8, name .. ": unseen mesh " .. (k - 4) .. ": " .. cells[k])
      if name == "Phong" then assert(peak > 0.6, "Phong's highlight on unseen mesh " .. (k - 4) .. ": " .. cells[k]) end
    end
    local ratio = tonumber(cells[11])
    assert(ratio and ratio < 10, name .. ": unseen / cloth image MSE " .. tostring(cells[11]))
  end
end
assert(n == 2, "Phong and GGX rows in the table:\n" .. md)
C.rm(dir)
print("quickstart: ok")
