-- Summaries of repeated runs. The thesis reports medians of 10 runs: robust to the occasional
-- run that stalls or diverges.
local stats = {}

local function finite(v) return type(v) == "number" and v == v and v ~= math.huge and v ~= -math.huge end
stats.finite = finite

-- Values of `list` (numbers, or records with field `key`), finite ones only, sorted.
local function values(list, key)
  local out = {}
  for _, v in ipairs(list) do
    local x = key and v[key] or v
    if finite(x) then out[#out + 1] = x end
  end
  table.sort(out)
  return out
end

-- Median of the finite values; nil when there is none. The count of values left out is the
-- second result, so callers can say "2 of 10 runs diverged" instead of hiding them.
function stats.median(list, key)
  local v = values(list, key)
  local n = #v
  if n == 0 then return nil, #list end
  local m = n % 2 == 1 and v[(n + 1) / 2] or 0.5 * (v[n / 2] + v[n / 2 + 1])
  return m, #list - n
end

function stats.min(list, key)
  local v = values(list, key)
  return v[1]
end

function stats.max(list, key)
  local v = values(list, key)
  return v[#v]
end

function stats.mean(list, key)
  local v = values(list, key)
  if #v == 0 then return nil end
  local s = 0
  for _, x in ipairs(v) do s = s + x end
  return s / #v
end

-- Linear-interpolated quantile q in [0, 1].
function stats.quantile(list, q, key)
  local v = values(list, key)
  local n = #v
  if n == 0 then return nil end
  local h = (n - 1) * q + 1
  local lo = math.floor(h)
  local hi = math.min(lo + 1, n)
  return v[lo] + (h - lo) * (v[hi] - v[lo])
end

return stats
