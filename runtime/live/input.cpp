#include "live/input.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace sn::live {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kDegPerPixel = 0.4;      // a drag across a 900-pixel window turns 360 degrees
constexpr double kZoomPerStep = 0.9;      // one wheel step moves 10% closer
constexpr double kLightStep = 5;          // degrees per arrow key press
// The letters and digits the controls below use (GLFW's key codes are their upper-case ASCII);
// every other one is free for sn.live.bind (shadenet.live.bind.lua keeps the same list).
constexpr const char* kBuiltinKeys = "1234CHIPQRS";
double rad(double d) { return d * kPi / 180; }
double deg(double r) { return r * 180 / kPi; }
}  // namespace

const char* mode_name(Mode m) {
  switch (m) {
    case Mode::network: return "network";
    case Mode::truth: return "truth";
    case Mode::error: return "error";
    case Mode::side: return "side";
  }
  return "network";
}

bool parse_mode(const std::string& name, Mode& out) {
  for (Mode m : {Mode::network, Mode::truth, Mode::error, Mode::side})
    if (name == mode_name(m)) return out = m, true;
  return false;
}

bool picture_pixel(double fx, double fy, int fw, int fh, int pw, int ph, int& x, int& y) {
  if (fw < 1 || fh < 1 || pw < 1 || ph < 1) return false;
  double s = std::min(double(fw) / pw, double(fh) / ph);
  double x0 = (fw - int(pw * s)) / 2, y0 = (fh - int(ph * s)) / 2;  // integer offsets, as present's
  double px = (fx - x0) / s, py = (fy - y0) / s;
  if (px < 0 || py < 0 || px >= pw || py >= ph) return false;
  x = int(px), y = int(py);
  return true;
}

std::array<double, 3> Orbit::position() const {
  double a = rad(azimuth), e = rad(elevation);
  return {center[0] + distance * std::cos(e) * std::sin(a), center[1] + distance * std::sin(e),
          center[2] + distance * std::cos(e) * std::cos(a)};
}

Orbit Orbit::from(const std::array<double, 3>& c, const std::array<double, 3>& p) {
  double dx = p[0] - c[0], dy = p[1] - c[1], dz = p[2] - c[2];
  Orbit o;
  o.center = c;
  o.distance = std::sqrt(dx * dx + dy * dy + dz * dz);
  if (o.distance > 0) {
    o.azimuth = deg(std::atan2(dx, dz));
    o.elevation = deg(std::asin(std::clamp(dy / o.distance, -1.0, 1.0)));
  }
  return o;
}

void Input::set_initial(const Orbit& camera, double fov, const Orbit& light, Mode mode, Reset reset) {
  initial_camera_ = camera, initial_light_ = light, initial_mode_ = mode;
  view_.fov = fov;
  if (reset.camera || !view_.camera_moved) view_.camera = camera, view_.camera_moved = false;
  if (reset.light || !view_.light_moved) view_.light = light, view_.light_moved = false;
  if (reset.mode) view_.mode = mode;
  dirty_ = true;
}

bool Input::take_dirty() {
  bool d = dirty_;
  dirty_ = false;
  return d;
}

Actions Input::take_actions() {
  Actions a = actions_;
  actions_ = {};
  return a;
}

bool Input::take_probe_dirty() {
  bool d = probe_dirty_;
  probe_dirty_ = false;
  return d;
}

void Input::move(double fx, double fy) {
  cursor_ = {fx, fy};
  if (probe_on_) probe_dirty_ = true;
}

bool Input::take_cancel() {
  bool c = actions_.cancel || actions_.quit;
  actions_.cancel = actions_.quit = false;
  return c;
}

const char* Input::help() {
  return "keys: 1 network  2 truth  3 |error| heatmap  4 side by side (truth | network | error)  Tab next view\n"
         "      left drag: orbit   wheel: zoom   right drag or arrows: move the light   Home: reset view\n"
         "      [ ] heatmap scale   I: probe the pixel under the cursor (truth, network, error)\n"
         "      S or F12: screenshot   R: record an orbit   P: print the view as Lua\n"
         "      H: this help   Esc or Q: quit (while training, recording or running Lua: stop it; C too)\n";
}

void Input::drag(double dx, double dy, bool light) {
  Orbit& o = light ? view_.light : view_.camera;
  // Dragging right turns the scene right: the eye moves left around it. The light follows the hand.
  double sign = light ? 1 : -1;
  o.azimuth = std::fmod(o.azimuth + sign * dx * kDegPerPixel, 360.0);
  o.elevation = std::clamp(o.elevation + (light ? -dy : dy) * kDegPerPixel, -89.0, 89.0);
  (light ? view_.light_moved : view_.camera_moved) = true;
  dirty_ = true;
}

void Input::zoom(double steps) {
  view_.camera.distance = std::clamp(view_.camera.distance * std::pow(kZoomPerStep, steps), 1e-3, 1e4);
  view_.camera_moved = true;
  dirty_ = true;
}

void Input::key(int k, int mods) {
  auto set_mode = [&](Mode m) {
    if (view_.mode != m) view_.mode = m, dirty_ = true;
  };
  switch (k) {
    case GLFW_KEY_1: set_mode(Mode::network); break;
    case GLFW_KEY_2: set_mode(Mode::truth); break;
    case GLFW_KEY_3: set_mode(Mode::error); break;
    case GLFW_KEY_4: set_mode(Mode::side); break;
    case GLFW_KEY_TAB: set_mode(Mode((int(view_.mode) + ((mods & GLFW_MOD_SHIFT) ? 3 : 1)) % 4)); break;
    case GLFW_KEY_LEFT: drag(-kLightStep / kDegPerPixel, 0, true); break;
    case GLFW_KEY_RIGHT: drag(kLightStep / kDegPerPixel, 0, true); break;
    case GLFW_KEY_UP: drag(0, -kLightStep / kDegPerPixel, true); break;
    case GLFW_KEY_DOWN: drag(0, kLightStep / kDegPerPixel, true); break;
    case GLFW_KEY_HOME:
      view_.camera = initial_camera_, view_.light = initial_light_, view_.mode = initial_mode_;
      view_.camera_moved = view_.light_moved = false;
      view_.error_scale_factor = 1;
      dirty_ = true;
      break;
    case GLFW_KEY_LEFT_BRACKET: view_.error_scale_factor /= 2, dirty_ = true; break;
    case GLFW_KEY_RIGHT_BRACKET: view_.error_scale_factor *= 2, dirty_ = true; break;
    case GLFW_KEY_S:
    case GLFW_KEY_F12: actions_.screenshot = true; break;
    case GLFW_KEY_R: actions_.record = true; break;
    case GLFW_KEY_P: actions_.print_view = true; break;
    case GLFW_KEY_I: probe_on_ = !probe_on_, probe_dirty_ = true; break;
    case GLFW_KEY_H:
    case GLFW_KEY_F1: actions_.help = true; break;
    case GLFW_KEY_ESCAPE: actions_.quit = actions_.escape = true; break;
    case GLFW_KEY_Q: actions_.quit = true; break;
    case GLFW_KEY_C: actions_.cancel = true; break;
    default: {  // for sn.live.bind
      bool shift = mods & GLFW_MOD_SHIFT;
      if (k >= GLFW_KEY_A && k <= GLFW_KEY_Z) actions_.keys.push_back({char('a' + (k - GLFW_KEY_A)), shift});
      if (k >= GLFW_KEY_0 && k <= GLFW_KEY_9) actions_.keys.push_back({char('0' + (k - GLFW_KEY_0)), shift});
      break;
    }
  }
}

void Input::attach(GLFWwindow* w) {
  glfwSetWindowUserPointer(w, this);
  glfwSetCursorPosCallback(w, on_cursor);
  glfwSetMouseButtonCallback(w, on_button);
  glfwSetScrollCallback(w, on_scroll);
  glfwSetKeyCallback(w, on_key);
  glfwSetWindowRefreshCallback(w, on_refresh);
}

void Input::on_refresh(GLFWwindow* w) { static_cast<Input*>(glfwGetWindowUserPointer(w))->actions_.present = true; }

void Input::on_cursor(GLFWwindow* w, double x, double y) {
  auto* self = static_cast<Input*>(glfwGetWindowUserPointer(w));
  if (self->dragging_ >= 0) self->drag(x - self->last_x_, y - self->last_y_, self->dragging_ == 1);
  self->last_x_ = x, self->last_y_ = y;
  int ww = 0, wh = 0, fw = 0, fh = 0;  // screen coordinates to framebuffer pixels (HiDPI)
  glfwGetWindowSize(w, &ww, &wh);
  glfwGetFramebufferSize(w, &fw, &fh);
  self->move(ww > 0 ? x * fw / ww : x, wh > 0 ? y * fh / wh : y);
}

void Input::on_button(GLFWwindow* w, int button, int action, int mods) {
  auto* self = static_cast<Input*>(glfwGetWindowUserPointer(w));
  if (action == GLFW_RELEASE) {
    self->dragging_ = -1;
    return;
  }
  glfwGetCursorPos(w, &self->last_x_, &self->last_y_);
  bool light = button == GLFW_MOUSE_BUTTON_RIGHT || (button == GLFW_MOUSE_BUTTON_LEFT && (mods & GLFW_MOD_SHIFT));
  self->dragging_ = light ? 1 : button == GLFW_MOUSE_BUTTON_LEFT ? 0 : -1;
}

void Input::on_scroll(GLFWwindow* w, double, double dy) {
  static_cast<Input*>(glfwGetWindowUserPointer(w))->zoom(dy);
}

void Input::on_key(GLFWwindow* w, int key, int, int action, int mods) {
  // Held arrows and bound keys repeat (a bound value steps on while its key is held); the
  // other keys act once (a held S is one screenshot).
  bool bindable = ((key >= GLFW_KEY_A && key <= GLFW_KEY_Z) || (key >= GLFW_KEY_0 && key <= GLFW_KEY_9)) &&
                  !std::strchr(kBuiltinKeys, key);
  if (action == GLFW_PRESS || (action == GLFW_REPEAT && ((key >= GLFW_KEY_RIGHT && key <= GLFW_KEY_UP) || bindable)))
    static_cast<Input*>(glfwGetWindowUserPointer(w))->key(key, mods);
}

}  // namespace sn::live
