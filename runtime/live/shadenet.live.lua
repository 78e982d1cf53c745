-- Live mode, the Lua side, one concern per module: what survives a reload (keep), which files
-- the script read (files), what the window shows and the same view headless (view),
-- screenshots and recordings (record), the pixel probe (probe), keys bound to values (bind), long work that keeps the window
-- alive (busy), and the C++ loop's side (loop, driven by
-- runtime/live/live_loop.cpp). A plain headless script uses the same functions, so every image
-- the window shows can be produced without a display.
local sn = require "shadenet.core"

local live = {}
sn.live = live

require "shadenet.live.files"
require "shadenet.live.keep"
require "shadenet.live.view"
require "shadenet.live.busy"
require "shadenet.live.record"
require "shadenet.live.probe"
require "shadenet.live.bind"
require "shadenet.live.loop"

return live
