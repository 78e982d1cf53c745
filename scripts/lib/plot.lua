-- Line and scatter plots through gnuplot (pngcairo). The plotted data is written first as a CSV
-- beside the PNG (series,x,y[,label]) and gnuplot reads that very file, so the CSV is exactly
-- what the picture shows.
local results = require "lib.results"
local options = require "lib.options"

local plot = {}

local function q(s) return '"' .. tostring(s):gsub('\\', '\\\\'):gsub('"', '\\"') .. '"' end

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

-- This process's id: a plot's temporary name is its own (".NAME.png.tmpPID", which
-- sn.fs.remove_stale_temporaries knows), so two processes plotting into one folder never take
-- each other's file (a fixed NAME.png.tmp.png made one of two fail half the time).
local ffi = require "ffi"
pcall(ffi.cdef, "int getpid(void);")
local pid = tostring(ffi.C.getpid())

-- Runs `script` (written beside the PNG as NAME.gp, which draws NAME.png when run by hand) with
-- its output at `tmp`, a name in the same folder.
local function run_gnuplot(script, png, tmp)
  local gp = png:gsub("%.png$", "") .. ".gp"
  results.write_file(gp, script)
  if later then return nil end
  local dir, name = gp:match("^(.*)/([^/]*)$")
  -- The output through a pipe, the exit status as its last line (LuaJIT's close does not give it).
  local pipe = assert(io.popen(string.format("cd %q && gnuplot -e %q %q 2>&1; printf '\\n%%d\\n' $?", dir or ".",
                                             string.format("out = '%s'", tmp), name or gp)))
  local out = pipe:read("*a")
  pipe:close()
  local status
  out = out:gsub("\n(%d+)\n$", function(code) status = tonumber(code); return "" end)
  if status ~= 0 then error("gnuplot failed on " .. gp .. ":\n" .. out, 0) end
  return out
end

local styles = { lines = "lines lw 2", linespoints = "linespoints lw 2 pt %d ps 0.8", points = "points pt %d ps 1.0" }

-- plot.lines{ path = "DIR/plots/NAME.png", title, xlabel, ylabel, logx, logy, width, height,
--             key = "outside right top" (gnuplot's `set key` words), series = { {name, x = {...}, y = {...}, style = "lines",
--             color = "#rrggbb", dash = 2, point = 6, labels = {...}}, ... } } -> path of the PNG
-- Non-finite y values are dropped (gnuplot cannot draw them) and counted in the returned
-- second value, so a diverged curve shows as a gap, never as a silent zero. With
-- SHADENET_PLOTS=later the first value is the gnuplot script's path: no PNG yet.
plot.keys = { "path", "title", "xlabel", "ylabel", "logx", "logy", "width", "height", "key", "series", "xtics", "xrange",
              "yrange" }
plot.series_keys = { "name", "x", "y", "style", "color", "dash", "point", "labels" }
function plot.lines(p)
  options.check(p, "plot.lines", plot.keys, { "path", "series" })
  options.check_list(p.series, "plot.lines series", plot.series_keys, { "name", "x", "y" })
  assert(p.path and p.path:match("%.png$"), "plot.lines: path must end in .png")
  assert(p.series and #p.series > 0, "plot.lines: no series")
  local csv_path = p.path:gsub("%.png$", ".csv")
  local png_name, csv_name = p.path:match("[^/]*$"), csv_path:match("[^/]*$")  -- gnuplot runs in their folder
  local lines = { "series,x,y,label" }
  local dropped = 0
  for _, s in ipairs(p.series) do
    assert(s.name and not s.name:find('[,"\n]'), "plot.lines: series names must not contain , \" or newlines")
    assert(#s.x == #s.y, "plot.lines: series '" .. s.name .. "' has " .. #s.x .. " x and " .. #s.y .. " y values")
    for i = 1, #s.x do
      local x, y = s.x[i], s.y[i]
      local bad = y ~= y or y == math.huge or y == -math.huge or (p.logy and y <= 0)
      if bad then
        dropped = dropped + 1
      else
        local label = s.labels and s.labels[i] or ""
        lines[#lines + 1] = string.format("%s,%.9g,%.9g,%s", s.name, x, y, label)
      end
    end
  end
  results.write_file(csv_path, table.concat(lines, "\n") .. "\n")

  local g = {
    -- noenhanced: titles, labels and series names are plain text ("my_sweep", "L*a*b*", "x^2"),
    -- never gnuplot's markup for sub- and superscripts.
    string.format("set terminal pngcairo size %d,%d font 'DejaVu Sans,10' noenhanced", p.width or 800, p.height or 520),
    -- `out` when the caller sets it (gnuplot -e "out = '...'"), else the PNG beside the script.
    "if (!exists('out')) out = " .. q(png_name),
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
  if p.yrange then g[#g + 1] = string.format("set yrange [%s:%s]", p.yrange[1] or "*", p.yrange[2] or "*") end
  if p.xrange then g[#g + 1] = string.format("set xrange [%s:%s]", p.xrange[1] or "*", p.xrange[2] or "*") end
  local parts = {}
  for i, s in ipairs(p.series) do
    local sel = string.format("(strcol(1) eq %s ? $3 : NaN)", q(s.name))
    local style = styles[s.style or "lines"] or error("plot.lines: unknown style '" .. tostring(s.style) ..
                                                      "' (valid: lines, linespoints, points)", 0)
    style = style:gsub("%%d", tostring(s.point or 7))  -- gnuplot point type: 7 disc, 6 circle, 4 square, ...
    local color = (s.color and (" lc rgb " .. q(s.color)) or "") .. (s.dash and (" dt " .. s.dash) or "")
    parts[#parts + 1] = string.format("%s skip 1 using 2:%s with %s%s title %s", q(csv_name), sel, style, color, q(s.name))
    if s.labels then
      parts[#parts + 1] = string.format("%s skip 1 using 2:%s:4 with labels offset 0.6,0.6 left font ',8' notitle",
                                        q(csv_name), sel)
    end
  end
  g[#g + 1] = "plot " .. table.concat(parts, ", \\\n     ")
  g[#g + 1] = "unset output"
  local tmp_name = "." .. png_name .. ".tmp" .. pid
  local tmp = p.path:sub(1, #p.path - #png_name) .. tmp_name
  if not run_gnuplot(table.concat(g, "\n") .. "\n", p.path, tmp_name) then return (p.path:gsub("%.png$", ".gp")), dropped end
  local ok, err = os.rename(tmp, p.path)
  if not ok then error("cannot write " .. p.path .. ": " .. tostring(err), 0) end
  return p.path, dropped
end

return plot
