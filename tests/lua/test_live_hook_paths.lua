-- The live test hooks' paths are names, not printf formats: "%d" becomes the count, any other
-- "%" stays ("50%off" lost its sign; "%s%s" crashed the session).
local sn = require "shadenet"
local dir = sn.fs.tempdir("live_hooks")
local script = dir .. "/view.lua"
sn.fs.write(script, [[
local sn = require "shadenet"
local scene = sn.scene { mesh = sn.mesh.sphere(), size = { 40, 30 }, light = { dir = { 0.5, 0.7, 0.6 } } }
sn.live.show { scene = scene, truth = sn.lighting.phong {}, mode = "truth" }
]])
local exe = arg[-1] or "build/shadenet"
if exe:sub(1, 1) ~= "/" then exe = os.getenv("PWD") .. "/" .. exe end
local cmd = ("cd %q && SHADENET_LIVE_SNAPSHOT='50%%off-%%s%%s-%%d.png' SHADENET_LIVE_SHOWN='shown%%x-%%d.png' "
             .. "SHADENET_LIVE_EXIT_AFTER=1 %q --watch view.lua < /dev/null 2>&1; echo \"rc $?\""):format(dir, exe)
local p = io.popen(cmd)
local out = p:read("*a")
p:close()
assert(out:find("rc 0", 1, true), "the session ends well:\n" .. out)
assert(sn.fs.exists(dir .. "/50%off-%s%s-1.png") == "file", "the snapshot keeps its name:\n" .. table.concat(sn.fs.list(dir), "\n"))
assert(sn.fs.exists(dir .. "/shown%x-1.png") == "file", "the shown picture keeps its name:\n" .. table.concat(sn.fs.list(dir), "\n"))
local w, h = sn.image.load(dir .. "/50%off-%s%s-1.png"):size()
assert(w == 40 and h == 30, ("the snapshot is the view: %dx%d"):format(w, h))
print("ok")
