-- expect: table_4_1_phong\.lua: unknown option '--qiuck' \(valid: --quick, --shard i/n, --out DIR, --backend cpu\|gl\|auto, --data poses\|cloth, --ggx thesis\|gold, --runs-per-job N, --help\)
-- then-missing: out/error_script_unknown_option
-- A typo in an experiment script's option fails at once, before anything is written.
arg = { [0] = "scripts/table_4_1_phong.lua", "--out", "out/error_script_unknown_option", "--qiuck" }
dofile("scripts/table_4_1_phong.lua")
