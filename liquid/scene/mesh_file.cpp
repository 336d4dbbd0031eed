#include "liquid/scene/mesh_file.h"

#include "liquid/scene/mesh_check.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <system_error>

namespace liquid {

TriangleMesh load_mesh_file(const std::filesystem::path& path) {
  const auto refuse = [&](const std::string& what) { throw SceneError(path.string() + ": " + what); };
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) refuse("no such mesh file");
  Assimp::Importer importer;
  // Faces of more than three corners become triangles; points and lines are left out.
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* scene = importer.ReadFile(path.string(), aiProcess_Triangulate | aiProcess_SortByPType);
  if (!scene) refuse(std::string("cannot read the mesh: ") + importer.GetErrorString());
  TriangleMesh mesh;
  mesh.file = path.string();
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* source = scene->mMeshes[m];
    const uint32_t first = uint32_t(mesh.vertices.size());
    for (unsigned v = 0; v < source->mNumVertices; ++v)
      mesh.vertices.emplace_back(source->mVertices[v].x, source->mVertices[v].y, source->mVertices[v].z);
    for (unsigned f = 0; f < source->mNumFaces; ++f) {
      const aiFace& face = source->mFaces[f];
      if (face.mNumIndices != 3) continue;
      for (int k = 0; k < 3; ++k) mesh.indices.push_back(first + face.mIndices[k]);
    }
  }
  weld_positions(mesh);
  if (const std::string problem = mesh_problem(mesh); !problem.empty()) refuse(problem);
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (const glm::vec3& v : mesh.vertices) {
    lo = glm::min(lo, v);
    hi = glm::max(hi, v);
  }
  const glm::vec3 middle = 0.5f * (lo + hi);
  for (glm::vec3& v : mesh.vertices) v -= middle;
  return mesh;
}

}  // namespace liquid
