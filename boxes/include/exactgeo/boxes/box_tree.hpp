#pragma once

// A bounding-volume hierarchy over the boxes of one kind of mesh primitive (vertices,
// edges, triangles or quads, given by their corners): built once, refitted as the
// vertices' boxes change. The mesh broad phase builds one per kind over the vertices'
// swept boxes (ccd/src/mesh/broad_phase.cpp), self-intersection one over the faces at
// rest (mesh/src/self_intersection.cpp).
//
// Build: the primitives are sorted along a Morton (Z-order) curve through their box
// centres, quantized to 2^10 cells per axis over the centres' bounds; then, top down, a
// node's run of the curve is split where its codes' highest differing bit changes, which
// is a plane halving the node's cell of the grid (an octree's split, one axis at a time,
// and axes along which the run does not spread are never split). Runs of at most two
// leaves, and runs of one cell, are halved instead, down to leaves of at most eight
// primitives. Sorting takes three passes of a radix sort and the splits a binary search
// each: no comparison sort, no pass over a node's primitives per level. Nodes are stored
// depth first: a node's left child follows it, and it keeps the index of its right child.
// A leaf's primitives are one Packet (packet.hpp).
//
// Refit: with the connectivity fixed, the same tree serves every new set of vertex boxes.
// Each leaf box is made anew from its corners' boxes, then each node box is the union of
// its children's (children come after their parent, so one backward pass does it). A
// node's box contains every box below it in any such tree, so a refitted tree finds
// exactly the overlapping pairs a fresh one finds; it only gets slower when the primitives
// grouped under one node have moved apart. centre_spread() measures that, and the owner
// rebuilds when it has grown.
//
// Each node also knows whether all vertices below it move by one and the same vector
// (standing still included): two subtrees that move together hold no pair that can
// collide (their pairs are rigid), nor does one such subtree with itself. Boxes at rest,
// with no motion known, never move together.

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include "exactgeo/boxes/float_box.hpp"
#include "exactgeo/boxes/morton.hpp"
#include "exactgeo/boxes/packet.hpp"
#include "exactgeo/predicates/point.hpp"

namespace exactgeo::boxes {

/// Every vertex's box and what is known of its motion, as the trees see it: for a CCD
/// step, its swept box and exact displacement (ccd/src/mesh/broad_phase.cpp); at rest,
/// its box alone (at_rest).
struct VertexBoxes {
  std::vector<FloatBox> box;  ///< the vertex's box, in one Scale for all
  /// p_t1 - p_t0 exactly, as its rounded value and the rest (head + tail, TwoDiff: equal
  /// differences have equal heads and tails); empty at rest
  std::vector<Vector3> displacement;
  std::vector<Vector3> displacement_tail;
  /// 0 when the vertex is known to stand still, else 1 (at rest: 1, nothing is known)
  std::vector<std::uint8_t> moving;
  /// A digest of the exact displacement: equal displacements have equal nonzero digests;
  /// 0 when none is known (an overflowing difference, or boxes at rest): the vertex then
  /// moves together with none.
  std::vector<std::uint32_t> motion;

  /// Whether a and b move by one and the same exactly known vector (standing included).
  bool move_together(VertexIndex a, VertexIndex b) const noexcept {
    return motion[a] != 0 && motion[a] == motion[b] && displacement[a] == displacement[b] &&
           displacement_tail[a] == displacement_tail[b];
  }

  /// Boxes of vertices with no motion: every pair of primitives over them counts.
  static VertexBoxes at_rest(std::vector<FloatBox> boxes) {
    VertexBoxes v;
    v.moving.assign(boxes.size(), 1);
    v.motion.assign(boxes.size(), 0);
    v.box = std::move(boxes);
    return v;
  }
};

template <std::size_t N>
class BoxTree {
 public:
  using Corners = std::array<VertexIndex, N>;

  using Leaf = Packet<N>;

  struct Node {
    FloatBox box;
    float extent = 0;         ///< half_perimeter(box), which of two nodes to open first
    std::uint32_t first = 0;  ///< leaf: its Packet; inner node: its right child
    std::uint8_t count = 0;   ///< primitives of a leaf; 0 for an inner node
    /// A vertex whose exact displacement every vertex below shares, or kNoVertex. Pairs
    /// of primitives that all move by one vector (or all stand) are rigid, not candidates.
    VertexIndex together = kNoVertex;

    bool is_leaf() const noexcept { return count > 0; }
  };

  BoxTree() = default;

  /// The tree over `primitives` (primitive i has corners primitives[i]) on this step's boxes.
  BoxTree(std::span<const Corners> primitives, const VertexBoxes& vertices) {
    if (primitives.empty()) return;
    const std::vector<std::uint64_t> order = morton_order(primitives, vertices);
    nodes_.reserve(2 * (primitives.size() / kPacketLanes + 1));
    leaves_.reserve(primitives.size() / (kPacketLanes / 2) + 1);
    build(order, primitives, 0, order.size());
    refit(vertices);
    built_centre_spread_ = centre_spread_;
  }

  /// This step's boxes for the same primitives.
  void refit(const VertexBoxes& vertices) {
    for (Leaf& leaf : leaves_)
      fit_leaf(leaf, vertices);
    fit_nodes(vertices);
  }

  /// The nodes' half-perimeters summed, over the primitives' summed plus the root's: the
  /// walk's work per primitive, roughly, for comparing trees built on the same boxes.
  double looseness() const noexcept {
    double node_sum = 0.0, leaf_sum = 0.0;
    for (const Node& n : nodes_) {
      node_sum += half_perimeter(n.box);
      if (!n.is_leaf()) continue;
      for (std::size_t j = 0; j < n.count; ++j)
        leaf_sum += half_perimeter(leaves_[n.first].box(j));
    }
    const double root = nodes_.empty() ? 0.0 : half_perimeter(nodes_[0].box);
    return leaf_sum + root > 0.0 ? node_sum / (leaf_sum + root) : 0.0;
  }

  /// How far apart the primitives grouped under each node are: the half-perimeters of the
  /// boxes of the primitives' box centres under each node, summed, over the root's. Unlike
  /// looseness() it does not see how large the boxes are (a step's motion changes that
  /// for every tree alike, fresh or refitted), nor motions that move everything alike
  /// (translations, uniform scaling); it grows when primitives kept together by the tree
  /// move apart, which is what makes a refitted tree slower than a fresh one.
  double centre_spread() const noexcept { return centre_spread_; }
  /// centre_spread() when the tree was built.
  double built_centre_spread() const noexcept { return built_centre_spread_; }

  bool empty() const noexcept { return nodes_.empty(); }
  const Node& node(std::uint32_t i) const noexcept { return nodes_[i]; }
  const Leaf& leaf(const Node& n) const noexcept { return leaves_[n.first]; }

 private:
  static FloatBox leaf_box(const Corners& corners, const VertexBoxes& vertices) noexcept {
    FloatBox box = vertices.box[corners[0]];
    for (std::size_t c = 1; c < N; ++c)
      box = united(box, vertices.box[corners[c]]);
    return box;
  }

  /// A box's centre as a box of one point.
  static FloatBox centre_of(const FloatBox& b) noexcept {
    FloatBox c;
    for (int k = 0; k < 3; ++k)
      c.lo[k] = c.hi[k] = b.lo[k] / 2 + b.hi[k] / 2;
    return c;
  }

  /// Each primitive as (Morton code << 32 | index), sorted: by code, ties by index. A
  /// centre that is not finite, or an axis whose centres' spread is not, gives cell 0 (a
  /// worse tree, never a wrong one: any order of the primitives makes a correct tree).
  static std::vector<std::uint64_t> morton_order(std::span<const Corners> primitives,
                                                 const VertexBoxes& vertices) {
    const std::size_t n = primitives.size();
    std::vector<std::array<float, 3>> centre(n);
    std::array<float, 3> lo{}, hi{};
    for (std::size_t i = 0; i < n; ++i) {
      centre[i] = centre_of(leaf_box(primitives[i], vertices)).lo;
      for (int k = 0; k < 3; ++k) {
        lo[k] = i == 0 ? centre[i][k] : std::min(lo[k], centre[i][k]);
        hi[k] = i == 0 ? centre[i][k] : std::max(hi[k], centre[i][k]);
      }
    }
    constexpr float kCells = 1 << kMortonBits;
    std::array<float, 3> cells_per_unit{};
    for (int k = 0; k < 3; ++k) {
      const float spread_k = hi[k] - lo[k];
      cells_per_unit[k] = spread_k > 0 && spread_k < INFINITY ? kCells / spread_k : 0.0f;
    }
    std::vector<std::uint64_t> keys(n);
    for (std::size_t i = 0; i < n; ++i) {
      std::uint32_t code = 0;
      for (int k = 0; k < 3; ++k) {
        const float cell = (centre[i][k] - lo[k]) * cells_per_unit[k];
        const float clamped = cell >= 0 ? std::min(cell, kCells - 1) : 0.0f;  // NaN: cell 0
        code |= morton_spread(static_cast<std::uint32_t>(clamped)) << k;
      }
      keys[i] = std::uint64_t{code} << 32 | i;
    }
    sort_morton_keys(keys);
    return keys;
  }

  /// Makes order[begin, end) (Morton order) a subtree and returns its root's index.
  std::uint32_t build(const std::vector<std::uint64_t>& order, std::span<const Corners> primitives,
                      std::size_t begin, std::size_t end) {
    const auto index = static_cast<std::uint32_t>(nodes_.size());
    nodes_.push_back({});
    if (end - begin <= kPacketLanes) {
      nodes_[index].first = static_cast<std::uint32_t>(leaves_.size());
      nodes_[index].count = static_cast<std::uint8_t>(end - begin);
      Leaf& leaf = leaves_.emplace_back();
      for (std::size_t j = 0; j < kPacketLanes; ++j) {
        const bool used = begin + j < end;
        leaf.id[j] = used ? static_cast<std::uint32_t>(order[begin + j]) : kNoVertex;
        for (std::size_t k = 0; k < N; ++k)
          leaf.corner[k][j] = used ? primitives[leaf.id[j]][k] : kNoVertex;
      }
      return index;
    }
    const std::size_t middle = split(order, begin, end);
    build(order, primitives, begin, middle);  // the left child is index + 1
    nodes_[index].first = build(order, primitives, middle, end);
    return index;
  }

  /// Where to split order[begin, end): the first key whose code has the highest bit in
  /// which the run's codes differ; the middle for a run of one code or of two leaves.
  static std::size_t split(const std::vector<std::uint64_t>& order, std::size_t begin,
                           std::size_t end) noexcept {
    const std::size_t middle = begin + (end - begin) / 2;
    const auto code = [&](std::size_t i) { return static_cast<std::uint32_t>(order[i] >> 32); };
    const std::uint32_t differ = code(begin) ^ code(end - 1);
    if (differ == 0 || end - begin <= 2 * kPacketLanes) return middle;
    const std::uint32_t bit = std::uint32_t{1} << (31 - std::countl_zero(differ));
    // The run shares every bit above `bit`; in Morton order its keys without `bit` come first.
    const auto first = order.begin() + static_cast<std::ptrdiff_t>(begin);
    const auto last = order.begin() + static_cast<std::ptrdiff_t>(end);
    return static_cast<std::size_t>(
        std::partition_point(
            first, last,
            [&](std::uint64_t key) { return (static_cast<std::uint32_t>(key >> 32) & bit) == 0; }) -
        order.begin());
  }

  static void fit_leaf(Leaf& leaf, const VertexBoxes& vertices) noexcept {
    leaf.moving = 0;
    for (std::size_t j = 0; j < kPacketLanes; ++j) {
      if (leaf.id[j] == kNoVertex) {
        leaf.set_box(j, kNoBox);
        continue;
      }
      const Corners corners = leaf.corners(j);
      leaf.set_box(j, leaf_box(corners, vertices));
      bool moving = false;
      std::uint32_t motion = vertices.motion[corners[0]];
      for (const VertexIndex v : corners) {
        moving = moving || vertices.moving[v] != 0;
        if (vertices.motion[v] != motion) motion = 0;
      }
      leaf.moving |= static_cast<unsigned>(moving) << j;
      leaf.motion[j] = motion;
    }
  }

  /// The vertex every corner of the leaf moves together with, or kNoVertex.
  static VertexIndex together(const Leaf& leaf, std::size_t count, const VertexBoxes& vertices) {
    for (std::size_t j = 0; j < count; ++j) {
      if (leaf.motion[j] == 0 || leaf.motion[j] != leaf.motion[0]) return kNoVertex;
    }
    const VertexIndex first = leaf.corner[0][0];
    for (std::size_t j = 0; j < count; ++j) {
      for (std::size_t k = 0; k < N; ++k) {
        if (!vertices.move_together(first, leaf.corner[k][j])) return kNoVertex;
      }
    }
    return first;
  }

  /// Every node's box, extent and `together`, and centre_spread_.
  void fit_nodes(const VertexBoxes& vertices) {
    double hull_sum = 0.0;
    centre_hull_.resize(nodes_.size());
    for (std::size_t i = nodes_.size(); i-- > 0;) {
      Node& n = nodes_[i];
      FloatBox& hull = centre_hull_[i];
      if (n.is_leaf()) {
        const Leaf& p = leaves_[n.first];
        n.box = p.box(0);
        hull = centre_of(n.box);
        for (std::size_t j = 1; j < n.count; ++j) {
          n.box = united(n.box, p.box(j));
          hull = united(hull, centre_of(p.box(j)));
        }
        n.together = together(p, n.count, vertices);
      } else {
        const Node &left = nodes_[i + 1], &right = nodes_[n.first];
        n.box = united(left.box, right.box);
        hull = united(centre_hull_[i + 1], centre_hull_[n.first]);
        const bool same = left.together != kNoVertex && right.together != kNoVertex &&
                          vertices.move_together(left.together, right.together);
        n.together = same ? left.together : kNoVertex;
      }
      n.extent = static_cast<float>(half_perimeter(n.box));
      hull_sum += half_perimeter(hull);
    }
    const double root_hull = nodes_.empty() ? 0.0 : half_perimeter(centre_hull_[0]);
    centre_spread_ = root_hull > 0.0 ? hull_sum / root_hull : 0.0;
  }

  std::vector<Node> nodes_;
  std::vector<Leaf> leaves_;  // one Packet per leaf node
  double centre_spread_ = 0.0;
  double built_centre_spread_ = 0.0;
  std::vector<FloatBox> centre_hull_;  // each node's box of its primitives' centres
};

}  // namespace exactgeo::boxes
