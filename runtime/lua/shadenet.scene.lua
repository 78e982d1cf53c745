-- Lua-side scene helpers (required by the prelude): scene:render, which shades a view with a
-- lighting model (the ground truth) or a trained network, through the same G-buffer.
local sn = require "shadenet.core"

local registry = debug.getregistry()
local Scene = registry.Scene.__index

local function type_name(x)
  local mt = getmetatable(x)
  return (type(mt) == "table" and mt.__name) or type(x)
end

-- scene:render(model_or_net [, { view = 1 }]) -> Image (RGBA float, alpha = coverage)
--   a "Lighting" model: the ground truth over the view's G-buffer (sn.render_truth);
--   an "Mlp": the network's own fragment pass over the attributes it reads (net:render).
function Scene.render(scene, what, options)
  options = options or {}
  if type(options) ~= "table" then
    error("scene:render: options table expected as argument 2, got " .. type(options), 2)
  end
  for k in pairs(options) do
    if k ~= "view" then error("scene:render: unknown option '" .. tostring(k) .. "' (valid: view)", 2) end
  end
  local view = options.view or 1
  local kind = type_name(what)
  if kind == "Lighting" then
    local g = scene:gbuffer { view = view, attributes = what:attributes() }
    return sn.render_truth(g, what, scene:light())
  elseif kind == "Mlp" then
    local inputs = what:inputs()
    if #inputs == 0 then
      error("scene:render: this network does not know which G-buffer attributes it reads; train it on a "
            .. "scene:dataset (or give it input names) first", 2)
    end
    if not what.render then error("scene:render: this build cannot render networks (net:render is missing)", 2) end
    local g = scene:gbuffer { view = view, attributes = inputs }
    return what:render(g)
  end
  error("scene:render: a lighting model (sn.lighting.*) or a network (sn.mlp) expected, got " .. kind, 2)
end

return Scene
