-- A results folder holds one experiment (lib.claim): the script's own flags are part of the claim,
-- compared by the runs they make, as merge.lua compares shards; merge.lua claims its output folder
-- before it copies anything; two processes claiming one folder at once are told apart by a lock.
local sn = require "shadenet"
local C = require "script_check"
local json = require "lib.json"
local results = require "lib.results"

-- A tiny experiment with a flag of its own: --epochs (default 1). CLAIM_ONLY stops it once it has
-- claimed its folder.
local script, root = C.child("claims", [[
package.path = "scripts/?.lua;" .. package.path
local exp = require "lib.experiment"
local E = exp.start("my_exp", arg, { flags = { { flag = "--epochs", value = "N", help = "epochs (default 1)" } } })
if os.getenv("CLAIM_ONLY") then print("claimed") os.exit(0) end
local epochs = tonumber(E.opts.extra.epochs or "1")
local desc = E:data_desc { model = "phong", data = "cloth", size = { 64, 48 }, views = 2, samples = 300 }
local runs = {}
for seed = 1, 2 do runs[seed] = exp.run { id = "s" .. seed, hidden = { 4 }, seed = seed, epochs = epochs, data = desc } end
local records = E:sweep(runs)
E.R:table { columns = { { key = "id" }, { key = "mse" } },
            rows = { { id = "s1", mse = records.s1 and records.s1.result.best_val_mse },
                     { id = "s2", mse = records.s2 and records.s2.result.best_val_mse } } }
E:finish { records = records }
]])
local function run(args, env) return C.run(script, args, env) end
local function runs_of(dir)
  local out = {}
  for _, f in ipairs(sn.fs.list(dir .. "/runs")) do out[f] = C.read(dir .. "/runs/" .. f) end
  return json.encode(out)
end
local function no_traceback(out) assert(not out:find("traceback"), "a user's error, no Lua traceback:\n" .. out) end

-- The script's own flags are part of the claim: --epochs 2 after --epochs 1 replaced every record
-- under the same ids without a word.
local X = root .. "/x"
C.ok(script, { "--quick", "--epochs", "1", "--out", X })
local before = runs_of(X)
local code, out = run { "--quick", "--epochs", "2", "--out", X }
assert(code == 2 and out:find(X .. " holds the results of my_exp --quick --epochs 1 (--data poses, --ggx thesis); my_exp "
                              .. "--quick --epochs 2 (--data poses, --ggx thesis) there would overwrite them (its runs "
                              .. "differ): give it its own --out DIR", 1, true), tostring(code) .. ":\n" .. out)
no_traceback(out)
assert(runs_of(X) == before, "the folder's records are untouched")
-- The same values typed another way, or the default left out, make the same runs: accepted.
out = C.ok(script, { "--quick", "--epochs=1.0", "--out", X })
assert(not out:find("resuming") and runs_of(X) == before, "--epochs=1.0 is --epochs 1:\n" .. out)
out = C.ok(script, { "--quick", "--out", X })
assert(out:find("holds the runs of my_exp --quick --epochs 1 (--data poses, --ggx thesis): the same runs as my_exp "
                .. "--quick (--data poses, --ggx thesis)", 1, true) and runs_of(X) == before, out)

-- Shards: one without --epochs, one with its default's value, merge (they were refused, with a Lua
-- traceback); shards whose flags make other runs are refused, the message alone, exit 2.
local S1, S2, S3 = root .. "/s1", root .. "/s2", root .. "/s3"
C.ok(script, { "--quick", "--shard", "1/2", "--out", S1 })
C.ok(script, { "--quick", "--shard", "2/2", "--epochs", "1", "--out", S2 })
C.ok(script, { "--quick", "--shard", "2/2", "--epochs", "2", "--out", S3 })
out = C.ok("scripts/merge.lua", { S1, S2, "--out", root .. "/merged" })
assert(out:find("they make the same runs", 1, true) and out:find("2 run files from 2 folders", 1, true), out)
assert(C.read(root .. "/merged/table.csv") == C.read(X .. "/table.csv"), "shards + merge = the whole run")
code, out = C.run("scripts/merge.lua", { S1, S3, "--out", root .. "/merged3" })
assert(code == 2 and out:find("merge.lua: " .. S1 .. " was run with the script's flags (none), " .. S3 .. " with "
                              .. "--epochs 2: their runs are different experiments", 1, true), out)
no_traceback(out)

-- Shards trained by another build: the merged run.json lists both builds, and merge says so.
local rec_file = S2 .. "/runs/s2.json"
local rec = C.json(rec_file)
assert(rec.build == sn.build, "a run record names the build that trained it: " .. tostring(rec.build))
rec.build = "0123456789ab-other"
results.write_file(rec_file, json.encode(rec))
out = C.ok("scripts/merge.lua", { S1, S2, "--out", root .. "/merged_builds" })
assert(out:find("my_exp: the tables' runs were trained by 2 builds (", 1, true) and
       out:find("0123456789ab-other: 1", 1, true) and out:find(sn.build .. ": 1", 1, true) and
       out:find("this binary is " .. sn.build .. "): numbers of different builds may differ", 1, true), out)
local per = C.json(root .. "/merged_builds/run.json").runs_per_build
assert(per[sn.build] == 1 and per["0123456789ab-other"] == 1, json.encode(per))

-- merge.lua into a folder of another experiment (or of this one in full mode): refused before a
-- run file is copied (72 records were replaced, then the experiment refused the folder).
for _, other in ipairs { { experiment = "table_4_2_ggx", quick = true, described = "table_4_2_ggx --quick" },
                         { experiment = "my_exp", quick = false, described = "my_exp --epochs 1" } } do
  local G = root .. "/other-" .. other.experiment
  results.write_json(G .. "/experiment.json", { experiment = other.experiment, quick = other.quick,
                                                options = { data = "poses", ggx = "thesis" },
                                                flags = other.experiment == "my_exp" and { ["--epochs"] = 1 } or {} })
  results.write_file(G .. "/runs/s1.json", "{\"id\": \"s1\", \"theirs\": true}\n")
  code, out = C.run("scripts/merge.lua", { S1, S2, "--out", G })
  assert(code == 2 and out:find(G .. " holds the results of " .. other.described .. " (--data poses, --ggx thesis); "
                                .. "my_exp --quick (--data poses, --ggx thesis) there would overwrite them", 1, true),
         tostring(code) .. ":\n" .. out)
  assert(not out:find("replaced") and not out:find("run files from"), "nothing copied:\n" .. out)
  assert(C.read(G .. "/runs/s1.json") == "{\"id\": \"s1\", \"theirs\": true}\n" and #sn.fs.list(G .. "/runs") == 1,
         "the folder's records are untouched")
  no_traceback(out)
end

-- Two experiments claiming one folder at once: while one holds the claim, another waits for it
-- and then sees its experiment.json (both read an empty folder, both ran, and the second
-- overwrote the first's results). A child started in the background, its exit status in a file.
local started = 0
local function start(dir, env)
  started = started + 1
  local status, log = root .. "/child" .. started .. ".status", root .. "/child" .. started .. ".log"
  local vars = {}
  for k, v in pairs(env or {}) do vars[#vars + 1] = k .. "=" .. v end
  C.sh(string.format("(env CLAIM_ONLY=1 %s %s %s --quick --out %s > %s 2>&1; echo $? > %s) &", table.concat(vars, " "),
                     C.shadenet, script, dir, log, status))
  return function()  -- waits for the child: its exit status and output
    for _ = 1, 600 do
      local s = C.read(status)
      if s and s:match("%d") then return tonumber(s:match("%d+")), C.read(log) end
      os.execute("sleep 0.05")
    end
    error("the child claiming " .. dir .. " did not end")
  end
end
local Y = root .. "/race"
sn.fs.mkdir(Y .. "/runs")
local lock = assert(sn.fs.lock(Y .. "/runs"))  -- another experiment, in the middle of its claim
local wait = start(Y)
os.execute("sleep 1")
results.write_json(Y .. "/experiment.json", { experiment = "table_4_2_ggx", quick = true, flags = {},
                                              options = { data = "poses", ggx = "thesis" } })
lock:share()
code, out = wait()
assert(code == 2 and out:find(Y .. " holds the results of table_4_2_ggx --quick (--data poses, --ggx thesis) (another "
                              .. "process is running it there now); my_exp --quick", 1, true), tostring(code) .. ":\n" .. out)
lock:release()
-- The same experiment twice at once may run (shards of a sweep do), and is told so; once the other
-- process is gone (a kill drops its lock too) the folder is the newcomer's alone.
local Z = root .. "/twice"
wait = start(Z)
code, out = wait()
assert(code == 0 and not out:find("another process"), out)
lock = assert(sn.fs.lock(Z .. "/runs", { shared = true }))
code, out = start(Z)()
assert(code == 0 and out:find("my_exp: another process is running my_exp --quick (--data poses, --ggx thesis) in " .. Z
                              .. " now", 1, true), out)
lock:release()
code, out = start(Z)()
assert(code == 0 and not out:find("another process"), out)

C.rm(root)
print("claims: ok")
