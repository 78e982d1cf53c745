-- expect: table_4_2_ggx\.lua: --shard 3/2: i must be 1\.\.n and n 1\.\.2\^31
-- then-missing: out/error_script_bad_shard
arg = { [0] = "scripts/table_4_2_ggx.lua", "--shard", "3/2", "--out", "out/error_script_bad_shard" }
dofile("scripts/table_4_2_ggx.lua")
