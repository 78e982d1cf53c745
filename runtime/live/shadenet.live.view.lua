-- What the window shows: sn.live.show declares the view, sn.live.render draws it headless (the
-- window draws the same function's output), sn.live.set_view / view_code / status for the
-- console and the tests.
local sn = require "shadenet.core"
local S = require "shadenet.live.state"
local check = require "shadenet.live.check"
local message_of = require("shadenet.where").message
local live = sn.live
local strict, check_vec3, check_light, check_size = check.strict, check.vec3, check.light, check.size
local is_camera, type_is, is_mode, MODES = check.is_camera, check.type_is, check.is_mode, check.MODES

-- For the record and loop modules: the spec in force, a view with its defaults, its image.
local M = {}

local SHOW_KEYS = { "network", "truth", "scene", "camera", "light", "mode", "title", "val_mse", "error_scale",
                    "colormap", "size", "backend" }

-- What `network` / `truth` may be: a function of the view, or with a `scene`, a network (Mlp)
-- or a lighting model (sn.lighting.*) that scene:render shades from the view's camera and light.
function M.drawer(spec, key)
  local x = spec[key]
  if x == nil or type(x) == "function" then return x end
  local kind = key == "network" and "Mlp" or "Lighting"
  if not type_is(x, kind) then
    error(("sn.live.show: '%s' must be a function(view) returning a Target or Image, or %s, got %s"):format(
      key, key == "network" and "a network (sn.mlp)" or "a lighting model (sn.lighting.*)", tostring(x)), 3)
  end
  if not spec.scene then
    error(("sn.live.show: '%s' is %s; give the scene it is rendered in: scene = sn.scene{...}"):format(
      key, tostring(x)), 3)
  end
  local scene = spec.scene
  if kind == "Lighting" then
    return function(view)
      return scene:render(x, { camera = view.camera, light = view.light, size = { view.width, view.height } })
    end
  end
  -- A network is drawn straight into the loop's target (`into`, when it has the view's size):
  -- no image on the host; the console says which backend drew it, once, and again only when that
  -- changes (the state outlives reloads: each run's sn.live.show made it say so again).
  local said = false
  return function(view, into)
    if not (into and select(1, into:size()) == view.width and select(2, into:size()) == view.height) then
      into = sn.target { width = view.width, height = view.height }
    end
    local out = scene:render(x, { camera = view.camera, size = { view.width, view.height }, target = into,
                                  backend = spec.backend })
    if not said and S.active then  -- the watching user's console, not a plain run's output
      said = true
      local info = sn.render_info()
      local line = ("[live] network view: %s backend (%s)"):format(info.backend, info.reason)
      if line ~= S.backend_said then print(line) end
      S.backend_said = line
    end
    return out
  end
end

-- sn.live.show{ network = net | function(view), truth = model | function(view), scene = scene,
--               camera = Camera, light = {dir = {x,y,z}}, mode = "network", title = "...",
--               val_mse = number | function() -> number, error_scale = 0.25,
--               colormap = "inferno", size = {w, h}, backend = "auto" | "gl" | "cpu" }
-- (`backend`: what draws a network given as a net, net:render's)
function live.show(spec)
  strict(spec, SHOW_KEYS, "sn.live.show", 2)
  if spec.network == nil and spec.truth == nil then
    error("sn.live.show: give at least one of 'network' or 'truth'", 2)
  end
  if spec.scene ~= nil and not type_is(spec.scene, "Scene") then
    error("sn.live.show: 'scene' must be a Scene (sn.scene{...}), got " .. tostring(spec.scene), 2)
  end
  if spec.camera ~= nil and not is_camera(spec.camera) then
    error("sn.live.show: 'camera' must be a Camera (sn.camera{...}), got " .. type(spec.camera), 2)
  end
  if spec.light ~= nil then check_light(spec.light, "sn.live.show: light", 2) end
  if spec.mode ~= nil and not is_mode(spec.mode) then
    error(("sn.live.show: unknown mode '%s' (valid: %s)"):format(tostring(spec.mode), table.concat(MODES, ", ")), 2)
  end
  if spec.error_scale ~= nil and not (type(spec.error_scale) == "number" and spec.error_scale > 0
                                       and spec.error_scale < math.huge) then
    error("sn.live.show: 'error_scale' must be a number > 0 (the error shown as the top colour)", 2)
  end
  if spec.colormap ~= nil and spec.colormap ~= "inferno" and spec.colormap ~= "viridis" and spec.colormap ~= "gray" then
    error(("sn.live.show: unknown colormap '%s' (valid: inferno, viridis, gray)"):format(tostring(spec.colormap)), 2)
  end
  if spec.size ~= nil then check_size(spec.size, "sn.live.show: size", 2) end
  if spec.backend ~= nil and spec.backend ~= "auto" and spec.backend ~= "gl" and spec.backend ~= "cpu" then
    error(("sn.live.show: unknown backend '%s' (valid: auto, gl, cpu)"):format(tostring(spec.backend)), 2)
  end
  if spec.val_mse ~= nil and type(spec.val_mse) ~= "number" and type(spec.val_mse) ~= "function" then
    error("sn.live.show: 'val_mse' must be a number or a function returning one", 2)
  end
  local copy = { draw = {} }
  for k, v in pairs(spec) do copy[k] = v end
  copy.draw.network, copy.draw.truth = M.drawer(spec, "network"), M.drawer(spec, "truth")
  -- Where an error about a part's picture points: the user's function where it was defined, or
  -- for a network or a model this sn.live.show call (what the user can change).
  local call = debug.getinfo(2, "Sl")
  local at_call = call and call.currentline > 0 and ("%s:%d"):format(call.short_src, call.currentline) or "sn.live.show"
  copy.where = {}
  for _, key in ipairs { "network", "truth" } do
    local f = spec[key]
    local info = type(f) == "function" and debug.getinfo(f, "S")
    copy.where[key] = info and info.linedefined > 0 and ("%s:%d"):format(info.short_src, info.linedefined) or at_call
  end
  copy.mode = copy.mode or (copy.network and "network" or "truth")
  local scene = spec.scene
  if scene then  -- the scene's first view, light and size unless the show says otherwise
    copy.camera = copy.camera or scene:views()[1]
    if not copy.light then
      local l = scene:light()
      copy.light = { dir = { l.dir[1], l.dir[2], l.dir[3] } }
    end
    if not copy.size then
      local w, h = scene:size()
      copy.default_size = { w, h }
    end
  end
  local net = spec.network
  if type_is(net, "Mlp") then
    copy.title = copy.title or tostring(net)
    copy.val_mse = copy.val_mse or function()
      local b = net:best()
      return b and b.val_mse
    end
  end
  if S.running then S.pending = copy else S.spec = copy end
end

function M.current_spec(what)
  local spec = S.spec
  if S.running and S.pending then spec = S.pending end
  if not spec then error(what .. ": nothing to show yet; call sn.live.show{ network = ..., truth = ... } first", 3) end
  return spec
end

-- A drawer's result as a Target of the view's size: Images (scene:render) are uploaded, into
-- `cache` when given. Anything else is an error at `where` (the user's function).
local function as_target(t, which, where, view, cache, key)
  local what = ("%s: sn.live.show's '%s'"):format(where, which)
  local image, target = type_is(t, "Image"), type_is(t, "Target")
  if not (image or target) then
    error(("%s returned %s; it must return a Target or an Image of the view's size (%dx%d)"):format(what,
      type(t) == "userdata" and tostring(t) or type(t), view.width, view.height), 0)
  end
  local w, h = t:size()
  if w ~= view.width or h ~= view.height then
    -- The window, the probe, the heatmap and the side view all take a part at the view's size.
    error(("%s returned a %dx%d picture for a %dx%d view: draw at view.width x view.height, or give the show a "
           .. "fixed size (sn.live.show{ size = { %d, %d } })"):format(what, w, h, view.width, view.height, w, h), 0)
  end
  if target then return t end
  local out = sn.live_upload(t, cache and cache[key])
  if cache then cache[key] = out end
  return out
end

function M.draw(spec, which, view, cache)
  local f = spec.draw[which]
  if not f then
    local has = spec.draw.network and "network" or "truth"
    error(("mode '%s' needs '%s' in sn.live.show{...} (this view has only '%s')"):format(view.mode, which, has), 0)
  end
  local key = which .. " " .. view.width .. "x" .. view.height
  -- An error a draw raises names this line (its caller); its message names what to fix (a model
  -- giving NaN showed runtime/live/shadenet.live.view.lua:145 as the place to fix).
  local ok, drawn = pcall(f, view, cache and cache[key])
  if not ok then
    error(message_of(drawn), 0)
  end
  local out = as_target(drawn, which, (spec.where or {})[which] or "sn.live.show", view, cache, key)
  if cache then cache[key] = out end
  return out
end

-- The view a mode renders, with every default filled in.
function M.resolve_view(spec, o)
  local size = spec.size or spec.default_size
  local w, h = o.width or (size and size[1]) or 640, o.height or (size and size[2]) or 480
  return {
    mode = o.mode or spec.mode,
    camera = o.camera or spec.camera or sn.camera {},
    light = o.light or spec.light or { dir = { 0, 0, 1 } },
    width = w, height = h,
  }
end

-- Side by side: 2 x 2 panels of the view's aspect (truth | network, error | -) filling the view.
function M.panel_size(w, h)
  return math.max(1, math.floor(w / 2)), math.max(1, math.floor(h / 2))
end

-- `cache` (the loop's) keeps GPU targets between frames; headless renders get fresh ones.
-- Returns the picture and what it was made of: { view = the view each part was drawn for (a
-- panel's in side mode), network = Target, truth = Target } (the probe reads them).
function M.render(spec, view, cache)
  local mode = view.mode
  local draw = M.draw
  if mode == "network" or mode == "truth" then
    local t = draw(spec, mode, view, cache)
    return t, { view = view, [mode] = t }
  end
  local v = view
  if mode == "side" then
    v = {}
    for k, x in pairs(view) do v[k] = x end
    v.width, v.height = M.panel_size(view.width, view.height)
  end
  local n, t = draw(spec, "network", v, cache), draw(spec, "truth", v, cache)
  local key = mode .. " " .. view.width .. "x" .. view.height
  local out = sn.live_compose { network = n, truth = t, layout = mode == "side" and "side" or "error",
                                scale = view.error_scale or spec.error_scale or 0.25, colormap = spec.colormap,
                                into = cache and cache[key] }
  if cache then cache[key] = out end
  return out, { view = v, network = n, truth = t }
end

-- sn.live.render{ mode = "network" | "truth" | "error" | "side", camera = Camera,
--                 light = {dir = {x,y,z}}, width = 640, height = 480, error_scale = 0.25 } -> Target
-- The image the window shows for that view (side: 2 x 2 panels of width/2 x height/2).
function live.render(o)
  o = o or {}
  strict(o, { "mode", "camera", "light", "width", "height", "error_scale" }, "sn.live.render", 2)
  if o.error_scale ~= nil and not (type(o.error_scale) == "number" and o.error_scale > 0 and o.error_scale < math.huge) then
    error("sn.live.render: 'error_scale' must be a number > 0 (the error shown as the heatmap's top colour)", 2)
  end
  if o.mode ~= nil and not is_mode(o.mode) then
    error(("sn.live.render: unknown mode '%s' (valid: %s)"):format(tostring(o.mode), table.concat(MODES, ", ")), 2)
  end
  if o.camera ~= nil and not is_camera(o.camera) then error("sn.live.render: 'camera' must be a Camera", 2) end
  if o.light ~= nil then check_light(o.light, "sn.live.render: light", 2) end
  for _, k in ipairs({ "width", "height" }) do
    if o[k] ~= nil and not (type(o[k]) == "number" and o[k] >= 1 and o[k] % 1 == 0) then
      error(("sn.live.render: '%s' must be a whole number >= 1"):format(k), 2)
    end
  end
  local spec = M.current_spec("sn.live.render")
  local view = M.resolve_view(spec, o)
  view.error_scale = o.error_scale
  local ok, r = pcall(M.render, spec, view)
  if not ok then error("sn.live.render: " .. tostring(r), 2) end
  return r  -- the picture only
end

-- The view shown now, or before the first frame the one the loop will show (at its size unless
-- the show names one), for screenshots, recordings and probes taken by the script as it runs.
function M.current_view(spec)
  if S.view then return S.view end
  local o = {}
  if not spec.size and S.loop_size then o.width, o.height = S.loop_size[1], S.loop_size[2] end
  return M.resolve_view(spec, o)
end

-- sn.live.view() -> the view the window shows now ({mode, camera, light, width, height}), to
-- reproduce it headless with sn.live.render(view); nil before the first frame.
function live.view()
  if not S.view then return nil end
  local v = {}
  for k, x in pairs(S.view) do v[k] = x end
  return v
end

-- sn.live.frames() -> how many frames the loop has rendered
function live.frames() return S.frames end

-- sn.live.active() -> true while `shadenet --watch` runs the script (false in a plain run), so a
-- script can do headless-only work (saving figures) when nobody watches.
function live.active() return S.active == true end

-- sn.live.quit(): ends the live loop after the current line or reload.
function live.quit() S.requests.quit = true end

-- sn.live.redraw(): renders the view again (e.g. after changing something the loop cannot see).
function live.redraw() S.requests.redraw = true end

-- sn.live.status() -> { title = the window's title, error = the error shown ("" when none),
--                       frames = frames rendered }
function live.status()
  local st = S.status or {}
  return { title = st.title or "", error = st.error or "", frames = S.frames }
end

local function vec_code(v)
  return ("{%.17g, %.17g, %.17g}"):format(v[1], v[2], v[3])
end

-- sn.live.set_view{ mode = "error", camera = Camera, light = {dir = {x,y,z}} }: what the
-- window's keys and mouse do, from code (the console): the loop takes it before its next frame.
function live.set_view(o)
  strict(o, { "mode", "camera", "light" }, "sn.live.set_view", 2)
  if o.mode ~= nil and not is_mode(o.mode) then
    error(("sn.live.set_view: unknown mode '%s' (valid: %s)"):format(tostring(o.mode), table.concat(MODES, ", ")), 2)
  end
  if o.camera ~= nil and not is_camera(o.camera) then error("sn.live.set_view: 'camera' must be a Camera", 2) end
  if o.light ~= nil then check_light(o.light, "sn.live.set_view: light", 2) end
  local r = S.requests.view or {}
  r.mode = o.mode or r.mode
  if o.camera then r.eye, r.target, r.fov = o.camera:eye(), o.camera:target(), o.camera:fov() end
  if o.light then r.light = o.light.dir end
  S.requests.view = r
end

-- sn.live.view_code([path]) -> a line of Lua that renders the current view headless and saves
-- it to `path` (default "view.png"); the P key prints it. It names every setting of the view
-- that changes its picture (the heatmap's scale too: [ and ] change it). Numbers are exact (%.17g).
function live.view_code(path)
  local v = S.view
  if not v then return "-- nothing rendered yet" end
  local c = v.camera
  local cam = ("sn.camera { eye = %s, target = %s, fov = %.17g%s }"):format(vec_code(c:eye()), vec_code(c:target()),
    c:fov(), c:aspect() and (", aspect = %.17g"):format(c:aspect()) or "")
  return ("sn.live.render { mode = %q, camera = %s, light = { dir = %s }, width = %d, height = %d, error_scale = %.17g }"
          .. ":read():save(%q)"):format(v.mode, cam, vec_code(v.light.dir), v.width, v.height,
                                        v.error_scale or S.spec and S.spec.error_scale or 0.25, path or "view.png")
end


return M
