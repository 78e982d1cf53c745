-- Line and scatter plots through gnuplot (pngcairo). The plotted data goes into a CSV
-- (series,x,y[,label]) that gnuplot reads, and the very same bytes are kept beside the PNG, so
-- the CSV is exactly what the picture shows.
local sn = require "shadenet"
local results = require "lib.results"
local options = require "lib.options"

local plot = {}

-- A gnuplot string literal: single quotes, where gnuplot runs no `command` and expands no
-- escapes (in double quotes a title's backquotes ran a shell command); a newline is joined in.
local function q(s)
  local parts = {}
  for line in (tostring(s) .. "\n"):gmatch("(.-)\n") do parts[#parts + 1] = "'" .. line:gsub("'", "''") .. "'" end
  return table.concat(parts, '."\\n".')
end

-- A word for sh: single quotes, where nothing expands (Lua's %q is not shell quoting: "$(...)" ran).
local function sh_quote(s) return "'" .. tostring(s):gsub("'", "'\\''") .. "'" end

-- SHADENET_PLOTS=later writes each plot's CSV and gnuplot script but does not run gnuplot (a
-- machine without it: a lent GPU); tools/draw_plots.sh DIR draws them afterwards. The script
-- names its files without a folder and runs in the plot's folder, so it draws wherever it lies.
local function plots_later()
  local v = os.getenv("SHADENET_PLOTS") or ""
  if v ~= "" and v ~= "now" and v ~= "later" then
    error("SHADENET_PLOTS='" .. v .. "': unknown value (valid: now, later)", 0)
  end
  return v == "later"
end
local later = plots_later()  -- checked when a script starts, not after its work

-- gnuplot draws in a private scratch folder (removed when the script ends) under fixed names, so
-- no path of the caller's reaches the shell or gnuplot's command line, a failed or killed
-- gnuplot leaves nothing in plots/, and its PNG is checked before it replaces the old one.
local work
local function workdir()
  work = work or sn.fs.tempdir("plot")
  return work
end

-- A PNG ends with its IEND chunk; cairo reports success on a full disk and leaves it cut short.
local function whole_png(bytes)
  return #bytes >= 20 and bytes:sub(1, 8) == "\137PNG\r\n\26\n" and bytes:sub(-12) == "\0\0\0\0IEND\174\66\96\130"
end

-- Runs `script` (kept beside the PNG as NAME.gp) on `csv` in the scratch folder; returns the PNG's
-- bytes. Errors name `png`, the plot's real path, and carry gnuplot's output.
local function draw(script, csv, png)
  local dir = workdir()
  results.write_file(dir .. "/plot.gp", script)
  results.write_file(dir .. "/data.csv", csv)
  os.remove(dir .. "/plot.png")  -- never mistake the last plot's picture for this one's
  -- The output through a pipe, the exit status as its last line (LuaJIT's close does not give it).
  local pipe = assert(io.popen(string.format(
    "{ cd -- %s && gnuplot -e \"out = 'plot.png'; data = 'data.csv'\" plot.gp; } 2>&1; printf '\\n%%d\\n' $?", sh_quote(dir))))
  local out = pipe:read("*a")
  pipe:close()
  local status
  out = out:gsub("\n(%d+)\n$", function(code) status = tonumber(code); return "" end)
  if status ~= 0 then
    local hint = status == 127 and "\n(no gnuplot? SHADENET_PLOTS=later leaves the plot for tools/draw_plots.sh)" or ""
    error(string.format("cannot draw %s: gnuplot failed (exit status %s):\n%s%s", png, tostring(status), out, hint), 0)
  end
  local bytes = results.read_file(dir .. "/plot.png") or ""
  os.remove(dir .. "/plot.png")
  if not whole_png(bytes) then
    error(string.format("cannot draw %s: gnuplot's PNG in %s is not whole (%d bytes, no IEND chunk at its end: a full "
                        .. "disk?)%s", png, dir, #bytes, out ~= "" and ":\n" .. out or ""), 0)
  end
  return bytes
end

local styles = { lines = "lines lw 2", linespoints = "linespoints lw 2 pt %d ps 0.8", points = "points pt %d ps 1.0" }

-- plot.lines{ path = "DIR/plots/NAME.png", title, xlabel, ylabel, logx, logy, width, height,
--             key = "outside right top" (gnuplot's `set key` words), series = { {name, x = {...}, y = {...}, style = "lines",
--             color = "#rrggbb", dash = 2, point = 6, labels = {...}}, ... } } -> path of the PNG
-- Non-finite y values (and y <= 0 with logy) are dropped (gnuplot cannot draw them) and counted
-- in the returned second value, so a diverged curve shows as a gap, never as a silent zero. A
-- series left with no point keeps its place in the key, named "NAME (no finite values)" ("no
-- positive values" on a log axis): the reader sees it ran and why no line is drawn. The PNG, its
-- CSV and NAME.gp are written together (sn.fs.write_all): a failure leaves the old three as they
-- were. With SHADENET_PLOTS=later the first value is the gnuplot script's path: no PNG yet.
plot.keys = { "path", "title", "xlabel", "ylabel", "logx", "logy", "width", "height", "key", "series", "xtics", "xrange",
              "yrange" }
plot.series_keys = { "name", "x", "y", "style", "color", "dash", "point", "labels" }
function plot.lines(p)
  options.check(p, "plot.lines", plot.keys, { "path", "series" })
  options.check_list(p.series, "plot.lines series", plot.series_keys, { "name", "x", "y" })
  -- Mistakes in the call are errors at the caller's line (options.error), not at this file's.
  if not (type(p.path) == "string" and p.path:match("%.png$")) then options.error("plot.lines: path must end in .png") end
  if #p.series == 0 then options.error("plot.lines: no series") end
  local stem = p.path:gsub("%.png$", "")
  local png_name = p.path:match("[^/]*$")
  local lines = { "series,x,y,label" }
  local dropped, drawn, empty = 0, 0, {}
  for k, s in ipairs(p.series) do
    if type(s.name) ~= "string" or s.name:find('[,"\n]') then
      options.error("plot.lines: series names must be strings without , \" or newlines")
    end
    if #s.x ~= #s.y then
      options.error("plot.lines: series '" .. s.name .. "' has " .. #s.x .. " x and " .. #s.y .. " y values")
    end
    if not styles[s.style or "lines"] then
      options.error("plot.lines: unknown style '" .. tostring(s.style) .. "' (valid: lines, linespoints, points)")
    end
    local kept, finite = 0, 0
    for i = 1, #s.x do
      local x, y = s.x[i], s.y[i]
      local nonfinite = y ~= y or y == math.huge or y == -math.huge
      if not nonfinite then finite = finite + 1 end
      if nonfinite or (p.logy and y <= 0) then
        dropped = dropped + 1
      else
        local label = s.labels and s.labels[i] or ""
        lines[#lines + 1] = string.format("%s,%.9g,%.9g,%s", s.name, x, y, label)
        kept = kept + 1
      end
    end
    drawn = drawn + kept
    if kept == 0 then empty[k] = finite > 0 and " (no positive values)" or " (no finite values)" end
  end
  local csv = table.concat(lines, "\n") .. "\n"

  local g = {
    -- noenhanced: titles, labels and series names are plain text ("my_sweep", "L*a*b*", "x^2"),
    -- never gnuplot's markup for sub- and superscripts.
    string.format("set terminal pngcairo size %d,%d font 'DejaVu Sans,10' noenhanced", p.width or 800, p.height or 520),
    -- `out` and `data` when the caller sets them (gnuplot -e "out = '...'; data = '...'"), else
    -- the files beside the script; "./" because gnuplot reads a name starting with "<" (data)
    -- or "|" (output) as a shell command.
    "if (!exists('out')) out = " .. q("./" .. png_name),
    "if (!exists('data')) data = " .. q("./" .. stem:match("[^/]*$") .. ".csv"),
    "set output out",
    "set datafile separator ','",
    -- The key goes outside the plot area by default: inside, its opaque box hid the points
    -- under it (the thesis' value at the top right of Table 4.2's plot).
    "set key " .. (p.key or "outside right top") .. " box opaque",
    "set grid xtics ytics lc rgb '#dddddd'",
    "set border lw 1",
    "set title " .. q(p.title or ""),
    "set xlabel " .. q(p.xlabel or "x"),
    "set ylabel " .. q(p.ylabel or "y"),
  }
  if p.logx then g[#g + 1] = "set logscale x" end
  if p.logy then g[#g + 1] = "set logscale y" g[#g + 1] = "set format y '%.0e'" end
  if p.xtics then g[#g + 1] = "set xtics " .. p.xtics end
  -- With no point at all gnuplot finds no range and fails ("x range is invalid"), and it drops a
  -- data file without rows from the key: the picture is an empty frame whose key says why (a
  -- sweep where every run diverged), each series a `keyentry`, a NaN function giving the axes.
  local nothing = drawn == 0
  for _, axis in ipairs { "y", "x" } do
    local r = p[axis .. "range"]
    if r or nothing then
      r = r or {}
      g[#g + 1] = string.format("set %srange [%s:%s]", axis, r[1] or (nothing and 1) or "*", r[2] or (nothing and 10) or "*")
    end
  end
  local parts = {}
  for k, s in ipairs(p.series) do
    local sel = string.format("(strcol(1) eq %s ? $3 : NaN)", q(s.name))
    local style = styles[s.style or "lines"]
    style = style:gsub("%%d", tostring(s.point or 7))  -- gnuplot point type: 7 disc, 6 circle, 4 square, ...
    local color = (s.color and (" lc rgb " .. q(s.color)) or "") .. (s.dash and (" dt " .. s.dash) or "")
    parts[#parts + 1] = string.format("%s with %s%s title %s", nothing and "keyentry" or "data skip 1 using 2:" .. sel,
                                      style, color, q(s.name .. (empty[k] or "")))
    if s.labels and not nothing then
      parts[#parts + 1] = string.format("data skip 1 using 2:%s:4 with labels offset 0.6,0.6 left font ',8' notitle", sel)
    end
  end
  if nothing then parts[#parts + 1] = "NaN notitle" end
  g[#g + 1] = "plot " .. table.concat(parts, ", \\\n     ")
  g[#g + 1] = "unset output"
  local script = table.concat(g, "\n") .. "\n"

  local files = { [stem .. ".csv"] = csv, [stem .. ".gp"] = script }
  if not later then files[p.path] = draw(script, csv, p.path) end
  results.write_files(files)
  return later and stem .. ".gp" or p.path, dropped
end

return plot
