// The README example: mesh a square with a centre point, check the result.
#include <acutemesh/acutemesh.h>
#include <cstdio>

int main() {
  acutemesh::Pslg square;
  square.points = {0, 0, 1, 0, 1, 1, 0, 1, 0.5, 0.5};
  square.segments = {0, 1, 1, 2, 2, 3, 3, 0};
  acutemesh::Result r = acutemesh::mesh(square);  // Mode::Cdt by default
  if (r.status != acutemesh::Status::Ok) return std::fprintf(stderr, "%s\n", r.message.c_str()), 2;
  std::printf("%zu triangles, max angle %.1f\n", r.mesh.triangleCount(), r.stats.maxAngle);
  return acutemesh::validate(square, r.mesh).ok ? 0 : 1;
}
