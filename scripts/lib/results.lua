-- Where an experiment's results go and how they are written: results/NAME/ (or --out DIR) with
-- table.md + table.csv, figures/*.png, plots/*.png (+ their .csv), run.json and runs/*.json.
-- Every file is written to a temporary name beside its target and renamed, so a crash or a
-- Ctrl-C never leaves a half-written result.
local sn = require "shadenet"
local json = require "lib.json"
local options = require "lib.options"

local results = {}


function results.mkdir(dir) return sn.fs.mkdir(dir) end

-- Writes `content` to path whole (sn.fs.write: temp file, every write, flush, fsync and close
-- checked, rename; folders created): on a full disk the old file stays and the error says why.
function results.write_file(path, content)
  local ok, err = pcall(sn.fs.write, path, content)
  if not ok then error(err, 0) end
  return path
end

-- The file's content, or nil when there is none; a FIFO or folder in its place is an error
-- (sn.fs.read), where io.open waited on a FIFO for ever.
function results.read_file(path)
  if not sn.fs.exists(path) then return nil end
  local ok, content = pcall(sn.fs.read, path)
  if not ok then error(content, 0) end
  return content
end

function results.write_json(path, value) return results.write_file(path, json.encode(value, "  ") .. "\n") end

-- Writes { [path] = content, ... }, each whole, flushed to the disk together (sn.fs.write_all:
-- one syncfs, not an fsync per file); a failure before the renames (a full disk) leaves every
-- old file as it was, so files that belong together stay one generation.
function results.write_files(files)
  local ok, err = pcall(sn.fs.write_all, files)
  if not ok then error(err, 0) end
end

-- Writes { [path] = value, ... } as JSON files, together (results.write_files).
function results.write_jsons(values)
  local files = {}
  for path, value in pairs(values) do files[path] = json.encode(value, "  ") .. "\n" end
  results.write_files(files)
end

function results.read_json(path)
  local s = results.read_file(path)
  if not s then return nil end
  return json.decode(s, path)
end

-- Removes temporary files a killed writer left in dir (they never replace a result), once they
-- are a minute old: a shard of the same sweep may be writing beside us.
function results.clean_temps(dir)
  return sn.fs.remove_stale_temporaries(dir)
end

-- ---- tables -------------------------------------------------------------------------------

local function is_finite(v) return type(v) == "number" and v == v and v ~= math.huge and v ~= -math.huge end

local function fmt(v, f)
  if v == nil then return nil end
  if type(v) == "number" then
    if v ~= v then return "nan" end
    if v == math.huge then return "inf" end
    if v == -math.huge then return "-inf" end
    if f then return string.format(f, v) end
    if v == math.floor(v) and math.abs(v) < 1e15 then return string.format("%d", v) end
    return string.format("%.6g", v)
  end
  if type(v) == "boolean" then return tostring(v) end
  return tostring(v)
end
results.format = fmt

local function csv_cell(v)
  if v == nil then return "" end
  local s = type(v) == "number" and (is_finite(v) and string.format("%.9g", v) or fmt(v)) or tostring(v)
  if s:find('[,"\n]') then s = '"' .. s:gsub('"', '""') .. '"' end
  return s
end

-- A table cell as literal Markdown text: "CIE L*a*b*" is not emphasis, "my_sweep" not a start of
-- it, a "|" not a column. A backslash is doubled only before punctuation (where Markdown reads it
-- as an escape), so "layers \ width" stays as it is.
local function md_cell(s)
  s = tostring(s):gsub("\\(%p)", "\\\\%1")
  return (s:gsub("[|*_`~]", "\\%0"))
end

-- The CSV text of rows under columns {key=...}: header = the keys, full precision numbers.
function results.csv(columns, rows)
  local lines = {}
  local head = {}
  for i, c in ipairs(columns) do head[i] = csv_cell(c.key) end
  lines[1] = table.concat(head, ",")
  for _, r in ipairs(rows) do
    local cells = {}
    for i, c in ipairs(columns) do cells[i] = csv_cell(r[c.key]) end
    lines[#lines + 1] = table.concat(cells, ",")
  end
  return table.concat(lines, "\n") .. "\n"
end

-- A Markdown table of rows under columns {key, header, format}.
function results.markdown(columns, rows)
  local head, rule = {}, {}
  for i, c in ipairs(columns) do
    head[i] = md_cell(c.header or c.key)
    rule[i] = c.align == "left" and "---" or "---:"
  end
  local lines = { "| " .. table.concat(head, " | ") .. " |", "|" .. table.concat(rule, "|") .. "|" }
  for _, r in ipairs(rows) do
    local cells = {}
    for i, c in ipairs(columns) do cells[i] = md_cell(fmt(r[c.key], c.format) or "–") end
    lines[#lines + 1] = "| " .. table.concat(cells, " | ") .. " |"
  end
  return table.concat(lines, "\n") .. "\n"
end

-- A 2-D view of rows: one table row per value of g.rows (e.g. layers), one column per value of
-- g.cols (e.g. width); each cell "ours (thesis)" when g.thesis names a field.
results.grid_keys = { "title", "rows", "cols", "value", "thesis", "format", "row_header", "col_header" }
function results.markdown_grid(g, rows)
  options.check(g, "results.markdown_grid", results.grid_keys, { "rows", "cols", "value" })
  local rvals, cvals, seen_r, seen_c, cell = {}, {}, {}, {}, {}
  for _, r in ipairs(rows) do
    local a, b = r[g.rows], r[g.cols]
    if not seen_r[a] then seen_r[a] = true rvals[#rvals + 1] = a end
    if not seen_c[b] then seen_c[b] = true cvals[#cvals + 1] = b end
    local key = tostring(a) .. "\0" .. tostring(b)
    if cell[key] then  -- one cell, two rows: keeping the last would hide the other
      error(string.format("results.markdown_grid: two rows have %s = %s and %s = %s; a grid shows one row per cell "
                          .. "(add the field that tells them apart to the grid or to the rows' values)",
                          tostring(g.rows), tostring(a), tostring(g.cols), tostring(b)), 0)
    end
    cell[key] = r
  end
  local head = { md_cell((g.row_header or g.rows) .. " \\ " .. (g.col_header or g.cols)) }
  local rule = { "---" }
  for i, b in ipairs(cvals) do head[i + 1] = md_cell(fmt(b)) rule[i + 1] = "---:" end
  local lines = {}
  if g.title then lines[#lines + 1] = "**" .. g.title .. "**\n" end
  lines[#lines + 1] = "| " .. table.concat(head, " | ") .. " |"
  lines[#lines + 1] = "|" .. table.concat(rule, "|") .. "|"
  for _, a in ipairs(rvals) do
    local cells = { md_cell(fmt(a)) }
    for i, b in ipairs(cvals) do
      local r = cell[tostring(a) .. "\0" .. tostring(b)]
      local s = "–"
      if r and r[g.value] ~= nil then
        s = fmt(r[g.value], g.format)
        if g.thesis and r[g.thesis] ~= nil then s = s .. " (" .. fmt(r[g.thesis], g.format) .. ")" end
      end
      cells[i + 1] = md_cell(s)
    end
    lines[#lines + 1] = "| " .. table.concat(cells, " | ") .. " |"
  end
  return table.concat(lines, "\n") .. "\n"
end

-- ---- one experiment's folder ----------------------------------------------------------------

local Results = {}
Results.__index = Results

-- results.open(options, name) with options from lib.cli: results/NAME (results/NAME-quick in
-- quick mode, so a smoke run never overwrites a full run's records and tables: their run ids are
-- the same), results/NAME/shard-i-of-n when sharded without --out, or --out DIR.
function results.open(o, name)
  local dir = o.out
  if not dir then
    dir = "results/" .. name .. (o.quick and "-quick" or "")
    if o.shard then dir = string.format("%s/shard-%d-of-%d", dir, o.shard.index, o.shard.count) end
  end
  dir = dir:gsub("/+$", "")
  sn.fs.mkdir(dir)
  -- Every folder a script writes into here (runs/: lib.sweep); a killed writer leaves a
  -- ".NAME.tmpPID" beside a figure or a plot as well as beside a table.
  for _, sub in ipairs { "", "/plots", "/figures" } do results.clean_temps(dir .. sub) end
  return setmetatable({ dir = dir, name = name, written = {} }, Results)
end

function Results:path(rel) return self.dir .. "/" .. rel end

function Results:write(rel, content)
  self.written[#self.written + 1] = rel
  return results.write_file(self:path(rel), content)
end

-- Writes { [rel] = content, ... } together (sn.fs.write_all): on a full disk every old file
-- stays, and no kill leaves one file of a new table beside one of the old.
function Results:write_all(files)
  local paths, rels = {}, {}
  for rel, content in pairs(files) do
    rels[#rels + 1] = rel
    paths[self:path(rel)] = content
  end
  table.sort(rels)
  for _, rel in ipairs(rels) do self.written[#self.written + 1] = rel end
  results.write_files(paths)
end

function Results:json(rel, value)
  self.written[#self.written + 1] = rel
  return results.write_json(self:path(rel), value)
end

-- R:table{ file = "table", title = "...", columns = {{key, header, format, align}...}, rows = {...},
--          grids = {{title, rows, cols, value, thesis, format, row_header, col_header}...}, notes = {"..."} }
-- writes FILE.md (title, grids, the long table, notes) and FILE.csv (the long table), together. Under its
-- title FILE.md prints R.notices (lines: quick mode, one shard) and R.partial (a stopped sweep).
results.column_keys = { "key", "header", "format", "align" }
function Results:table(t)
  options.check(t, "R:table", { "file", "title", "columns", "rows", "grids", "notes" }, { "columns", "rows" })
  options.check_list(t.columns, "R:table columns", results.column_keys, { "key" })
  options.check_list(t.grids, "R:table grids", results.grid_keys, { "rows", "cols", "value" })
  local file = t.file or "table"
  local md = {}
  if t.title then md[#md + 1] = "## " .. t.title .. "\n" end
  for _, n in ipairs(self.notices or {}) do md[#md + 1] = n .. "\n" end
  if self.partial then md[#md + 1] = self.partial .. "\n" end
  for _, g in ipairs(t.grids or {}) do md[#md + 1] = results.markdown_grid(g, t.rows) end
  md[#md + 1] = results.markdown(t.columns, t.rows)
  for _, n in ipairs(t.notes or {}) do md[#md + 1] = n .. "\n" end
  self:write_all { [file .. ".md"] = table.concat(md, "\n"), [file .. ".csv"] = results.csv(t.columns, t.rows) }
  return self:path(file .. ".md")
end

-- The first line of a /proc file (the kernel gives their size as 0: sn.fs.read reads nothing).
local function proc_line(path)
  local f = io.open(path)
  if not f then return nil end
  local line = f:read("*l")
  f:close()
  return line
end

-- The 1, 5 and 15 minute load averages (timings on a shared machine need them to be read).
function results.load_average()
  local line = proc_line("/proc/loadavg") or ""
  local a, b, c = line:match("^(%S+) (%S+) (%S+)")
  return a and { tonumber(a), tonumber(b), tonumber(c) } or nil
end

-- What every run.json carries besides the script's own configuration.
function results.environment()
  local info = sn.gl_info()
  local gp = io.popen("gnuplot --version 2>/dev/null")
  local gnuplot = gp and gp:read("*l") or nil
  if gp then gp:close() end
  local cpu
  local f = io.open("/proc/cpuinfo")
  if f then
    for line in f:lines() do
      cpu = line:match("^model name%s*:%s*(.-)%s*$")
      if cpu then break end
    end
    f:close()
  end
  local cores = 0
  f = io.open("/proc/cpuinfo")
  if f then
    for line in f:lines() do if line:match("^processor%s*:") then cores = cores + 1 end end
    f:close()
  end
  return {
    load_average = results.load_average(),
    shadenet = sn.version,
    build = sn.build,  -- the git commit the binary was built from ("-dirty": with uncommitted changes)
    luajit = jit and jit.version or _VERSION,
    gl = { renderer = info.renderer, version = info.version, vendor = info.vendor, software = info.software },
    gnuplot = gnuplot,
    cpu = cpu,
    cpu_threads = cores,
    date = os.date("!%Y-%m-%dT%H:%M:%SZ"),
    -- The kernel's name for the machine (bash does not export HOSTNAME: it was always null).
    host = (proc_line("/proc/sys/kernel/hostname") or os.getenv("HOSTNAME") or ""):match("^%s*(.-)%s*$"),
  }
end

return results
