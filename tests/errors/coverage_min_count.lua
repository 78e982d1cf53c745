-- expect: coverage_min_count\.lua:6: ds:coverage option 'min_count' must be at least 1 \(rows a bin needs to count as covered\), got 0
local sn = require "shadenet"

local data = sn.dataset { x = { { 0, 1, 0, 0, 1, 0 }, { 1, 0, 0, 1, 0, 0 } }, y = { { 0 }, { 1 } },
                          input_names = { "normal", "view" } }
local c = data:coverage { min_count = 0 }
