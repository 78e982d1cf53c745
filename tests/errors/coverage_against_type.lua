-- expect: coverage_against_type\.lua:6: ds:coverage option 'against': a Dataset or a Scene expected, got Mesh
local sn = require "shadenet"

local data = sn.dataset { x = { { 0, 1, 0, 0, 1, 0 }, { 1, 0, 0, 1, 0, 0 } }, y = { { 0 }, { 1 } },
                          input_names = { "normal", "view" } }
local c = data:coverage { against = sn.mesh.sphere {} }
