-- A results folder holds one experiment, in one mode, on one choice of data, with one setting of
-- the script's own flags: their run ids are the same, so a second one there overwrote the first's
-- records and tables without a word (a smoke run after a full Table 4.1 retrained 72 of its 360
-- runs; Table 4.1 into Table 4.2's folder replaced all 72; mysweep --epochs 5 after --epochs 20
-- replaced every record). experiment.json says which, from the start (run.json, written at the
-- end, was missing after a kill -9); writing it also finds an unwritable folder before any
-- training.
--
-- The claim is one process' at a time: an exclusive lock on DIR/runs (sn.fs.lock) while it reads
-- and writes experiment.json, so two different experiments started at the same moment cannot
-- both pass the check (both did, and the second overwrote the first's results); then a shared lock
-- held until the process ends, however it ends, so a newcomer knows the folder is in use. Shards of
-- one sweep may share a folder at once: they agree on all of it, and the newcomer says so.
--
-- Flags are compared by what they give: by their values ("--epochs 4" = "--epochs=4.0"), and
-- where those differ (a flag left at the script's default, another given the default's value) by
-- the runs they make: each E:sweep's runs, ids and configurations, hashed into a key that
-- experiment.json and run.json keep (`sweeps`). scripts/merge.lua compares shards the same way.
local sn = require "shadenet"
local cli = require "lib.cli"
local json = require "lib.json"
local results = require "lib.results"

local claim = {}

-- The flags as values: a number given as text ("4", "4.0", "4e0") is the number, a switch true.
function claim.flag_values(flags)
  local out = {}
  for k, v in pairs(flags or {}) do out[k] = type(v) == "string" and tonumber(v) or v end
  return out
end

local function same_flags(a, b) return json.encode(a or {}) == json.encode(b or {}) end

-- "--epochs 20 --model ggx" (sorted; a switch alone), or "" for none.
function claim.flags_text(flags)
  local out = {}
  for k, v in pairs(flags or {}) do out[#out + 1] = v == true and k or (k .. " " .. tostring(v)) end
  table.sort(out)
  return table.concat(out, " ")
end

-- "mysweep --quick --epochs 20 (--data poses, --ggx thesis)".
function claim.describe(e)
  local d, o = cli.defaults, e.options or {}
  local flags = claim.flags_text(e.flags)
  return string.format("%s%s%s (--data %s, --ggx %s)", e.experiment, e.quick and " --quick" or "",
                       flags ~= "" and " " .. flags or "", o.data or d.data, o.ggx or d.ggx)
end

-- The description without the flags: what no run may differ in.
local function base(e) return claim.describe { experiment = e.experiment, quick = e.quick, options = e.options } end

-- Each sweep's key: a hash of its runs' ids and configurations, in order.
function claim.runs_key(runs)
  local parts = {}
  for i, r in ipairs(runs) do parts[i] = r.id .. "\0" .. (r.config_text or json.encode(r.config or {})) end
  return sn.hash(table.concat(parts, "\n"))
end

-- A folder's claim as experiment.json (or, from before it, run.json) records it:
-- { experiment, quick, options = {data, ggx}, flags (values; nil: not recorded), sweeps = {key, ...} }, or nil.
function claim.read(dir)
  for _, file in ipairs { "experiment.json", "run.json" } do
    local path = dir .. "/" .. file
    local text = results.read_file(path)
    local ok, there = pcall(json.decode, text or "", path)
    if text and ok and type(there) == "table" and there.experiment then
      return claim.normalize(there)
    end
  end
end

-- experiment.json's or run.json's fields as claim.read gives them.
function claim.normalize(there)
  local d, o = cli.defaults, type(there.options) == "table" and there.options or {}
  local flags = there.flag_values or there.flags  -- run.json: flag_values; run.json from before it: flags as given
  local keys = {}
  for i, s in ipairs(type(there.sweeps) == "table" and there.sweeps or {}) do
    keys[i] = type(s) == "table" and s.key or type(s) == "string" and s or false  -- run.json: { key, ... } per sweep
  end
  return { experiment = there.experiment, quick = there.quick == true,
           options = { data = o.data or d.data, ggx = o.ggx or d.ggx },
           flags = type(flags) == "table" and claim.flag_values(flags) or nil, sweeps = keys }
end

-- Says `why` on stderr, alone (no Lua traceback: a user's mistake), and exits 2.
function claim.refuse(why)
  io.stderr:write(why, "\n")
  os.exit(2)
end

-- The folders this process holds (merge.lua claims its output, then runs the experiment there).
local held = {}

local Claim = {}
Claim.__index = Claim

-- claim.folder(dir, mine) -> Claim: mine = { experiment, quick, options, flags (values), sweeps
-- (keys, when known: merge.lua's shards') }. Exits 2 when the folder holds another experiment.
function claim.folder(dir, mine)
  dir = dir:gsub("/+$", "")
  local ok, err = pcall(sn.fs.mkdir, dir .. "/runs")
  if not ok then
    io.stderr:write(string.format("%s: cannot write its results folder: %s\n", mine.experiment, tostring(err)))
    os.exit(1)
  end
  local alone = true
  if not held[dir] then
    local lock = sn.fs.lock(dir .. "/runs", { wait = false })
    if not lock then  -- busy: another process works in this folder now; wait while it claims
      alone = false
      lock = sn.fs.lock(dir .. "/runs", { shared = true })
    end
    held[dir] = lock
  end
  local there = claim.read(dir)
  local self = setmetatable({ dir = dir, mine = mine, sweeps = {}, alone = alone }, Claim)
  if there then
    local busy = alone and "" or " (another process is running it there now)"
    if base(there) ~= base(mine) then
      claim.refuse(string.format("%s holds the results of %s%s; %s there would overwrite them: give it its own --out DIR",
                                 dir, claim.describe(there), busy, claim.describe(mine)))
    end
    for i, k in ipairs(there.sweeps) do self.sweeps[i] = k end
    -- Other flag values: the same experiment only if they make the same runs (checked per sweep).
    if there.flags and not same_flags(there.flags, mine.flags) then
      self.other = there
      for i, k in ipairs(mine.sweeps or {}) do self:check_sweep(i, k) end
    end
  end
  if alone then
    if not self.other then self:write() end
    held[dir]:share()  -- from here on others may work beside us (shards of the sweep)
  elseif not self.other then
    io.stderr:write(string.format("%s: another process is running %s in %s now (another shard of its sweeps, or the "
                                  .. "same command, which then trains the same runs)\n", mine.experiment,
                                  claim.describe(mine), dir))
  end
  return self
end

function Claim:write()
  local m = self.mine
  local ok, err = pcall(results.write_json, self.dir .. "/experiment.json",
                        { experiment = m.experiment, quick = m.quick, options = m.options, flags = m.flags or {},
                          sweeps = self.sweeps })
  if not ok then
    io.stderr:write(string.format("%s: cannot write its results folder: %s\n", m.experiment, tostring(err)))
    os.exit(1)
  end
end

-- The k-th sweep's runs, by their key: where the folder was claimed with other flag values, they
-- must be the runs found there (else exit 2); otherwise the key is recorded.
function Claim:check_sweep(k, key)
  if self.other then
    local there = self.other.sweeps[k]
    if there ~= key then
      claim.refuse(string.format("%s holds the results of %s; %s there would overwrite them (%s): give it its own "
                                 .. "--out DIR", self.dir, claim.describe(self.other), claim.describe(self.mine),
                                 there and "its runs differ" or "its runs there are not known to be the same"))
    end
    if not self.said then
      self.said = true
      print(string.format("%s: %s holds the runs of %s: the same runs as %s", self.mine.experiment, self.dir,
                          claim.describe(self.other), claim.describe(self.mine)))
    end
    return
  end
  if self.sweeps[k] ~= key then
    for i = 1, k - 1 do self.sweeps[i] = self.sweeps[i] or false end  -- (JSON: no holes)
    self.sweeps[k] = key
    self:write()
  end
end

return claim
