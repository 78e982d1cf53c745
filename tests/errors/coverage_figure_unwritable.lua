-- expect: coverage_figure_unwritable\.lua:7: ds:coverage option 'figure': .*Not a directory
local sn = require "shadenet"

-- The figure's folder would have to be made inside a file.
local data = sn.dataset { x = { { 0, 1, 0, 0, 1, 0 }, { 1, 0, 0, 1, 0, 0 } }, y = { { 0 }, { 1 } },
                          input_names = { "normal", "view" } }
local c = data:coverage { figure = "README.md/coverage.png" }
