-- expect: mlp_load_missing_activation\.lua:4: .*checkpoint_softsign\.snmlp: the network uses activation 'softsign', which is not defined; define it before sn\.load with sn\.activation\.define{ name = "softsign", glsl = "x / \(1\.0 \+ abs\(x\)\)", grad = "1\.0 / \(\(1\.0 \+ abs\(x\)\) \* \(1\.0 \+ abs\(x\)\)\)", lua = \.\.\., lua_grad = \.\.\. }
-- (tests/data/checkpoint_softsign.snmlp: a network with a user's activation, saved by net:save)
local sn = require "shadenet"
local net = sn.load("tests/data/checkpoint_softsign.snmlp")
