-- The stress table of scripts/stress_lighting.lua: every model at its defaults and at its domain
-- edges, over the adversarial grid, on GPU and twin -- every count must be zero.
local stress = dofile("scripts/stress_lighting.lua")
local rows = stress.rows()
assert(#rows >= 21, "stress cases: " .. #rows)
local seen = {}
for _, r in ipairs(rows) do
  seen[r.case:match("^(%S+)")] = true
  assert(r.samples > 30000, r.case .. ": only " .. r.samples .. " samples")
  for _, k in ipairs { "gpu_nan", "gpu_inf", "gpu_range", "twin_nan", "twin_inf", "twin_range",
                       "recorded_nan", "recorded_range" } do
    assert(r[k] == 0, string.format("%s: %s = %d", r.case, k, r[k]))
  end
  assert(r.max_raw > 0 and r.max_raw < 1e30, r.case .. ": largest raw value " .. r.max_raw)
end
for _, m in ipairs { "phong", "blinn_phong", "ggx", "toon3", "textured_phong" } do
  assert(seen[m], "no stress case for " .. m)
end
print("ok")
