-- The command line every experiment script shares:
--   shadenet scripts/NAME.lua [--quick] [--shard i/n] [--out DIR] [--backend cpu|gl|auto]
--                             [--data poses|cloth] [--ggx thesis|gold] [--runs-per-job N] [--help]
-- An unknown option is an error listing the valid ones. Without --shard, a Slurm job array
-- (SLURM_ARRAY_TASK_ID / SLURM_ARRAY_TASK_COUNT) picks the shard, so `sbatch --array=0-7`
-- (or 1-8) spreads a sweep over 8 machines with no extra flag.
local cli = {}

local common = {
  { flag = "--quick", help = "fewer seeds and epochs, smaller images: a smoke run under a minute" },
  { flag = "--shard", value = "i/n", help = "run only slice i of n of the sweep (1 <= i <= n)" },
  { flag = "--out", value = "DIR", help = "write results to DIR instead of results/NAME" },
  { flag = "--backend", choices = { "cpu", "gl", "auto" }, help = "training backend (default: the script's choice)" },
  { flag = "--data", choices = { "poses", "cloth" }, help = "training data: the cloth in 5 poses (default, covers the normal sphere) or the thesis' hanging cloth alone" },
  { flag = "--ggx", choices = { "thesis", "gold" }, help = "GGX ground truth: calibrated to the thesis' all-zeros MSE (the default: the gold metal plus diffuse 0.58, ambient 0.2) or the gold metal alone" },
  { flag = "--runs-per-job", value = "N", help = "train at most N runs in one job (default: every run that may share one, seeds included; fewer lose less to Ctrl-C)" },
  { flag = "--help", help = "print this help" },
}

-- The choices an experiment takes when its command line names none (run records from before
-- `options` was recorded, and merge.lua, read them too).
cli.defaults = { data = "poses", ggx = "thesis" }

-- What a flag takes: its value's name, its choices ("a|b"), or nil (a switch).
local function value_of(f)
  return f.value or (f.choices and table.concat(f.choices, "|"))
end

-- "--flag VALUE", or "--flag" for a switch.
local function shown(f)
  return value_of(f) and (f.flag .. " " .. value_of(f)) or f.flag
end

local function valid_list(flags)
  local names = {}
  for _, f in ipairs(flags) do names[#names + 1] = shown(f) end
  return table.concat(names, ", ")
end

function cli.usage(name, flags)
  local lines = { string.format("usage: shadenet scripts/%s.lua [options]", name), "options:" }
  for _, f in ipairs(flags) do
    lines[#lines + 1] = string.format("  %-24s %s", shown(f), f.help)
  end
  return table.concat(lines, "\n")
end

-- "2/8" -> {index = 2, count = 8}; errors name the problem.
function cli.parse_shard(text, where)
  local i, n = tostring(text):match("^(%d+)/(%d+)$")
  i, n = tonumber(i), tonumber(n)
  if not i then error(where .. ": --shard expects i/n (e.g. 2/8), got '" .. tostring(text) .. "'", 0) end
  -- (%s, not %d: a count past 2^53 printed as a negative number)
  if n < 1 or i < 1 or i > n or n > 2 ^ 31 then
    error(string.format("%s: --shard %s: i must be 1..n and n 1..2^31", where, tostring(text)), 0)
  end
  return { index = i, count = n }
end

-- The Slurm job array's slice, when this process is one task of one (ids may start at 0 or 1:
-- SLURM_ARRAY_TASK_MIN tells which; a stepped array, --array=0-14:2, has SLURM_ARRAY_TASK_STEP).
function cli.slurm_shard(getenv)
  getenv = getenv or os.getenv
  local id, count = tonumber(getenv("SLURM_ARRAY_TASK_ID")), tonumber(getenv("SLURM_ARRAY_TASK_COUNT"))
  if not id or not count then return nil end
  local min = tonumber(getenv("SLURM_ARRAY_TASK_MIN")) or 0
  local step = tonumber(getenv("SLURM_ARRAY_TASK_STEP")) or 1
  local index = step >= 1 and (id - min) / step + 1 or 0
  if count < 1 or index < 1 or index > count or index % 1 ~= 0 then
    error(string.format("SLURM_ARRAY_TASK_ID=%d (min %d, step %d) is outside an array of %d tasks", id, min, step,
                        count), 0)
  end
  return { index = index, count = count, from = "slurm" }
end

-- cli.parse(args, name [, extra_flags]) -> options
--   options = { quick, shard = {index, count} | nil, out, backend, data, ggx, runs_per_job, name }
-- `extra_flags` adds script-specific flags, same shape as `common` above (value flags give a
-- string, others true; a flag with `choices` takes one of them).
function cli.parse(args, name, extra, getenv, only)
  -- `only`, when given, lists the common flags the script takes ({"--quick", "--out", "--help"}
  -- for one that trains nothing): the others are unknown options there, and --help omits them.
  local taken = {}
  for _, f in ipairs(only or {}) do taken[f] = true end
  local flags = {}
  for _, f in ipairs(common) do
    if not only or taken[f.flag] then flags[#flags + 1] = f end
  end
  for _, f in ipairs(extra or {}) do flags[#flags + 1] = f end
  local by_flag = {}
  for _, f in ipairs(flags) do by_flag[f.flag] = f end
  local where = name .. ".lua"
  local o = { name = name, quick = false, extra = {} }
  local i = 1
  while i <= #args do
    local a = args[i]
    local flag, inline = a:match("^(%-%-[%w-]+)=(.*)$")
    flag = flag or a
    local f = by_flag[flag]
    if not f then
      error(string.format("%s: unknown option '%s' (valid: %s)", where, a, valid_list(flags)), 0)
    end
    local v = true
    if value_of(f) then
      v = inline
      if not v then
        i = i + 1
        v = args[i]
      end
      if not v or v == "" then error(string.format("%s: %s needs a value (%s)", where, flag, value_of(f)), 0) end
    elseif inline then
      error(string.format("%s: %s takes no value", where, flag), 0)
    end
    local key = flag:sub(3):gsub("-", "_")
    o.extra[key] = v
    i = i + 1
  end
  if o.extra.help then
    print(cli.usage(name, flags))
    os.exit(0)
  end
  o.quick = o.extra.quick == true
  o.out = o.extra.out
  -- A flag with choices takes one of them (o.backend, o.data, o.ggx).
  for _, f in ipairs(flags) do
    local key = f.flag:sub(3):gsub("-", "_")
    local v = o.extra[key]
    if f.choices and v then
      local known = false
      for _, c in ipairs(f.choices) do known = known or c == v end
      if not known then
        error(string.format("%s: unknown %s '%s' (valid: %s)", where, f.flag, v, table.concat(f.choices, ", ")), 0)
      end
      o[key] = v
    end
  end
  if o.extra.runs_per_job then
    o.runs_per_job = tonumber(o.extra.runs_per_job)
    if not o.runs_per_job or o.runs_per_job < 1 or o.runs_per_job % 1 ~= 0 then
      error(string.format("%s: --runs-per-job expects a whole number >= 1, got '%s'", where, o.extra.runs_per_job), 0)
    end
  end
  if o.extra.shard then
    o.shard = cli.parse_shard(o.extra.shard, where)
  else
    o.shard = cli.slurm_shard(getenv)
  end
  return o
end

-- cli.parse for a script's own command line: a mistake in it is the user's typing, not the
-- script's fault, so it prints the message alone (no Lua traceback) and exits 2, the usual
-- status of a command-line error.
function cli.parse_or_exit(args, name, extra, getenv, only)
  local ok, o = pcall(cli.parse, args, name, extra, getenv, only)
  if ok then return o end
  local script = arg and arg[0] or "scripts/" .. name .. ".lua"
  io.stderr:write(tostring(o), "\n(shadenet ", script, " --help lists the options)\n")
  os.exit(2)
end

return cli
