#include "measure/prepared_scene.hpp"

#include "measure/render_scene.hpp"

namespace tri {

PreparedScene prepare_scene(const SuiteScene& suite, std::size_t error_triangle_limit) {
  PreparedScene prepared{suite, generate_scene(suite.recipe), {}, {}, {}};
  prepared.triangles = scene_triangles(prepared.scene);
  prepared.batch = PreparedBatch(prepared.triangles);
  prepared.error_scene = prepared.scene;
  if (error_triangle_limit != 0 && prepared.triangles.size() > error_triangle_limit) {
    prepared.error_scene.primitives.clear();
    for (std::size_t i = 0; i < error_triangle_limit; ++i) {
      prepared.error_scene.primitives.emplace_back(prepared.triangles[i]);
    }
  }
  return prepared;
}

}  // namespace tri
