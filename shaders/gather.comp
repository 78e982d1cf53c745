// Compacts a G-buffer (runtime/scene/gather.cpp): each covered pixel (coverage in .w of the
// first attachment) inside the box that can hold them takes the next slot of an atomic counter
// and copies its ATTRIBUTES attachments there, so later passes touch covered pixels only.
layout(local_size_x = 8, local_size_y = 8) in;

uniform sampler2D u_attributes[ATTRIBUTES];
uniform ivec4 u_box;  // x0, y0, x1, y1 (exclusive): where covered pixels can be

layout(std430, binding = 0) buffer Counter { uint count; };
layout(std430, binding = 1) writeonly buffer Pixels { uint pixels[]; };
layout(std430, binding = 2) writeonly buffer Attribute0 { vec4 attribute0[]; };
#if ATTRIBUTES > 1
layout(std430, binding = 3) writeonly buffer Attribute1 { vec4 attribute1[]; };
#endif
#if ATTRIBUTES > 2
layout(std430, binding = 4) writeonly buffer Attribute2 { vec4 attribute2[]; };
#endif
#if ATTRIBUTES > 3
layout(std430, binding = 5) writeonly buffer Attribute3 { vec4 attribute3[]; };
#endif
#if ATTRIBUTES > 4
layout(std430, binding = 6) writeonly buffer Attribute4 { vec4 attribute4[]; };
#endif
#if ATTRIBUTES > 5
layout(std430, binding = 7) writeonly buffer Attribute5 { vec4 attribute5[]; };
#endif
#if ATTRIBUTES > 6
#error "at most 6 G-buffer attributes"
#endif

void main() {
  ivec2 p = u_box.xy + ivec2(gl_GlobalInvocationID.xy);
  if (p.x >= u_box.z || p.y >= u_box.w) return;
  ivec2 size = textureSize(u_attributes[0], 0);
  vec4 first = texelFetch(u_attributes[0], p, 0);
  if (!(first.w > 0.5)) return;  // background
  uint i = atomicAdd(count, 1u);
  pixels[i] = uint(p.y * size.x + p.x);
  attribute0[i] = first;
#if ATTRIBUTES > 1
  attribute1[i] = texelFetch(u_attributes[1], p, 0);
#endif
#if ATTRIBUTES > 2
  attribute2[i] = texelFetch(u_attributes[2], p, 0);
#endif
#if ATTRIBUTES > 3
  attribute3[i] = texelFetch(u_attributes[3], p, 0);
#endif
#if ATTRIBUTES > 4
  attribute4[i] = texelFetch(u_attributes[4], p, 0);
#endif
#if ATTRIBUTES > 5
  attribute5[i] = texelFetch(u_attributes[5], p, 0);
#endif
}
