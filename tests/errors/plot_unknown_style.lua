-- expect: plot_unknown_style\.lua:7: plot\.lines: unknown style 'bars' \(valid: lines, linespoints, points\)
-- A mistake in a plot call is reported at the script's line (it named scripts/lib/plot.lua's, or
-- none), before gnuplot is started.
package.path = "scripts/?.lua;" .. package.path
local plot = require "lib.plot"
local sn = require "shadenet"
plot.lines { path = sn.fs.tempdir("plot_style") .. "/p.png", series = { { name = "a", x = { 1, 2 }, y = { 1, 2 }, style = "bars" } } }
