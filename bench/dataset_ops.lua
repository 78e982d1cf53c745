-- Dataset algebra and files: wall time of sn.dataset.concat, ds:subset, ds:split, and of
-- ds:export + sn.dataset.load in both formats, on datasets of the thesis' size (64,149 rows of
-- 6 inputs -> 3 outputs, named normal + view, split 4:1).
--
--   shadenet bench/dataset_ops.lua [repeats] [dir]
--     repeats: timings per operation; the median is printed (default 7)
--     dir:     where the files go, an output folder made if missing (default: a scratch folder,
--              sn.fs.tempdir, removed after)
--
-- Times are sn.clock() (wall clock) around one call; exports include each file's fsync (the
-- atomic write), so the disk under `dir` counts. "load" is the 1-minute load average before
-- the operation's first run: other work on a shared machine slows the figures. Ctrl-C stops it
-- after the call in flight (that operation's row is not printed), removes the scratch folder
-- and exits 130.
local sn = require "shadenet"
package.path = (arg[0]:match("^(.*)/[^/]*$") or ".") .. "/?.lua;" .. package.path
local B = require "common"

-- An output folder: made when missing; "" (the default) is the scratch folder.
local folder = {
  form = "a folder to write into (made if missing), not a file",
  parse = function(s)
    local kind = s ~= "" and sn.fs.exists(s)
    return (not kind or kind == "folder") and s or nil
  end,
}
local o = B.args("bench/dataset_ops.lua", { { "repeats", "7", B.whole(1) }, { "dir", "", folder } })
local repeats = o.repeats
-- Before the scratch folder exists: SIGINT's default action would end the process before the
-- Lua state closes, and the folder would stay in TMPDIR.
B.catch_interrupt()
local dir = o.dir ~= "" and sn.fs.mkdir(o.dir) or sn.fs.tempdir("dataset_ops")

-- Rows written straight into float buffers (no Lua tables): unit normals and view directions
-- on a spiral, targets a smooth function of them.
local rows = 64149
local function make(seed)
  local bx = sn.buffer { type = "float32", size = rows * 6 }
  local by = sn.buffer { type = "float32", size = rows * 3 }
  local px, py = bx:ffi(), by:ffi()
  for i = 0, rows - 1 do
    local t = (i + seed * 0.37) * 0.0137
    local z = 1 - 2 * ((i * 0.618034 + seed * 0.1) % 1)
    local r = math.sqrt(1 - z * z)
    px[i * 6], px[i * 6 + 1], px[i * 6 + 2] = r * math.cos(t * 97), r * math.sin(t * 97), z
    px[i * 6 + 3], px[i * 6 + 4], px[i * 6 + 5] = 0, math.sin(t), math.cos(t)
    py[i * 3] = 0.5 + 0.4 * px[i * 6] * px[i * 6 + 4]
    py[i * 3 + 1] = 0.5 + 0.3 * z
    py[i * 3 + 2] = 0.2 + 0.1 * math.cos(t)
  end
  local d = sn.dataset { x = bx, inputs = 6, y = by, outputs = 3, split = 0.8, seed = seed,
                         input_names = { "normal", "view" } }
  bx:release()
  by:release()
  return d
end
local a, b = make(1), make(2)

print(("datasets: 2 x %d rows (6 -> 3, %d train / %d val), %d repeats, files in %s"):format(rows, select(1, a:counts()),
  select(2, a:counts()), repeats, dir))
print(("%-34s %10s %10s %10s %6s"):format("operation", "median ms", "min ms", "max ms", "load"))
local function bench(name, f)
  local load = B.load()
  local times = {}
  for i = 1, repeats do
    collectgarbage()
    local t0 = sn.clock()
    f()
    times[i] = (sn.clock() - t0) * 1e3
    B.stop_if_interrupted("the operation '" .. name .. "'")
  end
  local lo, hi = math.min(unpack(times)), math.max(unpack(times))
  print(("%-34s %10.2f %10.2f %10.2f %6s"):format(name, B.median(times), lo, hi, load))
end

bench("concat {a, b} (128,298 rows)", function() sn.dataset.concat { a, b } end)
bench("subset count 32000 (first rows)", function() a:subset { count = 32000 } end)
bench("subset count 32000 seed 1", function() a:subset { count = 32000, seed = 1 } end)
bench("subset where normal.x in [-1,0.4]", function() a:subset { where = { input = "normal", axis = "x", min = -1, max = 0.4 } } end)
bench("split 0.5 seed 2", function() a:split { split = 0.5, seed = 2 } end)
bench("export npy", function() a:export(dir .. "/a") end)
bench("load npy", function() sn.dataset.load(dir .. "/a.json") end)
bench("export + load npy", function() sn.dataset.load(a:export(dir .. "/a")) end)
bench("export csv", function() a:export(dir .. "/a.csv") end)
bench("load csv", function() sn.dataset.load(dir .. "/a.csv") end)
bench("export + load csv", function() sn.dataset.load(a:export(dir .. "/a.csv")) end)

local sizes = {}
for _, f in ipairs { "a.json", "a.inputs.npy", "a.targets.npy", "a.csv" } do
  local h = io.open(dir .. "/" .. f, "rb")
  sizes[#sizes + 1] = ("%s %.2f MB"):format(f, h:seek("end") / 1e6)
  h:close()
end
print("files: " .. table.concat(sizes, ", "))
