-- tools/pack_runtime.sh: the parts it writes are each within the size asked for, add up to an
-- archive whose libraries are every one the programs load beyond the C runtime and the GL
-- loaders, and whose build/ runs from the unpacked libraries alone; bad options are refused.
local C = require "script_check"
local sh, out_of = C.sh, C.output

local base = C.tmpdir("pack_runtime")
local listed = {}
for path in out_of("tools/pack_runtime.sh --list"):gmatch("[^\n]+") do listed[#listed + 1] = path end
assert(#listed > 10, "the libraries to pack: " .. table.concat(listed, ", "))
for _, path in ipairs(listed) do
  local name = path:match("[^/]+$")
  assert(not name:match("^libc%.") and not name:match("^ld%-linux") and not name:match("^libstdc%+%+") and
         not name:match("^libGLX") and not name:match("^libGLdispatch"), "packed but the other machine has its own: " .. path)
end

-- Parts of at most 30 MiB at the fastest level; their sha256 in the manifest.
local parts = base .. "/parts"
assert(sh(("tools/pack_runtime.sh --level 0 --part-mib 30 %s > %s/pack.out 2>&1"):format(parts, base)),
       C.read(base .. "/pack.out"))
local sizes = out_of("stat -c %s " .. parts .. "/runtime.tar.xz.part-*")
local n = 0
for size in sizes:gmatch("%d+") do
  n = n + 1
  assert(tonumber(size) <= 30 * 1048576, "a part over 30 MiB: " .. size)
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

-- Bad options: refused, naming what is valid.
assert(out_of("tools/pack_runtime.sh --part-mib 0 " .. base .. "/x"):find("--part-mib must be a whole number", 1, true))
assert(out_of("tools/pack_runtime.sh --level 12 " .. base .. "/x"):find("--level must be 0-9", 1, true))
assert(out_of("tools/pack_runtime.sh --zip " .. base .. "/x"):find("unknown option '--zip' (valid:", 1, true))
C.rm(base)
print("pack_runtime: ok")
