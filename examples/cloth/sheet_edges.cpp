#include "sheet_edges.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <utility>

namespace exactgeo::cloth {

using remesh::Edge;
using remesh::Surface;
using remesh::Triangle;
using remesh::TriangleChanges;
using remesh::VertexIndex;

SheetEdgeTable::SheetEdgeTable(const Surface& s) {
  build(s);
}

/// The triangles' sides are bucketed by their smaller vertex (a counting sort: linear, not
/// a sort of all sides), then paired within each bucket.
void SheetEdgeTable::build(const Surface& s) {
  struct BuildSide {
    VertexIndex other;  // the larger end
    std::size_t triangle;
    bool forward;  // the triangle walks smaller -> larger
  };
  std::vector<std::size_t> first(s.vertices.size() + 1, 0);
  // Which vertices are fixed, a byte each (read three times per triangle), and which
  // triangles are the sheets' (no corner fixed: the obstacles' are), asked once, used twice.
  std::vector<char> fixed(s.vertices.size(), 0);
  for (VertexIndex v = 0; v < s.vertices.size(); ++v)
    fixed[v] = s.is_fixed(v) ? 1 : 0;
  std::vector<char> sheet(s.triangles.size());
  for (std::size_t t = 0; t < s.triangles.size(); ++t) {
    const Triangle& tri = s.triangles[t];
    sheet[t] = (fixed[tri[0]] | fixed[tri[1]] | fixed[tri[2]]) == 0;
    if (!sheet[t]) continue;
    for (int k = 0; k < 3; ++k)
      ++first[std::min(tri[k], tri[(k + 1) % 3]) + 1];
  }
  for (std::size_t v = 1; v < first.size(); ++v)
    first[v] += first[v - 1];
  std::vector<BuildSide> sides(first.back());
  std::vector<std::size_t> next(first.begin(), first.end() - 1);
  for (std::size_t t = 0; t < s.triangles.size(); ++t) {
    const Triangle& tri = s.triangles[t];
    if (!sheet[t]) continue;
    for (int k = 0; k < 3; ++k) {
      const VertexIndex p = tri[k], q = tri[(k + 1) % 3];
      sides[next[std::min(p, q)]++] = {std::max(p, q), t, p < q};
    }
  }
  edges_.clear();
  edges_.reserve(sides.size());
  crowded_ = false;
  for (VertexIndex v = 0; v + 1 < first.size(); ++v) {
    const auto begin = sides.begin() + static_cast<std::ptrdiff_t>(first[v]);
    const auto end = sides.begin() + static_cast<std::ptrdiff_t>(first[v + 1]);
    // By (other, triangle): a bucket is filled in triangle order, so a stable insertion
    // sort by the other end (a bucket holds a few sides) leaves it so.
    for (auto i = begin; i != end; ++i) {
      const BuildSide side = *i;
      auto j = i;
      for (; j != begin && (j - 1)->other > side.other; --j)
        *j = *(j - 1);
      *j = side;
    }
    for (auto i = begin; i != end;) {
      auto j = i + 1;
      while (j != end && j->other == i->other)
        ++j;
      SheetEdge e = i->forward ? SheetEdge{v, i->other, i->triangle, std::nullopt}
                               : SheetEdge{i->other, v, i->triangle, std::nullopt};
      if (j == i + 2) e.right = (i + 1)->triangle;
      if (j - i <= 2) edges_.push_back(e);
      crowded_ = crowded_ || j - i > 2;
      i = j;
    }
  }
}

// The patch. An edge none of whose triangles changed keeps them (renumbered past the
// removed triangles), so its entry stands; the entry of an edge of a changed triangle (its
// corners before the pass or after) is made again from its triangles after the pass: those
// of its old entry that did not change, and the changed ones that have the edge now. The
// old entry holds all of the first kind unless the edge had more than two sheet triangles
// (left out of the table: `crowded_`, where the table is built again), and an edge without
// an entry had none. The entries stay in the order of their ends, as a build's: the old
// ones and the remade ones are merged, both in that order.
bool SheetEdgeTable::update(const Surface& after, const TriangleChanges& changes,
                            std::vector<VertexIndex>& touched) {
  touched.clear();
  if (crowded_) {
    build(after);
    return false;
  }
  // Fixed flags belong to vertices, which a pass only appends (none fixed), so a triangle
  // is the sheets' by the same flags before and after it.
  const auto sheet = [&](const Triangle& t) {
    return !after.is_fixed(t[0]) && !after.is_fixed(t[1]) && !after.is_fixed(t[2]);
  };
  const auto key_of = [](VertexIndex p, VertexIndex q) {
    return p < q ? std::uint64_t{p} << 32 | q : std::uint64_t{q} << 32 | p;
  };
  old_keys_.clear();
  keys_.clear();
  sides_.clear();
  changed_.assign(changes.triangles_before, 0);
  const auto add_keys = [&](const Triangle& t) {
    if (!sheet(t)) return;
    for (int k = 0; k < 3; ++k)
      old_keys_.push_back(key_of(t[k], t[(k + 1) % 3]));
  };
  const auto add_sides = [&](std::size_t index) {
    const Triangle& t = after.triangles[index];
    if (!sheet(t)) return;
    for (int k = 0; k < 3; ++k)
      sides_.push_back({key_of(t[k], t[(k + 1) % 3]), index});
  };
  for (const TriangleChanges::Was& w : changes.removed) {
    changed_[w.triangle] = 1;
    add_keys(w.corners);
  }
  for (const TriangleChanges::Was& w : changes.rewritten) {
    changed_[w.triangle] = 1;
    add_keys(w.corners);
    add_sides(changes.index_after(w.triangle));
  }
  for (std::size_t t = changes.first_added(); t < after.triangles.size(); ++t)
    add_sides(t);
  // The sides by edge, then triangle; the keys: the edges before and after, once each, in
  // order.
  std::sort(sides_.begin(), sides_.end(), [](const Side& x, const Side& y) {
    return x.edge != y.edge ? x.edge < y.edge : x.triangle < y.triangle;
  });
  std::sort(old_keys_.begin(), old_keys_.end());
  old_keys_.erase(std::unique(old_keys_.begin(), old_keys_.end()), old_keys_.end());
  // Merged with the sides' edges, which are in order already (the sort of the keys alone
  // is the smaller one).
  auto old_key = old_keys_.begin();
  for (const Side& side : sides_) {
    if (!keys_.empty() && keys_.back() == side.edge) continue;
    for (; old_key != old_keys_.end() && *old_key < side.edge; ++old_key)
      keys_.push_back(*old_key);
    if (old_key != old_keys_.end() && *old_key == side.edge) ++old_key;
    keys_.push_back(side.edge);
  }
  keys_.insert(keys_.end(), old_key, old_keys_.end());

  // Each triangle's index after the pass, when the pass removed some.
  const bool renumbered = !changes.removed.empty();
  if (renumbered) {
    after_.resize(changes.triangles_before);
    std::size_t below = 0;  // removed triangles below t
    for (std::size_t t = 0; t < changes.triangles_before; ++t) {
      if (below < changes.removed.size() && changes.removed[below].triangle == t) {
        ++below;
        continue;
      }
      after_[t] = t - below;
    }
  }
  const auto renumber = [&](std::size_t t) { return renumbered ? after_[t] : t; };

  next_.clear();
  next_.reserve(edges_.size() + sides_.size() / 2);
  auto side = sides_.begin();
  const auto remake = [&](std::uint64_t key, const SheetEdge* old) {
    const auto p = static_cast<VertexIndex>(key >> 32), q = static_cast<VertexIndex>(key);
    touched.push_back(p);
    touched.push_back(q);
    std::array<std::size_t, 2> found{};
    std::size_t count = 0;
    const auto add = [&](std::size_t t) {
      if (count < found.size()) found[count] = t;
      ++count;
    };
    if (old != nullptr) {
      if (!changed_[old->left]) add(renumber(old->left));
      if (old->right && !changed_[*old->right]) add(renumber(*old->right));
    }
    for (; side != sides_.end() && side->edge == key; ++side)
      add(side->triangle);
    if (count == 0) return;  // the edge is gone
    if (count > 2) {         // left out, as a build leaves it
      crowded_ = true;
      return;
    }
    if (count == 2 && found[1] < found[0]) std::swap(found[0], found[1]);
    // The triangle of smaller index names the edge's direction, as in a build.
    SheetEdge e = remesh::walks(after.triangles[found[0]], p, q)
                      ? SheetEdge{p, q, found[0], std::nullopt}
                      : SheetEdge{q, p, found[0], std::nullopt};
    if (count == 2) e.right = found[1];
    next_.push_back(e);
  };
  // The entries between two remade ones are copied in a run, each remade one found from
  // the last by a galloping search (the keys are sorted, as the table is).
  const auto key_at = [&](std::size_t i) { return key_of(edges_[i].a, edges_[i].b); };
  const auto copy_to = [&](std::size_t from, std::size_t to) {
    const std::size_t start = next_.size();
    next_.insert(next_.end(), edges_.begin() + static_cast<std::ptrdiff_t>(from),
                 edges_.begin() + static_cast<std::ptrdiff_t>(to));
    if (!renumbered) return;
    for (std::size_t i = start; i < next_.size(); ++i) {
      SheetEdge& e = next_[i];
      e.left = after_[e.left];
      if (e.right) e.right = after_[*e.right];
    }
  };
  std::size_t at = 0;  // the first entry not copied or remade
  for (const std::uint64_t key : keys_) {
    // The first entry from `at` on whose key is not below `key`: past `at + step - 1`
    // while the key there is below, then a binary search of the last step.
    std::size_t low = at, step = 1;
    while (low + step <= edges_.size() && key_at(low + step - 1) < key) {
      low += step;
      step *= 2;
    }
    const auto first = std::partition_point(
        edges_.begin() + static_cast<std::ptrdiff_t>(low),
        edges_.begin() + static_cast<std::ptrdiff_t>(std::min(low + step, edges_.size())),
        [&](const SheetEdge& e) { return key_of(e.a, e.b) < key; });
    const auto found = static_cast<std::size_t>(first - edges_.begin());
    copy_to(at, found);
    if (found < edges_.size() && key_at(found) == key) {
      remake(key, &edges_[found]);
      at = found + 1;
    } else {
      remake(key, nullptr);
      at = found;
    }
  }
  copy_to(at, edges_.size());
  edges_.swap(next_);
  return true;
}

void SheetEdgeTable::renumber(std::span<const VertexIndex> vertex,
                              std::span<const std::size_t> triangle) {
  for (SheetEdge& e : edges_) {
    e.a = vertex[e.a];
    e.b = vertex[e.b];
    e.left = triangle[e.left];
    if (e.right) e.right = triangle[*e.right];
  }
}

}  // namespace exactgeo::cloth
