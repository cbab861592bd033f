#include "exactgeo/mesh/self_intersection.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "exactgeo/boxes/box_tree.hpp"
#include "exactgeo/boxes/tree_pairs.hpp"
#include "exactgeo/parallel/blocks.hpp"
#include "face_contact/convex_polygons.hpp"
#include "face_contact/edge_method.hpp"
#include "face_contact/face_geometry.hpp"
#include "face_contact/separating_planes.hpp"

// The pair test, `contact` below, runs its stages in order, each in face_contact/: the
// shape class of each face (face_geometry.hpp), planes through corners
// (separating_planes.hpp), the exact test of two convex polygons (convex_polygons.hpp),
// edge-pair axes (separating_planes.hpp), then the edge method (edge_method.hpp). The
// broad phase, a box tree of exactgeo::boxes walked against itself, only proposes the
// pairs.

namespace exactgeo::mesh {

namespace {

// The pair test.
using internal::convex_polygons_contact;
using internal::edge_method;
using internal::FaceGeometry;
using internal::geometry_of;
using internal::separated_by_corner_plane;
using internal::separated_by_edge_pair_axis;
using internal::Shape;
using internal::shape_of;

/// The filters first (cheapest and most often decisive first: on a smooth quad mesh a
/// corner plane of one face settles most neighbours), then the exact method of the pair.
FaceContact contact(const FaceGeometry& a, const FaceGeometry& b,
                    CoplanarOverlap coplanar) noexcept {
  if (a.shape == Shape::degenerate || b.shape == Shape::degenerate) return FaceContact::apart;
  if (separated_by_corner_plane(a, b) || separated_by_corner_plane(b, a)) return FaceContact::apart;
  if (a.convex_polygon() && b.convex_polygon()) return convex_polygons_contact(a, b, coplanar);
  if (separated_by_edge_pair_axis(a, b)) return FaceContact::apart;
  // A coplanar pair gets here only with an other-flat quad (a skew quad lies in no plane).
  // Every edge then lies in the other face's plane, so each ray either misses the face or
  // is degenerate: undecided or apart, never intersecting, whichever way the faces face.
  // (A concave or butterfly patch folds over itself, so parts of it face each way.)
  return edge_method(a, b);
}

}  // namespace

std::string_view to_string(FaceContact contact) noexcept {
  switch (contact) {
    case FaceContact::apart:
      return "apart";
    case FaceContact::intersecting:
      return "intersecting";
    case FaceContact::undecided:
      return "undecided";
  }
  return "?";
}

FaceContact face_contact(const Mesh& mesh, std::size_t a, std::size_t b, CoplanarOverlap coplanar) {
  if (a == b) return FaceContact::apart;
  const Face& fa = mesh.faces[a];
  const Face& fb = mesh.faces[b];
  return contact(geometry_of(mesh, fa, shape_of(mesh, fa)),
                 geometry_of(mesh, fb, shape_of(mesh, fb)), coplanar);
}

namespace {

/// The faces' boxes at rest in one tree: every pair of faces whose closed boxes overlap,
/// faces that share corners included (they may still cross). Any other pair is apart: a
/// face lies in the box of its corners (a bilinear patch is a convex combination of
/// them), and the float boxes hold the exact ones (boxes/float_box.hpp), so no pair is
/// lost to rounding. The scale comes from the faces' corners only: a far vertex that no
/// face uses would shrink every box to a few float ulps and make every pair overlap.
template <class Report>
void overlapping_face_pairs(const Mesh& mesh, const std::vector<std::size_t>& faces,
                            Report&& report) {
  if (faces.empty()) return;
  double largest = 0.0;
  std::vector<std::array<VertexIndex, 4>> corners(faces.size());
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const Face& f = mesh.faces[faces[i]];
    for (std::size_t k = 0; k < 4; ++k) {
      corners[i][k] = f.corner(k);  // a triangle's third corner twice
      for (const double x : mesh.vertices[corners[i][k]])
        largest = std::max(largest, std::fabs(x));
    }
  }
  const boxes::Scale scale(largest);
  std::vector<boxes::FloatBox> vertex_boxes(mesh.vertices.size());
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    vertex_boxes[v] = boxes::point_box(mesh.vertices[v], scale);
  const boxes::VertexBoxes at_rest = boxes::VertexBoxes::at_rest(std::move(vertex_boxes));
  const boxes::BoxTree<4> tree(corners, at_rest);
  const boxes::Walk<4, 4> walk{tree, tree, at_rest, boxes::SharedCorners::keep};
  std::vector<boxes::NodePair> stack;
  boxes::overlapping_pairs(walk, {0, 0}, stack,
                           [&](const boxes::Packet<4>& a, std::size_t i, const boxes::Packet<4>& b,
                               std::size_t j) { report(faces[a.id[i]], faces[b.id[j]]); });
}

}  // namespace

SelfIntersections find_self_intersections(const Mesh& mesh, unsigned threads,
                                          CoplanarOverlap coplanar) {
  const std::size_t n = mesh.faces.size();
  std::vector<Shape> shapes(n);
  std::vector<std::size_t> faces;  // the non-degenerate ones, which alone can intersect
  faces.reserve(n);
  for (std::size_t f = 0; f < n; ++f) {
    shapes[f] = shape_of(mesh, mesh.faces[f]);
    if (shapes[f] != Shape::degenerate) faces.push_back(f);
  }

  // The tree's pairs gather in `pending`; each time it is full they are decided in blocks
  // on the workers, each answer in its own slot, and collected in order.
  constexpr std::size_t kPending = std::size_t{1} << 16;
  constexpr std::size_t kBlock = 1024;
  SelfIntersections result;
  std::vector<FacePair> pending;
  pending.reserve(kPending);
  std::vector<FaceContact> answers(kPending);
  const auto decide_pending = [&] {
    const std::size_t blocks = (pending.size() + kBlock - 1) / kBlock;
    parallel::for_each_block(blocks, threads, [&](std::size_t block) {
      const std::size_t end = std::min(pending.size(), (block + 1) * kBlock);
      for (std::size_t k = block * kBlock; k < end; ++k) {
        const FacePair& pair = pending[k];
        answers[k] =
            contact(geometry_of(mesh, mesh.faces[pair.first], shapes[pair.first]),
                    geometry_of(mesh, mesh.faces[pair.second], shapes[pair.second]), coplanar);
      }
    });
    for (std::size_t k = 0; k < pending.size(); ++k) {
      if (answers[k] == FaceContact::intersecting) result.intersecting.push_back(pending[k]);
      if (answers[k] == FaceContact::undecided) result.undecided.push_back(pending[k]);
    }
    result.candidate_pairs += pending.size();
    pending.clear();
  };
  overlapping_face_pairs(mesh, faces, [&](std::size_t i, std::size_t j) {
    pending.push_back({std::min(i, j), std::max(i, j)});
    if (pending.size() == kPending) decide_pending();
  });
  decide_pending();
  std::sort(result.intersecting.begin(), result.intersecting.end());
  std::sort(result.undecided.begin(), result.undecided.end());
  for (const FacePair& pair : result.undecided) {
    const Face& a = mesh.faces[pair.first];
    const Face& b = mesh.faces[pair.second];
    const auto end = [](const Face& f) {
      return f.corners.begin() + static_cast<std::ptrdiff_t>(f.size());
    };
    const auto shared = [&](VertexIndex v) {
      return std::find(b.corners.begin(), end(b), v) != end(b);
    };
    if (std::any_of(a.corners.begin(), end(a), shared)) {
      ++result.undecided_neighbours;
    }
  }
  return result;
}

}  // namespace exactgeo::mesh
