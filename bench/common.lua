-- What the benchmarks share: their positional options, checked before any work (a mistake is
-- an error naming the option and the form it takes, exit 2, as the experiment scripts' command
-- line does), the median and quantiles of scripts/lib/stats.lua, the load average, and Ctrl-C.
--
--   package.path = (arg[0]:match("^(.*)/[^/]*$") or ".") .. "/?.lua;" .. package.path
--   local B = require "common"
--   local o = B.args("bench/NAME.lua", { { "repeats", "3", B.whole(1) }, ... })
local sn = require "shadenet"

local here = (arg and arg[0] or ""):match("^(.*)/[^/]*$") or "."
package.path = here .. "/../scripts/?.lua;" .. package.path
local stats = require "lib.stats"
local results = require "lib.results"

local B = {}
B.dir = here  -- the bench folder, as this run reaches it
B.median = stats.median
B.quantile = stats.quantile

-- Parsers of one option's text: each returns the value, or nil when the text is not of its form;
-- `form` says what it takes, for the error.

-- A whole number from `min` (to `max`, when given).
function B.whole(min, max)
  return {
    form = max and ("a whole number from %d to %d"):format(min, max) or ("a whole number >= %d"):format(min),
    parse = function(s)
      local n = s:match("^%d+$") and tonumber(s)
      return n and n >= min and (not max or n <= max) and n or nil
    end,
  }
end

-- One of `choices`.
function B.one_of(choices)
  local known = {}
  for _, c in ipairs(choices) do known[c] = true end
  return { form = "one of " .. table.concat(choices, ", "), parse = function(s) return known[s] and s or nil end }
end

-- "AxB" as {a, b}, both whole numbers >= 1.
local function pair(form)
  return { form = form, parse = function(s)
    local a, b = s:match("^(%d+)x(%d+)$")
    a, b = tonumber(a), tonumber(b)
    return a and a >= 1 and b >= 1 and { a, b } or nil
  end }
end
B.arch = pair("LAYERSxWIDTH, both >= 1 (e.g. 8x8)")  -- hidden layers x width
B.size = pair("WIDTHxHEIGHT in pixels, both >= 1 (e.g. 640x480)")

-- A comma-separated list of one or more items of `item` (a list: the values in order).
function B.list(item)
  return {
    form = item.form .. "; one or more, comma separated",
    parse = function(s)
      local out = {}
      for part in (s .. ","):gmatch("([^,]*),") do
        local v = item.parse(part)
        if v == nil then return nil end
        out[#out + 1] = v
      end
      return out
    end,
  }
end

-- The usage line of a script and its options.
local function usage(script, specs)
  local names = {}
  for _, s in ipairs(specs) do names[#names + 1] = "[" .. s[1] .. "]" end
  return "shadenet " .. script .. " " .. table.concat(names, " ")
end

-- B.fail(script, specs, message): a command-line mistake, printed alone (no traceback), exit 2.
function B.fail(script, specs, message)
  io.stderr:write(script, ": ", message, "\n(usage: ", usage(script, specs), ")\n")
  os.exit(2)
end

-- B.args(script, specs) -> { name = value, ... } from arg[1..]. specs[i] = { name, default text,
-- parser }: the i-th argument, or the default when it is missing. Checked before the script does
-- any work, all of them: a value outside its form, or more arguments than there are options,
-- is an error (B.fail) naming it.
function B.args(script, specs)
  local n = #arg
  if n > #specs then
    B.fail(script, specs, ("%d arguments given, it takes at most %d"):format(n, #specs))
  end
  local o = {}
  for i, s in ipairs(specs) do
    local text = arg[i] or s[2]
    local v = s[3].parse(text)
    if v == nil then B.fail(script, specs, ("%s '%s': expected %s"):format(s[1], text, s[3].form)) end
    o[s[1]] = v
  end
  return o
end

-- The 1-minute load average as text ("?" where /proc/loadavg cannot be read).
function B.load()
  local l = results.load_average()
  return l and ("%.2f"):format(l[1]) or "?"
end

-- Ctrl-C (and SIGTERM): after B.catch_interrupt() the first one only sets a flag (and stops an
-- sn.train at its next step), so the benchmark stops at its next B.stop_if_interrupted(): the
-- figures printed before stand, the timing in flight is not printed (it was cut short), and the
-- exit status is 130 (143), as the experiment scripts'. os.exit closes the Lua state, so the
-- benchmark's sn.fs.tempdir folders are removed (SIGINT's default action left them). A second
-- Ctrl-C stops at once.
function B.catch_interrupt() sn.catch_interrupt() end

-- `what`: the work in flight when it came ("the job cpu 8x8 ..."), for the message, or nil.
function B.stop_if_interrupted(what)
  local caught, signal = sn.interrupted()
  if not caught then return end
  print(("stopped (%s)%s"):format(signal == 15 and "SIGTERM" or "Ctrl-C", what and ": " .. what .. " is not printed" or ""))
  os.exit(128 + (signal or 2))
end

return B
