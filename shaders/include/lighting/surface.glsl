// The surface point a lighting model's shade(Surface s, Params p) receives (runtime/shading/
// lighting_model.h has its double twin). World space; n, v, tangent and bitangent are unit or
// zero. Attributes the model does not declare hold the defaults written here.
struct Surface {
  vec3 n;               // normal
  vec3 v;               // towards the eye
  vec3 l;               // towards the light (unit)
  vec3 light_color;
  vec3 base_color;      // the mesh's base-colour texture at uv ("base_color"; else 1)
  vec2 uv;              // texture coordinates ("uv"; else 0)
  vec3 position;        // object-space position ("position"; else 0)
  vec3 world_position;  // ("world_position"; else 0)
  vec3 tangent;         // ("tangent"; else 0)
  vec3 bitangent;       // ("bitangent"; else 0)
};
