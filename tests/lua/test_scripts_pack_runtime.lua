-- tools/pack_runtime.sh: the parts it writes are each within the size asked for, add up to an
-- archive whose libraries are every one the programs load beyond the C runtime and the GL
-- loaders, OpenImageIO's readers of formats shadenet never reads as stand-ins, and whose build/
-- runs from the unpacked libraries alone, images included; bad options are refused.
local sn = require "shadenet"
local C = require "script_check"
local sh, out_of = C.sh, C.output

local base = C.tmpdir("pack_runtime")
local listed, stand_ins = {}, {}
for line in out_of("tools/pack_runtime.sh --list"):gmatch("[^\n]+") do
  local stood_in = line:match("^stand%-in (%S+)$")
  if stood_in then stand_ins[#stand_ins + 1] = stood_in else listed[#listed + 1] = line end
end
assert(#listed > 10, "the libraries to pack: " .. table.concat(listed, ", "))
for _, path in ipairs(listed) do
  local name = path:match("[^/]+$")
  assert(not name:match("^libc%.") and not name:match("^ld%-linux") and not name:match("^libstdc%+%+") and
         not name:match("^libGLX") and not name:match("^libGLdispatch"), "packed but the other machine has its own: " .. path)
  -- Only what a packed file needs: nothing that only a stood-in library (FFmpeg's codecs) loads.
  assert(not name:match("^libav") and not name:match("^libopencv") and not name:match("^libx26[45]"),
         "packed although only a stood-in reader needs it: " .. path)
end
local stood = " " .. table.concat(stand_ins, " ") .. " "
for _, name in ipairs { "libavformat.so.59", "libopencv_core.so.406", "libopenvdb.so.10.0", "libheif.so.1" } do
  assert(stood:find(" " .. name .. " ", 1, true), name .. " is not a stand-in: " .. stood)
end
local all = out_of("tools/pack_runtime.sh --all --list")
assert(not all:find("stand-in", 1, true), "--all packs every library")
assert(select(2, all:gsub("\n", "")) > #listed + 50, "--all packs FFmpeg's own too")

-- Parts of at most 8 MiB at the fastest level; their sha256 in the manifest.
local parts = base .. "/parts"
assert(sh(("tools/pack_runtime.sh --level 0 --part-mib 8 %s > %s/pack.out 2>&1"):format(parts, base)),
       C.read(base .. "/pack.out"))
local sizes = out_of("stat -c %s " .. parts .. "/runtime.tar.xz.part-*")
local n = 0
for size in sizes:gmatch("%d+") do
  n = n + 1
  assert(tonumber(size) <= 8 * 1048576, "a part over 8 MiB: " .. size)
end
assert(n >= 2, "the archive is split: " .. n .. " part(s)")
assert(sh(("cd %s && sed -n '/part-/p' MANIFEST | sha256sum -c --quiet"):format(parts)), "the parts match the manifest")

-- Put together and unpacked: every library listed, and build/shadenet runs on them.
local root = base .. "/unpacked"
assert(sh(("mkdir %s && cat %s/runtime.tar.xz.part-* | xz -d | tar -x -C %s"):format(root, parts, root)), "unpacking")
for _, path in ipairs(listed) do
  local name = path:match("[^/]+$")
  assert(sh(("test -s %s/lib/%s"):format(root, name)), "missing from the archive: " .. name)
end
local env = ("LD_LIBRARY_PATH=%s/lib "):format(root)
local ldd = out_of(env .. "ldd " .. root .. "/build/shadenet " .. root .. "/build/tests/shadenet_unit")
for line in ldd:gmatch("[^\n]+") do
  local name, path = line:match("^%s*(%S+) => (/%S+)")
  if name and not path:find(root, 1, true) then
    assert(name:match("^lib[cm]%.") or name:match("^libpthread") or name:match("^libdl") or name:match("^libresolv") or
           name:match("^librt") or name:match("^libstdc") or name:match("^libgcc_s") or name:match("^libGL") or
           name:match("^libEGL") or name:match("^libOpenGL"), "loaded from this machine, not the archive: " .. line)
  end
end
assert(out_of(env .. root .. "/build/shadenet --version"):match("^shadenet [%d.]+"), "the unpacked build runs")
assert(C.read(root .. "/lib/stand-ins.txt") == table.concat(stand_ins, "\n") .. "\n", "lib/stand-ins.txt lists the stand-ins")
for _, name in ipairs(stand_ins) do
  assert(out_of(env .. "ldd " .. root .. "/lib/libOpenImageIO.so.2.4"):find(name .. " => " .. root .. "/lib/" .. name, 1, true),
         name .. ": the stand-in is what OpenImageIO loads")
end

-- Images through the packed OpenImageIO, as tools/gpu_bench.sh --libs runs it: PNG and EXR written
-- and read back, a corrupt PNG refused by the PNG reader alone; a file of a stood-in format stops
-- the program, naming the stand-in and the function.
env = env .. "OPENIMAGEIO_OPTIONS=try_all_readers=0 "
local script = base .. "/images.lua"
sn.fs.write(script, ([[
local sn = require "shadenet"
local img = sn.image.new { width = 3, height = 2 }
img:set(2, 1, {0.25, 0.5, 1, 1})
for _, ext in ipairs { "png", "exr" } do
  img:save("%s/saved." .. ext)
  local back = sn.image.load("%s/saved." .. ext)
  assert(select(1, back:size()) == 3 and math.abs(back:get(2, 1)[1] - 0.25) < 0.003, ext)
end
local ok, err = pcall(sn.image.load, "tests/data/corrupt.png")
assert(not ok and err:find("PNG read error", 1, true), err)
io.write("images: ok\n"); io.flush()
if arg[1] then sn.image.load(arg[1]) end
]]):format(base, base))
local images = out_of(env .. root .. "/build/shadenet " .. script)
assert(images:match("images: ok\n$"), "images through the packed libraries:\n" .. images)
sn.fs.write(base .. "/movie.mp4", "not a movie")
local stopped = out_of(env .. root .. "/build/shadenet " .. script .. " " .. base .. "/movie.mp4")
assert(stopped:find("images: ok\n", 1, true) and stopped:find("libav%a+%.so%.%d+: [%w_]+ was called, but this copy of the library is a stand%-in"),
       "a stood-in reader stops the program, naming itself:\n" .. stopped)

-- Bad options: refused, naming what is valid.
assert(out_of("tools/pack_runtime.sh --part-mib 0 " .. base .. "/x"):find("--part-mib must be a whole number", 1, true))
assert(out_of("tools/pack_runtime.sh --level 12 " .. base .. "/x"):find("--level must be 0-9", 1, true))
assert(out_of("tools/pack_runtime.sh --zip " .. base .. "/x"):find("unknown option '--zip' (valid:", 1, true))
assert(out_of("tools/stub_library.sh /nonexistent.so " .. base .. "/x build/shadenet"):find("no library '/nonexistent.so'", 1, true))
C.rm(base)
print("pack_runtime: ok")
