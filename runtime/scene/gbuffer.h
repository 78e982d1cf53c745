// The G-buffer pass: one mesh-set seen from one camera, rasterised into per-pixel attributes.
// Only the attributes asked for are rasterised (the fragment shader is specialised by #define),
// each into its own RGBA32F attachment, in the order asked for: the value in .xyz (uv in .xy)
// and coverage in .w (1 on the mesh, 0 on the background).
#pragma once
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gl/render_target.h"

namespace sn::scene {

struct Mesh;
class Camera;

// Attribute names a G-buffer (and so a network input) can hold:
//   "normal"         world-space unit normal (3)
//   "view"           world-space unit direction from the surface towards the eye (3)
//   "position"       object-space position: the Mesh's vertex position before the draw's model
//                    matrix (the loader has already applied the file's node transforms) (3)
//   "world_position" world-space position (3)
//   "uv"             texture coordinates (2)
//   "base_color"     the mesh's base-colour texture at uv, as stored (3; for textured models)
//   "tangent"        world-space unit tangent, perpendicular to the normal (3; tangents.h says
//                    where it comes from)
//   "bitangent"      handedness x cross(normal, tangent) (3); on a back face both keep their
//                    direction while the normal turns towards the eye
const std::vector<std::string>& gbuffer_attribute_names();
// Components a network reads from the attribute (3, or 2 for "uv"); throws listing the valid names.
int attribute_width(const std::string& name);

// A rectangle of pixels [x0, x1) x [y0, y1) in GL's coordinates (row 0 at the bottom).
struct PixelBox {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  int width() const { return x1 - x0; }
  int height() const { return y1 - y0; }
};

struct GBuffer {
  std::shared_ptr<gl::RenderTarget> target;  // attachment i holds attributes[i]
  std::vector<std::string> attributes;
  int width = 0, height = 0;
  // When `bounded`, no pixel outside `covers` is covered: the screen box around the meshes'
  // projected bounding boxes (render_gbuffer leaves it unbounded when one reaches behind the eye),
  // so readers of the attachments skip the rest (nn/cpu_render.h). box(): that or the frame.
  PixelBox covers;
  bool bounded = false;
  PixelBox box() const { return bounded ? covers : PixelBox{0, 0, width, height}; }

  // Attachment index of `name`; throws listing the attributes this G-buffer holds.
  int attachment(const std::string& name) const;
};

// Checks an attribute list: known names, no repeats, 1..6 of them; throws naming the problem.
void check_attributes(const std::vector<std::string>& attributes);

// One mesh drawn with a model matrix (world = model * object).
struct MeshDraw {
  const Mesh* mesh;
  glm::dmat4 model{1.0};
};

// Rasterises `draws` seen by `camera` into a width x height G-buffer holding `attributes`. Back faces get their normal flipped towards the eye (two-sided
// surfaces such as cloth). Throws when a mesh lacks what an attribute needs: "uv" without
// texture coordinates, "base_color" without a base-colour texture.
GBuffer render_gbuffer(const std::vector<MeshDraw>& draws, const Camera& camera, int width, int height,
                       const std::vector<std::string>& attributes);

// How many G-buffer passes ran in this process (the dataset cache test watches it).
std::size_t gbuffer_renders();

}  // namespace sn::scene
