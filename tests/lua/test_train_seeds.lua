-- sn.train's seed per net: a job of nets with different shuffle seeds trains each exactly as a
-- job of that net alone with its seed, on every backend (the cpu backend pairs nets of one
-- architecture across seeds in its AVX-512 lanes; the gl backend a seed's permutation per net).
-- Bad seed tables are refused with the option's name.
local sn = require "shadenet"
local expect = require "expect"

local data = sn.dataset.sample { target = sn.lighting.phong {}, n = 4000, seed = 2 }
local seeds = { 7, 3, 7, 11, 3, 5, 11, 7 }
local function make(i)
  -- Two architectures, so that the cpu backend pairs within each; a 4-wide one among 8-wide.
  return sn.mlp { inputs = 6, hidden = i % 4 == 0 and { 4, 4 } or { 8, 8 }, outputs = 3, seed = 100 + i }
end
local same = expect.same_params

for _, backend in ipairs(sn.backends()) do
  local together = {}
  for i = 1, #seeds do together[i] = make(i) end
  local seen = {}
  local runs = sn.train { nets = together, data = data, epochs = 2, batch = 8, backend = backend, seed = seeds,
                          progress = function(e) seen[e.net] = (seen[e.net] or 0) + 1 end }
  for i = 1, #seeds do
    local alone = make(i)
    local run = sn.train { nets = alone, data = data, epochs = 2, batch = 8, backend = backend, seed = seeds[i] }[1]
    assert(same(together[i], alone), ("%s: net %d (seed %d) trains as alone"):format(backend, i, seeds[i]))
    assert(runs[i].val_mse[2] == run.val_mse[2], backend .. ": the same validation MSE")
    assert(seen[i] == 2, ("%s: net %d: progress heard %s epochs"):format(backend, i, tostring(seen[i])))
  end
  -- The seeds matter: nets 1 and 3 share seed 7 but not their start; 1 with seed 3 differs.
  local other = make(1)
  sn.train { nets = other, data = data, epochs = 2, batch = 8, backend = backend, seed = 3 }
  assert(not same(other, together[1]), backend .. ": another seed, another net")
  print(("%s: %s"):format(backend, runs[1].device))
end

-- A net that diverges mid-epoch inside a pair (the cpu backend's, nets 1 and 2 of 3 on 2
-- threads): it stops where it stops alone, and its partner goes on alone from the next step.
local function trio(i)
  local net = sn.mlp { inputs = 6, hidden = { 8, 8 }, outputs = 3, seed = i, activation = "exponential" }
  if i == 2 then  -- its weights x2.5: exp overflows after some steps
    local p = net:params()
    for k = 1, #p do p[k] = p[k] * 2.5 end
    net:set_params(p)
  end
  return net
end
local three = { trio(1), trio(2), trio(3) }
local runs = sn.train { nets = three, data = data, epochs = 2, batch = 8, backend = "cpu", adam = { lr = 0.01 } }
assert(runs[2].diverged and runs[2].diverged.step > 1 and not runs[1].diverged and not runs[3].diverged,
       "net 2 diverges part-way through, the others do not")
for i = 1, 3 do
  local alone = trio(i)
  local run = sn.train { nets = alone, data = data, epochs = 2, batch = 8, backend = "cpu", adam = { lr = 0.01 } }[1]
  assert(same(three[i], alone), "net " .. i .. " of the trio trains as alone")
  assert((run.diverged and run.diverged.step) == (runs[i].diverged and runs[i].diverged.step), "diverges at the same step")
end

expect.fails(function() sn.train { nets = { make(1), make(2) }, data = data, seed = { 1 } } end,
  "sn.train option 'seed': one seed per net, got 1 for 2 nets")
expect.fails(function() sn.train { nets = { make(1) }, data = data, seed = { -1 } } end,
  "sn.train option 'seed' entry 1 must be a whole number in 0..4294967295, got -1")
expect.fails(function() sn.train { nets = { make(1) }, data = data, seed = 1.5 } end, "sn.train option 'seed'")
-- The networks: one, or a table of them (the reader sn.render_errors shares).
expect.fails(function() sn.train { nets = { make(1), 5 }, data = data } end,
  "sn.train option 'nets': element 2 is number, not an Mlp")
expect.fails(function() sn.train { nets = "net", data = data } end,
  "sn.train option 'nets': an Mlp or a table of them expected, got string")
print("ok")
