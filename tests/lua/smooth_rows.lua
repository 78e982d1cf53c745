-- Rows of a smooth 6 -> 3 target, a stand-in for a lighting model of normal and view, for the
-- training tests: smooth_rows(n) -> xs, ys (Lua tables of n rows).
return function(n)
  local xs, ys = {}, {}
  for i = 1, n do
    local x = {}
    for k = 1, 6 do x[k] = math.sin(i * (k + 0.5) * 0.731) end
    xs[i] = x
    ys[i] = { 0.5 + 0.4 * x[1] * x[2], 0.5 + 0.4 * math.sin(x[3] + x[4]), 0.3 + 0.2 * x[5] - 0.1 * x[6] }
  end
  return xs, ys
end
