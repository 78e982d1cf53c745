// Fuzz target: sn.mesh.load on glTF (JSON) and GLB (binary) files. An input starting with the
// GLB magic is saved as .glb, any other as .gltf; files a .gltf names by URI resolve beside it.
#include <exception>

#include "fuzz_input.h"
#include "scene/gltf.h"
#include "scene/mesh.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  bool glb = size >= 4 && data[0] == 'g' && data[1] == 'l' && data[2] == 'T' && data[3] == 'F';
  std::string path = sn::fuzz::scratch_file(glb ? "input.glb" : "input.gltf", data, size);
  try {
    sn::scene::Mesh m = sn::scene::load_mesh(path);
    sn::scene::validate(m);  // whatever loads must be a mesh every later stage accepts
    if (m.base_color) (void)m.base_color->width;  // decoded on first read: the texture's bytes too
  } catch (const std::exception&) {
    // a clear error is the right answer to a bad file
  }
  return 0;
}
