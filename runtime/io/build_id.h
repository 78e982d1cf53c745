// Which source tree a binary was built from (tools/build_id.cmake writes it on every build): run
// records carry it, so a table can be traced to the code that made it.
#pragma once

namespace sn::io {

// The git commit (12 hex digits, "-dirty" with uncommitted changes), or "unknown".
const char* build_id();

}  // namespace sn::io
