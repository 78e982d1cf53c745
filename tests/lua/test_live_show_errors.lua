-- sn.live.show's parts must be pictures of the view's size; when one is not, the error names the
-- script's line to fix: the function's (where it was defined), in every mode, never a line of
-- runtime/live/. (A wrong size was an error only in the error and side views, at
-- shadenet.live.view.lua:192, and was shown as it was in the network view.)
local sn = require "shadenet"
local live = sn.live

local here = debug.getinfo(1, "S").short_src
local function fails(f, want, what)
  local ok, err = pcall(f)
  assert(not ok, what .. ": no error")
  err = tostring(err)
  assert(err:find(want, 1, true), ("%s: the error should hold\n  %s\nit is\n  %s"):format(what, want, err))
  assert(not err:find("runtime/live/", 1, true), what .. ": the error points inside the runtime: " .. err)
  return err
end
local function flat(w, h)
  return function(view)
    local t = sn.target { width = w or view.width, height = h or view.height }
    t:clear { 0.5, 0.5, 0.5, 1 }
    return t
  end
end

local LINE_NIL = debug.getinfo(1, "l").currentline + 1
local function returns_nil(view) end
live.show { network = returns_nil, truth = flat(), size = { 64, 48 } }
fails(function() live.render { mode = "network" } end,
      ("%s:%d: sn.live.show's 'network' returned nil; it must return a Target or an Image of the view's size (64x48)")
        :format(here, LINE_NIL), "a function returning nil")

local LINE_SMALL = debug.getinfo(1, "l").currentline + 1
local small = function(view) return flat(7, 5)(view) end
live.show { network = small, truth = flat(), size = { 64, 48 } }
for _, mode in ipairs { "network", "error", "side" } do
  local panel = mode == "side" and "32x24" or "64x48"
  fails(function() live.render { mode = mode } end,
        ("%s:%d: sn.live.show's 'network' returned a 7x5 picture for a %s view"):format(here, LINE_SMALL, panel),
        "a 7x5 picture in the " .. mode .. " view")
end
-- An Image (what scene:render returns) is held to the same size.
local LINE_IMAGE = debug.getinfo(1, "l").currentline + 1
live.show { truth = function(view) return sn.image.new { width = 3, height = 3, channels = 4, fill = 1 } end, size = { 8, 8 } }
fails(function() live.render {} end, ("%s:%d: sn.live.show's 'truth' returned a 3x3 picture for a 8x8 view")
                                       :format(here, LINE_IMAGE), "an Image of the wrong size")
-- A picture of the view's size is fine in every mode.
live.show { network = flat(), truth = flat(), size = { 64, 48 } }
for _, mode in ipairs { "network", "truth", "error", "side" } do
  assert(select(1, live.render { mode = mode }:size()) == 64, mode)
end
print("sn.live.show's parts: nil and wrong sizes are errors at the function's line, in every mode")
