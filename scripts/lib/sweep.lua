-- A sweep: a list of runs with deterministic ids, trained in groups, each finished run written
-- at once to DIR/runs/ID.json (atomically). Re-running skips every run whose file exists with
-- the same configuration, so a killed or interrupted sweep resumes where it stopped; a shard
-- i/n takes runs i, i+n, i+2n, ... of the list (round robin, so every shard gets a fair mix of
-- small and large networks); results from several shards merge by copying run files together.
local sn = require "shadenet"
local json = require "lib.json"
local results = require "lib.results"
local Progress = require "lib.progress"
local options = require "lib.options"

local Sweep = {}
Sweep.__index = Sweep

-- sweep.new{ dir = results folder, runs = { {id = "L4-W6-s3", config = {...}}, ... },
--            shard = {index, count} | nil, label = "table_4_1_phong",
--            accept = function(record, run) -> false when a finished record may not be reused
--                     (lib.experiment: trained on another backend than --backend asks for) }
function Sweep.new(o)
  options.check(o, "Sweep.new", { "dir", "runs", "shard", "label", "accept" }, { "dir", "runs" },
                { dir = "the results folder", runs = "a list of { id, config }" })
  local ids = {}
  for k, r in ipairs(o.runs) do
    if type(r.id) ~= "string" or not r.id:match("^[%w._-]+$") then
      error(string.format("sweep: run %d has id '%s'; ids must be made of letters, digits, '.', '_' and '-'",
                          k, tostring(r.id)), 0)
    end
    if ids[r.id] then error("sweep: two runs have the id '" .. r.id .. "'", 0) end
    ids[r.id] = true
    r.config_text = json.encode(r.config or {})
  end
  local self = setmetatable({ dir = o.dir, runs_dir = o.dir .. "/runs", runs = o.runs, shard = o.shard,
                              label = o.label or "sweep", accept = o.accept }, Sweep)
  sn.fs.mkdir(self.runs_dir)
  results.clean_temps(self.runs_dir)
  return self
end

-- The runs this process is responsible for.
function Sweep:slice()
  if not self.shard then return self.runs end
  local out = {}
  for k, r in ipairs(self.runs) do
    if (k - 1) % self.shard.count == self.shard.index - 1 then out[#out + 1] = r end
  end
  return out
end

function Sweep:file(run) return self.runs_dir .. "/" .. run.id .. ".json" end

-- "sweep: ignoring FILE: why", once per file and reason however often the file is read.
function Sweep:warn(run, why)
  local line = "sweep: ignoring " .. self:file(run) .. ": " .. why .. " (not a finished run)\n"
  self.warned = self.warned or {}
  if self.warned[line] then return end
  self.warned[line] = true
  io.stderr:write(line)
end

-- The finished record of `run`, or nil when it has not run with this configuration (or `accept`
-- refuses it; `any` = true skips that test). A run file that cannot be read is reported and
-- treated as not finished (it will be trained again).
function Sweep:record(run, any)
  local text = results.read_file(self:file(run))
  if not text then return nil end
  local ok, rec = pcall(json.decode, text, self:file(run))
  if not ok or type(rec) ~= "table" then
    self:warn(run, "unreadable: " .. tostring(rec))
    return nil
  end
  if json.encode(rec.config or {}) ~= run.config_text then return nil end
  -- A record's result is a table whose errors are numbers >= 0 (or NaN, a diverged run; or
  -- absent, a run that diverged before any validation): a tampered or corrupt one would enter
  -- the tables or stop the sweep, so it is reported (once) and trained again.
  if type(rec.result) ~= "table" then
    self:warn(run, "its result is " .. (rec.result == nil and "missing" or "a " .. type(rec.result) .. ", not a table"))
    return nil
  end
  -- (An error is a number or, for a curve such as val_mse, a list of numbers.)
  local function bad(k, v)
    if type(v) ~= "number" then return string.format("%s = %s is a %s, not a number", k, json.encode(v), type(v)) end
    if v < 0 then return k .. " = " .. tostring(v) .. " is negative" end
  end
  for k, v in pairs(rec.result) do
    if type(k) == "string" and k:find("mse$") then
      local why
      if type(v) == "table" then
        for i, x in pairs(v) do why = why or bad(k .. "[" .. tostring(i) .. "]", x) end
      else
        why = bad(k, v)
      end
      if why then
        self:warn(run, why)
        return nil
      end
    end
  end
  if self.accept and not any and not self.accept(rec, run) then return nil end
  return rec
end

function Sweep:pending()
  local out = {}
  for _, r in ipairs(self:slice()) do
    if not self:record(r) then out[#out + 1] = r end
  end
  return out
end

-- All finished records of the whole sweep found in the folder (this shard's and any other's
-- copied in), in the sweep's order; runs without a record are absent.
function Sweep:records()
  local out = {}
  for _, r in ipairs(self.runs) do
    local rec = self:record(r)
    if rec then out[#out + 1] = rec end
  end
  return out
end

-- sweep:run{ train = function(group, tick) -> results, one table per run of `group`, in order
--                    (tick(fraction) may report how far the group is, for the progress line);
--            group_key = function(run) -> key (runs with equal keys may train together; default
--                        all), chunk = max runs per group (default all),
--            score = function(result) -> number (lower is better; for the progress line),
--            describe = function(run) -> short text (for the progress line) }
-- Returns finished, interrupted: the number of finished runs of the slice, and true when
-- Ctrl-C stopped the sweep early (every run finished before it is kept). Ctrl-C stops sn.train
-- at its next step: a result flagged `interrupted` is a run stopped part-way, not written, so
-- the next run of the same command trains it again from the start.
function Sweep:run(o)
  options.check(o, "sweep:run", { "train", "group_key", "chunk", "score", "describe" }, { "train" },
                { train = "function(group, tick) -> one result table per run of the group" })
  local slice = self:slice()
  local pending = self:pending()
  local done = #slice - #pending
  local progress = Progress.new { total = #slice, label = self.label, already = done }
  local best, best_text
  local function consider(run, result)
    local s = o.score and o.score(result)
    if s and s == s and (not best or s < best) then
      best = s
      best_text = string.format("%.6g", s) .. (o.describe and (" (" .. o.describe(run) .. ")") or "")
    end
  end
  for _, r in ipairs(slice) do
    local rec = self:record(r)
    if rec then consider(r, rec.result) end
  end
  if #pending == 0 then return done, false end
  if done > 0 then
    print(string.format("%s: resuming, %d of %d runs already finished in %s", self.label, done, #slice, self.runs_dir))
  end

  -- Groups: runs with the same key, in list order, cut into chunks.
  local groups, by_key, order = {}, {}, {}
  for _, r in ipairs(pending) do
    local key = o.group_key and tostring(o.group_key(r)) or "all"
    if not by_key[key] then by_key[key] = {} order[#order + 1] = key end
    local list = by_key[key]
    local last = list[#list]
    if not last or (o.chunk and #last >= o.chunk) then
      last = {}
      list[#list + 1] = last
    end
    last[#last + 1] = r
  end
  for _, key in ipairs(order) do
    for _, g in ipairs(by_key[key]) do groups[#groups + 1] = g end
  end

  sn.catch_interrupt()
  progress:update(done, best_text)
  local interrupted, stopped_part_way = false, 0
  for _, group in ipairs(groups) do
    local t0 = sn.clock()
    -- tick(f): the group is fraction f done (for the ETA while a long group trains).
    local base = done
    local function tick(f) progress:update(base + math.max(0, math.min(1, f)) * #group, best_text, base) end
    local out = o.train(group, tick)
    assert(type(out) == "table" and #out == #group,
           string.format("sweep: train returned %s results for %d runs", type(out) == "table" and #out or type(out), #group))
    local seconds = sn.clock() - t0
    local stopped, records = 0, {}
    for k, r in ipairs(group) do
      if type(out[k]) == "table" and out[k].interrupted then
        stopped = stopped + 1
      else
        records[self:file(r)] = { id = r.id, config = r.config, result = out[k], group_size = #group,
                                  group_seconds = seconds, finished = os.date("!%Y-%m-%dT%H:%M:%SZ"),
                                  build = sn.build }  -- the binary that trained it (run.json lists them all)
        done = done + 1
        consider(r, out[k])
      end
    end
    results.write_jsons(records)
    progress:update(done, best_text)
    stopped_part_way = stopped_part_way + stopped
    if sn.interrupted() or stopped > 0 then
      interrupted = true
      break
    end
  end
  -- Past the sweep nothing is lost by stopping at once: Ctrl-C gets its default action back.
  sn.catch_interrupt(false)
  progress:finish()
  if interrupted then
    local never = #slice - done - stopped_part_way
    local left = {}
    if stopped_part_way > 0 then left[#left + 1] = "the " .. stopped_part_way .. " stopped part-way" end
    if never > 0 then left[#left + 1] = "the " .. never .. " not started" end
    print(string.format("%s: stopped (Ctrl-C or SIGTERM); %d of %d runs finished and kept in %s; run the same command "
                        .. "to resume%s", self.label, done, #slice, self.runs_dir,
                        #left > 0 and " (it trains " .. table.concat(left, " and ") .. ")" or ""))
  end
  return done, interrupted
end

return Sweep
