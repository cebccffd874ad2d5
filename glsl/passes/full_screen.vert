// full_screen.vert — one triangle that covers the viewport, from
// gl_VertexID alone (no vertex buffer): the vertex stage of a full-screen
// fragment pass (pcss_one_call.frag).

#ifdef VULKAN
#define PN_VERTEX_INDEX gl_VertexIndex  // SPIR-V's name for it
#else
#define PN_VERTEX_INDEX gl_VertexID
#endif

void main() {
  vec2 corner = vec2(float((PN_VERTEX_INDEX << 1) & 2), float(PN_VERTEX_INDEX & 2));  // (0,0), (2,0), (0,2)
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
