-- docs/experiments.md's script table gives each committed full run's wall time and the load at its
-- start; they are the ones its run.json records. (They had drifted: 87 s quoted for a run.json's
-- 129 s, 2 s for 11 s at load 7.)
package.path = "scripts/?.lua;" .. package.path
local results = require "lib.results"

local doc = assert(results.read_file("docs/experiments.md"))
local checked = 0
for script, seconds, load in doc:gmatch("\n| `([%w_]+)%.lua` |[^\n]-| (%d+) s %(([%d.]+)%) |") do
  local info = results.read_json("docs/results/" .. script .. "/run.json")
  assert(info, "docs/experiments.md gives a wall time for " .. script .. ", which has no committed run.json")
  local total, at_start = info.timings.total, info.load_average.at_start[1]
  assert(tonumber(seconds) == math.floor(total + 0.5) and tonumber(load) == math.floor(at_start * 10 + 0.5) / 10,
         string.format("docs/experiments.md: %s.lua %s s (load %s); its run.json: %.1f s (load %.2f)", script, seconds,
                       load, total, at_start))
  checked = checked + 1
end
assert(checked >= 13, "the script table's times were not found (" .. checked .. " rows read)")
print(checked .. " wall times as the committed run.json files record them")
