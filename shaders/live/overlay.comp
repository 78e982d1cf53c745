// Blends an overlay (RGBA, rows bottom first as GL keeps them) over a region of a target, in
// place: rgb = mix(target, overlay, overlay.a). One invocation per overlay pixel.
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D u_overlay;
layout(binding = 0, rgba32f) uniform image2D u_target;
uniform ivec2 u_origin;  // the overlay's bottom-left pixel in the target

void main() {
  ivec2 q = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(q, textureSize(u_overlay, 0)))) return;
  ivec2 p = u_origin + q;
  if (any(lessThan(p, ivec2(0))) || any(greaterThanEqual(p, imageSize(u_target)))) return;
  vec4 o = texelFetch(u_overlay, q, 0);
  vec4 t = imageLoad(u_target, p);
  imageStore(u_target, p, vec4(mix(t.rgb, o.rgb, o.a), o.a + t.a * (1.0 - o.a)));
}
