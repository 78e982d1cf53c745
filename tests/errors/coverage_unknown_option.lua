-- expect: coverage_unknown_option\.lua:6: ds:coverage: unknown option 'bins' \(valid: min_count, against, figure, title, normal_bands, normal_sectors, view_bands, view_sectors\)
local sn = require "shadenet"

local data = sn.dataset { x = { { 0, 1, 0, 0, 1, 0 }, { 1, 0, 0, 1, 0, 0 } }, y = { { 0 }, { 1 } },
                          input_names = { "normal", "view" } }
local c = data:coverage { bins = 512 }
