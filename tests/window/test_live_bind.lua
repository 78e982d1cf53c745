-- sn.live.bind with real keys: the script binds K to a first-layer weight; K raises it (the
-- picture's green rises), Shift+K lowers it, the terminal prints the value, and the window lists
-- the binding with its value in the bottom-left corner. A reload puts the script's weight back.
local sn = require "shadenet"
package.path = "tests/live/?.lua;" .. package.path
local H = require "harness"

local dir = "out/live_tests/bind"
local script, template = H.scenario(dir, function(text)
  return (text:gsub("%-%- EDITS\n", '-- EDITS\nsn.live.bind { key = "k", param = "net.layers[1].weight[1][2]", step = 0.2 }\n'))
end)

local s = H.start { dir = dir, script = script, size = "240x180", shown = true }
s:wait_frame(1)
local first = s:image(1)
local x11 = H.x11()
x11:move(120, 90)
local function after(key, mod)
  local n = s:frames()
  x11:key(key, mod)
  s:wait_frame(n + 1, 10)
  return s:image(s:frames())
end
local px, py = 120, 90
local up = after("k")
local value = tonumber(s:wait_log("%[live%] net%.layers%[1%]%.weight%[1%]%[2%] = (%S+)\n"))
assert(up:get(px, py)[2] > first:get(px, py)[2] + 0.05, ("K raised the green: %g -> %g"):format(first:get(px, py)[2],
  up:get(px, py)[2]))
assert(math.abs(up:get(px, py)[1] - first:get(px, py)[1]) < 1e-6, "the red stayed")
local down = after("k", "Shift_L")
assert(math.abs(down:get(px, py)[2] - first:get(px, py)[2]) < 1e-5, "Shift+K stepped back to the trained weight")

-- The window lists the binding: text in the bottom-left corner that the view has not.
local n, shown = s:wait_shown(s:shown() - 1)
local frame = s:image(s:frames())
local text = 0
for y = 166, 180 do
  for x = 1, 120 do
    local p, q = shown:get(x, y), frame:get(x, y)
    if p[3] > 0.8 and p[2] > 0.8 and math.abs(p[3] - q[3]) > 0.3 then text = text + 1 end
  end
end
assert(text > 30, "the binding's line is drawn bottom-left: " .. text .. " text pixels in picture " .. n)

-- A reload runs the script again: the weight is the trained one again.
x11:key("k")
H.write(script, template .. "\n-- saved\n")
s:wait_log("%[live%] ran [^\n]+\n[%s%S]*%[live%] ran ")
local reloaded = s:image(s:settle())
assert(math.abs(reloaded:get(px, py)[2] - first:get(px, py)[2]) < 1e-5, "the reload put the weight back")
x11:close()
s:stop()
print(("bind: K raised the weight to %g (green up), Shift+K lowered it, listed in the window, reset by a reload"):format(value))
