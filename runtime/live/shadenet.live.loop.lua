-- The C++ loop's side of live mode (runtime/live/live_loop.cpp drives it through these live._*
-- functions). Not for scripts.
local sn = require "shadenet.core"
local S = require "shadenet.live.state"
local keep = require "shadenet.live.keep"
local bind = require "shadenet.live.bind"
local view_of = require "shadenet.live.view"
local live = sn.live
local snapshot, restore = keep.snapshot, keep.restore
local render, resolve_view = view_of.render, view_of.resolve_view

-- Before each (re)run of the watched script: its modules load afresh, kept networks go back
-- to their snapshot, and sn.live.show calls collect in `pending`. width x height: what the loop
-- draws the view at (0 x 0: the show's size decides).
function live._begin_run(width, height)
  S.loop_size = width and width > 0 and height > 0 and { width, height } or nil
  S.active = true
  for name in pairs(S.modules) do package.loaded[name] = nil end
  S.modules = {}
  S.files_before, S.files = S.files, {}
  for _, k in pairs(S.kept) do restore(k.snapshot) end
  S.running, S.pending, S.pending_binds = true, nil, nil
end

-- After it: a good run makes its sn.live.show the view and its networks the good state; a
-- failed one puts the networks back as the last good run left them and keeps that view.
function live._end_run(ok)
  S.running = false
  bind.end_run(ok)
  if ok then
    S.spec = S.pending or S.spec
    for _, k in pairs(S.kept) do k.good = snapshot(k.value) end
  else
    for _, k in pairs(S.kept) do restore(k.good or k.snapshot) end
    for f in pairs(S.files_before or {}) do S.files[f] = true end  -- keep watching what a fix may touch
  end
  S.pending, S.files_before = nil, nil
end

-- Around each console line: one that fails puts back the networks it may have changed (the kept
-- ones, the show's, the script's top-level locals that are networks) as they were before it, and
-- drops the view it asked for, so that a failed line changes nothing the window shows.
function live._line_begin()
  local values = {}
  for _, k in pairs(S.kept) do values[#values + 1] = k.value end
  if S.spec and keep.restorable(S.spec.network) then values[#values + 1] = S.spec.network end
  for _, v in pairs(S.locals or {}) do
    if keep.restorable(v) then values[#values + 1] = v end
  end
  S.line_snapshot = snapshot(values)
end

function live._line_end(ok)
  if not ok then
    restore(S.line_snapshot)
    S.requests.view, S.requests.quit = nil, nil
  end
  S.line_snapshot = nil
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
  local target, parts = render(spec, view, S.out)
  S.view, S.frames, S.drawn = view, S.frames + 1, parts
  parts.frame = S.frames
  local parts = { spec.title or "shadenet", view.mode }
  if view.mode == "error" or view.mode == "side" then
    parts[#parts + 1] = ("|error| scale %.3g"):format(view.error_scale)
  end
  parts[#parts + 1] = format_mse(spec)
  return target, table.concat(parts, " · "), view.error_scale
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

