#include "app/options.h"

#include <stdexcept>

namespace sn::app {

std::string usage() {
  return "usage: shadenet [options] script.lua [args...]\n"
         "Runs a Lua experiment script (require \"shadenet\"); its arguments are in the global `arg`.\n"
         "options:\n"
         "  --window           open a GLFW window instead of running headless (EGL)\n"
         "  --size WxH         window size (default 960x720); headless --watch: the view's size\n"
         "                     (default: sn.live.show's size, else its scene's, else 640x480)\n"
         "  --watch            live mode: re-run the script when it, a module it requires or a shader\n"
         "                     it uses is saved (sn.keep values survive); Lua lines on stdin run in\n"
         "                     the script's state (see docs/live-mode.md)\n"
         "  --help             print this help\n"
         "  --version          print the version and build (git commit), GL renderer and GL version\n"
         "  --gl-info          print the EGL platform and device, the GL renderer and the limits the\n"
         "                     kernels are sized by (SHADENET_EGL_PLATFORM=auto|device|surfaceless picks\n"
         "                     the platform; see README.md, \"On a GPU\")\n";
}

Options parse_options(int argc, char** argv) {
  Options o;
  o.program = argc > 0 ? argv[0] : "shadenet";
  int i = 1;
  for (; i < argc; ++i) {
    std::string a = argv[i];
    if (a.empty() || a[0] != '-' || a == "-") break;
    if (a == "--") {
      ++i;
      break;
    }
    if (a == "--help" || a == "-h") o.help = true;
    else if (a == "--version" || a == "-v") o.version = true;
    else if (a == "--gl-info") o.gl_info = true;
    else if (a == "--window") o.window = true;
    else if (a == "--watch") o.watch = true;
    else if (a == "--size") {
      if (i + 1 >= argc) throw std::invalid_argument("--size needs a value such as 1280x720");
      std::string v = argv[++i];
      if (sscanf(v.c_str(), "%dx%d", &o.width, &o.height) != 2 || o.width < 1 || o.height < 1)
        throw std::invalid_argument("--size: expected WIDTHxHEIGHT, got '" + v + "'");
      o.size_given = true;
    } else
      throw std::invalid_argument("unknown option '" + a + "' (valid: --window, --watch, --size, --help, --version, --gl-info)");
  }
  if (i < argc) {
    o.script = argv[i++];
    for (; i < argc; ++i) o.script_args.push_back(argv[i]);
  }
  if (o.script.empty() && !o.help && !o.version && !o.gl_info) throw std::invalid_argument("no script given");
  if (o.size_given && !o.window && !o.watch)
    throw std::invalid_argument("--size is the window's (or live mode's view's) size: give --window or --watch with it");
  return o;
}

}  // namespace sn::app
