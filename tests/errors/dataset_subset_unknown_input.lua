-- expect: dataset_subset_unknown_input\.lua:5: dataset:subset: where: no input 'uv' \(the dataset's inputs: normal, view\)
local sn = require "shadenet"
local data = sn.dataset { x = { { 0, 0, 1, 0, 0, 1 }, { 0, 1, 0, 0, 0, 1 } }, y = { { 1, 0, 0 }, { 0, 1, 0 } },
                          input_names = { "normal", "view" } }
data:subset { where = { input = "uv", axis = "u", min = 0, max = 0.5 } }
