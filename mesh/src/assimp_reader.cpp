#include "assimp_reader.hpp"

#include <assimp/scene.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <fstream>
#include <string_view>
#include <utility>
#include <vector>

#include "assimp_library.hpp"
#include "exactgeo/io/input_error.hpp"
#include "exactgeo/io/read_bytes.hpp"
#include "exactgeo/io/text_scan.hpp"
#include "exactgeo/mesh/weld.hpp"
#include "polygon.hpp"

namespace exactgeo::mesh::internal {

using io::InputError;
using io::quoted;
using io::require_readable;

namespace {

using Matrix = std::array<std::array<double, 4>, 4>;

constexpr Matrix kIdentity = {{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}};

Matrix to_matrix(const aiMatrix4x4& m) {
  return {{{m.a1, m.a2, m.a3, m.a4},
           {m.b1, m.b2, m.b3, m.b4},
           {m.c1, m.c2, m.c3, m.c4},
           {m.d1, m.d2, m.d3, m.d4}}};
}

Matrix multiply(const Matrix& a, const Matrix& b) {
  Matrix c{};
  for (std::size_t i = 0; i < 4; ++i) {
    for (std::size_t j = 0; j < 4; ++j) {
      for (std::size_t k = 0; k < 4; ++k)
        c[i][j] += a[i][k] * b[k][j];
    }
  }
  return c;
}

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  std::string message = path;
  message.append(": ");
  message.append(what);
  throw InputError(message);
}

class SceneMerger {
 public:
  SceneMerger(const aiScene& scene, const std::string& path, const LoadOptions& options,
              LoadedMesh& out)
      : scene_(scene), path_(path), options_(options), out_(out) {}

  /// Every mesh of the scene, placed by its nodes' transforms, then its polygons split.
  void merge() {
    add_meshes();
    faces_.finish(out_, path_, options_);
  }

 private:
  void add_meshes() {
    if (scene_.mRootNode == nullptr) {
      for (unsigned m = 0; m < scene_.mNumMeshes; ++m)
        add_mesh(m, kIdentity);
      return;
    }
    // Depth first, with an explicit stack: scene graphs can be deep.
    std::vector<std::pair<const aiNode*, Matrix>> stack;
    stack.emplace_back(scene_.mRootNode, to_matrix(scene_.mRootNode->mTransformation));
    while (!stack.empty()) {
      const auto [node, transform] = stack.back();
      stack.pop_back();
      for (unsigned i = 0; i < node->mNumMeshes; ++i)
        add_mesh(node->mMeshes[i], transform);
      for (unsigned i = node->mNumChildren; i-- > 0;) {
        const aiNode* child = node->mChildren[i];
        if (child != nullptr) {
          stack.emplace_back(child, multiply(transform, to_matrix(child->mTransformation)));
        }
      }
    }
  }

  void add_mesh(unsigned m, const Matrix& transform) {
    if (m >= scene_.mNumMeshes || scene_.mMeshes[m] == nullptr) return;
    const aiMesh& mesh = *scene_.mMeshes[m];
    auto& vertices = out_.mesh.vertices;
    const std::size_t base = vertices.size();
    if (mesh.mNumVertices > kMaxVertices - base) fail(path_, "too many vertices");
    const bool identity = transform == kIdentity;
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D& a = mesh.mVertices[v];
      Point3 p{a.x, a.y, a.z};
      if (!identity) {
        Point3 q{};
        for (std::size_t i = 0; i < 3; ++i) {
          q[i] = transform[i][0] * p[0] + transform[i][1] * p[1] + transform[i][2] * p[2] +
                 transform[i][3];
        }
        p = q;
      }
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
        std::string what = "mesh ";
        what.append(std::to_string(m));
        what.append(", vertex ");
        what.append(std::to_string(v));
        what.append(": a coordinate is not finite");
        fail(path_, what);
      }
      vertices.push_back(p);
    }
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices < 3) continue;  // points and lines bound no volume
      auto fail_face = [&](const std::string& what) {
        std::string message = "mesh ";
        message.append(std::to_string(m));
        message.append(", face ");
        message.append(std::to_string(f));
        message.append(": ");
        message.append(what);
        fail(path_, message);
      };
      corners_.clear();
      for (unsigned c = 0; c < face.mNumIndices; ++c) {
        const unsigned index = face.mIndices[c];
        if (index >= mesh.mNumVertices) {
          std::string what = "vertex index ";
          what.append(std::to_string(index));
          what.append(" is out of range");
          fail_face(what);
        }
        corners_.push_back(static_cast<VertexIndex>(base + index));
      }
      if (auto why = faces_.add(corners_, 0, out_)) fail_face(*why);
    }
  }

  const aiScene& scene_;
  const std::string& path_;
  const LoadOptions& options_;
  LoadedMesh& out_;
  std::vector<VertexIndex> corners_;
  FileFaces faces_;
};

void require_supported(const AssimpLibrary& assimp, const std::string& source,
                       const std::string& extension) {
  std::string dotted = ".";
  dotted.append(extension);
  if (extension.empty() || !assimp.supports(dotted)) {
    std::string what = "unsupported mesh format ";
    what.append(extension.empty() ? "(no file extension; name it with --format)"
                                  : quoted(extension));
    what.append(": expected obj, off, ply, stl or a format assimp reads (gltf, glb, 3ds, ...)");
    fail(source, what);
  }
}

/// The first bytes of a zip archive.
constexpr std::string_view kZipSignature{"PK\x03\x04", 4};

/// The AMF format allows the file to be a zip archive holding the XML, which assimp's AMF
/// importer does not open (it fails on the archive's bytes with an XML parser's message):
/// said in the file's terms instead, with the way out.
void refuse_zipped_amf(const std::string& source, const std::string& extension,
                       std::string_view first_bytes) {
  if (extension != "amf" || first_bytes.substr(0, kZipSignature.size()) != kZipSignature) return;
  fail(source,
       "a zip-compressed AMF file (it starts with the zip signature PK\\3\\4), which "
       "assimp reads only uncompressed: unzip the XML it holds (unzip -p FILE > plain.amf) "
       "and read that");
}

/// The first `n` bytes of the file at `path` (fewer if it is shorter).
std::string first_bytes(const std::string& path, std::size_t n) {
  std::ifstream in(path, std::ios::binary);
  std::string bytes(n, '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(n));
  bytes.resize(static_cast<std::size_t>(std::max<std::streamsize>(in.gcount(), 0)));
  return bytes;
}

/// `read` runs the importer; its exceptions and failures become InputErrors naming `source`.
template <class Read>
LoadedMesh read_scene(const AssimpLibrary& assimp, const std::string& source,
                      const std::string& extension, const LoadOptions& options, Read read) {
  AssimpLibrary::Scene scene(nullptr, {&assimp});
  try {
    scene = read();  // no post-processing: quads stay quads
  } catch (const std::exception& e) {
    std::string what = "assimp: ";
    what.append(e.what());
    fail(source, what);
  }
  if (scene == nullptr) {
    std::string what = "assimp cannot read it: ";
    what.append(assimp.error());
    fail(source, what);
  }
  if ((scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) != 0) {
    fail(source, "assimp read an incomplete scene (no mesh data?)");
  }

  LoadedMesh out;
  out.format = "assimp ";
  out.format.append(extension);
  out.coordinates_via_float = true;
  // Always welded, before polygons are split: assimp splits vertices at texture seams and
  // per material.
  LoadOptions welded = options;
  welded.weld = true;
  SceneMerger(*scene, source, welded, out).merge();
  return out;
}

}  // namespace

LoadedMesh read_with_assimp(const std::string& path, const std::string& extension,
                            const LoadOptions& options) {
  const AssimpLibrary& assimp = AssimpLibrary::open(path);
  require_supported(assimp, path, extension);
  require_readable(path);  // the same message as for the other formats
  refuse_zipped_amf(path, extension, first_bytes(path, kZipSignature.size()));
  return read_scene(assimp, path, extension, options, [&] { return assimp.read_file(path); });
}

LoadedMesh read_with_assimp_from_memory(const std::string& bytes, const std::string& source,
                                        const std::string& extension, const LoadOptions& options) {
  const AssimpLibrary& assimp = AssimpLibrary::open(source);
  require_supported(assimp, source, extension);
  refuse_zipped_amf(source, extension, bytes);
  return read_scene(assimp, source, extension, options,
                    [&] { return assimp.read_memory(bytes, extension); });
}

}  // namespace exactgeo::mesh::internal
