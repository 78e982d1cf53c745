-- expect: shade_missing_base\.lua:5: model:shade: the model textured_phong reads the attribute 'base_color': give base = {\.\.\.}
-- What a model reads must be given to its twin (without base it shaded white, 0.73 here).
local sn = require "shadenet"
local model = sn.lighting.textured_phong {}
local c = model:shade { normal = { 0, 1, 0 }, view = { 0, 1, 0 } }
