// The window's controls, from GLFW callbacks into a plain state: an orbit camera (left drag
// turns it, the wheel zooms), the light direction (right drag or the arrow keys), the view
// mode, the pixel probe and one-shot actions (screenshot, recording, ...). The live loop reads it each frame.
#pragma once
#include <array>
#include <string>
#include <utility>
#include <vector>

struct GLFWwindow;

namespace sn::live {

enum class Mode { network, truth, error, side };
const char* mode_name(Mode m);
bool parse_mode(const std::string& name, Mode& out);

// A direction around a centre: azimuth from +Z towards +X, elevation above the XZ plane
// (degrees), as sn.orbit places its cameras.
struct Orbit {
  double azimuth = 0, elevation = 0, distance = 1;
  std::array<double, 3> center{0, 0, 0};
  std::array<double, 3> position() const;  // center + distance * direction
  static Orbit from(const std::array<double, 3>& center, const std::array<double, 3>& point);
};

struct ViewState {
  Mode mode = Mode::network;
  Orbit camera;
  double fov = 45;
  bool camera_moved = false;  // false: the script's own camera, exactly
  Orbit light;  // distance 1: a unit direction towards the light
  bool light_moved = false;
  double error_scale_factor = 1;  // [ and ] halve / double the heatmap's scale
};

struct Actions {
  bool screenshot = false, record = false, print_view = false, quit = false, help = false, cancel = false;
  bool escape = false;  // the quit came from Esc (which also stops work), not Q
  bool present = false;  // the window was uncovered: show the last frame again (no new render)
  // Letters and digits no control uses, in order, for sn.live.bind: the key ('a'..'z', '0'..'9')
  // and whether Shift was held (steps down).
  std::vector<std::pair<char, bool>> keys;
};

// Where a point of the window's framebuffer (fx, fy from the top-left) falls in a pw x ph picture
// the window shows letterboxed (as gl::Context::present draws it): 0-based pixel (x, y); false
// when the point is outside the picture.
bool picture_pixel(double fx, double fy, int fw, int fh, int pw, int ph, int& x, int& y);

class Input {
 public:
  // Installs the callbacks on `window` (its user pointer is this object).
  void attach(GLFWwindow* window);
  // Sets the camera, light and mode the script asked for; what the user changed since is
  // dropped only for the parts in `reset` (the script changed that part).
  struct Reset {
    bool camera = false, light = false, mode = false;
  };
  void set_initial(const Orbit& camera, double fov, const Orbit& light, Mode mode, Reset reset);

  ViewState& view() { return view_; }
  // True once since the last call when the view changed (a redraw is due).
  bool take_dirty();
  Actions take_actions();
  // True once when Esc, Q or C was pressed since the last call: long work (training, recording,
  // Lua that runs long) stops. The other actions wait for the loop.
  bool take_cancel();
  static const char* help();  // the key bindings, for the terminal

  // The pixel probe (I toggles it): on or off, and the cursor in framebuffer pixels. True once
  // since the last call when the probe was toggled or the cursor moved while it is on.
  bool probe_on() const { return probe_on_; }
  std::array<double, 2> cursor() const { return cursor_; }
  bool take_probe_dirty();

  // What the callbacks do (public so tests and the loop can drive them without a window).
  void drag(double dx, double dy, bool light);  // pixels
  void zoom(double wheel_steps);
  void key(int glfw_key, int mods);
  void move(double fx, double fy);  // the cursor, in framebuffer pixels

 private:
  static void on_cursor(GLFWwindow* w, double x, double y);
  static void on_button(GLFWwindow* w, int button, int action, int mods);
  static void on_scroll(GLFWwindow* w, double dx, double dy);
  static void on_key(GLFWwindow* w, int key, int scancode, int action, int mods);
  static void on_refresh(GLFWwindow* w);

  ViewState view_;
  Orbit initial_camera_, initial_light_;
  Mode initial_mode_ = Mode::network;
  bool dirty_ = true;
  Actions actions_;
  int dragging_ = -1;  // 0 = camera, 1 = light
  double last_x_ = 0, last_y_ = 0;
  bool probe_on_ = false, probe_dirty_ = false;
  std::array<double, 2> cursor_{-1, -1};
};

}  // namespace sn::live
