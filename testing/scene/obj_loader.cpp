#include "scene/obj_loader.hpp"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <system_error>
#include <unordered_map>

#include "scene/obj_syntax_check.hpp"
#include "scene/polygon_triangulation.hpp"

namespace edgewise::scene {
namespace {

// tinyobjloader keeps a face's corner count in an unsigned char.
constexpr std::size_t kMaxCornersTinyobj = std::numeric_limits<unsigned char>::max();

// A whole regular file, or nothing and `error` says why. Devices and pipes are refused: they may
// never end (/dev/zero).
std::optional<std::string> read_file(const std::filesystem::path& path, std::uint64_t max_bytes,
                                     std::string& error) {
  std::error_code code;
  const auto status = std::filesystem::status(path, code);
  if (code) {
    error = code.message();
    return std::nullopt;
  }
  if (!std::filesystem::exists(status)) {
    error = std::make_error_code(std::errc::no_such_file_or_directory).message();
    return std::nullopt;
  }
  if (!std::filesystem::is_regular_file(status)) {
    error = "not a regular file";
    return std::nullopt;
  }
  const std::uintmax_t size = std::filesystem::file_size(path, code);
  if (code) {
    error = code.message();
    return std::nullopt;
  }
  if (size > max_bytes) {
    error = "file of " + std::to_string(size) + " bytes is larger than " +
            std::to_string(max_bytes) + " bytes (max_file_bytes)";
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary);
  std::string text(static_cast<std::size_t>(size), '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  if (!in || in.gcount() != static_cast<std::streamsize>(text.size())) {
    error = "cannot read";
    return std::nullopt;
  }
  return text;
}

// Reads the MTL files an OBJ names, from the OBJ's directory, with the same size limit and
// refusal of non-regular files as the OBJ itself (tinyobjloader's own reader has neither).
class MaterialDirectoryReader : public tinyobj::MaterialReader {
 public:
  MaterialDirectoryReader(std::filesystem::path directory, std::uint64_t max_bytes)
      : directory_(std::move(directory)), max_bytes_(max_bytes) {}

  bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                  std::map<std::string, int>* material_map, std::string* warning,
                  std::string* error) override {
    const std::filesystem::path path = directory_ / name;
    std::string problem;
    std::optional<std::string> text = read_file(path, max_bytes_, problem);
    if (!text) {
      *warning += "material file " + path.string() + ": " + problem + "\n";
      return false;
    }
    std::istringstream in(std::move(*text));
    tinyobj::LoadMtl(material_map, materials, &in, warning, error);
    return true;
  }

 private:
  std::filesystem::path directory_;
  std::uint64_t max_bytes_;
};

Vec3 normalized_or_fallback(double x, double y, double z) {
  const double length = std::sqrt(x * x + y * y + z * z);
  if (!(length > 0) || !std::isfinite(length)) return kFallbackNormal;
  return {static_cast<float>(x / length), static_cast<float>(y / length),
          static_cast<float>(z / length)};
}

// One corner of a face as the file names it; corners that agree on all four are one vertex.
struct CornerKey {
  int position, texcoord, normal, material;
  bool operator==(const CornerKey&) const = default;
};

struct CornerKeyHash {
  std::size_t operator()(const CornerKey& key) const {
    std::uint64_t h = static_cast<std::uint32_t>(key.position);
    for (const int part : {key.texcoord, key.normal, key.material}) {
      h = (h ^ static_cast<std::uint32_t>(part)) * 0x9e3779b97f4a7c15ull;
    }
    return static_cast<std::size_t>(h ^ (h >> 32));
  }
};

// Turns tinyobjloader's faces into one indexed triangle mesh.
class MeshBuilder {
 public:
  MeshBuilder(const tinyobj::attrib_t& attrib, const std::vector<tinyobj::material_t>& materials)
      : attrib_(attrib),
        materials_(materials),
        vertex_colors_(!attrib.colors.empty() && attrib.colors.size() == attrib.vertices.size()),
        material_colors_(!vertex_colors_ && !materials.empty()) {}

  // Adds one shape's faces; a message when its bookkeeping does not add up or an index is out
  // of range (both excluded by check_obj_syntax, so this is a second line of defence).
  std::optional<std::string> add(const tinyobj::mesh_t& faces) {
    if (faces.material_ids.size() != faces.num_face_vertices.size()) {
      return "inconsistent face lists";
    }
    std::size_t first = 0;
    for (std::size_t face = 0; face < faces.num_face_vertices.size(); ++face) {
      const std::size_t count = faces.num_face_vertices[face];
      if (count > faces.indices.size() - first) return "inconsistent face lists";
      const int material = material_colors_ ? faces.material_ids[face] : -1;

      corners_.clear();
      keys_.clear();
      for (std::size_t k = 0; k < count; ++k) {
        const tinyobj::index_t& index = faces.indices[first + k];
        if (!in_range(index.vertex_index, attrib_.vertices.size(), 3) ||
            !optional_in_range(index.texcoord_index, attrib_.texcoords.size(), 2) ||
            !optional_in_range(index.normal_index, attrib_.normals.size(), 3)) {
          return "face " + std::to_string(face + 1) + " has an index out of range";
        }
        const auto p = static_cast<std::size_t>(index.vertex_index) * 3;
        corners_.push_back({attrib_.vertices[p], attrib_.vertices[p + 1], attrib_.vertices[p + 2]});
        keys_.push_back({index.vertex_index, index.texcoord_index, index.normal_index, material});
      }
      first += count;

      local_triangles_.clear();
      triangulate_polygon(corners_, local_triangles_);
      for (const std::uint32_t corner : local_triangles_) {
        const std::optional<std::uint32_t> vertex = vertex_for(keys_[corner]);
        if (!vertex) return "more vertices than a 32-bit index can address";
        mesh_.indices.push_back(*vertex);
      }
    }
    return std::nullopt;
  }

  // The mesh, with smooth normals where the file lacked some; `warnings` says so.
  Mesh finish(std::string& warnings) {
    if (!any_texcoord_) mesh_.uvs.clear();
    if (vertices_without_normal_ > 0) {
      compute_smooth_normals(mesh_);
      warnings += std::to_string(vertices_without_normal_) +
                  " vertices without a normal: smooth normals computed for every vertex\n";
    }
    return std::move(mesh_);
  }

 private:
  static bool in_range(int index, std::size_t values, std::size_t per_element) {
    return index >= 0 && static_cast<std::size_t>(index) < values / per_element;
  }
  static bool optional_in_range(int index, std::size_t values, std::size_t per_element) {
    return index == -1 || in_range(index, values, per_element);
  }

  std::optional<std::uint32_t> vertex_for(const CornerKey& key) {
    const auto found = vertex_of_corner_.find(key);
    if (found != vertex_of_corner_.end()) return found->second;
    if (mesh_.positions.size() >= std::numeric_limits<std::uint32_t>::max()) return std::nullopt;
    const auto vertex = static_cast<std::uint32_t>(mesh_.positions.size());
    vertex_of_corner_.emplace(key, vertex);

    const auto p = static_cast<std::size_t>(key.position) * 3;
    mesh_.positions.push_back(
        {attrib_.vertices[p], attrib_.vertices[p + 1], attrib_.vertices[p + 2]});

    if (key.normal >= 0) {
      const auto n = static_cast<std::size_t>(key.normal) * 3;
      mesh_.normals.push_back(normalized_or_fallback(attrib_.normals[n], attrib_.normals[n + 1],
                                                     attrib_.normals[n + 2]));
    } else {
      mesh_.normals.push_back(kFallbackNormal);
      ++vertices_without_normal_;
    }

    if (key.texcoord >= 0) {
      const auto t = static_cast<std::size_t>(key.texcoord) * 2;
      mesh_.uvs.push_back({attrib_.texcoords[t], 1.0f - attrib_.texcoords[t + 1]});
      any_texcoord_ = true;
    } else {
      mesh_.uvs.push_back({0.0f, 0.0f});
    }

    if (vertex_colors_) {
      mesh_.colors.push_back(
          {attrib_.colors[p], attrib_.colors[p + 1], attrib_.colors[p + 2], 1.0f});
    } else if (material_colors_) {
      mesh_.colors.push_back(material_color(key.material));
    }
    return vertex;
  }

  Vec4 material_color(int material) const {
    if (material < 0 || static_cast<std::size_t>(material) >= materials_.size()) {
      return {1.0f, 1.0f, 1.0f, 1.0f};
    }
    const tinyobj::material_t& m = materials_[static_cast<std::size_t>(material)];
    return {m.diffuse[0], m.diffuse[1], m.diffuse[2], m.dissolve};
  }

  const tinyobj::attrib_t& attrib_;
  const std::vector<tinyobj::material_t>& materials_;
  const bool vertex_colors_;
  const bool material_colors_;

  Mesh mesh_;
  std::unordered_map<CornerKey, std::uint32_t, CornerKeyHash> vertex_of_corner_;
  bool any_texcoord_ = false;
  std::size_t vertices_without_normal_ = 0;
  // Per-face scratch space, kept to avoid an allocation per face.
  std::vector<Vec3> corners_;
  std::vector<CornerKey> keys_;
  std::vector<std::uint32_t> local_triangles_;
};

std::string trimmed(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == '.' || text.back() == ' ')) {
    text.pop_back();
  }
  std::replace(text.begin(), text.end(), '\n', ' ');
  return text;
}

MeshResult load_text(std::string_view text, std::string_view name, const ObjLoadOptions& options,
                     tinyobj::MaterialReader* material_reader) {
  const std::string prefix = std::string(name) + ": ";
  if (text.find_first_not_of(" \t\r\n") == std::string_view::npos) {
    return MeshResult::failure(prefix + "empty file (no faces)");
  }
  const ObjSyntaxCheck check =
      check_obj_syntax(text, std::min(options.max_face_vertices, kMaxCornersTinyobj));
  if (check.problem) return MeshResult::failure(prefix + *check.problem);
  if (check.summary.faces == 0) {
    return MeshResult::failure(prefix + "no faces (" + std::to_string(check.summary.positions) +
                               " vertices, nothing to draw)");
  }

  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::string warnings, errors;
  std::istringstream in{std::string(text)};
  // Polygons are kept whole (triangulate = false): polygon_triangulation.hpp says why. Vertex
  // colours are only reported when every vertex has one (no white fallback).
  const bool parsed = tinyobj::LoadObj(&attrib, &shapes, &materials, &warnings, &errors, &in,
                                       material_reader, /*triangulate=*/false,
                                       /*default_vcols_fallback=*/false);
  if (!parsed) return MeshResult::failure(prefix + trimmed(errors));

  MeshBuilder builder(attrib, materials);
  for (const tinyobj::shape_t& shape : shapes) {
    if (auto problem = builder.add(shape.mesh)) return MeshResult::failure(prefix + *problem);
  }
  Mesh mesh = builder.finish(warnings);
  if (mesh.indices.empty()) return MeshResult::failure(prefix + "no triangles");
  if (auto problem = validate(mesh)) return MeshResult::failure(prefix + *problem);
  if (!errors.empty()) warnings += errors;  // non-fatal MTL problems land here
  return MeshResult::success(std::move(mesh), std::move(warnings));
}

}  // namespace

MeshResult load_obj(const std::string& path, const ObjLoadOptions& options) {
  std::string problem;
  const std::optional<std::string> text = read_file(path, options.max_file_bytes, problem);
  if (!text) return MeshResult::failure(path + ": " + problem);
  MaterialDirectoryReader materials(std::filesystem::path(path).parent_path(),
                                    options.max_file_bytes);
  return load_text(*text, path, options, options.load_materials ? &materials : nullptr);
}

MeshResult parse_obj(std::string_view text, std::string_view name, const ObjLoadOptions& options) {
  if (text.size() > options.max_file_bytes) {
    return MeshResult::failure(std::string(name) + ": text of " + std::to_string(text.size()) +
                               " bytes is larger than " + std::to_string(options.max_file_bytes) +
                               " bytes (max_file_bytes)");
  }
  return load_text(text, name, options, nullptr);
}

}  // namespace edgewise::scene
