-- A progress line for long sweeps: runs done / total, the current best, elapsed time and ETA.
-- On a terminal it redraws one line with \r; otherwise (CI logs, Slurm output files, pipes) it
-- prints a plain line at most every `every` seconds and at the end.
local sn = require "shadenet"
local options = require "lib.options"

local Progress = {}
Progress.__index = Progress

local function clock() return sn.clock() end

local function duration(s)
  if not s or s ~= s or s == math.huge then return "?" end
  s = math.floor(s + 0.5)
  if s < 60 then return s .. "s" end
  if s < 3600 then return string.format("%dm%02ds", math.floor(s / 60), s % 60) end
  return string.format("%dh%02dm", math.floor(s / 3600), math.floor(s / 60) % 60)
end
Progress.duration = duration

-- Progress.new{ total = N, label = "table_4_1_phong", tty = (default: stdout is a terminal),
--               every = 10 (seconds between plain lines), out = io.stdout, clock = (tests),
--               already = runs finished before this process (resumed) }
function Progress.new(o)
  options.check(o, "Progress.new", { "total", "label", "tty", "every", "out", "clock", "already" }, { "total" })
  local tty = o.tty
  if tty == nil then tty = sn.isatty("stdout") end
  local c = o.clock or clock
  local self = setmetatable({ total = o.total, label = o.label or "", tty = tty, every = o.every or 10,
                              out = o.out or io.stdout, done = 0, start_done = o.already or 0, clock = c,
                              t0 = c(), last_print = -math.huge, width = sn.terminal_width() or 100 }, Progress)
  self.done, self.finished = self.start_done, self.start_done
  Progress.active = self
  return self
end

-- The text of the line (exposed for tests).
-- The ETA is the rate of the work since the first progress was reported (the training alone:
-- the dataset and shader setup before it would inflate the first estimates many times over),
-- shown once 2% of this run's work (at least a twentieth of a run) and a second lie behind it.
function Progress:text()
  local now = self.clock()
  local elapsed = now - self.t0
  local remaining = self.total - self.done
  local eta
  if self.anchor then
    local work, seconds = self.done - self.anchor.done, now - self.anchor.t
    local enough = math.max(0.02 * (self.total - self.start_done), 0.05)
    if work >= enough and seconds >= 1 then eta = seconds / work * remaining end
  end
  -- Most useful first: a narrow terminal cuts the end of the line.
  -- Runs finished (kept on disk), and the share of the work done where a group in flight adds to
  -- it: "288/360 runs" for a group 80% trained let Ctrl-C look as if it would keep 288.
  local runs = string.format("%s %d/%d runs", self.label, self.finished, self.total)
  if self.done > self.finished + 1e-9 and self.total > 0 then
    runs = runs .. string.format(" (%d%% done)", math.floor(100 * self.done / self.total))
  end
  local parts = { runs }
  if remaining > 0 then parts[#parts + 1] = "ETA " .. (eta and duration(eta) or "?") end
  parts[#parts + 1] = "elapsed " .. duration(elapsed)
  if self.best then parts[#parts + 1] = "best " .. self.best end
  return table.concat(parts, "  ")
end

local function bar(frac, n)
  local full = math.floor(frac * n + 0.5)
  return "[" .. string.rep("#", full) .. string.rep(".", n - full) .. "]"
end

-- p:update(done [, best_text [, finished]]): `done` runs' worth of work so far (including resumed
-- runs; a fraction for a group in flight), `finished` the runs finished and kept (default: done).
function Progress:update(done, best, finished)
  self.done = done
  self.finished = math.floor((finished or done) + 1e-9)
  if best then self.best = best end
  local now = self.clock()
  if not self.anchor and done > self.start_done then self.anchor = { t = now, done = done } end
  if self.tty then
    -- Redraw at most 10 times a second (and always at the end).
    if now - self.last_print < 0.1 and self.finished < self.total then return end
    self.last_print = now
    local line = bar(self.total > 0 and self.done / self.total or 1, 20) .. " " .. self:text()
    if #line > self.width - 1 then line = line:sub(1, self.width - 1) end
    self.out:write("\r", line, string.rep(" ", math.max(0, (self.last_len or 0) - #line)))
    self.last_len = #line
    self.out:flush()
  else
    local final = self.finished >= self.total  -- runs finished: work done in flight is not the end
    if now - self.last_print >= self.every or (final and not self.final_printed) then
      self.out:write(self:text(), "\n")
      self.out:flush()
      self.last_print = now
      self.final_printed = final
    end
  end
end

-- Ends the line on a terminal.
function Progress:finish()
  if self.tty and self.last_len then self.out:write("\n") self.out:flush() end
  self.last_len = nil
  if Progress.active == self then Progress.active = nil end
end

-- Prints a message without tearing the progress line: on a terminal the line is cleared first
-- and redrawn by the next update.
function Progress.say(text)
  local p = Progress.active
  if p and p.tty and p.last_len then
    p.out:write("\r", string.rep(" ", p.last_len), "\r")
    p.last_len = nil
    p.last_print = -math.huge
  end
  print(text)
end

return Progress
