-- expect: dataset_load_missing\.lua:3: sn\.dataset\.load: cannot read dataset 'no/such/cloth\.json': no such file
local sn = require "shadenet"
sn.dataset.load("no/such/cloth")
