-- Helpers for the experiment script tests (tests/lua/test_scripts_*.lua): run a script in a
-- child shadenet, read its tables, compare folders.
package.path = "scripts/?.lua;" .. package.path
local sn = require "shadenet"
local results = require "lib.results"
local json = require "lib.json"

local C = {}

C.shadenet = arg[-1] or "build/shadenet"

-- A fresh folder, removed when the test ends (sn.fs.tempdir).
function C.tmpdir(tag) return sn.fs.tempdir(tag) end

-- A child script: `source` written as child.lua in a fresh temporary folder; its path and the folder.
function C.child(tag, source)
  local dir = C.tmpdir(tag)
  return sn.fs.write(dir .. "/child.lua", source), dir
end

local function sh_quote(s) return "'" .. tostring(s):gsub("'", "'\\''") .. "'" end

-- Runs `shadenet SCRIPT ARGS...`; returns exit code and output (stdout + stderr).
function C.run(script, args, env)
  local parts = {}
  for k, v in pairs(env or {}) do parts[#parts + 1] = k .. "=" .. sh_quote(v) end
  parts[#parts + 1] = sh_quote(C.shadenet)
  parts[#parts + 1] = sh_quote(script)
  for _, a in ipairs(args or {}) do parts[#parts + 1] = sh_quote(a) end
  local pipe = assert(io.popen(table.concat(parts, " ") .. " 2>&1; printf '\\n%d\\n' $?"))
  local out = pipe:read("*a")
  pipe:close()
  local code
  out = out:gsub("\n(%d+)\n$", function(c) code = tonumber(c); return "" end)
  return code, out
end

-- Runs a shell command: true when it exits 0.
function C.sh(cmd)
  local status = os.execute(cmd)
  return status == 0 or status == true
end

-- A shell command's output, stdout and stderr.
function C.output(cmd)
  local p = io.popen(cmd .. " 2>&1")
  local text = p:read("*a")
  p:close()
  return text
end

-- Runs and asserts success.
function C.ok(script, args, env)
  local code, out = C.run(script, args, env)
  assert(code == 0, script .. " " .. table.concat(args or {}, " ") .. " failed (" .. tostring(code) .. "):\n" .. out)
  return out
end

-- Reads a CSV written by lib.results into a list of rows keyed by the header.
function C.csv(path)
  local text = results.read_file(path)
  assert(text, path .. " is missing")
  local lines = {}
  for line in text:gmatch("[^\n]+") do lines[#lines + 1] = line end
  local function split(line)
    local out, field, i, quoted = {}, "", 1, false
    while i <= #line do
      local c = line:sub(i, i)
      if quoted then
        if c == '"' and line:sub(i + 1, i + 1) == '"' then field = field .. '"' i = i + 1
        elseif c == '"' then quoted = false
        else field = field .. c end
      elseif c == '"' then quoted = true
      elseif c == "," then out[#out + 1] = field field = ""
      else field = field .. c end
      i = i + 1
    end
    out[#out + 1] = field
    return out
  end
  local head = split(lines[1])
  local rows = {}
  for k = 2, #lines do
    local cells, row = split(lines[k]), {}
    for j, h in ipairs(head) do
      local v = cells[j]
      row[h] = (v ~= nil and v ~= "" and tonumber(v)) or (v ~= "" and v or nil)
    end
    rows[#rows + 1] = row
  end
  return rows, head
end

function C.exists(path) return sn.fs.exists(path) == "file" end

function C.assert_files(dir, files)
  for _, f in ipairs(files) do assert(C.exists(dir .. "/" .. f), dir .. "/" .. f .. " is missing") end
end

function C.finite(v) return type(v) == "number" and v == v and v ~= math.huge and v ~= -math.huge end

-- Every value of `key` in rows is a finite number in [lo, hi].
function C.assert_range(rows, key, lo, hi, what)
  for i, r in ipairs(rows) do
    local v = r[key]
    assert(C.finite(v) and v >= lo and v <= hi,
           string.format("%s row %d: %s = %s, expected a finite number in [%g, %g]", what or "", i, key, tostring(v), lo, hi))
  end
end

function C.read(path) return results.read_file(path) end
function C.json(path) return results.read_json(path) end

-- Copies the run files whose index (in sorted order) passes keep(i) from src/runs to dst/runs.
function C.copy_runs(src, dst, keep)
  sn.fs.mkdir(dst .. "/runs")
  local n = 0
  for i, f in ipairs(sn.fs.list(src .. "/runs")) do
    if keep(i) then
      results.write_file(dst .. "/runs/" .. f, results.read_file(src .. "/runs/" .. f))
      n = n + 1
    end
  end
  return n
end

-- The `result` parts of every run file of a folder, by id (timings left out: they differ run to run).
function C.run_results(dir)
  local out = {}
  for _, f in ipairs(sn.fs.list(dir .. "/runs")) do
    local rec = json.decode(results.read_file(dir .. "/runs/" .. f), f)
    local r = rec.result
    out[rec.id] = json.encode { r.best_val_mse, r.best_epoch, r.val_mse, r.train_mse, r.params }
  end
  return out
end

-- Runs a script in a child shadenet with a Ctrl-C sent to itself after its first training
-- group: a deterministic stand-in for a person pressing Ctrl-C mid-sweep. With `in_training`
-- = n, the Ctrl-C comes inside the n-th sn.train call instead, after its first epoch (sn.train
-- then stops at its next step); with `in_training` = 0 it comes as the first group begins, before
-- its dataset is built. `signal` (default 2, SIGINT) is the signal sent: 15 is SIGTERM.
function C.run_interrupted(script, args, in_training, signal)
  local wrapper = C.tmpdir("interrupted") .. "/wrapper.lua"
  results.write_file(wrapper, string.format([[
package.path = "scripts/?.lua;" .. package.path
local sn = require "shadenet"
local exp = require "lib.experiment"
local ffi = require "ffi"
ffi.cdef "int getpid(void); int kill(int pid, int sig);"
local in_training, signal = %s, %d
local train_group = exp.Experiment.train_group
local sent = false
local function ctrl_c()
  sent = true
  ffi.C.kill(ffi.C.getpid(), signal)  -- SIGINT: as a terminal's Ctrl-C sends
end
exp.Experiment.train_group = function(self, group, tick)
  if in_training == 0 and not sent then ctrl_c() end
  local out = train_group(self, group, tick)
  if not sent and not in_training then ctrl_c() end
  return out
end
local train, calls = sn.train, 0
sn.train = function(o)
  calls = calls + 1
  if calls == in_training then
    local progress = o.progress
    o.progress = function(e)
      if not sent then ctrl_c() end
      if progress then return progress(e) end
    end
  end
  return train(o)
end
arg[0] = %q
dofile(%q)
]], tostring(in_training), signal or 2, script, script))
  local code, out = C.run(wrapper, args)
  return code, out
end

function C.rm(dir) os.execute("rm -rf " .. sh_quote(dir)) end

return C
