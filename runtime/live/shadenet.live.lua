-- Live mode, the Lua side: what survives a reload (sn.keep), what the window shows
-- (sn.live.show), the same view headless (sn.live.render), screenshots and recordings
-- (sn.live.screenshot, sn.record). The C++ loop (runtime/live/live_loop.cpp) drives it through
-- the live._* functions at the bottom; a plain headless script uses the same functions, so
-- every image the window shows can be produced without a display.
local sn = require "shadenet.core"

local live = {}
sn.live = live

-- Survives reloads: this module is never unloaded (only the script's own modules are).
local S = {
  kept = {},        -- name -> { value, key, snapshot }
  spec = nil,       -- the sn.live.show{...} in force
  pending = nil,    -- the one given during the run in progress (committed when the run succeeds)
  running = false,  -- a (re)run of the watched script is in progress
  modules = {},     -- module name -> file, for modules `require`d from files
  files = {},       -- file -> true: modules and dofile'd scripts, watched for saves
  view = nil,       -- the last view the loop rendered ({mode, camera, light, width, height})
  frames = 0,       -- frames rendered by the loop
  requests = {},    -- actions asked of the loop from Lua (quit)
  out = {},         -- the loop's targets, reused between frames (by "what WxH")
}

local MODES = { "network", "truth", "error", "side" }
local function is_mode(m)
  for _, v in ipairs(MODES) do if v == m then return true end end
  return false
end

---------------------------------------------------------------------------------------------
-- Which files the script read: a package loader that records every Lua module found on
-- package.path, and dofile. The loop watches them and re-runs the script when one is saved.

local function record_file(path)
  S.files[path] = true
end

local function file_loader(name)
  local path, err = package.searchpath(name, package.path)
  if not path then return err end
  S.modules[name] = path
  record_file(path)
  local chunk, msg = loadfile(path)
  if not chunk then
    error(("error loading module '%s' from file '%s':\n\t%s"):format(name, path, msg), 3)
  end
  return chunk
end

do  -- before Lua's own file searcher, after preload and the embedded modules
  local loaders = package.loaders
  local at = #loaders >= 2 and 3 or #loaders + 1
  table.insert(loaders, at, file_loader)
end

local plain_dofile = dofile
function dofile(path)  -- luacheck: ignore (the global, wrapped to record the file)
  if path then record_file(path) end
  return plain_dofile(path)
end

---------------------------------------------------------------------------------------------
-- sn.keep: values made once and kept across reloads.

-- Networks (and tables holding them) are snapshotted when made; every re-run starts from the
-- snapshot, so the script's edits apply to the trained weights and deleting an edit undoes it.
live.restorers = {
  Mlp = {  -- the weights and biases in the shared flat layout; counters stay as they are
    snapshot = function(net) return net:params() end,
    restore = function(net, params) net:set_params(params) end,
  },
}

local function type_of(v)
  local mt = getmetatable(v)
  if type(v) ~= "userdata" or not mt then return nil end
  for name, r in pairs(live.restorers) do
    if debug.getregistry()[name] == mt then return name, r end
  end
  return nil
end

local function snapshot(v, seen)
  seen = seen or {}
  local _, r = type_of(v)
  if r then return { value = v, state = r.snapshot(v) } end
  if type(v) == "table" and not seen[v] then
    seen[v] = true
    local parts = {}
    for _, x in pairs(v) do
      local s = snapshot(x, seen)
      if s then
        if s.value then parts[#parts + 1] = s else for _, p in ipairs(s) do parts[#parts + 1] = p end end
      end
    end
    if #parts > 0 then return parts end
  end
  return nil
end

local function restore(snap)
  if not snap then return end
  if snap.value then
    local _, r = type_of(snap.value)
    r.restore(snap.value, snap.state)
  else
    for _, s in ipairs(snap) do restore(s) end
  end
end

-- Keys compare by value (numbers, strings, booleans, nested tables of them).
local function same_key(a, b)
  if type(a) ~= type(b) then return false end
  if type(a) ~= "table" then return a == b end
  for k, v in pairs(a) do if not same_key(v, b[k]) then return false end end
  for k in pairs(b) do if a[k] == nil then return false end end
  return true
end

-- sn.keep(name, make [, key]) -> the value make() returned the first time. A different `key`
-- (e.g. the training settings) makes it again; sn.forget(name) too.
function sn.keep(name, make, key)
  if type(name) ~= "string" then error("sn.keep: the first argument must be a name (a string), got " .. type(name), 2) end
  if type(make) ~= "function" then
    error(("sn.keep('%s', make): make must be a function that builds the value, got %s"):format(name, type(make)), 2)
  end
  local k = S.kept[name]
  if k and (key == nil or same_key(key, k.key)) then return k.value end
  local value = make()
  if value == nil then error(("sn.keep('%s'): the function returned nil; it must return the value to keep"):format(name), 2) end
  S.kept[name] = { value = value, key = key, snapshot = snapshot(value) }
  return value
end

-- sn.forget(name): the next sn.keep(name, ...) makes the value again (nil: forget all).
function sn.forget(name)
  if name == nil then S.kept = {} return end
  if S.kept[name] == nil then
    local names = {}
    for n in pairs(S.kept) do names[#names + 1] = n end
    table.sort(names)
    error(("sn.forget: nothing kept under '%s' (kept: %s)"):format(tostring(name),
      #names > 0 and table.concat(names, ", ") or "none"), 2)
  end
  S.kept[name] = nil
end

-- sn.kept() -> sorted names of the kept values
function sn.kept()
  local names = {}
  for n in pairs(S.kept) do names[#names + 1] = n end
  table.sort(names)
  return names
end

---------------------------------------------------------------------------------------------
-- sn.live.show / sn.live.render

local SHOW_KEYS = { "network", "truth", "scene", "camera", "light", "mode", "title", "val_mse", "error_scale",
                    "colormap", "size" }

local function strict(t, valid, what, level)
  if type(t) ~= "table" then error(("%s expects a table of options, got %s"):format(what, type(t)), level + 1) end
  local ok = {}
  for _, k in ipairs(valid) do ok[k] = true end
  for k in pairs(t) do
    if not ok[k] then
      error(("%s: unknown option '%s' (valid: %s)"):format(what, tostring(k), table.concat(valid, ", ")), level + 1)
    end
  end
end

local function check_vec3(v, what, level)
  if type(v) ~= "table" or #v ~= 3 then error(what .. " must be {x, y, z}", level + 1) end
  for i = 1, 3 do
    if type(v[i]) ~= "number" or v[i] ~= v[i] or v[i] == math.huge or v[i] == -math.huge then
      error(("%s[%d] must be a finite number, got %s"):format(what, i, tostring(v[i])), level + 1)
    end
  end
end

local function check_light(light, what, level)
  if type(light) ~= "table" then error(what .. " must be a table { dir = {x, y, z} }", level + 1) end
  strict(light, { "dir" }, what, level + 1)
  check_vec3(light.dir, what .. ".dir", level + 1)
  local d = light.dir
  if d[1] == 0 and d[2] == 0 and d[3] == 0 then error(what .. ".dir must not be zero", level + 1) end
end

local function check_size(size, what, level)
  if type(size) ~= "table" or type(size[1]) ~= "number" or type(size[2]) ~= "number" or size[1] < 1 or size[2] < 1
     or size[1] % 1 ~= 0 or size[2] % 1 ~= 0 then
    error(what .. " must be {width, height} in whole pixels >= 1", level + 1)
  end
end

local function is_camera(v)
  return type(v) == "userdata" and getmetatable(v) == debug.getregistry().Camera
end

local function type_is(v, name)
  return type(v) == "userdata" and getmetatable(v) == debug.getregistry()[name]
end

-- What `network` / `truth` may be: a function of the view, or with a `scene`, a network (Mlp)
-- or a lighting model (sn.lighting.*) that scene:render shades from the view's camera and light.
local function drawer(spec, key)
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
  return function(view)
    return scene:render(x, { camera = view.camera, light = view.light, size = { view.width, view.height } })
  end
end

-- sn.live.show{ network = net | function(view), truth = model | function(view), scene = scene,
--               camera = Camera, light = {dir = {x,y,z}}, mode = "network", title = "...",
--               val_mse = number | function() -> number, error_scale = 0.25,
--               colormap = "inferno", size = {w, h} }
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
  if spec.val_mse ~= nil and type(spec.val_mse) ~= "number" and type(spec.val_mse) ~= "function" then
    error("sn.live.show: 'val_mse' must be a number or a function returning one", 2)
  end
  local copy = { draw = {} }
  for k, v in pairs(spec) do copy[k] = v end
  copy.draw.network, copy.draw.truth = drawer(spec, "network"), drawer(spec, "truth")
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

local function current_spec(what)
  local spec = S.spec
  if S.running and S.pending then spec = S.pending end
  if not spec then error(what .. ": nothing to show yet; call sn.live.show{ network = ..., truth = ... } first", 3) end
  return spec
end

-- A drawer's result as a Target: Images (scene:render) are uploaded, into `cache` when given.
local function as_target(t, what, cache, key)
  if type_is(t, "Target") then return t end
  if type_is(t, "Image") then
    local into = cache and cache[key]
    local out = sn.live_upload(t, into)
    if cache then cache[key] = out end
    return out
  end
  error(("%s must return a Target or an Image, got %s"):format(what, type(t) == "userdata" and tostring(t) or type(t)), 0)
end

local function draw(spec, which, view, cache)
  local f = spec.draw[which]
  if not f then
    local has = spec.draw.network and "network" or "truth"
    error(("mode '%s' needs '%s' in sn.live.show{...} (this view has only '%s')"):format(view.mode, which, has), 0)
  end
  return as_target(f(view), "sn.live.show's '" .. which .. "'", cache, which .. " " .. view.width .. "x" .. view.height)
end

-- The view a mode renders, with every default filled in.
local function resolve_view(spec, o)
  local size = spec.size or spec.default_size
  local w, h = o.width or (size and size[1]) or 640, o.height or (size and size[2]) or 480
  return {
    mode = o.mode or spec.mode,
    camera = o.camera or spec.camera or sn.camera {},
    light = o.light or spec.light or { dir = { 0, 0, 1 } },
    width = w, height = h,
  }
end

-- Side by side: three panels of the view's aspect across the view's width.
local function panel_size(w, h)
  local pw = math.max(1, math.floor(w / 3))
  return pw, math.max(1, math.floor(pw * h / w + 0.5))
end

-- `cache` (the loop's) keeps GPU targets between frames; headless renders get fresh ones.
local function render(spec, view, cache)
  local mode = view.mode
  if mode == "network" then return draw(spec, "network", view, cache) end
  if mode == "truth" then return draw(spec, "truth", view, cache) end
  local v = view
  if mode == "side" then
    v = {}
    for k, x in pairs(view) do v[k] = x end
    v.width, v.height = panel_size(view.width, view.height)
  end
  local n, t = draw(spec, "network", v, cache), draw(spec, "truth", v, cache)
  local key = mode .. " " .. view.width .. "x" .. view.height
  local out = sn.live_compose { network = n, truth = t, layout = mode == "side" and "side" or "error",
                                scale = view.error_scale or spec.error_scale or 0.25, colormap = spec.colormap,
                                into = cache and cache[key] }
  if cache then cache[key] = out end
  return out
end

-- sn.live.render{ mode = "network" | "truth" | "error" | "side", camera = Camera,
--                 light = {dir = {x,y,z}}, width = 640, height = 480 } -> Target
-- The image the window shows for that view (side: 3 panels of width/3 each).
function live.render(o)
  o = o or {}
  strict(o, { "mode", "camera", "light", "width", "height" }, "sn.live.render", 2)
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
  local spec = current_spec("sn.live.render")
  local ok, r = pcall(render, spec, resolve_view(spec, o))
  if not ok then error("sn.live.render: " .. tostring(r), 2) end
  return r
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
-- it to `path` (default "view.png"); the P key prints it. Numbers are exact (%.17g).
function live.view_code(path)
  local v = S.view
  if not v then return "-- nothing rendered yet" end
  local c = v.camera
  local cam = ("sn.camera { eye = %s, target = %s, fov = %.17g%s }"):format(vec_code(c:eye()), vec_code(c:target()),
    c:fov(), c:aspect() and (", aspect = %.17g"):format(c:aspect()) or "")
  return ("sn.live.render { mode = %q, camera = %s, light = { dir = %s }, width = %d, height = %d }"
          .. ":read():save(%q)"):format(v.mode, cam, vec_code(v.light.dir), v.width, v.height, path or "view.png")
end

---------------------------------------------------------------------------------------------
-- Screenshots and recordings

local function numbered(dir, stem, ext)
  os.execute(("mkdir -p %q"):format(dir))
  for i = 1, 99999 do
    local p = ("%s/%s-%04d%s"):format(dir, stem, i, ext)
    local f = io.open(p, "r")
    if not f then return p end
    f:close()
  end
  error("sn.live: no free file name in " .. dir)
end

local absolute = sn.live_absolute

-- sn.live.screenshot([path]) -> absolute path: saves the current view (PNG unless the path
-- says otherwise); by default out/live/screenshot-NNNN.png.
function live.screenshot(path)
  local view = S.view or resolve_view(current_spec("sn.live.screenshot"), {})
  path = path or numbered("out/live", "screenshot", ".png")
  local spec = current_spec("sn.live.screenshot")
  render(spec, view):read():save(path)
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
  local base = S.view or resolve_view(spec, {})
  local view = {}
  for k, v in pairs(base) do view[k] = v end
  if o.mode ~= nil then
    if not is_mode(o.mode) then
      error(("sn.record: unknown mode '%s' (valid: %s)"):format(tostring(o.mode), table.concat(MODES, ", ")), 2)
    end
    view.mode = o.mode
  end
  view.width, view.height = o.width or view.width, o.height or view.height
  local dir = o.dir
  if not dir then
    os.execute("mkdir -p out/live")
    for i = 1, 9999 do
      dir = ("out/live/record-%04d"):format(i)
      local f = io.open(dir .. "/frame-0001.png", "r")
      if not f then break end
      f:close()
    end
  end
  os.execute(("mkdir -p %q"):format(dir))
  local paths = {}
  local function frame(k)
    local p = ("%s/frame-%04d.png"):format(dir, k)
    render(spec, view):read():save(p)
    paths[#paths + 1] = absolute(p)
  end
  if o.orbit then
    strict(o.orbit, { "count", "elevation", "distance" }, "sn.record: orbit", 2)
    local count = o.orbit.count or 36
    local cam = view.camera
    local e, t = cam:eye(), cam:target()
    local d = { e[1] - t[1], e[2] - t[2], e[3] - t[3] }
    local dist = o.orbit.distance or math.sqrt(d[1] ^ 2 + d[2] ^ 2 + d[3] ^ 2)
    local elev = o.orbit.elevation and math.rad(o.orbit.elevation)
                 or math.asin(math.max(-1, math.min(1, d[2] / math.sqrt(d[1] ^ 2 + d[2] ^ 2 + d[3] ^ 2))))
    local az0 = math.atan2(d[1], d[3])
    for k = 1, count do
      local az = az0 + 2 * math.pi * (k - 1) / count
      view.camera = sn.camera { eye = { t[1] + dist * math.cos(elev) * math.sin(az), t[2] + dist * math.sin(elev),
                                        t[3] + dist * math.cos(elev) * math.cos(az) },
                                target = t, fov = cam:fov(), aspect = cam:aspect() }
      frame(k)
    end
  else
    strict(o.sweep, { "set", "get", "from", "to", "count" }, "sn.record: sweep", 2)
    local s = o.sweep
    if type(s.set) ~= "function" then error("sn.record: sweep.set must be a function(value) that applies the value", 2) end
    local from, to, count = s.from or -2, s.to or 2, s.count or 9
    local before = s.get and s.get()
    local ok, err = pcall(function()
      for k = 1, count do
        s.set(count == 1 and from or from + (to - from) * (k - 1) / (count - 1))
        frame(k)
      end
    end)
    if before ~= nil then s.set(before) end
    if not ok then error("sn.record: " .. tostring(err), 2) end
  end
  return absolute(dir), paths
end
live.record = sn.record

---------------------------------------------------------------------------------------------
-- The loop's side (runtime/live/live_loop.cpp). Not for scripts.

-- Before each (re)run of the watched script: its modules load afresh, kept networks go back
-- to their snapshot, and sn.live.show calls collect in `pending`.
function live._begin_run()
  S.active = true
  for name in pairs(S.modules) do package.loaded[name] = nil end
  S.modules = {}
  S.files_before, S.files = S.files, {}
  for _, k in pairs(S.kept) do restore(k.snapshot) end
  S.running, S.pending = true, nil
end

-- After it: a good run makes its sn.live.show the view and its networks the good state; a
-- failed one puts the networks back as the last good run left them and keeps that view.
function live._end_run(ok)
  S.running = false
  if ok then
    S.spec = S.pending or S.spec
    for _, k in pairs(S.kept) do k.good = snapshot(k.value) end
  else
    for _, k in pairs(S.kept) do restore(k.good or k.snapshot) end
    for f in pairs(S.files_before or {}) do S.files[f] = true end  -- keep watching what a fix may touch
  end
  S.pending, S.files_before = nil, nil
end

-- The files to watch besides the script (modules and dofile'd scripts).
function live._watched()
  local list = {}
  for f in pairs(S.files) do list[#list + 1] = f end
  table.sort(list)
  return list
end

function live._has_view() return S.spec ~= nil end

-- The spec's camera and light, for the loop's orbit controls: eye, target, fov, light dir.
function live._initial_view()
  local spec = S.spec
  if not spec then return nil end
  local cam = spec.camera or sn.camera {}
  local light = (spec.light or { dir = { 0, 0, 1 } }).dir
  return cam:eye(), cam:target(), cam:fov(), light, spec.mode, spec.size
end

local function format_mse(spec)
  local v = spec.val_mse
  if type(v) == "function" then
    local ok, r = pcall(v)
    v = ok and r or nil
  end
  if type(v) == "number" then return ("val MSE %.3g"):format(v) end
  return nil
end

-- One frame for the loop: `view` = {mode, width, height, eye, target, fov, light} from the
-- window's controls (eye/target/light absent when the user has not moved them). Returns the
-- Target to present and the title's text.
function live._frame(v)
  local spec = S.spec
  local camera = spec.camera
  if v.eye then
    camera = sn.camera { eye = v.eye, target = v.target, fov = v.fov,
                         aspect = spec.camera and spec.camera:aspect() or nil }
  end
  local o = { mode = v.mode, camera = camera, light = v.light and { dir = v.light } or nil }
  if not spec.size then o.width, o.height = v.width, v.height end
  local view = resolve_view(spec, o)
  view.error_scale = (spec.error_scale or 0.25) * (v.error_scale_factor or 1)
  local size = view.width .. "x" .. view.height
  if S.out_size ~= size then S.out, S.out_size = {}, size end  -- a resized window frees the old targets
  local target = render(spec, view, S.out)
  S.view, S.frames = view, S.frames + 1
  local parts = { spec.title or "shadenet", view.mode }
  if view.mode == "error" or view.mode == "side" then
    parts[#parts + 1] = ("|error| scale %.3g"):format(view.error_scale)
  end
  parts[#parts + 1] = format_mse(spec)
  return target, table.concat(parts, " · ")
end

-- Requests from Lua code to the loop (sn.live.quit(), sn.live.redraw()), taken once.
function live._take_requests()
  local r = S.requests
  S.requests = {}
  return r.quit == true, r.redraw == true, r.view
end

-- Console lines see the globals and the script's top-level locals of its last good run;
-- assigning to such a name changes what later lines see (the script's closures keep theirs).
function live._set_locals(locals) S.locals = locals end

local console_env = setmetatable({}, {
  __index = function(_, k)
    local l = S.locals
    if l and l[k] ~= nil then return l[k] end
    return _G[k]
  end,
  __newindex = function(_, k, v)
    local l = S.locals
    if l and l[k] ~= nil then l[k] = v else _G[k] = v end
  end,
})
function live._console_env() return console_env end

function live._set_status(title, err)
  S.status = { title = title, error = err }
end

return live
