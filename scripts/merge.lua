-- Merges the results of a sweep run in shards (--shard i/n, a Slurm job array, GNU parallel)
-- into the table a single run gives:
--   shadenet scripts/merge.lua [--out DIR] SHARD_DIR...
-- Every shard folder holds run.json (which experiment, quick or full) and runs/*.json (one file
-- per finished run). The run files are copied into DIR/runs (default: the shards' parent folder,
-- e.g. results/table_4_1_phong for results/table_4_1_phong/shard-*), then the experiment script
-- runs on DIR: every run is finished, so it trains nothing and writes the table, plots and
-- run.json from the merged runs.
package.path = (arg and arg[0] and arg[0]:match("^(.*)/[^/]*$") or ".") .. "/?.lua;" .. package.path
local sn = require "shadenet"
local results = require "lib.results"
local cli = require "lib.cli"
local claim = require "lib.claim"
local json = require "lib.json"

local usage = "usage: shadenet scripts/merge.lua [--out DIR] SHARD_DIR..."
-- Every refusal is the user's to mend, not a fault of the script: the message alone on stderr (no
-- Lua traceback) and exit status 2, as a command-line error (lib.claim.refuse).
local function fail(why) claim.refuse("merge.lua: " .. why) end
local dirs, out = {}, nil
local i = 1
while i <= #arg do
  local a = arg[i]
  if a == "--out" then
    out = arg[i + 1] and arg[i + 1]:gsub("/+$", "")
    if not out then fail("--out needs a folder\n" .. usage) end
    i = i + 1
  elseif a == "--help" then
    print(usage)
    os.exit(0)
  elseif a:sub(1, 2) == "--" then
    fail("unknown option '" .. a .. "' (valid: --out DIR, --help)\n" .. usage)
  else
    dirs[#dirs + 1] = (a:gsub("/+$", ""))
  end
  i = i + 1
end
if #dirs == 0 then fail("no shard folders given\n" .. usage) end

-- The options that choose the experiment's data (--data, --ggx) as a shard's run.json records
-- them; a run.json from before `options` was recorded has them on its command line (absent
-- there: the defaults). nil when neither tells.
local function recorded(info, key)
  if type(info.options) == "table" and info.options[key] then return info.options[key] end
  if type(info.command) ~= "string" then return nil end
  return info.command:match("%-%-" .. key .. "=(%S+)") or info.command:match("%-%-" .. key .. "%s+(%S+)")
         or cli.defaults[key]
end

-- Which experiment, in which mode, on which data: every shard must agree.
local name, quick, backend, recorded_script, flags_json, flags, flag_values
local keys = {}  -- the first shard's sweep keys
local options, first_with = {}, {}
for _, d in ipairs(dirs) do
  if sn.fs.exists(d) ~= "folder" then fail("'" .. d .. "' is not a folder") end
  local info = results.read_json(d .. "/run.json")
  if not info then
    fail(d .. "/run.json is missing: not a results folder, or its run was stopped before the end")
  end
  if name and info.experiment ~= name then
    fail(string.format("%s is from %s, %s from %s; merge one experiment at a time", dirs[1], name, d,
                       tostring(info.experiment)))
  end
  if quick ~= nil and info.quick ~= quick then
    local with, without = d, dirs[1]
    if quick then with, without = dirs[1], d end
    fail(with .. " was run with --quick, " .. without .. " without it: their runs are different experiments")
  end
  for _, key in ipairs { "data", "ggx" } do
    local v = recorded(info, key)
    if not v then
      fail(string.format("%s/run.json records neither options nor a command line: which --%s its runs used is "
                         .. "unknown; merge by hand (copy the run files together and run the experiment with the "
                         .. "shards' options)", d, key))
    end
    if options[key] and options[key] ~= v then
      fail(string.format("%s was run with --%s %s, %s with --%s %s: their runs are different experiments",
                         first_with[key], key, options[key], d, key, v))
    end
    options[key], first_with[key] = v, first_with[key] or d
  end
  -- The script's own flags (exp.start's `flags`): every shard must have been given the same values
  -- ("--epochs 4" = "--epochs=4.0"), or values that make the same runs (a flag left at its
  -- default, another given the default's value): each sweep's key in run.json (lib.claim).
  local given = claim.normalize(info)
  local values = json.encode(given.flags or {})
  if flags_json and values ~= flags_json then
    local same = #keys > 0 and #given.sweeps == #keys
    for k, key in ipairs(keys) do same = same and key and given.sweeps[k] == key end
    local function shown(f)
      local t = claim.flags_text(type(f) == "table" and f or {})
      return t ~= "" and t or "(none)"
    end
    if not same then
      fail(string.format("%s was run with the script's flags %s, %s with %s: their runs are different experiments%s",
                         dirs[1], shown(flags), d, shown(info.flags),
                         #given.sweeps == 0 and " (or are not known to be the same: no sweep keys in run.json)" or ""))
    end
    print(string.format("merge.lua: %s was run with the script's flags %s, %s with %s: they make the same runs", dirs[1],
                        shown(flags), d, shown(info.flags)))
  end
  if not flags_json then
    flags_json, flags, keys = values, type(info.flags) == "table" and info.flags or {}, given.sweeps
    flag_values = given.flags or {}
  end
  name, quick = info.experiment, info.quick
  recorded_script = recorded_script or info.script or
                    (type(info.command) == "string" and info.command:match("^%S+%s+(%S+%.lua)") or nil)
  -- The backend the shards asked for, when they agree (each shard trained its runs on it);
  -- otherwise auto, which takes every run whatever trained it.
  local asked = info.backend and info.backend.requested or "auto"
  backend = (backend == nil or backend == asked) and asked or "auto"
end
-- The experiment script: where the shards ran it from (run.json's `script`, or its command
-- line's), else the one of that name beside merge.lua.
local beside = (arg[0] and (arg[0]:match("^(.*)/[^/]*$") or ".") or "scripts") .. "/" .. name .. ".lua"
local script = recorded_script
if not script or sn.fs.exists(script) ~= "file" then script = beside end
if sn.fs.exists(script) ~= "file" then
  fail("the experiment script is missing: " .. (recorded_script and (recorded_script .. " (as the shards ran it), ") or "")
       .. beside)
end

if not out then
  local parent = dirs[1]:match("^(.*)/[^/]+$") or "."
  for _, d in ipairs(dirs) do
    if (d:match("^(.*)/[^/]+$") or ".") ~= parent then
      fail("the shard folders have different parents; say where the merged results go with --out DIR")
    end
  end
  out = parent
end

-- The output folder is claimed for the shards' experiment before anything is copied into it: a
-- folder holding another experiment's results is refused (exit 2) with them untouched (the run
-- files were copied first, and the check came only when the experiment ran on the folder).
claim.folder(out, { experiment = name, quick = quick, options = { data = options.data, ggx = options.ggx },
                    flags = flag_values, sweeps = keys })

-- The run files. The same run in two shard folders must hold the same configuration (a different
-- one means two different experiments were mixed up); the first one's record is kept. Checked
-- for all before any is copied.
local plan, order = {}, {}
for _, d in ipairs(dirs) do
  local rd = d .. "/runs"
  if sn.fs.exists(rd) == "folder" then
    for _, f in ipairs(sn.fs.list(rd)) do
      if f:match("%.json$") and not f:match("^%.") then
        local text = results.read_file(rd .. "/" .. f)
        local first = plan[f]
        if first then
          local _, have = pcall(json.decode, first.text, first.from)
          local _, new = pcall(json.decode, text, rd .. "/" .. f)
          if type(have) == "table" and type(new) == "table" and json.encode(have.config) ~= json.encode(new.config) then
            fail(rd .. "/" .. f .. " and " .. first.from .. " hold the same run with different configurations")
          end
          first.copies = first.copies + 1
        else
          plan[f] = { text = text, from = rd .. "/" .. f, copies = 1 }
          order[#order + 1] = f
        end
      end
    end
  end
end
-- A record the output folder held before the merge gives way to the shards' (it was kept over
-- them: an earlier gl run's records over the cpu shards merged, and the table came out empty).
local copied, same, replaced = 0, 0, 0
for _, f in ipairs(order) do
  local target = out .. "/runs/" .. f
  local before = results.read_file(target)
  if before == plan[f].text then
    same = same + 1
  else
    results.write_file(target, plan[f].text)
    if before then replaced = replaced + 1 else copied = copied + 1 end
  end
  same = same + plan[f].copies - 1
end
print(string.format("merge.lua: %d run files from %d folders into %s/runs (%d already there%s)", copied, #dirs, out, same,
                    replaced > 0 and string.format("; %d records the folder held before replaced by the shards'", replaced)
                      or ""))

-- The experiment itself writes the merged table: nothing is left to train.
arg = { [0] = script, [-1] = arg[-1], "--out", out }
if quick then arg[#arg + 1] = "--quick" end
for _, key in ipairs { "data", "ggx" } do
  arg[#arg + 1] = "--" .. key
  arg[#arg + 1] = options[key]
end
if backend then
  arg[#arg + 1] = "--backend"
  arg[#arg + 1] = backend
end
local own = {}
for flag in pairs(flags) do own[#own + 1] = flag end
table.sort(own)
for _, flag in ipairs(own) do  -- a flag without a value was recorded as true
  arg[#arg + 1] = flags[flag] == true and flag or flag .. "=" .. tostring(flags[flag])
end
require("lib.experiment").report_only = true
dofile(script)
