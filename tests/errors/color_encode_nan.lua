-- expect: color_encode_nan\.lua:4: sn\.color\.encode colour: component 1 is nan; colours must be finite
local sn = require "shadenet"
-- It gave {0, 0, nan} without a word.
sn.color.encode("hsv", { 0 / 0, 0.5, 0.5 })
