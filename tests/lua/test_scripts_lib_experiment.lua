-- lib.experiment takes what the runtime takes. Datasets whose inputs include tangent, bitangent,
-- world_position or a varied parameter train in a sweep (the library kept its own list of five
-- attributes, and failed "unknown input attribute 'tangent'" after building the dataset); a name
-- that is neither an attribute nor a varied parameter is an error at the script's line before
-- anything is rendered. E:compare takes its nets and meshes named or in order, as the docs show
-- both (the order alone failed "options must be named").
package.path = "scripts/?.lua;" .. package.path
local sn = require "shadenet"
local exp = require "lib.experiment"

local E = exp.start("experiment_inputs", { "--quick", "--out", sn.fs.tempdir("test_scripts_lib_experiment"),
                                           "--data", "cloth" })
local here = debug.getinfo(1, "S").short_src

-- An unknown input: at this file's line, naming the runtime's attributes; nothing built.
local builds = sn.dataset_stats().builds
local line = debug.getinfo(1, "l").currentline + 1
local ok, err = pcall(function() return E:data_desc { model = "ggx", inputs = { "normal", "tangnet" } } end)
assert(not ok and err:find(here .. ":" .. line .. ": E:data_desc option 'inputs': 'tangnet' is not a G-buffer attribute "
                           .. "(normal, view, position, world_position, uv, base_color, tangent, bitangent) nor a "
                           .. "parameter in vary", 1, true), tostring(err))
ok, err = pcall(function() return E:data_desc { model = "ggx", vary = { roughness = { 0.2, 0.6 } } } end)
assert(not ok and err:find("the varied parameter 'roughness' must be in inputs too", 1, true), tostring(err))
assert(sn.dataset_stats().builds == builds, "nothing built for a bad description")

-- Six attributes (a G-buffer holds six at most) and a varied parameter, encoded or not, through a sweep and back from its record.
local inputs = { "normal", "view", "tangent", "bitangent", "world_position", "uv", "roughness" }
local desc = E:data_desc { model = "ggx", inputs = inputs, vary = { roughness = { 0.2, 0.6 } }, samples = 800,
                           size = { 48, 48 }, views = 2 }
local runs = { exp.run { id = "all", hidden = { 6 }, seed = 1, epochs = 1, data = desc, keep_params = true,
                         encoding = { world_position = { "frequency", bands = 2 } } } }
local records = E:sweep(runs)
local rec = records.all
assert(rec and rec.result.best_val_mse == rec.result.best_val_mse, "trained: " .. tostring(rec and rec.result.best_val_mse))
local net = exp.net_from_record(rec)
assert(table.concat(net:inputs(), " ") == table.concat(inputs, " "), table.concat(net:inputs(), " "))
local data = E:data(desc)
assert(data:inputs() == 3 * 5 + 2 + 1 and table.concat(data:input_names(), " ") == table.concat(inputs, " "))
print(("six attributes and a varied parameter: %d inputs, val MSE %.4g"):format(data:inputs(), rec.result.best_val_mse))

-- E:compare: named entries and entries in order give the same rows.
local phong = sn.mlp { inputs = { "normal", "view" }, hidden = { 4 }, seed = 3 }
local sphere = sn.mesh.sphere {}
local function compare(nets, meshes, file)
  return E:compare { file = file, model = "phong", nets = nets, meshes = meshes, size = { 40, 30 } }
end
local named = compare({ { net = phong, label = "net" } }, { { mesh = sphere, label = "sphere", views = { 2 }, view_count = 4 } },
                      "figures/named.png")
local ordered = compare({ { phong, "net" } }, { { sphere, "sphere", { 2 }, 4 } }, "figures/ordered.png")
assert(#named == 1 and #ordered == 1 and named[1].view == 2 and ordered[1].view == 2 and named[1].mse == ordered[1].mse,
       ("named %s, in order %s"):format(tostring(named[1] and named[1].mse), tostring(ordered[1] and ordered[1].mse)))
line = debug.getinfo(1, "l").currentline + 1
ok, err = pcall(function() return compare({ { phong, "net", "extra" } }, { { sphere, "sphere" } }, "figures/x.png") end)
assert(not ok and err:find(here .. ":" .. line .. ": E:compare nets[1]: at most 2 values in order (net, label), got one at [3]",
                           1, true), tostring(err))
ok, err = pcall(function() return compare({ { phong, label = "a", net = phong } }, { { sphere, "sphere" } }, "figures/x.png") end)
assert(not ok and err:find("E:compare nets[1]: 'net' given twice, as [1] and by name", 1, true), tostring(err))
print("ok")
