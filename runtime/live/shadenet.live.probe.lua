-- The pixel probe: the truth, the network and their error at one pixel of the view the window
-- shows. The window's I key shows it under the cursor (the loop calls live._probe_lines); the
-- console and the tests call sn.live.probe(x, y).
local sn = require "shadenet.core"
local S = require "shadenet.live.state"
local view_of = require "shadenet.live.view"
local live = sn.live

local probe = {}

local function rgb(p) return { p[1], p[2], p[3] } end

-- sn.live.probe(x, y) -> truth, network, error: {r, g, b} each at pixel (x, y) of the current
-- view (1-based from the top-left; in side mode a pixel of any panel names the same point of
-- all three). error = {|dr|, |dg|, |db|, mean = their mean} (what the heatmap colours); a part
-- the show lacks is nil. The window's last frame is read back, not drawn again; headless the
-- view is drawn for the call.
function live.probe(x, y)
  if type(x) ~= "number" or type(y) ~= "number" or x % 1 ~= 0 or y % 1 ~= 0 then
    error(("sn.live.probe(x, y): x and y must be whole pixel numbers, got %s, %s"):format(tostring(x), tostring(y)), 2)
  end
  local spec = view_of.current_spec("sn.live.probe")
  local view = view_of.current_view(spec)
  if x < 1 or x > view.width or y < 1 or y > view.height then
    error(("sn.live.probe: pixel (%d, %d) is outside the %dx%d view (x 1..%d, y 1..%d)"):format(
      x, y, view.width, view.height, view.width, view.height), 2)
  end
  -- The last frame's parts when the window drew this view; otherwise drawn now.
  local parts = S.view and S.drawn and S.drawn.frame == S.frames and S.drawn or nil
  local v = parts and parts.view or view
  if not parts and view.mode == "side" then
    v = {}
    for k, val in pairs(view) do v[k] = val end
    v.width, v.height = view_of.panel_size(view.width, view.height)
  end
  local px, py = (x - 1) % v.width + 1, (y - 1) % v.height + 1
  local function value(which)
    if not spec.draw[which] then return nil end
    local t = parts and parts[which]
    if not t then
      local ok, r = pcall(view_of.draw, spec, which, v, S.view and S.out or nil)
      if not ok then error("sn.live.probe: " .. tostring(r), 3) end
      t = r
      if parts then parts[which] = t end  -- a second probe of this frame reads it back
    end
    return rgb(t:pixel(px, py))
  end
  local truth, network = value("truth"), value("network")
  local err
  if truth and network then
    err = {}
    for c = 1, 3 do err[c] = math.abs(network[c] - truth[c]) end
    err.mean = (err[1] + err[2] + err[3]) / 3
  end
  return truth, network, err
end

local function row(name, v, extra)
  if not v then return nil end
  return ("%-8s %.3f %.3f %.3f%s"):format(name, v[1], v[2], v[3], extra or "")
end

-- For the loop: the probe box's lines at pixel (x, y) of the last frame; nil (and the reason)
-- when there is nothing to probe there.
function live._probe_lines(x, y)
  if not S.view or x < 1 or y < 1 or x > S.view.width or y > S.view.height then return nil end
  local ok, t, n, e = pcall(live.probe, x, y)
  if not ok then return nil, t end
  local lines = { ("pixel %d, %d"):format(x, y) }
  lines[#lines + 1] = row("truth", t)
  lines[#lines + 1] = row("network", n)
  lines[#lines + 1] = row("|error|", e, e and (" (mean %.3f)"):format(e.mean))
  return lines
end

return probe
