-- expect: subset_axis_letter\.lua:6: dataset:subset option 'where' option 'axis': input 'normal' has the axes x, y, z \(or a 1-based index\), not 'u'
-- A letter of another input's axes was taken as the same component ('u' of a normal as x).
local sn = require "shadenet"
local data = sn.dataset { x = { { 0, 0, 1, 0.5, 0.5 }, { 0, 1, 0, 0.25, 0.5 } }, y = { { 1 }, { 0 } },
                          input_names = { "normal", "uv" } }
local sub = data:subset { where = { input = "normal", axis = "u", min = 0 } }
