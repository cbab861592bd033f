// The mesh CCD broad phase against the broad phases people use, on the same boxes
// (scripts/broad-phase-peers.py runs it over the Spot meshes and the cloth steps).
//
//   broad_phase_peers FRAME0 [FRAME1] [--motion A] [--seed S] [--threads T] [--repeat R]
//                     [--peers exactgeo,cgal,fcl,bullet,embree] [--scene NAME]
//                     [--max-seconds S] [--bullet-margin M]
//
// Two steps: FRAME0 moved by A mean edge lengths at most per coordinate (uniform, seeded
// with S; default 0.2), or FRAME0 to FRAME1; then the first step's t1 moved on by a new
// random motion (seed S + 1). Quads are split into two triangles (bench/mesh_step.hpp).
//
// Every peer gets exactly exactgeo's boxes: each vertex's swept box rounded outward to
// float in the step's scale, made by the library's own sweep (ccd::internal::sweep_vertices),
// each edge's and face's the union of its corners' boxes, closed. Every pair a peer reports
// goes through one rule (keep_vertex_face, keep_edge_edge): no shared vertex, not rigid
// (every corner of both primitives moves by exactly the same p_t1 - p_t0, standing still
// included: boxes::VertexBoxes::move_together), as MeshBroadPhase decides. Its sorted pairs are
// then compared with MeshBroadPhase's (vertex-face as (vertex, face), edge-edge as (smaller,
// larger) index into the sorted unique edges).
//
// Times, best of R runs (fewer once a peer has spent --max-seconds, default 20), each on
// steady_clock:
//   one_shot    building the peer's structure from the boxes, its query and the filtered
//               pairs collected; the boxes themselves and the displacements are made
//               before the clock starts. exactgeo's is MeshBroadPhase's construction and
//               first candidates() call, which sweeps (makes the boxes) itself.
//   step_after  the second step on the structure of the first, updated the peer's own
//               incremental way, and its query. CGAL keeps nothing between steps: its
//               step_after is a one-shot run on the second step.
// CGAL, FCL and Bullet are single-threaded and run only with --threads 1; Embree's device
// gets threads=T, exactgeo T threads.
//
// Prints one JSON object per peer (stdout) and whether its pairs are exactgeo's on each
// step (stderr).

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "exactgeo/boxes/float_box.hpp"
#include "exactgeo/predicates/kernel/unit_magnitude.hpp"
#include "exactgeo/ccd/mesh/internal/broad_phase.hpp"
#include "exactgeo/ccd/mesh/mesh_ccd.hpp"
#include "mesh_step.hpp"

#if defined(EXACTGEO_PEER_CGAL)
#include <CGAL/Box_intersection_d/Box_with_info_d.h>
#include <CGAL/box_intersection_d.h>
#endif
#if defined(EXACTGEO_PEER_FCL)
#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/narrowphase/collision_object.h>
#endif
#if defined(EXACTGEO_PEER_BULLET)
#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletCollision/CollisionDispatch/btDefaultCollisionConfiguration.h>
#include <LinearMath/btAabbUtil2.h>
#endif
#if defined(EXACTGEO_PEER_EMBREE)
#include <embree3/rtcore.h>
#endif

namespace {

using namespace exactgeo;
using boxes::FloatBox;
using ccd::Edge;
using ccd::Triangle;
using ccd::VertexFacePair;
using ccd::bench::MeshStep;
using ccd::internal::EdgeIndexPair;

// ---------------------------------------------------------------------------------------
// The step: its boxes and the rule for its pairs, shared by every peer.

struct MeshView {
  std::size_t vertex_count = 0;
  std::span<const Triangle> faces;
  std::span<const Edge> edges;  ///< sorted, unique (MeshCcd::edges)
};

struct Step {
  MeshView mesh;
  ccd::StepPositions positions;
  double largest = 0.0;  ///< the largest magnitude of both frames
  /// Each vertex's swept box and exact displacement, made as the library's broad phase
  /// makes them (MeshBroadPhase's own sweep).
  boxes::VertexBoxes swept;
  std::vector<FloatBox> edge, face;
};

template <std::size_t N>
FloatBox primitive_box(const std::array<VertexIndex, N>& corners,
                       const std::vector<FloatBox>& vertex) {
  FloatBox box = vertex[corners[0]];
  for (std::size_t c = 1; c < N; ++c)
    box = boxes::united(box, vertex[corners[c]]);
  return box;
}

Step make_step(const MeshView& mesh, const MeshStep& mesh_step) {
  Step s;
  s.mesh = mesh;
  s.positions = {mesh_step.t0, mesh_step.t1};
  s.largest = std::max(kernel::largest_magnitude(mesh_step.t0),
                       kernel::largest_magnitude(mesh_step.t1));
  ccd::internal::sweep_vertices(s.positions, s.largest, 0.0, 1, s.swept);
  for (const Edge& e : mesh.edges)
    s.edge.push_back(primitive_box(e, s.swept.box));
  for (const Triangle& f : mesh.faces)
    s.face.push_back(primitive_box(f, s.swept.box));
  return s;
}

/// Whether every corner of both primitives moves with the first (standing still included).
template <std::size_t NA, std::size_t NB>
bool rigid(const Step& s, const std::array<VertexIndex, NA>& a,
           const std::array<VertexIndex, NB>& b) noexcept {
  for (const VertexIndex v : a)
    if (!s.swept.move_together(a[0], v)) return false;
  for (const VertexIndex v : b)
    if (!s.swept.move_together(a[0], v)) return false;
  return true;
}

template <std::size_t NA, std::size_t NB>
bool share_corner(const std::array<VertexIndex, NA>& a,
                  const std::array<VertexIndex, NB>& b) noexcept {
  for (const VertexIndex u : a)
    for (const VertexIndex v : b)
      if (u == v) return true;
  return false;
}

bool adjacent_vertex_face(const MeshView& m, std::uint32_t v, std::uint32_t f) noexcept {
  return share_corner(std::array<VertexIndex, 1>{v}, m.faces[f]);
}

bool adjacent_edges(const MeshView& m, std::uint32_t a, std::uint32_t b) noexcept {
  return share_corner(m.edges[a], m.edges[b]);
}

/// The rule for every peer's vertex-face pair whose boxes overlap.
bool keep_vertex_face(const Step& s, std::uint32_t v, std::uint32_t f) noexcept {
  return !adjacent_vertex_face(s.mesh, v, f) &&
         !rigid(s, std::array<VertexIndex, 1>{v}, s.mesh.faces[f]);
}

/// The rule for every peer's edge-edge pair (a != b) whose boxes overlap.
bool keep_edge_edge(const Step& s, std::uint32_t a, std::uint32_t b) noexcept {
  return !adjacent_edges(s.mesh, a, b) && !rigid(s, s.mesh.edges[a], s.mesh.edges[b]);
}

// ---------------------------------------------------------------------------------------
// Pairs and peers.

struct Pairs {
  std::vector<VertexFacePair> vertex_face;
  std::vector<EdgeIndexPair> edge_edge;
  /// Pairs the peer handed over before the rule (and, for Bullet and Embree, before the
  /// box test): what a user's callback sees.
  std::size_t reported = 0;

  void add_vertex_face(const Step& s, std::uint32_t v, std::uint32_t f) {
    if (keep_vertex_face(s, v, f)) vertex_face.push_back({v, f});
  }
  void add_edge_edge(const Step& s, std::uint32_t a, std::uint32_t b) {
    if (keep_edge_edge(s, a, b)) edge_edge.push_back({std::min(a, b), std::max(a, b)});
  }
  std::size_t size() const noexcept { return vertex_face.size() + edge_edge.size(); }
};

/// Both kinds sorted, for comparing sets.
std::vector<std::array<std::uint32_t, 3>> sorted(const Pairs& p) {
  std::vector<std::array<std::uint32_t, 3>> out;
  out.reserve(p.size());
  for (const VertexFacePair& q : p.vertex_face)
    out.push_back({0, q.vertex, q.face});
  for (const EdgeIndexPair& q : p.edge_edge)
    out.push_back({1, q.a, q.b});
  std::sort(out.begin(), out.end());
  return out;
}

class Peer {
 public:
  virtual ~Peer() = default;
  /// Builds the structure on the first step's boxes and finds its pairs.
  virtual Pairs first(const Step& step) = 0;
  /// Updates the structure to the next step's boxes its own way and finds their pairs.
  virtual Pairs next(const Step& step) = 0;
  /// Whether the boxes inside the peer are exactly the step's (checked after a query).
  virtual bool boxes_exact(const Step&) const { return true; }
  /// Peer-specific JSON fields of the last query, each as `, "key": value`.
  virtual std::string json_fields() const { return ""; }
};

const char* boolean(bool b) {
  return b ? "true" : "false";
}

// exactgeo: MeshBroadPhase, built on the first step, refitted (or rebuilt when too loose)
// on the next.
class ExactgeoPeer : public Peer {
 public:
  explicit ExactgeoPeer(unsigned threads) : threads_(threads) {}
  Pairs first(const Step& s) override {
    broad_phase_.emplace(s.mesh.vertex_count, s.mesh.faces, s.mesh.edges);
    return candidates(s);
  }
  Pairs next(const Step& s) override { return candidates(s); }
  std::string json_fields() const override {
    return std::string(", \"rebuilt_on_step_after\": ") + boolean(rebuilt_);
  }

 private:
  Pairs candidates(const Step& s) {
    ccd::internal::MeshCandidates c = broad_phase_->candidates(s.positions, s.largest, threads_);
    rebuilt_ = c.trees_rebuilt;
    Pairs p{std::move(c.vertex_face), std::move(c.edge_edge), 0};
    p.reported = p.size();
    return p;
  }
  unsigned threads_;
  std::optional<ccd::internal::MeshBroadPhase> broad_phase_;
  bool rebuilt_ = false;
};

#if defined(EXACTGEO_PEER_CGAL)
// CGAL: box_intersection_d (vertices against faces) and box_self_intersection_d (edges),
// closed boxes, single-precision coordinates; nothing is kept between calls.
using CgalBox = CGAL::Box_intersection_d::Box_with_info_d<float, 3, std::uint32_t>;

std::vector<CgalBox> cgal_boxes(const std::vector<FloatBox>& boxes) {
  std::vector<CgalBox> out;
  out.reserve(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    float lo[3] = {boxes[i].lo[0], boxes[i].lo[1], boxes[i].lo[2]};
    float hi[3] = {boxes[i].hi[0], boxes[i].hi[1], boxes[i].hi[2]};
    out.emplace_back(lo, hi, static_cast<std::uint32_t>(i));
  }
  return out;
}

class CgalPeer : public Peer {
 public:
  Pairs first(const Step& s) override {
    std::vector<CgalBox> vertices = cgal_boxes(s.swept.box), faces = cgal_boxes(s.face),
                         edges = cgal_boxes(s.edge);
    Pairs p;
    constexpr std::ptrdiff_t kCutoff = 10;  // CGAL's default
    CGAL::box_intersection_d(
        vertices.begin(), vertices.end(), faces.begin(), faces.end(),
        [&](const CgalBox& v, const CgalBox& f) {
          ++p.reported;
          p.add_vertex_face(s, v.info(), f.info());
        },
        kCutoff, CGAL::Box_intersection_d::CLOSED, CGAL::Box_intersection_d::BIPARTITE);
    CGAL::box_self_intersection_d(
        edges.begin(), edges.end(),
        [&](const CgalBox& a, const CgalBox& b) {
          ++p.reported;
          p.add_edge_edge(s, a.info(), b.info());
        },
        kCutoff, CGAL::Box_intersection_d::CLOSED);
    return p;
  }
  Pairs next(const Step& s) override { return first(s); }
};
#endif

#if defined(EXACTGEO_PEER_FCL) || defined(EXACTGEO_PEER_BULLET)
// Primitives of all kinds by one id (the kind in the low two bits), for peers that hold
// them together as user data (FCL, Bullet).
enum class Kind : std::uint8_t { vertex, face, edge };

struct PrimitiveId {
  Kind kind;
  std::uint32_t index;
};

std::uintptr_t encode(Kind kind, std::size_t index) noexcept {
  return (static_cast<std::uintptr_t>(index) << 2) | static_cast<std::uintptr_t>(kind);
}

PrimitiveId decode(const void* user) noexcept {
  const auto bits = reinterpret_cast<std::uintptr_t>(user);
  return {static_cast<Kind>(bits & 3u), static_cast<std::uint32_t>(bits >> 2)};
}

/// A pair of primitives by id, of any kind and order: the rule, then into `p`.
void add_pair(const Step& s, PrimitiveId a, PrimitiveId b, Pairs& p) {
  if (a.kind == Kind::face) std::swap(a, b);
  if (a.kind == Kind::vertex && b.kind == Kind::face)
    p.add_vertex_face(s, a.index, b.index);
  else if (a.kind == Kind::edge && b.kind == Kind::edge)
    p.add_edge_edge(s, a.index, b.index);
}
#endif

#if defined(EXACTGEO_PEER_FCL)
// FCL: one DynamicAABBTreeCollisionManager per kind of primitive; each primitive a
// CollisionObject with identity transform whose geometry's local AABB is the box (so
// computeAABB gives it exactly). Vertices against faces by collide(other_manager), edges
// by collide() within their manager. The next step: new local AABBs, computeAABB, and the
// managers' update() (refit, rebalanced when too unbalanced).
using FclObject = fcl::CollisionObject<double>;
using FclManager = fcl::DynamicAABBTreeCollisionManager<double>;

fcl::AABB<double> fcl_box(const FloatBox& b) {
  return {fcl::Vector3<double>(b.lo[0], b.lo[1], b.lo[2]),
          fcl::Vector3<double>(b.hi[0], b.hi[1], b.hi[2])};
}

class FclPeer : public Peer {
 public:
  Pairs first(const Step& s) override {
    make(vertices_, s.swept.box, Kind::vertex);
    make(faces_, s.face, Kind::face);
    make(edges_, s.edge, Kind::edge);
    return query(s);
  }
  Pairs next(const Step& s) override {
    update(vertices_, s.swept.box);
    update(faces_, s.face);
    update(edges_, s.edge);
    return query(s);
  }
  bool boxes_exact(const Step& s) const override {
    return exact(vertices_, s.swept.box) && exact(faces_, s.face) && exact(edges_, s.edge);
  }

 private:
  struct Set {
    std::vector<std::shared_ptr<fcl::Box<double>>> shapes;
    std::vector<std::unique_ptr<FclObject>> objects;
    std::unique_ptr<FclManager> manager;
  };
  struct Query {
    const Step* step;
    Pairs* pairs;
  };

  static void make(Set& set, const std::vector<FloatBox>& boxes, Kind kind) {
    set.shapes.resize(boxes.size());
    set.objects.resize(boxes.size());
    std::vector<FclObject*> objects(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      set.shapes[i] = std::make_shared<fcl::Box<double>>(0.0, 0.0, 0.0);
      set.objects[i] = std::make_unique<FclObject>(set.shapes[i]);
      set.shapes[i]->aabb_local = fcl_box(boxes[i]);
      set.objects[i]->computeAABB();
      set.objects[i]->setUserData(reinterpret_cast<void*>(encode(kind, i)));
      objects[i] = set.objects[i].get();
    }
    set.manager = std::make_unique<FclManager>();
    set.manager->registerObjects(objects);
    set.manager->setup();
  }

  static void update(Set& set, const std::vector<FloatBox>& boxes) {
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      set.shapes[i]->aabb_local = fcl_box(boxes[i]);
      set.objects[i]->computeAABB();
    }
    set.manager->update();
  }

  static bool exact(const Set& set, const std::vector<FloatBox>& boxes) {
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      const fcl::AABB<double>& b = set.objects[i]->getAABB();
      for (int k = 0; k < 3; ++k)
        if (b.min_[k] != boxes[i].lo[k] || b.max_[k] != boxes[i].hi[k]) return false;
    }
    return true;
  }

  static bool on_pair(FclObject* a, FclObject* b, void* data) {
    auto* q = static_cast<Query*>(data);
    ++q->pairs->reported;
    add_pair(*q->step, decode(a->getUserData()), decode(b->getUserData()), *q->pairs);
    return false;  // never stop
  }

  Pairs query(const Step& s) {
    Pairs p;
    Query q{&s, &p};
    vertices_.manager->collide(faces_.manager.get(), &q, on_pair);
    edges_.manager->collide(&q, on_pair);
    return p;
  }

  Set vertices_, faces_, edges_;
};
#endif

#if defined(EXACTGEO_PEER_BULLET)
// Bullet: one btDbvtBroadphase holding every primitive as a proxy with its box; collision
// filter groups let only vertices meet faces and edges meet edges, and an overlap filter
// callback drops adjacent pairs before they enter the pair cache. The pair cache is
// persistent and conservative (a proxy's tree volume grows but never shrinks while its box
// stays inside it, and stale pairs are removed a few per call), so the step's pairs are
// read from it and kept when the proxies' current boxes overlap (TestAabbAgainstAabb2,
// closed) and the rule keeps them; rigidity changes from step to step, so it is decided
// there, not in the filter callback. The next step: setAabb per proxy, then
// calculateOverlappingPairs (its incremental update). A proxy whose new box leaves its tree
// volume is reinserted with the volume grown by gDbvtMargin on each side: Bullet's default,
// 0.05, is meant for scenes in metres; in the boxes' scale (coordinates below 1 in
// magnitude, edges of 1e-3 to 1e-2) it holds dozens of neighbours, so it is set here
// (--bullet-margin, default 0: the swept boxes cover the step's motion already).
class BulletPeer : public Peer {
 public:
  explicit BulletPeer(double margin) : dispatcher_(&configuration_) {
    gDbvtMargin = static_cast<btScalar>(margin);
  }
  BulletPeer(const BulletPeer&) = delete;
  BulletPeer& operator=(const BulletPeer&) = delete;
  ~BulletPeer() override {
    broad_phase_.reset();  // the broad phase frees its trees and pair cache, not its proxies
    for (btBroadphaseProxy* proxy : proxies_)
      btAlignedFree(proxy);
  }

  Pairs first(const Step& s) override {
    filter_.mesh = s.mesh;
    broad_phase_ = std::make_unique<btDbvtBroadphase>();
    broad_phase_->getOverlappingPairCache()->setOverlapFilterCallback(&filter_);
    add(s.swept.box, Kind::vertex);
    add(s.face, Kind::face);
    add(s.edge, Kind::edge);
    broad_phase_->calculateOverlappingPairs(&dispatcher_);
    return read(s);
  }
  Pairs next(const Step& s) override {
    std::size_t i = 0;
    for (const auto* boxes : {&s.swept.box, &s.face, &s.edge})
      for (const FloatBox& b : *boxes)
        broad_phase_->setAabb(proxies_[i++], low(b), high(b), &dispatcher_);
    broad_phase_->calculateOverlappingPairs(&dispatcher_);
    return read(s);
  }
  std::string json_fields() const override {
    return ", \"margin\": " + std::to_string(static_cast<double>(gDbvtMargin));
  }
  bool boxes_exact(const Step& s) const override {
    std::size_t i = 0;
    for (const auto* boxes : {&s.swept.box, &s.face, &s.edge}) {
      for (const FloatBox& b : *boxes) {
        const btBroadphaseProxy* p = proxies_[i++];
        if (!(p->m_aabbMin == low(b)) || !(p->m_aabbMax == high(b))) return false;
      }
    }
    return true;
  }

 private:
  // Collision filter groups and masks: vertices meet faces, edges meet edges.
  static constexpr int kVertexGroup = 1, kFaceGroup = 2, kEdgeGroup = 4;

  struct AdjacencyFilter : btOverlapFilterCallback {
    MeshView mesh;
    bool needBroadphaseCollision(btBroadphaseProxy* a, btBroadphaseProxy* b) const override {
      if ((a->m_collisionFilterGroup & b->m_collisionFilterMask) == 0 ||
          (b->m_collisionFilterGroup & a->m_collisionFilterMask) == 0)
        return false;
      PrimitiveId p = decode(a->m_clientObject), q = decode(b->m_clientObject);
      if (p.kind == Kind::face) std::swap(p, q);
      if (p.kind == Kind::edge) return !adjacent_edges(mesh, p.index, q.index);
      return !adjacent_vertex_face(mesh, p.index, q.index);
    }
  };

  static btVector3 low(const FloatBox& b) { return {b.lo[0], b.lo[1], b.lo[2]}; }
  static btVector3 high(const FloatBox& b) { return {b.hi[0], b.hi[1], b.hi[2]}; }

  void add(const std::vector<FloatBox>& boxes, Kind kind) {
    const int group = kind == Kind::vertex ? kVertexGroup
                      : kind == Kind::face ? kFaceGroup
                                           : kEdgeGroup;
    const int mask = kind == Kind::vertex ? kFaceGroup
                     : kind == Kind::face ? kVertexGroup
                                          : kEdgeGroup;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      proxies_.push_back(broad_phase_->createProxy(
          low(boxes[i]), high(boxes[i]), BOX_SHAPE_PROXYTYPE,
          reinterpret_cast<void*>(encode(kind, i)), group, mask, &dispatcher_));
    }
  }

  Pairs read(const Step& s) const {
    Pairs p;
    const btBroadphasePairArray& pairs =
        broad_phase_->getOverlappingPairCache()->getOverlappingPairArray();
    p.reported = static_cast<std::size_t>(pairs.size());
    for (int i = 0; i < pairs.size(); ++i) {
      const btBroadphaseProxy* a = pairs[i].m_pProxy0;
      const btBroadphaseProxy* b = pairs[i].m_pProxy1;
      if (!TestAabbAgainstAabb2(a->m_aabbMin, a->m_aabbMax, b->m_aabbMin, b->m_aabbMax)) continue;
      add_pair(s, decode(a->m_clientObject), decode(b->m_clientObject), p);
    }
    return p;
  }

  btDefaultCollisionConfiguration configuration_;
  btCollisionDispatcher dispatcher_;
  AdjacencyFilter filter_;
  std::unique_ptr<btDbvtBroadphase> broad_phase_;
  std::vector<btBroadphaseProxy*> proxies_;  // vertices, faces, edges
};
#endif

#if defined(EXACTGEO_PEER_EMBREE)
// Embree 3: one scene per kind of primitive, each a user geometry whose bounds function
// returns the box. Scenes are dynamic with build quality LOW (the two-level structure) and
// the geometries REFIT, so the next step refits: rtcCommitGeometry and rtcCommitScene once
// the bounds have changed. rtcCollide(vertices, faces) and rtcCollide(edges, edges). Embree
// reports every pair of primitives from two leaves whose boxes overlap, without testing the
// primitives' own boxes (the documented contract: the callback filters), and within one
// scene each pair twice, in both orders: the callback tests the boxes (closed), keeps edge
// pairs with primID0 < primID1 and counts the mirrored ones to show that none is lost.
// Callbacks may run on several threads: each thread fills its own list.
class EmbreePeer : public Peer {
 public:
  explicit EmbreePeer(RTCDevice device) : device_(device) {}
  EmbreePeer(const EmbreePeer&) = delete;
  EmbreePeer& operator=(const EmbreePeer&) = delete;
  ~EmbreePeer() override {
    for (Scene* s : {&vertices_, &faces_, &edges_}) {
      if (s->geometry) rtcReleaseGeometry(s->geometry);
      if (s->scene) rtcReleaseScene(s->scene);
    }
  }

  Pairs first(const Step& s) override {
    build(vertices_, s.swept.box);
    build(faces_, s.face);
    build(edges_, s.edge);
    return query(s);
  }
  Pairs next(const Step& s) override {
    refit(vertices_, s.swept.box);
    refit(faces_, s.face);
    refit(edges_, s.edge);
    return query(s);
  }
  /// Whether every edge pair kept was also reported in the other order (last query).
  std::string json_fields() const override {
    return std::string(", \"edge_pairs_reported_in_both_orders\": ") + boolean(mirrored_);
  }

 private:
  struct Scene {
    RTCScene scene = nullptr;
    RTCGeometry geometry = nullptr;
    const FloatBox* boxes = nullptr;  // the bounds function reads the step's boxes here
  };

  static void bounds(const RTCBoundsFunctionArguments* args) {
    const FloatBox& b = static_cast<const Scene*>(args->geometryUserPtr)->boxes[args->primID];
    RTCBounds& out = *args->bounds_o;
    out.lower_x = b.lo[0];
    out.lower_y = b.lo[1];
    out.lower_z = b.lo[2];
    out.upper_x = b.hi[0];
    out.upper_y = b.hi[1];
    out.upper_z = b.hi[2];
  }

  void build(Scene& s, const std::vector<FloatBox>& boxes) {
    s.boxes = boxes.data();
    s.scene = rtcNewScene(device_);
    rtcSetSceneFlags(s.scene, RTC_SCENE_FLAG_DYNAMIC);
    rtcSetSceneBuildQuality(s.scene, RTC_BUILD_QUALITY_LOW);
    s.geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(s.geometry, static_cast<unsigned>(boxes.size()));
    rtcSetGeometryUserData(s.geometry, &s);
    rtcSetGeometryBoundsFunction(s.geometry, bounds, nullptr);
    rtcSetGeometryBuildQuality(s.geometry, RTC_BUILD_QUALITY_REFIT);
    rtcCommitGeometry(s.geometry);
    rtcAttachGeometry(s.scene, s.geometry);
    rtcCommitScene(s.scene);
  }

  static void refit(Scene& s, const std::vector<FloatBox>& boxes) {
    s.boxes = boxes.data();
    rtcCommitGeometry(s.geometry);
    rtcCommitScene(s.scene);
  }

  /// One rtcCollide call's state: the boxes of both sides and a list per thread.
  struct Collide {
    const Step* step;
    const FloatBox* a;
    const FloatBox* b;
    bool edges;  // edges against edges, else vertices against faces
    std::uint64_t id;
    std::mutex mutex;
    std::vector<std::unique_ptr<Pairs>> lists;
    std::atomic<std::size_t> mirrored{0};

    Pairs& local() {
      thread_local std::uint64_t owner = 0;
      thread_local Pairs* list = nullptr;
      if (owner != id) {
        const std::lock_guard<std::mutex> lock(mutex);
        list = lists.emplace_back(std::make_unique<Pairs>()).get();
        owner = id;
      }
      return *list;
    }
  };

  static void on_collisions(void* user, RTCCollision* c, unsigned int n) {
    auto& q = *static_cast<Collide*>(user);
    Pairs& p = q.local();
    p.reported += n;
    std::size_t mirrored = 0;
    for (unsigned int i = 0; i < n; ++i) {
      const std::uint32_t u = c[i].primID0, v = c[i].primID1;
      if (!boxes::overlap(q.a[u], q.b[v])) continue;
      if (!q.edges) {
        p.add_vertex_face(*q.step, u, v);
      } else if (u < v) {
        p.add_edge_edge(*q.step, u, v);
      } else if (keep_edge_edge(*q.step, u, v)) {
        ++mirrored;
      }
    }
    if (mirrored != 0) q.mirrored += mirrored;
  }

  Pairs query(const Step& s) {
    static std::atomic<std::uint64_t> next_id{1};
    Collide vf{&s, s.swept.box.data(), s.face.data(), false, next_id++, {}, {}, {}};
    rtcCollide(vertices_.scene, faces_.scene, on_collisions, &vf);
    Collide ee{&s, s.edge.data(), s.edge.data(), true, next_id++, {}, {}, {}};
    rtcCollide(edges_.scene, edges_.scene, on_collisions, &ee);
    Pairs p;
    for (const Collide* q : {&vf, &ee}) {
      for (const auto& list : q->lists) {
        p.vertex_face.insert(p.vertex_face.end(), list->vertex_face.begin(),
                             list->vertex_face.end());
        p.edge_edge.insert(p.edge_edge.end(), list->edge_edge.begin(), list->edge_edge.end());
        p.reported += list->reported;
      }
    }
    mirrored_ = ee.mirrored.load() == p.edge_edge.size();
    return p;
  }

  RTCDevice device_;
  Scene vertices_, faces_, edges_;
  bool mirrored_ = false;
};
#endif

// ---------------------------------------------------------------------------------------
// Measuring.

double seconds(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct Measurement {
  double one_shot = INFINITY, step_after = INFINITY;
  int runs = 0;
  Pairs first, next;  // the first run's pairs
  bool boxes_exact = true;
  std::string extra;  // peer-specific JSON fields, ", \"key\": value" each
};

struct Settings {
  int repeat = 3;
  double max_seconds = 20.0;
  unsigned threads = 1;
  double bullet_margin = 0.0;
#if defined(EXACTGEO_PEER_EMBREE)
  RTCDevice embree = nullptr;
#endif
};

template <class Make>
Measurement measure(const Step& first, const Step& next, const Settings& settings, Make make) {
  Measurement m;
  double spent = 0.0;
  for (int r = 0; r < settings.repeat && (r == 0 || spent < settings.max_seconds); ++r) {
    auto peer = make();
    auto start = std::chrono::steady_clock::now();
    Pairs a = peer->first(first);
    const double one_shot = seconds(start);
    if (r == 0) m.boxes_exact = peer->boxes_exact(first);
    start = std::chrono::steady_clock::now();
    Pairs b = peer->next(next);
    const double step_after = seconds(start);
    m.one_shot = std::min(m.one_shot, one_shot);
    m.step_after = std::min(m.step_after, step_after);
    spent += one_shot + step_after;
    ++m.runs;
    if (r == 0) {
      m.boxes_exact = m.boxes_exact && peer->boxes_exact(next);
      m.first = std::move(a);
      m.next = std::move(b);
      m.extra = peer->json_fields();
    }
  }
  return m;
}

std::optional<Measurement> measure_peer(const std::string& name, const Step& first,
                                        const Step& next, const Settings& settings) {
  if (name == "exactgeo")
    return measure(first, next, settings,
                   [&] { return std::make_unique<ExactgeoPeer>(settings.threads); });
#if defined(EXACTGEO_PEER_CGAL)
  if (name == "cgal")
    return measure(first, next, settings, [] { return std::make_unique<CgalPeer>(); });
#endif
#if defined(EXACTGEO_PEER_FCL)
  if (name == "fcl")
    return measure(first, next, settings, [] { return std::make_unique<FclPeer>(); });
#endif
#if defined(EXACTGEO_PEER_BULLET)
  if (name == "bullet")
    return measure(first, next, settings,
                   [&] { return std::make_unique<BulletPeer>(settings.bullet_margin); });
#endif
#if defined(EXACTGEO_PEER_EMBREE)
  if (name == "embree")
    return measure(first, next, settings,
                   [&] { return std::make_unique<EmbreePeer>(settings.embree); });
#endif
  return std::nullopt;
}

/// The peers compiled in.
std::vector<std::string> available_peers() {
  std::vector<std::string> peers{"exactgeo"};
#if defined(EXACTGEO_PEER_CGAL)
  peers.push_back("cgal");
#endif
#if defined(EXACTGEO_PEER_FCL)
  peers.push_back("fcl");
#endif
#if defined(EXACTGEO_PEER_BULLET)
  peers.push_back("bullet");
#endif
#if defined(EXACTGEO_PEER_EMBREE)
  peers.push_back("embree");
#endif
  return peers;
}

bool single_threaded(const std::string& peer) {
  return peer == "cgal" || peer == "fcl" || peer == "bullet";
}

void print_row(const std::string& scene, const std::string& path, const MeshView& mesh,
               const std::string& peer, unsigned threads, const Measurement& m, bool same_first,
               bool same_next) {
  const std::size_t primitives = mesh.vertex_count + mesh.edges.size() + mesh.faces.size();
  std::printf(
      "{\"scene\": \"%s\", \"mesh\": \"%s\", \"triangles\": %zu, \"vertices\": %zu, "
      "\"edges\": %zu, \"primitives\": %zu, \"peer\": \"%s\", \"threads\": %u, "
      "\"candidates\": %zu, \"vertex_face\": %zu, \"edge_edge\": %zu, "
      "\"step_after_candidates\": %zu, \"reported_pairs\": %zu, "
      "\"step_after_reported_pairs\": %zu, \"one_shot_ms\": %.6g, \"step_after_ms\": %.6g, "
      "\"runs\": %d, \"same_one_shot\": %s, \"same_step_after\": %s, \"same\": %s, "
      "\"boxes_exact\": %s%s}\n",
      scene.c_str(), path.c_str(), mesh.faces.size(), mesh.vertex_count, mesh.edges.size(),
      primitives, peer.c_str(), threads, m.first.size(), m.first.vertex_face.size(),
      m.first.edge_edge.size(), m.next.size(), m.first.reported, m.next.reported, 1e3 * m.one_shot,
      1e3 * m.step_after, m.runs, boolean(same_first), boolean(same_next),
      boolean(same_first && same_next), boolean(m.boxes_exact), m.extra.c_str());
  std::fflush(stdout);
}

std::vector<std::string> split_list(const std::string& list) {
  std::vector<std::string> out;
  std::stringstream in(list);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

[[noreturn]] void usage(const std::string& why) {
  std::cerr << "broad_phase_peers: " << why << "\n";
  std::exit(2);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> paths;
  double motion = 0.2;
  std::uint64_t seed = 1;
  Settings settings;
  std::vector<std::string> peers = available_peers();
  std::string scene;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto value = [&] {
      if (i + 1 >= argc) usage(a + " needs a value");
      return std::string(argv[++i]);
    };
    if (a == "--motion")
      motion = std::stod(value());
    else if (a == "--seed")
      seed = std::stoull(value());
    else if (a == "--threads")
      settings.threads = static_cast<unsigned>(std::stoul(value()));
    else if (a == "--repeat")
      settings.repeat = std::stoi(value());
    else if (a == "--max-seconds")
      settings.max_seconds = std::stod(value());
    else if (a == "--bullet-margin")
      settings.bullet_margin = std::stod(value());
    else if (a == "--peers")
      peers = split_list(value());
    else if (a == "--scene")
      scene = value();
    else if (!a.empty() && a[0] == '-')
      usage("unknown option " + a);
    else
      paths.push_back(a);
  }
  if (paths.empty() || paths.size() > 2) usage("one or two mesh files expected");
  if (settings.threads == 0 || settings.repeat < 1) usage("--threads and --repeat must be >= 1");
  const std::vector<std::string> known = available_peers();
  for (const std::string& p : peers)
    if (std::find(known.begin(), known.end(), p) == known.end())
      usage("peer " + p + " unknown or not compiled in");
  if (peers.empty() || peers[0] != "exactgeo") peers.insert(peers.begin(), "exactgeo");
  if (scene.empty()) scene = paths[0];

  const std::optional<MeshStep> loaded = ccd::bench::load_step(paths, motion, 0.0, seed);
  if (!loaded) usage("frames differ in vertex count");
  const MeshStep following = ccd::bench::moved_on(*loaded, motion, 0.0, seed + 1);
  const ccd::MeshCcd connectivity(loaded->t0.size() / 3, loaded->faces);
  const MeshView mesh{connectivity.vertex_count(), connectivity.faces(), connectivity.edges()};
  const Step first = make_step(mesh, *loaded);
  const Step next = make_step(mesh, following);

#if defined(EXACTGEO_PEER_EMBREE)
  const std::string config = "threads=" + std::to_string(settings.threads);
  settings.embree = rtcNewDevice(config.c_str());
  if (!settings.embree) usage("rtcNewDevice failed");
  rtcSetDeviceErrorFunction(
      settings.embree,
      [](void*, RTCError, const char* message) {
        std::cerr << "broad_phase_peers: embree: " << message << "\n";
        std::exit(1);
      },
      nullptr);
#endif

  std::vector<std::array<std::uint32_t, 3>> expected_first, expected_next;
  for (const std::string& peer : peers) {
    if (settings.threads > 1 && single_threaded(peer)) {
      std::cerr << peer << ": single-threaded, measured with --threads 1 only\n";
      continue;
    }
    const std::optional<Measurement> m = measure_peer(peer, first, next, settings);
    if (peer == "exactgeo") {
      expected_first = sorted(m->first);
      expected_next = sorted(m->next);
    }
    const bool same_first = sorted(m->first) == expected_first;
    const bool same_next = sorted(m->next) == expected_next;
    std::cerr << scene << " " << peer << ": one-shot same: " << boolean(same_first)
              << ", step after same: " << boolean(same_next) << "\n";
    print_row(scene, paths[0], mesh, peer, settings.threads, *m, same_first, same_next);
  }
#if defined(EXACTGEO_PEER_EMBREE)
  rtcReleaseDevice(settings.embree);
#endif
  return 0;
}
