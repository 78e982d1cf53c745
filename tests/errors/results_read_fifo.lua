-- expect: cannot read file '.*/experiment\.json': not a regular file
-- A FIFO where an experiment's record belongs is an error; io.open waited on it for ever.
local sn = require "shadenet"
package.path = "scripts/?.lua;" .. package.path
local results = require "lib.results"

local dir = sn.fs.tempdir("fifo")
os.execute(("mkfifo %q"):format(dir .. "/experiment.json"))
results.read_json(dir .. "/experiment.json")
