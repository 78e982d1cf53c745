// The command line: shadenet [options] script.lua [args...], options before the script.
#pragma once
#include <string>
#include <vector>

namespace sn::app {

struct Options {
  bool help = false, version = false, gl_info = false, window = false, watch = false;
  int width = 960, height = 720;  // window size; headless --watch: the view's size when given
  bool size_given = false;        // --size was on the command line
  std::string program;  // argv[0]
  std::string script;
  std::vector<std::string> script_args;
};

// Throws with a message naming the bad option and listing the valid ones.
Options parse_options(int argc, char** argv);
std::string usage();

}  // namespace sn::app
