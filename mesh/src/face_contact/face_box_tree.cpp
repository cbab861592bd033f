#include "face_box_tree.hpp"

#include <algorithm>
#include <cstddef>

namespace exactgeo::mesh::face_contact_detail {

namespace {

Aabb merged(const Aabb& a, const Aabb& b) noexcept {
  Aabb m = a;
  for (std::size_t k = 0; k < 3; ++k) {
    m.lower[k] = std::min(m.lower[k], b.lower[k]);
    m.upper[k] = std::max(m.upper[k], b.upper[k]);
  }
  return m;
}

}  // namespace

Aabb box_of(const Mesh& mesh, const Face& face) noexcept {
  Aabb box{mesh.vertices[face.corners[0]], mesh.vertices[face.corners[0]]};
  for (std::size_t i = 1; i < face.size(); ++i) {
    const Point3& p = mesh.vertices[face.corners[i]];
    for (std::size_t k = 0; k < 3; ++k) {
      box.lower[k] = std::min(box.lower[k], p[k]);
      box.upper[k] = std::max(box.upper[k], p[k]);
    }
  }
  return box;
}

std::size_t BoxTree::build(std::size_t begin, std::size_t end) {
  const std::size_t index = nodes_.size();
  nodes_.push_back({boxes_[items_[begin]], begin, end});
  Aabb centres{centre(items_[begin]), centre(items_[begin])};
  for (std::size_t i = begin + 1; i < end; ++i) {
    nodes_[index].box = merged(nodes_[index].box, boxes_[items_[i]]);
    centres = merged(centres, Aabb{centre(items_[i]), centre(items_[i])});
  }
  if (end - begin <= kLeafSize) return index;
  std::size_t axis = 0;
  for (std::size_t k = 1; k < 3; ++k)
    if (centres.upper[k] - centres.lower[k] > centres.upper[axis] - centres.lower[axis]) axis = k;
  const std::size_t middle = begin + (end - begin) / 2;
  std::nth_element(items_.begin() + static_cast<std::ptrdiff_t>(begin),
                   items_.begin() + static_cast<std::ptrdiff_t>(middle),
                   items_.begin() + static_cast<std::ptrdiff_t>(end),
                   [&](std::size_t x, std::size_t y) { return centre(x)[axis] < centre(y)[axis]; });
  const std::size_t left = build(begin, middle);
  const std::size_t right = build(middle, end);
  nodes_[index].left = left;
  nodes_[index].right = right;
  return index;
}

}  // namespace exactgeo::mesh::face_contact_detail
