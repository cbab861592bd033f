#include "exactgeo/mesh/self_intersection.hpp"

#include <algorithm>
#include <utility>
#include <vector>

#include "exactgeo/parallel/blocks.hpp"
#include "face_contact/convex_polygons.hpp"
#include "face_contact/edge_method.hpp"
#include "face_contact/face_box_tree.hpp"
#include "face_contact/face_geometry.hpp"
#include "face_contact/separating_planes.hpp"

// The pair test, `contact` below, runs its stages in order, each in face_contact/: the
// shape class of each face (face_geometry.hpp), planes through corners
// (separating_planes.hpp), the exact test of two convex polygons (convex_polygons.hpp),
// edge-pair axes (separating_planes.hpp), then the edge method (edge_method.hpp). The
// broad phase (face_box_tree.hpp) only proposes the pairs.

namespace exactgeo::mesh {

namespace {

// The pair test.
using face_contact_detail::convex_polygons_contact;
using face_contact_detail::edge_method;
using face_contact_detail::FaceGeometry;
using face_contact_detail::geometry_of;
using face_contact_detail::separated_by_corner_plane;
using face_contact_detail::separated_by_edge_pair_axis;
using face_contact_detail::Shape;
using face_contact_detail::shape_of;
// The broad phase.
using face_contact_detail::Aabb;
using face_contact_detail::box_of;
using face_contact_detail::BoxTree;

/// The filters first (cheapest and most often decisive first: on a smooth quad mesh a
/// corner plane of one face settles most neighbours), then the exact method of the pair.
FaceContact contact(const FaceGeometry& a, const FaceGeometry& b) noexcept {
  if (a.shape == Shape::degenerate || b.shape == Shape::degenerate) return FaceContact::apart;
  if (separated_by_corner_plane(a, b) || separated_by_corner_plane(b, a)) return FaceContact::apart;
  if (a.convex_polygon() && b.convex_polygon()) return convex_polygons_contact(a, b);
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

FaceContact face_contact(const Mesh& mesh, std::size_t a, std::size_t b) {
  if (a == b) return FaceContact::apart;
  const Face& fa = mesh.faces[a];
  const Face& fb = mesh.faces[b];
  return contact(geometry_of(mesh, fa, shape_of(mesh, fa)),
                 geometry_of(mesh, fb, shape_of(mesh, fb)));
}

SelfIntersections find_self_intersections(const Mesh& mesh, unsigned threads) {
  const std::size_t n = mesh.faces.size();
  std::vector<Shape> shapes(n);
  std::vector<Aabb> boxes(n);
  std::vector<std::size_t> items;
  items.reserve(n);
  for (std::size_t f = 0; f < n; ++f) {
    shapes[f] = shape_of(mesh, mesh.faces[f]);
    boxes[f] = box_of(mesh, mesh.faces[f]);
    if (shapes[f] != Shape::degenerate) items.push_back(f);
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
        answers[k] = contact(geometry_of(mesh, mesh.faces[pair.first], shapes[pair.first]),
                             geometry_of(mesh, mesh.faces[pair.second], shapes[pair.second]));
      }
    });
    for (std::size_t k = 0; k < pending.size(); ++k) {
      if (answers[k] == FaceContact::intersecting) result.intersecting.push_back(pending[k]);
      if (answers[k] == FaceContact::undecided) result.undecided.push_back(pending[k]);
    }
    result.candidate_pairs += pending.size();
    pending.clear();
  };
  const BoxTree tree(std::move(items), boxes);
  tree.overlapping_pairs([&](std::size_t i, std::size_t j) {
    pending.push_back({std::min(i, j), std::max(i, j)});
    if (pending.size() == kPending) decide_pending();
  });
  decide_pending();
  std::sort(result.intersecting.begin(), result.intersecting.end());
  std::sort(result.undecided.begin(), result.undecided.end());
  return result;
}

}  // namespace exactgeo::mesh
