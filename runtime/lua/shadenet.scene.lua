-- Lua-side scene helpers (required by the prelude): scene:render, which shades a view with a
-- lighting model (the ground truth) or a trained network, through the same G-buffer.
local sn = require "shadenet.core"

local registry = debug.getregistry()
local Scene = registry.Scene.__index

local function type_name(x)
  local mt = getmetatable(x)
  return (type(mt) == "table" and mt.__name) or type(x)
end

-- scene:render(model_or_net [, { view = 1, pose = 1, camera = Camera, light = {dir, color}, size = {w, h},
--                                values = { condition = x }, backend = "auto", target = Target,
--                                nonfinite = "warn" | "error" | "ignore" }])
--   -> Image (RGBA float, alpha = coverage), or the Target given
--   a "Lighting" model: the ground truth over the view's G-buffer (sn.render_truth);
--   an "Mlp": the network over the attributes it reads (net:render; sn.render_info() says which
--   backend drew it and why).
-- `camera` replaces the scene's view (live mode's orbit), `light` the scene's light for the
-- ground truth (a network shows what it learned), `size` the scene's image size, `values` a
-- conditioned network's condition inputs (net:conditions()), `backend` a network's renderer
-- ("gl", "cpu" or "auto", net:render's), `target` a Target the network is drawn into instead of
-- a new Image (net:render's; what a window shows), `nonfinite` what a network's NaN or infinite
-- pixels give (net:render's: a warning, an error, nothing).
-- scene:gbuffer(where) for scene:render: an error (a view, pose, size or camera outside what the
-- scene has) is raised at the script's line, under the name the script called.
local function gbuffer_for_render(scene, where)
  local ok, g = pcall(scene.gbuffer, scene, where)
  if ok then return g end
  error((tostring(g):gsub("^scene:gbuffer", "scene:render")), 3)
end

-- obj:method() for scene:render: its error (a released model, network or scene) is raised at the
-- script's line under scene:render's name; called here, it named this file's line.
local message_of = require("shadenet.where").message
local function method(obj, name)
  local ok, r = pcall(function() return obj[name](obj) end)
  if not ok then error("scene:render: " .. message_of(r), 3) end
  return r
end

local RENDER_KEYS = { view = true, pose = true, camera = true, light = true, size = true, values = true,
                      backend = true, target = true, nonfinite = true }
function Scene.render(scene, what, options)
  options = options or {}
  if type(options) ~= "table" then
    error("scene:render: options table expected as argument 2, got " .. type(options), 2)
  end
  for k in pairs(options) do
    if not RENDER_KEYS[k] then
      error("scene:render: unknown option '" .. tostring(k) .. "' (valid: backend, camera, light, nonfinite, pose, size, target, values, view)", 2)
    end
  end
  if options.view ~= nil and options.camera ~= nil then error("scene:render: give 'view' or 'camera', not both", 2) end
  local where = { view = options.camera == nil and (options.view or 1) or options.view, camera = options.camera,
                  size = options.size, pose = options.pose }
  local kind = type_name(what)
  if kind == "Lighting" then
    if options.values then
      error("scene:render: 'values' sets a conditioned network's inputs; for a lighting model use model:with{...}", 2)
    end
    if options.backend or options.target or options.nonfinite then
      error("scene:render: 'backend', 'target' and 'nonfinite' are a network's (net:render); a lighting model is "
            .. "drawn by its shader into a new Image", 2)
    end
    local light = method(scene, "light")
    if options.light ~= nil then
      if type(options.light) ~= "table" then
        error("scene:render option 'light': { dir = {x, y, z}, color = {r, g, b} } expected, got " .. type(options.light), 2)
      end
      for k in pairs(options.light) do
        if k ~= "dir" and k ~= "color" then
          error("scene:render option 'light': unknown key '" .. tostring(k) .. "' (valid: color, dir)", 2)
        end
      end
      light = { dir = options.light.dir or light.dir, color = options.light.color or light.color }
    end
    where.attributes = method(what, "attributes")
    local g = gbuffer_for_render(scene, where)
    local ok, img = pcall(sn.render_truth, g, what, light)
    g:release()  -- its target goes back to the pool now, not at the next garbage collection
    if not ok then error((tostring(img):gsub("^sn%.render_truth", "scene:render")), 2) end
    return img
  elseif kind == "Mlp" then
    local inputs = method(what, "inputs")
    if #inputs == 0 then
      error("scene:render: this network does not know which G-buffer attributes it reads; train it on a "
            .. "scene:dataset (or give it input names) first", 2)
    end
    if not what.render then error("scene:render: this build cannot render networks (net:render is missing)", 2) end
    local conditions = {}
    for _, c in ipairs(method(what, "conditions")) do conditions[c.name] = true end
    local attributes = {}
    for _, name in ipairs(inputs) do
      if not conditions[name] then attributes[#attributes + 1] = name end
    end
    where.attributes = attributes
    local g = gbuffer_for_render(scene, where)
    -- Through pcall: the G-buffer goes back to the pool whatever happens, and an error (C
    -- functions called by pcall carry no position) is raised at the caller's line.
    local ok, img = pcall(what.render, what, g, { values = options.values, backend = options.backend,
                                                   target = options.target, nonfinite = options.nonfinite })
    g:release()
    if not ok then error(img, 2) end
    return img
  end
  error("scene:render: a lighting model (sn.lighting.*) or a network (sn.mlp) expected, got "
        .. registry["shadenet.type_name"](what), 2)
end

return Scene
