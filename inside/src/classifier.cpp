#include "exactgeo/inside/classifier.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <mutex>
#include <optional>
#include <span>
#include <stdexcept>

#include "exactgeo/inside/internal/candidates.hpp"
#include "exactgeo/inside/internal/corner_boxes.hpp"
#include "exactgeo/inside/internal/open_label.hpp"
#include "exactgeo/inside/internal/open_space_cells.hpp"
#include "exactgeo/inside/internal/open_winding.hpp"
#include "exactgeo/inside/internal/space_cells.hpp"
#include "exactgeo/inside/internal/tree_candidates.hpp"
#include "exactgeo/inside/internal/unit_frame.hpp"
#include "exactgeo/mesh/boundary_chain.hpp"
#include "exactgeo/mesh/check.hpp"
#include "exactgeo/predicates/crossing_parity.hpp"
#include "exactgeo/predicates/kernel/signs.hpp"
#include "exactgeo/predicates/ray_directions.hpp"

namespace exactgeo::inside {
namespace {

/// Directions the sequence has before they stop being exact in double (t_k^2 needs
/// (2k + 3)^2 < 2^53). For exact arithmetic the loop ends long before: at most
/// V + 2 (E + F) directions are degenerate (ray_directions.hpp), fewer than 2^25 for any
/// mesh below about four million faces.
constexpr std::size_t kExactDirections = std::size_t{1} << 25;
/// Plain double signs can call every ray degenerate; after this many the point is called
/// outside (a wrong answer is what that baseline may give).
constexpr std::size_t kPlainDoubleDirections = 64;

/// An open surface's space cells (open_space_cells.hpp): the rays tried from a box's
/// centre (one that meets an edge of F or of the cap gives no count), the most variation
/// over a box worth a ray, and the variation past which its parts are not worth trying
/// either (their reach is half the box's). Costs, not certificates: any values give the
/// labels' guarantee.
constexpr std::size_t kBoxRays = 4;
constexpr double kBoxVariation = 0.5;
constexpr double kHopelessVariation = 2.0;

std::size_t max_rays(Arithmetic arithmetic) noexcept {
  return arithmetic == Arithmetic::plain_double ? kPlainDoubleDirections : kExactDirections;
}

/// The mesh's faces as a face set over its vertices: quads as patches, in tensor order.
std::vector<SurfaceFace> surface_faces(const mesh::Mesh& mesh) {
  std::vector<SurfaceFace> faces;
  faces.reserve(mesh.faces.size());
  for (const mesh::Face& f : mesh.faces) {
    const auto& c = f.corners;
    faces.push_back(f.is_triangle() ? SurfaceFace::triangle(c[0], c[1], c[2])
                                    : SurfaceFace::patch(c[0], c[1], c[2], c[3]));
  }
  return faces;
}

/// The mesh without its faces of zero area: they bound nothing and add no crossing, and
/// a ray that met one would only be cast again. The edge counts are taken before, with
/// them (a sliver closing a T-junction keeps the edges around it balanced).
mesh::Mesh without_zero_area_faces(mesh::Mesh mesh, const mesh::MeshCheck& check) {
  if (check.zero_area_faces.count == 0) return mesh;
  std::size_t kept = 0;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    if (!check.face_findings[f].zero_area) mesh.faces[kept++] = mesh.faces[f];
  }
  mesh.faces.resize(kept);
  return mesh;
}

/// The finder CandidateSearch::automatic stands for with these options and faces.
CandidateSearch candidate_search(const ClassifierOptions& options, std::size_t faces) noexcept {
  if (options.candidates != CandidateSearch::automatic) return options.candidates;
  const std::size_t enough_faces = !options.expected_points ? kBoxTreeFaces
                                   : *options.expected_points < kEmbreePoints
                                       ? std::numeric_limits<std::size_t>::max()
                                       : kBoxTreeFacesManyPoints;
  return faces < enough_faces ? CandidateSearch::box_tree : CandidateSearch::embree;
}

/// The rule's label of a point whose w = S - w_Cap, w_Cap strictly between the two
/// half-integers around `cap` (enclosure_apart): w lies strictly between n - 1/2 and
/// n + 1/2, n = S - j, so |w| >= 1/2 exactly where n != 0 and w >= 1/2 where n >= 1.
Location cap_label(FillRule rule, std::int64_t crossings, const Enclosure& cap) noexcept {
  const auto j = static_cast<std::int64_t>(std::nearbyint(cap.lower));
  return holds(rule, crossings - j) ? Location::inside : Location::outside;
}

template <class Signs>
std::vector<PatchSpan> spans_of(const Signs& signs, const std::vector<SurfaceFace>& faces,
                                std::span<const Point3> points) {
  std::vector<PatchSpan> spans(faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f)
    spans[f] = span_of(signs, faces[f], points);
  return spans;
}

}  // namespace

struct Classifier::State {
  mesh::Mesh mesh;
  mesh::Examples<std::size_t> zero_area_faces;
  FillRule rule = FillRule::nonzero;
  bool oriented = false;
  mesh::Box box;
  std::vector<SurfaceFace> faces;
  /// Every face's span, found once with exact signs (for the exact and rational
  /// arithmetics, which agree on every sign) and with plain double signs (for the baseline,
  /// which runs the whole algorithm in doubles).
  std::vector<PatchSpan> exact_spans;
  std::vector<PatchSpan> double_spans;
  std::optional<internal::EmbreeCandidates> embree;
  std::optional<internal::TreeCandidates> tree;
  std::optional<internal::SpaceCells> cells;
  /// An open surface's: cells whose points all certainly have one label.
  std::optional<internal::OpenSpaceCells> open_cells;
  /// The vertices the exact rays see: the mesh's, or the mesh's brought to magnitude 1.
  internal::UnitFrame frame;
  /// The boundary of an open surface (empty for a closed one): the kept faces', the
  /// surface being open with the faces of zero area counted (Classifier's constructor).
  std::vector<BoundaryEdge> boundary;
  /// The same edges in a tree (boundary_tree.hpp), over the vertices the exact rays see:
  /// the cone's term from near edges and far nodes, for the points the cap does not settle
  /// (one on a cap triangle, or whose w_Cap lies too near a half-integer). Built on first
  /// use, once, by whichever thread asks first: most surfaces never ask.
  const BoundaryTree& boundary_tree() const {
    std::call_once(boundary_tree_once,
                   [this] { lazy_boundary_tree = BoundaryTree(ray_vertices(), boundary); });
    return lazy_boundary_tree;
  }
  mutable std::once_flag boundary_tree_once;
  mutable BoundaryTree lazy_boundary_tree;
  /// The cap of the same chain over the same vertices (cap_tree.hpp): F + Cap is closed,
  /// and w_F = S - w_Cap, S the signed count of a ray's crossings with F and the cap.
  CapTree cap;
  /// The cap's triangles as faces (indices into the mesh's vertices), their spans (none:
  /// triangles) and their candidate search (nullopt: every cap triangle, for
  /// CandidateSearch::brute_force).
  std::vector<SurfaceFace> cap_faces;
  std::vector<PatchSpan> cap_spans;
  std::optional<internal::TreeCandidates> cap_search;

  /// The vertices the exact rays see: the unit frame's when it is on.
  std::span<const Point3> ray_vertices() const noexcept {
    return frame.on() ? frame.vertices() : std::span<const Point3>(mesh.vertices);
  }

  /// `point` in the tree's coordinates (the unit frame's when it is on), when it maps
  /// there exactly.
  std::optional<Point3> in_tree_frame(const Point3& point) const noexcept {
    if (frame.on()) return frame.map(point);
    return point;
  }

  /// The cap of `boundary` over `vertices` (the ones the exact rays see), its faces and
  /// their candidate search: a box tree over the cap's triangles alone, in the float frame
  /// of the faces' corners' box (which holds every cap corner: each is a boundary vertex,
  /// a corner of a face), or none (`every`: each ray tries every cap triangle).
  void build_cap(std::span<const Point3> vertices, bool every) {
    cap = CapTree(vertices, boundary);
    for (const CapTriangle& t : cap.triangles()) {
      // (The tree's triangles have multiplicity 1; any other is the same chain.)
      for (std::int32_t m = 0; m < std::abs(t.multiplicity); ++m)
        cap_faces.push_back(t.multiplicity > 0 ? SurfaceFace::triangle(t.a, t.b, t.c)
                                               : SurfaceFace::triangle(t.a, t.c, t.b));
    }
    cap_spans.assign(cap_faces.size(), PatchSpan{});
    if (every || cap_faces.empty()) return;
    // A mesh of the cap's corners only (the search's ids are the faces', in order).
    mesh::Mesh corners;
    std::vector<VertexIndex> index(mesh.vertices.size(), kNoVertex);
    for (const SurfaceFace& f : cap_faces) {
      std::array<VertexIndex, 3> c{};
      for (std::size_t i = 0; i < 3; ++i) {
        VertexIndex& at = index[f.corners[i]];
        if (at == kNoVertex) {
          at = static_cast<VertexIndex>(corners.vertices.size());
          corners.vertices.push_back(mesh.vertices[f.corners[i]]);
        }
        c[i] = at;
      }
      corners.faces.push_back(mesh::make_triangle(c[0], c[1], c[2]));
    }
    cap_search.emplace(corners, box);
  }

  PreparedFaces prepared(Arithmetic arithmetic) const noexcept {
    return {faces, arithmetic == Arithmetic::plain_double ? double_spans : exact_spans};
  }
};

/// A query point as given (for the candidate search, which takes any magnitude) and as
/// the exact rays see it, with the vertices they see it against: both in the unit frame
/// when that maps the point exactly, else both as given.
struct Classifier::RayOrigin {
  RayOrigin(const State& s, const Point3& point) noexcept : given(point) {
    if (const std::optional<Point3> mapped = s.frame.map(point)) {
      exact = *mapped;
      vertices = s.frame.vertices();
    } else {
      exact = point;
      vertices = s.mesh.vertices;
    }
  }
  const Point3& given;
  Point3 exact;
  std::span<const Point3> vertices;
};

template <class Signs>
SignedRayCount Classifier::count_ray(const State& s, const Signs& signs, Arithmetic arithmetic,
                                     const RayOrigin& origin, std::size_t k,
                                     ClassifierScratch& scratch) {
  if (s.tree) {  // any direction the exact rays cast: exact in double
    s.tree->find(origin.given, k, scratch.candidates);
  } else if (s.embree && k < kFloatExactRayDirections) {
    s.embree->find(origin.given, k, scratch.candidates);
  } else {
    internal::all_faces(s.mesh, scratch.candidates);
  }
  const auto corner = [&](VertexIndex i) {
    return kernel::Offset::between(origin.exact, origin.vertices[i]);
  };
  const Vector3 direction = ray_direction(k);
  return count_signed_crossings(signs, s.prepared(arithmetic), scratch.candidates, corner,
                                kernel::Offset::vector(direction));
}

template <class Signs>
SignedRayCount Classifier::count_cap_ray(const State& s, const Signs& signs,
                                         const RayOrigin& origin, std::size_t k,
                                         ClassifierScratch& scratch) {
  if (s.cap_search) {
    s.cap_search->find(origin.given, k, scratch.cap_candidates);
  } else {
    scratch.cap_candidates.resize(s.cap_faces.size());
    for (std::size_t f = 0; f < s.cap_faces.size(); ++f)
      scratch.cap_candidates[f] = static_cast<std::uint32_t>(f);
  }
  const auto corner = [&](VertexIndex i) {
    return kernel::Offset::between(origin.exact, origin.vertices[i]);
  };
  const Vector3 direction = ray_direction(k);
  return count_signed_crossings(signs, PreparedFaces{s.cap_faces, s.cap_spans},
                                scratch.cap_candidates, corner, kernel::Offset::vector(direction));
}

/// The signed crossing count of `point` along the ray sequence, a tree proposing the
/// candidate faces. Precondition: point in s.box, the closed box of the faces' corners.
std::optional<std::int64_t> Classifier::cast_rays(const State& s, const Point3& point,
                                                  Arithmetic arithmetic,
                                                  ClassifierScratch& scratch) {
  const RayOrigin origin(s, point);
  const auto found = kernel::with_signs(arithmetic, [&](const auto& signs) {
    return exactgeo::winding_number(max_rays(arithmetic), [&](std::size_t k) {
      return count_ray(s, signs, arithmetic, origin, k, scratch);
    });
  });
  if (!found) return 0;  // plain double only (see kPlainDoubleDirections): outside
  return found->winding;
}

/// The generalized winding number's label. First through the cap (cap_tree.hpp): with
/// S the signed crossings of a ray with F and the cap together (exact) and
/// j - 1/2 < w_Cap < j + 1/2 certified, w = S - w_Cap lies strictly between n - 1/2 and
/// n + 1/2, n = S - j, so the rule's label is that of the integer n. Where the cap does
/// not settle the point (it lies on a cap triangle, w_Cap is too near a half-integer, or
/// the point does not map into the trees' frame), and for plain doubles: the ray's count
/// with F plus the cone's term, from the boundary tree, else over every edge, exactly.
/// Outside the box, a ray away from it crosses no face and no cap triangle (S = 0, w =
/// -w_Cap): an open surface can hold points beyond its corners' box (a rolled sheet does).
Location Classifier::classify_open(const State& s, const Point3& point, Arithmetic arithmetic,
                                   ClassifierScratch& scratch) {
  // The cap first, then the tree's term (certified, and settling all but points near a
  // level); the term over every edge, with its exact stages, where neither settles it.
  const bool certified = arithmetic != Arithmetic::plain_double;
  if (internal::strictly_outside(s.box, point)) {
    const Vector3 ray = internal::ray_away_from(s.box, point);
    if (const std::optional<Point3> mapped = s.in_tree_frame(point); mapped && certified) {
      if (const std::optional<Enclosure> cap = s.cap.enclosure_apart(*mapped, scratch.cap)) {
        ++scratch.routes.cap;
        return cap_label(s.rule, 0, *cap);
      }
      ++scratch.routes.cap_unsettled;
      if (const auto label = internal::open_label_from_tree(s.rule, 0, *mapped, ray,
                                                            s.boundary_tree(), scratch.boundary)) {
        ++scratch.routes.cone;
        return *label;
      }
    }
    const auto label =
        internal::open_label(s.rule, 0, point, ray, s.mesh.vertices, s.boundary, arithmetic);
    if (certified) ++scratch.routes.cone;
    return label.value_or(Location::undecided);  // a ray that meets no edge: never nullopt
  }
  if (s.open_cells && certified) {
    if (const std::optional<Location> known = s.open_cells->lookup(point)) return *known;
  }
  const RayOrigin origin(s, point);
  // The trees hold the vertices the rays see; a point the frame cannot map sees others.
  const bool tree_sees_origin =
      certified && (!s.frame.on() || origin.vertices.data() == s.frame.vertices().data());
  return kernel::with_signs(arithmetic, [&](const auto& signs) {
    // The cap's enclosure does not depend on the ray: found once, at the first ray that
    // crosses F and the cap cleanly.
    enum class CapRoute : std::uint8_t { untried, settled, off };
    CapRoute route = tree_sees_origin ? CapRoute::untried : CapRoute::off;
    Enclosure cap{};
    for (std::size_t k = 0; k < max_rays(arithmetic); ++k) {
      const SignedRayCount count = count_ray(s, signs, arithmetic, origin, k, scratch);
      if (count.kind == RayCount::origin_on_face) return Location::boundary;
      if (count.kind == RayCount::degenerate) continue;
      if (route != CapRoute::off) {
        const SignedRayCount on_cap = count_cap_ray(s, signs, origin, k, scratch);
        if (on_cap.kind == RayCount::degenerate) {
          ++scratch.routes.cap_degenerate_rays;
          continue;
        }
        if (on_cap.kind == RayCount::origin_on_face) {
          // On the cap, not on F: w_Cap is not defined there, w_F is; the cone decides.
          ++scratch.routes.on_cap;
          route = CapRoute::off;
        } else if (route == CapRoute::untried) {
          if (const std::optional<Enclosure> e = s.cap.enclosure_apart(origin.exact, scratch.cap)) {
            cap = *e;
            route = CapRoute::settled;
          } else {
            ++scratch.routes.cap_unsettled;
            route = CapRoute::off;
          }
        }
        if (route == CapRoute::settled) {
          ++scratch.routes.cap;
          return cap_label(s.rule, count.total + on_cap.total, cap);
        }
      }
      if (tree_sees_origin) {
        if (const auto label =
                internal::open_label_from_tree(s.rule, count.total, origin.exact, ray_direction(k),
                                               s.boundary_tree(), scratch.boundary)) {
          ++scratch.routes.cone;
          return *label;
        }
      }
      if (const auto label = internal::open_label(s.rule, count.total, point, ray_direction(k),
                                                  s.mesh.vertices, s.boundary, arithmetic)) {
        if (certified) ++scratch.routes.cone;
        return *label;
      }
    }
    return Location::outside;  // plain double only (see kPlainDoubleDirections)
  });
}

/// The label of every point of the closed box [lower, upper], which no face reaches
/// (open_space_cells.hpp): with delta the cap tree's bound on w's variation over the
/// box and c its centre, w(c) = S - w_Cap(c) as for a point (classify_open), w_Cap(c)
/// enclosed with delta to spare between the half-integers j - 1/2 and j + 1/2; then
/// every p of the box has w(p) within delta of w(c), strictly between n - 1/2 and n + 1/2
/// (n = S - j), and the label of n (cap_label). nullopt where that does not settle (c on
/// a cap triangle, w_Cap(c) too near a half-integer for delta, or the box or its centre
/// not in the trees' frame).
internal::OpenBoxAnswer Classifier::open_box_label(const State& s, const Point3& lower,
                                                   const Point3& upper,
                                                   ClassifierScratch& scratch) {
  Point3 centre;
  for (int i = 0; i < 3; ++i)
    centre[i] = std::clamp(lower[i] / 2 + upper[i] / 2, lower[i], upper[i]);
  const RayOrigin origin(s, centre);
  Point3 tree_lower = lower, tree_upper = upper;
  if (s.frame.on()) {
    const std::optional<Point3> l = s.frame.map(lower), u = s.frame.map(upper);
    if (!l || !u || origin.vertices.data() != s.frame.vertices().data()) {
      return {std::nullopt, true, false};
    }
    tree_lower = *l;
    tree_upper = *u;
  }
  const std::optional<double> variation =
      s.cap.variation(tree_lower, tree_upper, origin.exact, kHopelessVariation);
  if (!variation || *variation > kBoxVariation) return {std::nullopt, variation.has_value(), false};
  const std::optional<Location> label =
      kernel::with_signs(Arithmetic::exact, [&](const auto& signs) -> std::optional<Location> {
        for (std::size_t k = 0; k < kBoxRays; ++k) {
          const SignedRayCount count = count_ray(s, signs, Arithmetic::exact, origin, k, scratch);
          if (count.kind == RayCount::origin_on_face) return std::nullopt;  // (no face is there)
          if (count.kind == RayCount::degenerate) continue;
          const SignedRayCount on_cap = count_cap_ray(s, signs, origin, k, scratch);
          // On a cap triangle w_Cap is not defined: no label (a cost; its points go on).
          if (on_cap.kind == RayCount::origin_on_face) return std::nullopt;
          if (on_cap.kind == RayCount::degenerate) continue;
          const std::optional<Enclosure> cap =
              s.cap.enclosure_apart(origin.exact, scratch.cap, *variation);
          if (!cap) return std::nullopt;
          return cap_label(s.rule, count.total + on_cap.total, *cap);
        }
        return std::nullopt;
      });
  return {label, true, true};
}

/// The generalized winding number's bounds, rays cast as for its label.
std::optional<Enclosure> Classifier::open_winding_number(const State& s, const Point3& point,
                                                         Arithmetic arithmetic,
                                                         ClassifierScratch& scratch) {
  const auto value = [&](std::int64_t crossings, const Vector3& ray) {
    return internal::open_winding(crossings, point, ray, s.mesh.vertices, s.boundary, arithmetic);
  };
  using internal::OpenWindingKind;
  if (internal::strictly_outside(s.box, point)) {
    const internal::OpenWinding w = value(0, internal::ray_away_from(s.box, point));
    // A ray that leaves the box behind meets no edge: never ray_on_edge.
    if (w.kind == OpenWindingKind::on_edge) return std::nullopt;
    return w.w;
  }
  const RayOrigin origin(s, point);
  return kernel::with_signs(arithmetic, [&](const auto& signs) -> std::optional<Enclosure> {
    for (std::size_t k = 0; k < max_rays(arithmetic); ++k) {
      const SignedRayCount count = count_ray(s, signs, arithmetic, origin, k, scratch);
      if (count.kind == RayCount::origin_on_face) return std::nullopt;
      if (count.kind == RayCount::degenerate) continue;
      const internal::OpenWinding w = value(count.total, ray_direction(k));
      if (w.kind == OpenWindingKind::on_edge) return std::nullopt;
      if (w.kind == OpenWindingKind::enclosed) return w.w;
    }
    return Enclosure{0.0, 0.0};  // plain double only (see kPlainDoubleDirections), as classify
  });
}

/// The same, points outside the box and in labelled space cells answered first.
std::optional<std::int64_t> Classifier::signed_count(const State& s, const Point3& point,
                                                     Arithmetic arithmetic,
                                                     ClassifierScratch& scratch) {
  // The solid lies in the convex hull of its surface, hence in the box.
  if (internal::strictly_outside(s.box, point)) return 0;
  if (s.cells && arithmetic != Arithmetic::plain_double) {
    if (const auto known = s.cells->lookup(point)) return *known;
  }
  return cast_rays(s, point, arithmetic, scratch);
}

Classifier::Classifier(mesh::Mesh mesh, ClassifierOptions options)
    : state_(std::make_unique<State>()) {
  const mesh::MeshCheck check = mesh::check_mesh(mesh);
  const FillRule rule = rule_for(check, options.rule);
  if (auto problem = rule_problem(check, rule, options.allow_non_manifold)) {
    throw std::invalid_argument(*problem);
  }
  State& s = *state_;
  // Parity counts crossings modulo 2 on a closed surface, whatever the orientations.
  // Closed or open is decided with the faces of zero area (a sliver closing a T-junction
  // leaves no boundary); an open surface's boundary is then the kept faces' alone, since a
  // dropped face is not surface: a point on its edges is labelled as on a closed mesh,
  // and its edges ask nothing of the rays (their solid angles sum to zero off their line).
  // The chain is the unbalanced edges, so a surface the check found balanced has none
  // (and is spared a second sort of every edge).
  if (rule != FillRule::parity && check.unbalanced_edges.count > 0) {
    s.boundary = mesh::boundary_chain(mesh);
  }
  s.mesh = without_zero_area_faces(std::move(mesh), check);
  if (!s.boundary.empty() && check.zero_area_faces.count > 0) {
    s.boundary = mesh::boundary_chain(s.mesh);
  }
  s.zero_area_faces = check.zero_area_faces;
  s.rule = rule;
  s.oriented = check.unbalanced_edges.count == 0;
  // The box of the faces' corners, not of every vertex: a vertex no face uses bounds
  // nothing. The candidate search's float frame and the space cells are built on this one
  // box, and both need every point they are asked about to lie in it (classify answers
  // the points outside it first). The checks leave a face of nonzero area, so it exists.
  s.box = *internal::corner_box(s.mesh);
  s.faces = surface_faces(s.mesh);
  s.frame = internal::UnitFrame(s.mesh, s.box);
  // Spans in the frame the rays use: the same for the exact signs (a power of two changes
  // no sign), and the plain double baseline then runs entirely in one frame.
  const std::span<const Point3> ray_vertices = s.ray_vertices();
  s.exact_spans = spans_of(kernel::ExactSigns{}, s.faces, ray_vertices);
  s.double_spans = spans_of(kernel::DoubleSigns{}, s.faces, ray_vertices);
  const CandidateSearch search = candidate_search(options, s.mesh.faces.size());
  if (!s.boundary.empty()) {
    s.build_cap(ray_vertices, search == CandidateSearch::brute_force);
  }
  if (search == CandidateSearch::embree) s.embree.emplace(s.mesh, s.box);
  if (search == CandidateSearch::box_tree) s.tree.emplace(s.mesh, s.box);
  // A cell's points share one integer winding number; an open surface's vary, and its
  // cells are labelled where the variation is bounded (open_space_cells.hpp).
  if (options.space_cells && !s.boundary.empty() && s.rule != FillRule::parity) {
    ClassifierScratch scratch;
    s.open_cells.emplace(
        s.mesh, s.box,
        [&](const Point3& lower, const Point3& upper) {
          return open_box_label(s, lower, upper, scratch);
        },
        internal::SpaceCells::cell_count(s.mesh.faces.size(), options.expected_points),
        options.expected_points);
  }
  if (options.space_cells && s.boundary.empty()) {
    ClassifierScratch scratch;
    s.cells.emplace(
        s.mesh, s.box, [&](const Point3& p) { return cast_rays(s, p, Arithmetic::exact, scratch); },
        options.expected_points);
  }
}

Classifier::~Classifier() = default;
Classifier::Classifier(Classifier&&) noexcept = default;
Classifier& Classifier::operator=(Classifier&&) noexcept = default;

const mesh::Mesh& Classifier::mesh() const noexcept {
  return state_->mesh;
}

std::optional<Classifier::CellSummary> Classifier::space_cells() const noexcept {
  if (!state_->cells) return std::nullopt;
  const internal::SpaceCells& c = *state_->cells;
  return CellSummary{c.resolution(), c.cells(), c.surface_cells(), c.components()};
}

const mesh::Examples<std::size_t>& Classifier::zero_area_faces() const noexcept {
  return state_->zero_area_faces;
}

FillRule Classifier::rule() const noexcept {
  return state_->rule;
}

bool Classifier::oriented() const noexcept {
  return state_->oriented;
}

bool Classifier::open() const noexcept {
  return !state_->boundary.empty();
}

std::span<const BoundaryEdge> Classifier::boundary() const noexcept {
  return state_->boundary;
}

std::optional<std::string> Classifier::open_note() const {
  if (!open()) return std::nullopt;
  const std::size_t edges = state_->boundary.size();
  return "the surface is open (" + std::to_string(edges) + (edges == 1 ? " edge" : " edges") +
         " run more often one way than the other): inside where its generalized winding number w "
         "is " +
         (state_->rule == FillRule::positive ? "at least 1/2" : "at least 1/2 in magnitude") +
         ", certified; undecided where no precision settles it (w = 1/2 exactly, or too "
         "close to it for 2048-bit arithmetic)";
}

Location Classifier::classify(const Point3& point, Arithmetic arithmetic) const {
  ClassifierScratch scratch;
  return classify(point, arithmetic, scratch);
}

Location Classifier::classify(const Point3& point, Arithmetic arithmetic,
                              ClassifierScratch& scratch) const {
  if (open()) return classify_open(*state_, point, arithmetic, scratch);
  return location_of(signed_count(*state_, point, arithmetic, scratch));
}

std::optional<Location> Classifier::space_cell_label(const Point3& point) const noexcept {
  const State& s = *state_;
  if (internal::strictly_outside(s.box, point)) return std::nullopt;
  if (s.open_cells) return s.open_cells->lookup(point);
  if (s.cells) {
    if (const std::optional<std::int64_t> known = s.cells->lookup(point)) return location_of(known);
  }
  return std::nullopt;
}

Location Classifier::location_of(const std::optional<std::int64_t>& winding) const noexcept {
  if (!winding) return Location::boundary;
  return holds(state_->rule, *winding) ? Location::inside : Location::outside;
}

std::optional<Enclosure> Classifier::generalized_winding_number(const Point3& point,
                                                                Arithmetic arithmetic) const {
  ClassifierScratch scratch;
  return generalized_winding_number(point, arithmetic, scratch);
}

std::optional<Enclosure> Classifier::generalized_winding_number(const Point3& point,
                                                                Arithmetic arithmetic,
                                                                ClassifierScratch& scratch) const {
  if (open()) return open_winding_number(*state_, point, arithmetic, scratch);
  const std::optional<std::int64_t> w = winding_number(point, arithmetic, scratch);
  if (!w) return std::nullopt;
  const auto exact = static_cast<double>(*w);  // |w| is at most the faces a ray crosses
  return Enclosure{exact, exact};
}

std::optional<std::int64_t> Classifier::winding_number(const Point3& point,
                                                       Arithmetic arithmetic) const {
  ClassifierScratch scratch;
  return winding_number(point, arithmetic, scratch);
}

std::optional<std::int64_t> Classifier::winding_number(const Point3& point, Arithmetic arithmetic,
                                                       ClassifierScratch& scratch) const {
  if (open()) {
    throw std::logic_error(
        "this surface is open: its generalized winding numbers are not integers (classify "
        "labels points by them)");
  }
  if (!state_->oriented) {
    throw std::logic_error(
        "winding numbers need a closed oriented surface (every edge used as often in each "
        "direction); this mesh is classified by crossing parity only");
  }
  return signed_count(*state_, point, arithmetic, scratch);
}

}  // namespace exactgeo::inside
