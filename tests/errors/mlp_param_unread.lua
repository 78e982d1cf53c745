-- expect: mlp_param_unread\.lua:4: sn\.mlp option 'omega': neither activation of this network \(tanh, linear\) reads it; omega is the parameter of sine
local sn = require "shadenet"
-- omega given with tanh was ignored: a sine sweep that forgot its activation trained tanh networks.
sn.mlp { inputs = 6, hidden = { 8 }, omega = 30 }
