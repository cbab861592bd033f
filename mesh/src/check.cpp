#include "exactgeo/mesh/check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <string_view>

#include "exactgeo/predicates/orient3d.hpp"

namespace exactgeo::mesh {

namespace {

bool is_finite(const Point3& p) noexcept {
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

/// One use of an undirected edge by a face, `forward` when the face walks it from the
/// smaller index to the larger one, packed into one integer that sorts by the edge and
/// then backward before forward: (smaller << 33) | (larger << 1) | forward. (std::array
/// edges compare equal through memcmp, a library call per comparison of the sort.)
struct EdgeUse {
  std::uint64_t key;
  std::size_t face;

  EdgeUse(VertexIndex a, VertexIndex b, std::size_t f) noexcept
      : key(std::uint64_t{std::min(a, b)} << 33 | std::uint64_t{std::max(a, b)} << 1 |
            std::uint64_t{a < b}),
        face(f) {}
  std::uint64_t edge_key() const noexcept { return key >> 1; }
  bool forward() const noexcept { return (key & 1) != 0; }
  Edge edge() const noexcept {
    return {static_cast<VertexIndex>(key >> 33), static_cast<VertexIndex>(key >> 1)};
  }
};

/// Union-find over vertices, with path halving and union by size.
class DisjointSets {
 public:
  explicit DisjointSets(std::size_t n) : parent_(n), size_(n, 1) {
    std::iota(parent_.begin(), parent_.end(), std::size_t{0});
  }
  std::size_t find(std::size_t x) noexcept {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }
  void unite(std::size_t a, std::size_t b) noexcept {
    a = find(a);
    b = find(b);
    if (a == b) return;
    if (size_[a] < size_[b]) std::swap(a, b);
    parent_[b] = a;
    size_[a] += size_[b];
  }

 private:
  std::vector<std::size_t> parent_;
  std::vector<std::size_t> size_;
};

/// Zero area, decided exactly. A quad is degenerate when its patch collapses to a segment
/// or a point; the patch {a, b, c, c} of a triangle does so exactly when a, b, c are
/// collinear, asked directly (classify_patch would first find the tetrahedron (a, b, c, c)
/// flat, an exact zero that the filters cannot certify: most of a triangle mesh's check).
/// Every other flat shape (convex, concave, butterfly, or a quad with a collinear corner)
/// spans a non-zero area. Precondition: finite corners in range.
bool zero_area(const Mesh& mesh, const Face& face) noexcept {
  if (face.is_triangle()) {
    const auto& v = mesh.vertices;
    return collinear(v[face.corners[0]], v[face.corners[1]], v[face.corners[2]]);
  }
  const PatchShape shape = classify_patch(patch_of(mesh, face));
  return shape == PatchShape::segment || shape == PatchShape::point;
}

bool repeated_corner(const Face& face) noexcept {
  const std::size_t n = face.size();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      if (face.corners[i] == face.corners[j]) return true;
    }
  }
  return false;
}

void check_edges(std::vector<EdgeUse>& uses, MeshCheck& check) {
  std::sort(uses.begin(), uses.end(),
            [](const EdgeUse& a, const EdgeUse& b) { return a.key < b.key; });
  bool every_edge_twice = !uses.empty();
  bool opposite_directions = true;
  for (std::size_t begin = 0; begin < uses.size();) {
    std::size_t end = begin + 1;
    while (end < uses.size() && uses[end].edge_key() == uses[begin].edge_key())
      ++end;
    const std::size_t count = end - begin;
    const Edge edge = uses[begin].edge();
    const auto forward =
        static_cast<std::size_t>(std::count_if(uses.begin() + static_cast<std::ptrdiff_t>(begin),
                                               uses.begin() + static_cast<std::ptrdiff_t>(end),
                                               [](const EdgeUse& use) { return use.forward(); }));
    if (2 * forward != count) check.unbalanced_edges.add(edge);
    if (2 * forward >= count + 2 || 2 * forward + 2 <= count) check.misoriented_edges.add(edge);
    if (count == 1) check.boundary_edges.add(edge);
    if (count > 2) check.non_manifold_edges.add(edge);
    for (std::size_t use = begin; use < end; ++use) {
      FaceFindings& face = check.face_findings[uses[use].face];
      face.boundary_edge = face.boundary_edge || count == 1;
      face.non_manifold_edge = face.non_manifold_edge || count > 2;
    }
    if (count % 2 == 1) check.odd_edges.add(edge);
    if (count != 2) every_edge_twice = false;
    // Sorted with backward before forward: two uses in opposite directions differ.
    if (count == 2 && uses[begin].forward() == uses[begin + 1].forward())
      opposite_directions = false;
    begin = end;
  }
  if (every_edge_twice) check.consistently_oriented = opposite_directions;
}

template <class T, class Format>
std::string first_list(const Examples<T>& examples, Format format) {
  std::string s = "first: ";
  for (std::size_t i = 0; i < examples.first.size(); ++i) {
    if (i > 0) s.append(", ");
    s.append(format(examples.first[i]));
  }
  if (examples.count > examples.first.size()) s.append(", ...");
  return s;
}

/// "head (before first: a, b, ...)": a problem with its first examples.
template <class T, class Format>
std::string with_examples(std::string head, const Examples<T>& examples, Format format,
                          std::string_view before = {}) {
  head.append(" (").append(before).append(first_list(examples, format)).append(")");
  return head;
}

/// "<count> <noun or plural>", e.g. "1 boundary edge", "42 boundary edges".
std::string counted(std::size_t count, std::string_view singular, std::string_view plural) {
  std::string s = std::to_string(count);
  s.append(" ");
  s.append(count == 1 ? singular : plural);
  return s;
}

}  // namespace

MeshCheck check_mesh(const Mesh& mesh) {
  MeshCheck check;
  const std::size_t n = mesh.vertices.size();
  check.vertices = n;
  check.faces = mesh.faces.size();
  check.face_findings.resize(mesh.faces.size());

  std::vector<bool> finite(n);
  for (std::size_t v = 0; v < n; ++v) {
    const Point3& p = mesh.vertices[v];
    finite[v] = is_finite(p);
    if (!finite[v]) {
      check.non_finite_vertices.add(v);
      continue;
    }
    if (!check.bounding_box) {
      check.bounding_box = Box::of(p);
    } else {
      check.bounding_box->add(p);
    }
  }

  std::vector<EdgeUse> uses;
  uses.reserve(4 * mesh.faces.size());
  std::vector<bool> referenced(n);
  DisjointSets components(n);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const Face& face = mesh.faces[f];
    const std::size_t size = face.size();
    (face.is_triangle() ? check.triangles : check.quads) += 1;
    const auto bad = std::find_if(face.corners.begin(), face.corners.begin() + size,
                                  [n](VertexIndex c) { return c >= n; });
    if (bad != face.corners.begin() + size) {
      if (check.out_of_range_faces.count == 0) check.first_out_of_range_corner = *bad;
      check.out_of_range_faces.add(f);
      continue;  // no edges, references or geometry from a face that is not all there
    }

    bool all_finite = true;
    for (std::size_t i = 0; i < size; ++i) {
      const VertexIndex a = face.corner(i);
      const VertexIndex b = face.corner(i + 1);
      referenced[a] = true;
      all_finite = all_finite && finite[a];
      components.unite(a, b);
      // A repeated corner makes a zero-length "edge": it joins nothing, so it is not counted.
      if (a != b) uses.emplace_back(a, b, f);
    }

    FaceFindings& findings = check.face_findings[f];
    findings.degenerate = repeated_corner(face);
    // The exact predicates need finite coordinates.
    findings.zero_area = all_finite && zero_area(mesh, face);
    findings.degenerate = findings.degenerate || findings.zero_area;
    if (findings.zero_area) check.zero_area_faces.add(f);
    if (findings.degenerate) check.degenerate_faces.add(f);
    if (findings.degenerate && !findings.zero_area) check.repeated_corner_faces.add(f);
    if (findings.degenerate || !all_finite) continue;
    const BilinearPatch patch = patch_of(mesh, face);
    if (!face.is_triangle() && orient3d(patch.p00, patch.p10, patch.p11, patch.p01) != Sign::zero) {
      check.non_planar_quads.add(f);  // skew: never zero area
      findings.non_planar = true;
    }
  }

  check_edges(uses, check);

  std::vector<bool> counted_root(n);
  for (std::size_t v = 0; v < n; ++v) {
    if (!referenced[v]) {
      ++check.unreferenced_vertices;
      continue;
    }
    const std::size_t root = components.find(v);
    if (!counted_root[root]) {
      counted_root[root] = true;
      ++check.components;
    }
  }
  return check;
}

namespace {

/// The rule every edge must follow.
enum class EdgeRule : std::uint8_t {
  two_faces,   ///< shared by exactly two faces
  even_faces,  ///< shared by an even number of faces
  orientable,  ///< any number of faces, but never two more one way than the other
};

std::optional<std::string> surface_problem(const MeshCheck& check, EdgeRule rule,
                                           const FileNumbering& numbering) {
  // Vertices and faces as the file numbers them.
  const auto vertex_text = [&](std::size_t v) { return numbering.vertex(v); };
  const auto face_text = [&](std::size_t f) { return numbering.face(f); };
  const auto edge_text = [&](const Edge& e) {
    return vertex_text(e[0]).append("-").append(vertex_text(e[1]));
  };
  std::vector<std::string> problems;
  if (check.faces == 0) {
    problems.emplace_back("mesh has no faces");
  } else if (check.zero_area_faces.count == check.faces) {
    problems.emplace_back("every face has zero area");
  }

  if (const auto& bad = check.out_of_range_faces; bad.count > 0) {
    std::string s;
    if (bad.count > 1) {
      s = counted(bad.count, "face has", "faces have");
      s.append(" corner indices out of range (");
      s.append(first_list(bad, face_text));
      s.append("): ");
    }
    s.append("face ");
    s.append(face_text(bad.first.front()));
    s.append(" has corner index ");
    s.append(vertex_text(check.first_out_of_range_corner));
    s.append(", but there ");
    s.append(check.vertices == 1 ? "is " : "are ");
    s.append(counted(check.vertices, "vertex", "vertices"));
    problems.push_back(std::move(s));
  }

  if (const auto& bad = check.non_finite_vertices; bad.count > 0) {
    std::string head = counted(bad.count, "vertex has", "vertices have");
    head.append(" non-finite coordinates");
    problems.push_back(with_examples(std::move(head), bad, vertex_text));
  }

  // Beyond two faces per edge the rule is "an even number of faces", so the odd edges are the ones
  // to name when some of them are not boundary edges.
  const bool odd_beyond_boundary = check.odd_edges.count > check.boundary_edges.count;
  if (rule == EdgeRule::orientable) {
    // On an open surface a net count of two or more may be a boundary the surface runs
    // twice (two copies of a bowl): only a closed surface says the faces disagree.
    if (check.closed() && check.misoriented_edges.count > 0) {
      std::string head = "faces not oriented alike: ";
      head.append(counted(check.misoriented_edges.count, "edge is", "edges are"));
      head.append(" run the same way by two more faces than the other way");
      problems.push_back(with_examples(std::move(head), check.misoriented_edges, edge_text));
    }
  } else if (odd_beyond_boundary) {  // with two_faces too: named at once with non-manifold
    std::string head = "mesh is not closed: ";
    head.append(counted(check.odd_edges.count, "edge", "edges"));
    head.append(" used by an odd number of faces");
    problems.push_back(with_examples(std::move(head), check.odd_edges, edge_text));
  } else if (check.boundary_edges.count > 0) {
    std::string head = "mesh is not closed: ";
    head.append(counted(check.boundary_edges.count, "boundary edge", "boundary edges"));
    problems.push_back(with_examples(std::move(head), check.boundary_edges, edge_text));
  }
  if (rule == EdgeRule::two_faces && check.non_manifold_edges.count > 0) {
    problems.push_back(with_examples(
        counted(check.non_manifold_edges.count, "non-manifold edge", "non-manifold edges"),
        check.non_manifold_edges, edge_text, "used by more than two faces; "));
  }

  if (const auto& bad = check.repeated_corner_faces; bad.count > 0) {
    problems.push_back(with_examples(
        counted(bad.count, "face repeats a corner", "faces repeat a corner"), bad, face_text));
  }

  if (problems.empty()) return std::nullopt;
  std::string message;
  for (const std::string& p : problems) {
    if (!message.empty()) message.append("; ");
    message.append(p);
  }
  return message;
}

}  // namespace

std::optional<std::string> closed_surface_problem(const MeshCheck& check, bool allow_non_manifold,
                                                  const FileNumbering& numbering) {
  return surface_problem(check, allow_non_manifold ? EdgeRule::even_faces : EdgeRule::two_faces,
                         numbering);
}

std::optional<std::string> orientable_surface_problem(const MeshCheck& check,
                                                      const FileNumbering& numbering) {
  return surface_problem(check, EdgeRule::orientable, numbering);
}

namespace {

/// A problem found in a file's numbering, saying which.
std::optional<std::string> with_numbering(std::optional<std::string> problem,
                                          const LoadedMesh& loaded) {
  if (problem) problem->append(loaded.numbering.vertices_and_faces_said());
  return problem;
}

}  // namespace

std::optional<std::string> closed_surface_problem(const MeshCheck& check, const LoadedMesh& loaded,
                                                  bool allow_non_manifold) {
  return with_numbering(closed_surface_problem(check, allow_non_manifold, loaded.numbering),
                        loaded);
}

std::optional<std::string> zero_area_note(const Examples<std::size_t>& faces,
                                          const FileNumbering& numbering) {
  if (faces.count == 0) return std::nullopt;
  return with_examples(counted(faces.count, "face", "faces") + " of zero area", faces,
                       [&](std::size_t f) { return numbering.face(f); }) +
         (faces.count == 1 ? " bounds" : " bound") + " nothing: dropped" + numbering.faces_said();
}

std::optional<std::string> orientable_surface_problem(const MeshCheck& check,
                                                      const LoadedMesh& loaded) {
  return with_numbering(orientable_surface_problem(check, loaded.numbering), loaded);
}

std::optional<std::string> self_intersection_problem(const SelfIntersections& found,
                                                     const FileNumbering& numbering) {
  if (found.intersecting.empty() && found.undecided.empty()) return std::nullopt;
  const auto pairs = [&](const std::vector<FacePair>& list) {
    Examples<FacePair> examples;
    for (const FacePair& pair : list)
      examples.add(pair);
    return first_list(examples, [&](const FacePair& p) {
      return numbering.face(p.first) + "-" + numbering.face(p.second);
    });
  };
  std::vector<std::string> parts;
  if (!found.intersecting.empty()) {
    parts.push_back(
        counted(found.intersecting.size(), "pair of faces intersects", "pairs of faces intersect") +
        " (" + pairs(found.intersecting) + ")");
  }
  if (!found.undecided.empty()) {
    parts.push_back(counted(found.undecided.size(), "pair", "pairs") + " undecided (" +
                    pairs(found.undecided) + ")");
  }
  std::string message = parts[0];
  if (parts.size() > 1) message.append("; ").append(parts[1]);
  message.append(numbering.faces_said());
  return message;
}

}  // namespace exactgeo::mesh
