// relocate_vertex and relocate_vertices: vertices moved on straight lines, a smoothing pass
// as one pseudo-motion through the mesh broad phase (a single relocation is a pass of one).

#include <cmath>
#include <limits>
#include <vector>

#include "exactgeo/ccd/mesh/mesh_ccd.hpp"
#include "exactgeo/predicates/orient3d.hpp"
#include "exactgeo/predicates/segment_triangle.hpp"
#include "exactgeo/remesh/operations.hpp"
#include "operation_checks.hpp"

namespace exactgeo::remesh {

namespace {

constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

class Pass {
 public:
  Pass(const Surface& surface, std::span<const Move> moves)
      : surface_(surface),
        moves_(moves),
        outcomes_(moves.size()),
        move_of_(surface.vertices.size(), kNone) {}

  std::vector<Outcome> run(Surface& surface) {
    check_each();
    refuse_zero_area();
    refuse_collisions();
    surface.vertices = targets();
    return std::move(outcomes_);
  }

 private:
  bool live(std::size_t i) const { return outcomes_[i].applied(); }

  void refuse(std::size_t i, Verdict verdict, std::string reason,
              std::optional<Blocker> blocker = std::nullopt) {
    if (!live(i)) return;
    outcomes_[i] = {verdict, std::move(reason), blocker, std::nullopt};
    move_of_[moves_[i].vertex] = kNone;
  }

  /// The vertices' positions with every live move made.
  std::vector<Point3> targets() const {
    std::vector<Point3> p = surface_.vertices;
    for (std::size_t i = 0; i < moves_.size(); ++i) {
      if (live(i)) p[moves_[i].vertex] = moves_[i].to;
    }
    return p;
  }

  void check_each() {
    std::vector<bool> used(surface_.vertices.size());
    for (const Triangle& t : surface_.triangles) {
      for (const VertexIndex v : t)
        used[v] = true;
    }
    for (std::size_t i = 0; i < moves_.size(); ++i) {
      const VertexIndex v = moves_[i].vertex;
      const std::string name = "vertex " + std::to_string(v);
      const Point3& to = moves_[i].to;
      if (v >= surface_.vertices.size()) {
        outcomes_[i] = {Verdict::refused_topology, name + " does not exist", {}, {}};
      } else if (surface_.is_fixed(v)) {
        outcomes_[i] = {Verdict::refused_topology, name + " is fixed", {}, {}};
      } else if (!used[v]) {
        outcomes_[i] = {Verdict::refused_topology, name + " is used by no triangle", {}, {}};
      } else if (!std::isfinite(to[0]) || !std::isfinite(to[1]) || !std::isfinite(to[2])) {
        outcomes_[i] = {Verdict::refused_topology, "the new position is not finite", {}, {}};
      } else if (move_of_[v] != kNone) {
        outcomes_[i] = {Verdict::refused_topology, name + " is moved twice", {}, {}};
      } else {
        move_of_[v] = i;
      }
    }
  }

  /// Refuses the moves at the corners of every triangle they would flatten, until none
  /// does (a move refused puts its vertex back, which can flatten another triangle whose
  /// other corners move; the triangles as they are have area).
  void refuse_zero_area() {
    for (bool refused = true; refused;) {
      refused = false;
      const std::vector<Point3> p = targets();
      for (const Triangle& t : surface_.triangles) {
        if (!collinear(p[t[0]], p[t[1]], p[t[2]])) continue;
        for (const VertexIndex c : t) {
          if (move_of_[c] == kNone) continue;
          refuse(move_of_[c], Verdict::refused_topology,
                 "a triangle around vertex " + std::to_string(c) + " would have zero area");
          refused = true;
        }
      }
    }
  }

  void refuse_collisions() {
    ccd::MeshCcd mesh_ccd(surface_.vertices.size(), surface_.triangles);
    const std::vector<double> t0 = ccd::flat_positions(surface_.vertices);
    for (;;) {
      const std::vector<double> t1 = ccd::flat_positions(targets());
      const ccd::MeshCcdResult step = mesh_ccd.step({t0, t1});
      if (!step.collision()) return;
      const auto hit = [&](VertexIndex v, const Blocker& blocker) {
        if (move_of_[v] == kNone) return;
        refuse(move_of_[v], Verdict::refused_collision,
               "moving vertex " + std::to_string(v) + " would meet " + to_string(blocker), blocker);
      };
      for (const ccd::VertexFacePair& pair : step.vertex_face) {
        const Triangle& t = surface_.triangles[pair.face];
        hit(pair.vertex, {Blocker::Kind::triangle, t});
        for (const VertexIndex c : t)
          hit(c, {Blocker::Kind::vertex, {pair.vertex, kNoVertex, kNoVertex}});
      }
      for (const ccd::EdgeEdgePair& pair : step.edge_edge) {
        const Blocker a{Blocker::Kind::edge, {pair.a[0], pair.a[1], kNoVertex}};
        const Blocker b{Blocker::Kind::edge, {pair.b[0], pair.b[1], kNoVertex}};
        for (const VertexIndex v : pair.a)
          hit(v, b);
        for (const VertexIndex v : pair.b)
          hit(v, a);
      }
    }
  }

  const Surface& surface_;
  std::span<const Move> moves_;
  std::vector<Outcome> outcomes_;
  std::vector<std::size_t> move_of_;  ///< per vertex: its live move, or kNone
};

}  // namespace

std::vector<Outcome> relocate_vertices(Surface& surface, std::span<const Move> moves) {
  return Pass(surface, moves).run(surface);
}

Outcome relocate_vertex(Surface& surface, VertexIndex v, const Point3& to) {
  // A pass of one move: the same checks, one code path.
  const Move move{v, to};
  return relocate_vertices(surface, std::span(&move, 1)).front();
}

}  // namespace exactgeo::remesh
