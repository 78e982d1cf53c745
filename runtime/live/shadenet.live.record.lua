-- Screenshots and recordings of the current view: sn.live.screenshot, sn.record (an orbit of the
-- camera or a sweep of one value), with or without a window.
local sn = require "shadenet.core"
local check = require "shadenet.live.check"
local view_of = require "shadenet.live.view"
local busy = require "shadenet.live.busy"
local live = sn.live
local strict, is_mode, MODES, whole = check.strict, check.is_mode, check.MODES, check.whole
local render, current_spec = view_of.render, view_of.current_spec

local message_of = require("shadenet.where").message

local absolute = sn.live_absolute
local MAX_FRAMES = 100000

-- sn.live.screenshot([path]) -> absolute path: saves the current view (PNG unless the path
-- says otherwise); by default out/live/screenshot-NNNN.png.
function live.screenshot(path)
  if path ~= nil and type(path) ~= "string" then error("sn.live.screenshot: path must be a string, got " .. type(path), 2) end
  local spec = current_spec("sn.live.screenshot")
  local view = view_of.current_view(spec)
  local ok, image = pcall(function() return render(spec, view):read() end)
  if not ok then error("sn.live.screenshot: " .. message_of(image), 2) end
  -- claimed, not looked for: another instance saving at the same moment gets the next number
  local claimed = path == nil
  path = path or sn.fs.claim("out/live", "screenshot", ".png")
  local err
  ok, err = pcall(image.save, image, path)
  if not ok then
    if claimed then os.remove(path) end  -- no empty screenshot-NNNN.png left by a full disk
    error("sn.live.screenshot: " .. message_of(err), 2)
  end
  return absolute(path)
end

-- sn.record{ orbit = {count = 36, elevation = deg (current), distance = (current)}
--          | sweep = {set = function(v), from = -2, to = 2, count = 9},
--            mode = (current), width, height, dir = "out/live/record-NNNN" }
-- -> dir (absolute), {frame paths}. Writes frame-0001.png, ... of an orbit of the camera
-- around its target, or of a sweep of one value (a weight: set = function(v) w[2][3] = v end);
-- the value is put back afterwards.
function sn.record(o)
  strict(o, { "orbit", "sweep", "mode", "width", "height", "dir" }, "sn.record", 2)
  if (o.orbit == nil) == (o.sweep == nil) then error("sn.record: give either 'orbit' or 'sweep'", 2) end
  local spec = current_spec("sn.record")
  local base = view_of.current_view(spec)
  local view = {}
  for k, v in pairs(base) do view[k] = v end
  if o.mode ~= nil then
    if not is_mode(o.mode) then
      error(("sn.record: unknown mode '%s' (valid: %s)"):format(tostring(o.mode), table.concat(MODES, ", ")), 2)
    end
    view.mode = o.mode
  end
  -- Checked here: width = 0 was reported as "scene:render option 'size'" with no line.
  if o.width ~= nil then whole(o.width, 1, 16384, "sn.record: width", 2) end
  if o.height ~= nil then whole(o.height, 1, 16384, "sn.record: height", 2) end
  view.width, view.height = o.width or view.width, o.height or view.height
  local dir = o.dir
  local claimed = dir == nil
  local paths = {}
  local count_of = o.orbit and (o.orbit.count or 36) or (o.sweep and o.sweep.count or 9)
  local function frame(k)
    busy.tick(("recording frame %d/%d  (Esc cancels)"):format(k, count_of), (k - 1) / count_of)
    if k == 1 then  -- the folder is made once the options were checked: no empty folder on a typo
      dir = dir and sn.fs.mkdir(dir) or sn.fs.claim("out/live", "record")
    end
    local p = ("%s/frame-%04d.png"):format(dir, k)
    local image = render(spec, view):read()
    local ok, err = pcall(image.save, image, p)
    if not ok then
      if claimed and #paths == 0 then os.remove(dir) end  -- no empty record-NNNN folder
      error(err, 0)
    end
    paths[#paths + 1] = absolute(p)
  end
  if o.orbit then
    strict(o.orbit, { "count", "elevation", "distance" }, "sn.record: orbit", 2)
    local count = o.orbit.count or 36
    whole(count, 1, MAX_FRAMES, "sn.record: orbit.count", 2)
    -- At +-90 degrees the camera looks along its up vector: no orbit can be framed there.
    local elevation = o.orbit.elevation
    if elevation ~= nil and not (type(elevation) == "number" and elevation > -90 and elevation < 90) then
      error("sn.record: orbit.elevation must be a number of degrees in (-90, 90), got " .. tostring(elevation), 2)
    end
    local distance = o.orbit.distance
    if distance ~= nil and not (type(distance) == "number" and distance > 0 and distance < math.huge) then
      error("sn.record: orbit.distance must be a finite number > 0, got " .. tostring(distance), 2)
    end
    local cam = view.camera
    local e, t = cam:eye(), cam:target()
    local d = { e[1] - t[1], e[2] - t[2], e[3] - t[3] }
    local dist = o.orbit.distance or math.sqrt(d[1] ^ 2 + d[2] ^ 2 + d[3] ^ 2)
    local elev = o.orbit.elevation and math.rad(o.orbit.elevation)
                 or math.asin(math.max(-1, math.min(1, d[2] / math.sqrt(d[1] ^ 2 + d[2] ^ 2 + d[3] ^ 2))))
    local az0 = math.atan2(d[1], d[3])
    local ok, err = pcall(function()
      for k = 1, count do
        local az = az0 + 2 * math.pi * (k - 1) / count
        view.camera = sn.camera { eye = { t[1] + dist * math.cos(elev) * math.sin(az), t[2] + dist * math.sin(elev),
                                          t[3] + dist * math.cos(elev) * math.cos(az) },
                                  target = t, fov = cam:fov(), aspect = cam:aspect() }
        frame(k)
      end
    end)
    if not ok then error("sn.record: " .. message_of(err), 2) end
  else
    strict(o.sweep, { "set", "get", "from", "to", "count" }, "sn.record: sweep", 2)
    local s = o.sweep
    if type(s.set) ~= "function" then error("sn.record: sweep.set must be a function(value) that applies the value", 2) end
    local from, to, count = s.from or -2, s.to or 2, s.count or 9
    whole(count, 1, MAX_FRAMES, "sn.record: sweep.count", 2)
    for _, k in ipairs({ "from", "to" }) do
      local v = s[k] or 0
      if type(v) ~= "number" or v ~= v or v == math.huge or v == -math.huge then
        error(("sn.record: sweep.%s must be a finite number, got %s"):format(k, tostring(s[k])), 2)
      end
    end
    local before = s.get and s.get()
    local ok, err = pcall(function()
      for k = 1, count do
        s.set(count == 1 and from or from + (to - from) * (k - 1) / (count - 1))
        frame(k)
      end
    end)
    if before ~= nil then s.set(before) end
    if not ok then error("sn.record: " .. message_of(err), 2) end
  end
  return absolute(dir), paths
end
live.record = sn.record
