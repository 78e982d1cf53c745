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
--                                values = { condition = x }, nonfinite = "warn" | "error" | "ignore" }])
--   -> Image (RGBA float, alpha = coverage)
--   a "Lighting" model: the ground truth over the view's G-buffer (sn.render_truth);
--   an "Mlp": the network's own fragment pass over the attributes it reads (net:render).
-- `camera` replaces the scene's view (live mode's orbit), `light` the scene's light for the
-- ground truth (a network shows what it learned), `size` the scene's image size, `values` a
-- conditioned network's condition inputs (net:conditions()), `nonfinite` what a network's NaN or
-- infinite pixels give (net:render: a warning, an error, nothing).
local RENDER_KEYS = { view = true, pose = true, camera = true, light = true, size = true, values = true,
                      nonfinite = true }
function Scene.render(scene, what, options)
  options = options or {}
  if type(options) ~= "table" then
    error("scene:render: options table expected as argument 2, got " .. type(options), 2)
  end
  for k in pairs(options) do
    if not RENDER_KEYS[k] then
      error("scene:render: unknown option '" .. tostring(k) .. "' (valid: camera, light, nonfinite, pose, size, values, view)", 2)
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
    if options.nonfinite then
      error("scene:render: 'nonfinite' is for networks (net:render), not lighting models", 2)
    end
    where.attributes = what:attributes()
    local g = scene:gbuffer(where)
    local light = scene:light()
    if options.light then
      light = { dir = options.light.dir or light.dir, color = options.light.color or light.color }
    end
    return sn.render_truth(g, what, light)
  elseif kind == "Mlp" then
    local inputs = what:inputs()
    if #inputs == 0 then
      error("scene:render: this network does not know which G-buffer attributes it reads; train it on a "
            .. "scene:dataset (or give it input names) first", 2)
    end
    if not what.render then error("scene:render: this build cannot render networks (net:render is missing)", 2) end
    local conditions = {}
    for _, c in ipairs(what:conditions()) do conditions[c.name] = true end
    local attributes = {}
    for _, name in ipairs(inputs) do
      if not conditions[name] then attributes[#attributes + 1] = name end
    end
    where.attributes = attributes
    local g = scene:gbuffer(where)
    return what:render(g, { values = options.values, nonfinite = options.nonfinite })
  end
  error("scene:render: a lighting model (sn.lighting.*) or a network (sn.mlp) expected, got " .. kind, 2)
end

return Scene
