// The exact classifier (classifier.hpp) against truths that do not come from it, one file
// per theme: this one (known truth), classifier_winding_test.cpp (winding numbers and fill
// rules), classifier_open_surface_test.cpp, classifier_zero_area_test.cpp,
// classifier_unused_vertices_test.cpp, classifier_polygon_faces_test.cpp and
// classifier_real_meshes_test.cpp.
//
// Point-in-volume classification against solids whose truth is known exactly from their
// construction: random polycubes (voxel occupancy decides every half-integer lattice
// point), the same split into triangles, moved to skew patches by dyadic offsets (voxel
// centres keep their truth, exact points on faces are boundary, one ulp off a face is
// not), mapped by exact maps (scaling by 2^k, translation, axis scalings and shears that
// make the first ray meet edges or lie in face planes: labels unchanged), and hand-made
// solids with a closed-form inside (a box, a box with skew top and bottom, a tetrahedron)
// or a partly known one (a hexahedron with a vertex moved along its diagonal). Every exact
// label is checked against the truth, brute-force candidates, batches on 1 and 3 threads
// and, on fewer points, rational arithmetic. Plain double is run and its disagreements
// counted. A wrong polycube label is reduced to a locally minimal voxel set and reported.

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <ostream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "exactgeo/inside/batch.hpp"
#include "exactgeo/inside/classifier.hpp"
#include "exactgeo/inside/fill_rule.hpp"
#include "exactgeo/inside/location.hpp"
#include "exactgeo/mesh/check.hpp"
#include "exactgeo/mesh/load.hpp"
#include "exactgeo/mesh/off_reader.hpp"
#include "exactgeo/predicates/bilinear_patch.hpp"
#include "exactgeo/predicates/ray_directions.hpp"
#include "exactgeo/predicates/ray_triangle.hpp"
#include "inside/polycube.hpp"
#include "inside/scaled_cube.hpp"
#include "mesh/hexahedron.hpp"
#include "support/generators.hpp"
#include "support/hexahedron.hpp"
#include "support/polygon_oracle.hpp"
#include "support/rational_oracle.hpp"
#include "support/seed.hpp"
#include "support/solid_angle_oracle.hpp"

namespace exactgeo::inside::known_truth {
namespace {

using mesh::Face;
using mesh::make_triangle;
using mesh::Mesh;

using polycube::FaceOrigin;
using polycube::Lattice;
using polycube::Polycube;
using polycube::Voxels;
using Weights = std::array<double, 4>;

constexpr double kInf = std::numeric_limits<double>::infinity();

std::ostream& operator<<(std::ostream& out, Location l) {
  return out << to_string(l);
}

/// The arguments streamed one after the other.
template <class... Parts>
std::string cat(const Parts&... parts) {
  std::ostringstream out;
  (out << ... << parts);
  return out.str();
}

std::string hex(const Point3& p) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "(%a, %a, %a)", p[0], p[1], p[2]);
  return buf;
}

std::string str(Location l) {
  return std::string(to_string(l));
}

std::string describe(const Voxels& v) {
  std::ostringstream s;
  s << "n = " << v.n << ", filled voxels:";
  for (const Lattice& c : v.filled_list())
    s << " (" << c[0] << "," << c[1] << "," << c[2] << ")";
  return s.str();
}

std::string describe(const Mesh& mesh) {
  std::ostringstream s;
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
    s << "  v" << i << " " << hex(mesh.vertices[i]) << "\n";
  for (const Face& f : mesh.faces) {
    s << "  f";
    for (std::size_t k = 0; k < f.size(); ++k)
      s << " " << f.corners[k];
    s << "\n";
  }
  return s.str();
}

/// Embree's and the box tree's candidates with the space cells on; brute force, the
/// reference, without them: every comparison with it checks the cells' labels too.
/// The options for `mesh`: the default nonzero rule when its faces are oriented, parity
/// (which needs no orientation) otherwise. The solids here are embedded, so both rules
/// label alike; check_solid checks that they do where both apply.
ClassifierOptions search(CandidateSearch candidates, const Mesh& mesh) {
  ClassifierOptions options;
  options.candidates = candidates;
  options.allow_non_manifold = true;
  options.space_cells = candidates != CandidateSearch::brute_force;
  if (mesh::check_mesh(mesh).unbalanced_edges.count > 0) options.rule = FillRule::parity;
  return options;
}

// ---------------------------------------------------------------------------------------
// Classifying a probe set every way and comparing

/// A point to classify, with its truth when the construction gives one.
struct Probe {
  Point3 point{};
  std::optional<Location> truth;
  bool rational = false;  ///< also classify with Arithmetic::rational (slow)
};

struct CheckOptions {
  bool brute_force = true;
  bool batch = true;
  std::size_t brute_force_stride = 1;  ///< brute force on every k-th point only
};

struct SolidReport {
  std::vector<Location> exact;     ///< Embree candidates, exact, one point at a time
  std::vector<Location> doubles;   ///< Embree candidates, plain double
  std::vector<std::size_t> wrong;  ///< probes with a wrong or inconsistent label
  std::size_t with_truth = 0;
};

/// Classifies every probe with Embree's, the box tree's and brute-force candidates, in
/// batches of 1 and 3
/// threads, with rational arithmetic where asked and with plain double (only counted).
/// Expects every exact label to equal the truth and all exact ways to agree.
SolidReport check_solid(std::string_view name, const Mesh& mesh, const std::vector<Probe>& probes,
                        CheckOptions options = {}) {
  SolidReport r;
  const auto start = std::chrono::steady_clock::now();
  const Classifier embree(mesh, search(CandidateSearch::embree, mesh));
  std::vector<Point3> points;
  points.reserve(probes.size());
  for (const Probe& p : probes)
    points.push_back(p.point);

  std::size_t failures = 0;
  std::string messages;
  const auto bad = [&](std::size_t i, const std::string& what) {
    if (r.wrong.empty() || r.wrong.back() != i) r.wrong.push_back(i);
    if (++failures <= 10) messages += cat("  ", hex(points[i]), ": ", what, "\n");
  };

  ClassifierScratch scratch;
  r.exact.resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    r.exact[i] = embree.classify(points[i], Arithmetic::exact, scratch);
    if (probes[i].truth) {
      ++r.with_truth;
      if (r.exact[i] != *probes[i].truth)
        bad(i, cat("exact ", r.exact[i], ", truth ", *probes[i].truth));
    }
  }
  if (options.brute_force) {
    const Classifier brute(mesh, search(CandidateSearch::brute_force, mesh));
    for (std::size_t i = 0; i < points.size(); i += options.brute_force_stride) {
      const Location b = brute.classify(points[i], Arithmetic::exact, scratch);
      if (b != r.exact[i]) bad(i, cat("brute force ", b, ", embree ", r.exact[i]));
    }
  }
  {
    const Classifier tree(mesh, search(CandidateSearch::box_tree, mesh));
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Location t = tree.classify(points[i], Arithmetic::exact, scratch);
      if (t != r.exact[i]) bad(i, cat("box tree ", t, ", embree ", r.exact[i]));
    }
  }
  if (options.batch) {
    for (const unsigned threads : {1u, 3u}) {
      std::vector<Location> out(points.size(), Location::boundary);
      classify_batch(embree, points, out, Arithmetic::exact, threads);
      for (std::size_t i = 0; i < points.size(); ++i)
        if (out[i] != r.exact[i])
          bad(i, cat("batch on ", threads, " threads ", out[i], ", single ", r.exact[i]));
    }
  }
  std::size_t rational_count = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!probes[i].rational) continue;
    ++rational_count;
    const Location q = embree.classify(points[i], Arithmetic::rational, scratch);
    if (q != r.exact[i]) bad(i, cat("rational ", q, ", exact ", r.exact[i]));
  }
  // Every rule labels an embedded solid alike: parity against the default nonzero.
  if (embree.rule() != FillRule::parity) {
    ClassifierOptions parity = search(CandidateSearch::embree, mesh);
    parity.rule = FillRule::parity;
    const Classifier by_parity(mesh, parity);
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Location l = by_parity.classify(points[i], Arithmetic::exact, scratch);
      if (l != r.exact[i]) bad(i, cat("parity rule ", l, ", nonzero ", r.exact[i]));
    }
  }
  // Plain double may be wrong; it must only run (within its 64 rays).
  std::size_t disagreements = 0;
  r.doubles.resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    r.doubles[i] = embree.classify(points[i], Arithmetic::plain_double, scratch);
    if (r.doubles[i] != r.exact[i]) ++disagreements;
  }
  std::cout << "[ info     ] " << name << ": " << points.size() << " points (" << r.with_truth
            << " with known truth, " << rational_count << " also rational), " << mesh.faces.size()
            << " faces; plain double disagrees with exact on " << disagreements << "; "
            << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
            << " s\n";

  EXPECT_EQ(failures, 0u) << name << ": " << failures << " wrong or inconsistent labels, first:\n"
                          << messages;
  return r;
}

// ---------------------------------------------------------------------------------------
// Points on faces at dyadic parameters

/// Corner weights (1-u)(1-v), u(1-v), uv, (1-u)v of a quad at u = i/8, v = j/8, or the
/// barycentric weights i/8, j/8, (8-i-j)/8 of a triangle, for every such (i, j) with i and
/// j multiples of `step`.
std::vector<Weights> dyadic_weights(bool triangle, int step = 1) {
  std::vector<Weights> out;
  for (int i = 0; i <= 8; i += step)
    for (int j = 0; j <= 8; j += step) {
      const double u = i / 8.0, v = j / 8.0;
      if (!triangle) {
        out.push_back({(1 - u) * (1 - v), u * (1 - v), u * v, (1 - u) * v});
      } else if (i + j <= 8) {
        out.push_back({u, v, (8 - i - j) / 8.0, 0.0});
      }
    }
  return out;
}

/// The point sum_k w_k corner_k evaluated in double, corner by corner (for a quad this is
/// p(u, v) written as above), and whether it equals the exact value (checked in rationals).
Point3 face_point(const Mesh& mesh, const Face& face, const Weights& w, bool& exact) {
  Point3 p{};
  for (std::size_t i = 0; i < 3; ++i) {
    double sum = 0;
    mpq_class reference = 0;
    for (std::size_t k = 0; k < face.size(); ++k) {
      const double c = mesh.vertices[face.corners[k]][i];
      sum += w[k] * c;
      reference += mpq_class(w[k]) * mpq_class(c);
    }
    p[i] = sum;
    if (mpq_class(sum) != reference) exact = false;
  }
  return p;
}

Point3 nudged(Point3 p, std::size_t axis, double towards) {
  p[axis] = std::nextafter(p[axis], towards);
  return p;
}

/// Whether q lies on some face (exact oracle, independent of the library).
bool on_some_face(const Mesh& mesh, const Point3& q) {
  for (const Face& f : mesh.faces) {
    bool in_box = true;
    for (std::size_t i = 0; i < 3 && in_box; ++i) {
      double lo = kInf, hi = -kInf;
      for (std::size_t k = 0; k < f.size(); ++k) {
        lo = std::min(lo, mesh.vertices[f.corners[k]][i]);
        hi = std::max(hi, mesh.vertices[f.corners[k]][i]);
      }
      in_box = lo <= q[i] && q[i] <= hi;
    }
    if (in_box && testing::point_on_patch_oracle(q, patch_of(mesh, f))) return true;
  }
  return false;
}

// ---------------------------------------------------------------------------------------
// Polycube probes, with truths that can be recomputed on a smaller voxel set

struct Variant {
  bool triangles = false;
  bool perturb = false;
  std::uint64_t seed = 0;  ///< diagonals and offsets
  /// Instead of perturb: y scaled by 2^kShearYExponent, vertices moved along ray 0.
  bool shear = false;

  std::string describe() const {
    return cat(triangles ? "triangles" : "quads", perturb ? ", perturbed" : "",
               shear ? ", y scaled and sheared along ray 0" : "", ", variant seed ", seed);
  }
};

/// With y scaled by 2^-4, ray direction k becomes (1, 2k+3, ...) in lattice units: from
/// points with half-integer x and y, it passes through lattice lines parallel to z.
constexpr int kShearYExponent = -4;

Polycube make(const Voxels& voxels, const Variant& v) {
  Polycube p = polycube::build_polycube(voxels);
  if (v.triangles) p = polycube::split_quads(p, v.seed);
  if (v.perturb) p = polycube::perturbed(std::move(p), polycube::mix(v.seed + 1));
  if (v.shear)
    p = polycube::sheared(std::move(p), polycube::mix(v.seed + 2), kShearYExponent,
                          ray_direction(0));
  return p;
}

/// Where a probe's truth comes from.
struct VoxelTruth {
  enum class Kind : std::uint8_t {
    none,          ///< unknown: only cross-checked
    half_lattice,  ///< coordinates twice / 2: the voxels around it decide
    on_face,       ///< on `face`: boundary
    beside_face,   ///< one ulp off the interior of `face`, on the side `above`
  };
  Kind kind = Kind::none;
  Lattice twice{};
  FaceOrigin face{};
  bool above = false;
};

std::optional<Location> evaluate(const VoxelTruth& t, const Voxels& voxels, const Polycube& p) {
  switch (t.kind) {
    case VoxelTruth::Kind::none:
      return std::nullopt;
    case VoxelTruth::Kind::half_lattice:
      return polycube::truth_at_half_lattice(voxels, t.twice);
    case VoxelTruth::Kind::on_face:
    case VoxelTruth::Kind::beside_face:
      // Removing voxels keeps a face only if its filled side stays filled.
      if (std::find(p.origins.begin(), p.origins.end(), t.face) == p.origins.end())
        return std::nullopt;
      if (t.kind == VoxelTruth::Kind::on_face) return Location::boundary;
      return voxels.filled(t.face.voxel(t.above)) ? Location::inside : Location::outside;
  }
  return std::nullopt;
}

struct PolycubeProbes {
  std::vector<Point3> points;
  std::vector<VoxelTruth> truths;
  std::vector<bool> rational;
  std::vector<bool> random_ulp;  ///< boundary exactly when on some face (oracle)
  std::size_t inexact_face_points = 0;

  void add(const Point3& p, const VoxelTruth& t, bool with_rational = false, bool ulp = false) {
    points.push_back(p);
    truths.push_back(t);
    rational.push_back(with_rational);
    random_ulp.push_back(ulp);
  }
};

void add_half_lattice_points(PolycubeProbes& probes, int n, bool moved, int y_exponent = 0) {
  for (int z = -2; z <= 2 * n + 2; ++z)
    for (int y = -2; y <= 2 * n + 2; ++y)
      for (int x = -2; x <= 2 * n + 2; ++x) {
        // On a moved surface only voxel centres (all odd) keep a known truth: they are 1/2
        // away from the original surface in its normal coordinate, and every point of the
        // surface moved by less than 1/2 in each coordinate (lattice units).
        const bool centre = (x & 1) && (y & 1) && (z & 1);
        VoxelTruth t;
        t.kind = (!moved || centre) ? VoxelTruth::Kind::half_lattice : VoxelTruth::Kind::none;
        t.twice = {x, y, z};
        probes.add({x / 2.0, std::ldexp(y / 2.0, y_exponent), z / 2.0}, t);
      }
}

/// Exact points on every face at dyadic parameters (boundary), and points one ulp off the
/// middle of each face along its lattice normal axis. The moved face is a graph over its
/// two lattice axes and stays within 1/8 of its square; from parameters whose unmoved
/// position is in [3/8, 5/8]^2 of the square, the segment along the normal to the voxel
/// centre's level, then to the centre, meets no other face: the point has the truth of the
/// voxel on its side.
void add_face_points(PolycubeProbes& probes, const Polycube& p, int step, bool beside = true) {
  for (std::size_t f = 0; f < p.mesh.faces.size(); ++f) {
    const Face& face = p.mesh.faces[f];
    const FaceOrigin& o = p.origins[f];
    const auto a = static_cast<std::size_t>(o.axis);
    for (const Weights& w : dyadic_weights(face.is_triangle(), step)) {
      bool exact = true;
      const Point3 q = face_point(p.mesh, face, w, exact);
      if (!exact) ++probes.inexact_face_points;
      probes.add(q, {VoxelTruth::Kind::on_face, {}, o, false});

      // The unmoved position, in the square's own coordinates.
      bool middle = true;
      for (std::size_t i = 0; i < 3; ++i) {
        if (i == a) continue;
        double s = 0;
        for (std::size_t k = 0; k < face.size(); ++k)
          s += w[k] * p.lattice[face.corners[k]][i];
        const double local = s - o.low[i];
        middle = middle && local >= 0.375 && local <= 0.625;
      }
      if (!beside || !middle) continue;
      probes.add(nudged(q, a, kInf), {VoxelTruth::Kind::beside_face, {}, o, true},
                 probes.points.size() % 7 == 0);
      probes.add(nudged(q, a, -kInf), {VoxelTruth::Kind::beside_face, {}, o, false},
                 probes.points.size() % 7 == 0);
    }
  }
}

/// Points one ulp from a random face point (edges and corners included) in a random
/// coordinate and direction: only cross-checked, and boundary exactly when on some face.
void add_random_ulp_points(PolycubeProbes& probes, const Polycube& p, std::mt19937_64& rng,
                           int count) {
  std::uniform_int_distribution<std::size_t> face_of(0, p.mesh.faces.size() - 1);
  std::uniform_int_distribution<std::size_t> axis_of(0, 2);
  std::bernoulli_distribution up(0.5);
  for (int r = 0; r < count; ++r) {
    const Face& face = p.mesh.faces[face_of(rng)];
    const std::vector<Weights> ws = dyadic_weights(face.is_triangle());
    std::uniform_int_distribution<std::size_t> weight_of(0, ws.size() - 1);
    bool exact = true;
    const Point3 q = face_point(p.mesh, face, ws[weight_of(rng)], exact);
    if (!exact) ++probes.inexact_face_points;
    probes.add(nudged(q, axis_of(rng), up(rng) ? kInf : -kInf), {}, true, true);
  }
}

/// A locally minimal voxel set (no single voxel can be removed) on which the probe still
/// gets a wrong or inconsistent exact label (with `ulp`: or is boundary exactly when it lies
/// on no face).
Voxels minimise(Voxels voxels, const Variant& variant, const Point3& point, const VoxelTruth& t,
                bool rational, bool ulp) {
  const auto fails = [&](const Voxels& v) {
    const Polycube p = make(v, variant);
    const Classifier e(p.mesh, search(CandidateSearch::embree, p.mesh));
    const Classifier b(p.mesh, search(CandidateSearch::brute_force, p.mesh));
    const Location le = e.classify(point), lb = b.classify(point);
    if (le != lb) return true;
    if (const auto truth = evaluate(t, v, p); truth && le != *truth) return true;
    if (ulp && (le == Location::boundary) != on_some_face(p.mesh, point)) return true;
    return rational && e.classify(point, Arithmetic::rational) != le;
  };
  if (!fails(voxels)) return voxels;  // e.g. a batch-only difference
  for (bool progress = true; progress;) {
    progress = false;
    for (const Lattice& c : voxels.filled_list()) {
      Voxels smaller = voxels;
      smaller.set(c, false);
      if (smaller.filled_list().empty() || !fails(smaller)) continue;
      voxels = smaller;
      progress = true;
    }
  }
  return voxels;
}

/// Classifies the probes against the polycube variant; on a wrong label, reports a
/// minimal voxel set for the first one.
SolidReport check_polycube(std::string_view name, const Voxels& voxels, const Variant& variant,
                           const PolycubeProbes& probes, CheckOptions options = {}) {
  const Polycube p = make(voxels, variant);
  EXPECT_EQ(probes.inexact_face_points, 0u) << name << ": face points not exact in double";
  std::vector<Probe> list(probes.points.size());
  for (std::size_t i = 0; i < list.size(); ++i)
    list[i] = {probes.points[i], evaluate(probes.truths[i], voxels, p), probes.rational[i]};
  SolidReport r = check_solid(name, p.mesh, list, options);

  for (std::size_t i = 0; i < list.size(); ++i) {
    if (!probes.random_ulp[i]) continue;
    const bool on = on_some_face(p.mesh, list[i].point);
    if ((r.exact[i] == Location::boundary) != on) {
      if (r.wrong.empty() || r.wrong.front() != i) r.wrong.insert(r.wrong.begin(), i);
      ADD_FAILURE() << name << ": " << hex(list[i].point) << " is " << str(r.exact[i])
                    << " but lies " << (on ? "on" : "on no") << " face";
    }
  }
  if (!r.wrong.empty()) {
    const std::size_t i = r.wrong.front();
    const Voxels m = minimise(voxels, variant, list[i].point, probes.truths[i], probes.rational[i],
                              probes.random_ulp[i]);
    const Polycube mp = make(m, variant);
    const auto truth = evaluate(probes.truths[i], m, mp);
    const Classifier e(mp.mesh, search(CandidateSearch::embree, mp.mesh));
    const Classifier b(mp.mesh, search(CandidateSearch::brute_force, mp.mesh));
    ADD_FAILURE() << name << ": minimal failing case (" << variant.describe() << ")\n  "
                  << describe(m) << "\n  point " << hex(list[i].point) << ": exact "
                  << str(e.classify(list[i].point)) << ", brute force "
                  << str(b.classify(list[i].point)) << ", rational "
                  << str(e.classify(list[i].point, Arithmetic::rational)) << ", truth "
                  << (truth ? str(*truth) : "unknown") << "\n"
                  << (mp.mesh.faces.size() <= 48 ? describe(mp.mesh) : "");
  }
  return r;
}

/// The mesh facts of a polycube: closed, every edge used by an even number of faces, the
/// four-face edges exactly those of the voxel set, accepted iff non-manifold is allowed.
void expect_polycube_mesh(const Voxels& voxels, const Polycube& p, bool triangles) {
  const mesh::MeshCheck c = mesh::check_mesh(p.mesh);
  const std::size_t non_manifold = polycube::count_non_manifold_edges(voxels);
  EXPECT_TRUE(c.closed());
  EXPECT_EQ(c.odd_edges.count, 0u);
  EXPECT_EQ(c.boundary_edges.count, 0u);
  EXPECT_EQ(c.non_manifold_edges.count, non_manifold) << describe(voxels);
  EXPECT_EQ(c.degenerate_faces.count, 0u);
  EXPECT_EQ(c.triangles, triangles ? c.faces : 0u);
  if (non_manifold == 0) {
    EXPECT_EQ(c.consistently_oriented, std::optional<bool>(true));
  }
  EXPECT_FALSE(mesh::closed_surface_problem(c, /*allow_non_manifold=*/true).has_value());
  // Every voxel face outward, so every edge is balanced, four-face edges included: the
  // winding rules accept the mesh; parity needs allow_non_manifold for four-face edges.
  EXPECT_EQ(c.unbalanced_edges.count, 0u);
  EXPECT_NO_THROW(Classifier(p.mesh, ClassifierOptions{}));
  ClassifierOptions parity;
  parity.rule = FillRule::parity;
  if (non_manifold > 0) {
    EXPECT_THROW(Classifier(p.mesh, parity), std::invalid_argument);
  } else {
    EXPECT_NO_THROW(Classifier(p.mesh, parity));
  }
}

/// How many of the points (every `stride`-th) lie on no face and see a degenerate first
/// ray: direction 0 of the sequence meets an edge or a vertex of a face (or lies in a flat
/// face's plane), so the classifier has to re-cast.
std::size_t degenerate_first_rays(const Mesh& mesh, const std::vector<Probe>& probes,
                                  std::size_t stride) {
  const Vector3 d = ray_direction(0);
  std::size_t count = 0;
  for (std::size_t i = 0; i < probes.size(); i += stride) {
    const Point3& o = probes[i].point;
    bool on = false, degenerate = false;
    for (const Face& f : mesh.faces) {
      if (f.is_triangle()) {
        const auto& v = mesh.vertices;
        const RayTriangle k =
            classify_ray_triangle(o, d, v[f.corners[0]], v[f.corners[1]], v[f.corners[2]]).kind;
        on = on || k == RayTriangle::origin_on;
        degenerate = degenerate || k == RayTriangle::edge || k == RayTriangle::vertex ||
                     k == RayTriangle::coplanar;
      } else {
        const RayPatch k = ray_patch_parity(o, d, patch_of(mesh, f));
        on = on || k == RayPatch::origin_on_patch;
        degenerate = degenerate || k == RayPatch::degenerate;
      }
    }
    if (degenerate && !on) ++count;
  }
  return count;
}

// ---------------------------------------------------------------------------------------
// 1, 2. Polycubes on the integer lattice, as quads and as triangles

/// A random voxel set in an n^3 grid, with a random density in [0.3, 0.7].
Voxels random_density_voxels(std::mt19937_64& rng, int n) {
  const double density = std::uniform_real_distribution<double>(0.3, 0.7)(rng);
  return polycube::random_voxels(rng, n, density);
}

void lattice_points_test(std::string_view stream, bool triangles) {
  auto rng = testing::seeded_engine(stream);
  std::size_t non_manifold_total = 0;
  const std::array<int, 4> sizes{4, 5, 6, 4};
  for (std::size_t trial = 0; trial < sizes.size(); ++trial) {
    const int n = sizes[trial];
    const Voxels voxels = random_density_voxels(rng, n);
    const Variant variant{triangles, false, rng()};
    const Polycube p = make(voxels, variant);
    SCOPED_TRACE(cat(describe(voxels), "; ", variant.describe()));
    expect_polycube_mesh(voxels, p, triangles);
    non_manifold_total += polycube::count_non_manifold_edges(voxels);

    PolycubeProbes probes;
    add_half_lattice_points(probes, n, false);
    const std::string name = cat(stream, " trial ", trial);
    const SolidReport r = check_polycube(name, voxels, variant, probes);

    // Plain double is expected right on voxel centres of the unmoved polycube.
    for (std::size_t i = 0; i < probes.points.size(); ++i) {
      const Lattice& t = probes.truths[i].twice;
      if ((t[0] & 1) && (t[1] & 1) && (t[2] & 1)) {
        const Location truth = polycube::truth_at_half_lattice(voxels, t);
        EXPECT_EQ(r.doubles[i], truth)
            << "plain double " << str(r.doubles[i]) << " at voxel centre " << hex(probes.points[i])
            << ", truth " << str(truth);
      }
    }

    // Orientation does not matter: flip a random half of the faces.
    std::bernoulli_distribution flip(0.5);
    std::vector<bool> flips(p.mesh.faces.size());
    for (std::size_t f = 0; f < flips.size(); ++f)
      flips[f] = flip(rng);
    const Mesh flipped =
        polycube::with_flipped_faces(p.mesh, [&](std::size_t f) { return flips[f]; });
    std::vector<Probe> list(probes.points.size());
    for (std::size_t i = 0; i < list.size(); ++i)
      list[i] = {probes.points[i], r.exact[i], false};
    check_solid(cat(name, " flipped"), flipped, list, {false, false});
  }
  // The random sets must exercise edges shared by four faces.
  EXPECT_GT(non_manifold_total, 0u);
}

TEST(KnownTruthPolycube, QuadsAtHalfLatticePoints) {
  lattice_points_test("KnownTruthPolycube.QuadsAtHalfLatticePoints", false);
}

TEST(KnownTruthPolycube, TrianglesAtHalfLatticePoints) {
  lattice_points_test("KnownTruthPolycube.TrianglesAtHalfLatticePoints", true);
}

TEST(KnownTruthPolycube, SingleVoxelAndEdgeTouchingPair) {
  // The smallest cases, every half-lattice point: one voxel, and two voxels sharing only
  // an edge (four faces on it) or only a vertex.
  for (const std::vector<Lattice>& filled : std::vector<std::vector<Lattice>>{
           {{0, 0, 0}}, {{0, 0, 0}, {1, 1, 0}}, {{0, 0, 0}, {1, 1, 1}}, {{1, 0, 0}, {0, 1, 1}}}) {
    Voxels voxels(2);
    for (const Lattice& c : filled)
      voxels.set(c, true);
    for (const bool triangles : {false, true}) {
      const Variant variant{triangles, false, 7};
      SCOPED_TRACE(cat(describe(voxels), "; ", variant.describe()));
      expect_polycube_mesh(voxels, make(voxels, variant), triangles);
      PolycubeProbes probes;
      add_half_lattice_points(probes, voxels.n, false);
      check_polycube(cat("small, ", describe(voxels)), voxels, variant, probes);
    }
  }
}

// ---------------------------------------------------------------------------------------
// 3. Skew patches: every lattice vertex moved by k/64, |k| <= 8

void moved_test(std::string_view stream, bool triangles) {
  auto rng = testing::seeded_engine(stream);
  const std::array<int, 3> sizes{4, 5, 4};
  // Every size at least once at a lower effort (tests/support/seed.hpp).
  const std::size_t trials = testing::scaled_trials(sizes.size(), 2);
  for (std::size_t trial = 0; trial < trials; ++trial) {
    const int n = sizes[trial];
    const Voxels voxels = random_density_voxels(rng, n);
    const Variant variant{triangles, true, rng()};
    const Polycube p = make(voxels, variant);
    SCOPED_TRACE(cat(describe(voxels), "; ", variant.describe()));
    expect_polycube_mesh(voxels, p, triangles);
    if (!triangles) {
      EXPECT_GT(mesh::check_mesh(p.mesh).non_planar_quads.count, 0u);
    }

    PolycubeProbes probes;
    add_half_lattice_points(probes, n, true);
    add_face_points(probes, p, 1);
    add_random_ulp_points(probes, p, rng, 40);
    check_polycube(cat(stream, " trial ", trial), voxels, variant, probes);
  }
}

TEST(KnownTruthPolycube, SkewQuadsKeepCentresAndFacePoints) {
  moved_test("KnownTruthPolycube.SkewQuadsKeepCentresAndFacePoints", false);
}

TEST(KnownTruthPolycube, MovedTrianglesKeepCentresAndFacePoints) {
  moved_test("KnownTruthPolycube.MovedTrianglesKeepCentresAndFacePoints", true);
}

TEST(KnownTruthPolycube, ShearedSkewPatchesForceRecasts) {
  // Skew patches on which the first ray from many voxel centres meets an edge: y scaled by
  // 2^-4 (exact), every vertex moved by k/64 times ray direction 0, |k| <= 8. In lattice
  // units the move is at most 1/8 in x, 3/8 in y and 9/2048 in z, less than the 1/2
  // between a voxel centre and the surface in the face's normal coordinate: centres keep
  // their truth.
  auto rng = testing::seeded_engine("KnownTruthPolycube.ShearedSkewPatchesForceRecasts");
  for (const bool triangles : {false, true}) {
    const int n = 5;
    const Voxels voxels = random_density_voxels(rng, n);
    Variant variant{triangles, false, rng()};
    variant.shear = true;
    const Polycube p = make(voxels, variant);
    SCOPED_TRACE(cat(describe(voxels), "; ", variant.describe()));
    expect_polycube_mesh(voxels, p, triangles);
    if (!triangles) {
      EXPECT_GT(mesh::check_mesh(p.mesh).non_planar_quads.count, 0u);
    }
    PolycubeProbes probes;
    add_half_lattice_points(probes, n, true, kShearYExponent);
    add_face_points(probes, p, 2, /*beside=*/false);
    add_random_ulp_points(probes, p, rng, 30);
    check_polycube(cat("sheared, ", variant.describe()), voxels, variant, probes);

    std::vector<Probe> centres;
    for (std::size_t i = 0; i < probes.points.size(); ++i)
      if (probes.truths[i].kind == VoxelTruth::Kind::half_lattice)
        centres.push_back({probes.points[i], {}, false});
    const std::size_t recast = degenerate_first_rays(p.mesh, centres, 1);
    std::cout << "[ info     ] " << recast << " of " << centres.size()
              << " voxel centres see a degenerate first ray\n";
    EXPECT_GT(recast, 0u);
  }
}

// ---------------------------------------------------------------------------------------
// 4. Exact maps (scaling by 2^k, translation, axis scalings, shears): identical labels

/// An affine map of space with dyadic coefficients, image = matrix p + offset (the same
/// offset in every coordinate), evaluated in double. Used only where it is exact.
struct ExactMap {
  std::string name;
  std::array<Vector3, 3> matrix{};  ///< rows
  double offset = 0;

  /// Coordinate i of the image is coordinate axes[i] times 2^exponents[i], plus offset.
  static ExactMap scaling(std::string name, const std::array<int, 3>& exponents, double offset = 0,
                          const std::array<std::size_t, 3>& axes = {0, 1, 2}) {
    ExactMap m{std::move(name), {}, offset};
    for (std::size_t i = 0; i < 3; ++i)
      m.matrix[i][axes[i]] = std::ldexp(1.0, exponents[i]);
    return m;
  }

  Point3 operator()(const Point3& p) const {
    Point3 q{};
    for (std::size_t i = 0; i < 3; ++i)
      q[i] = matrix[i][0] * p[0] + matrix[i][1] * p[1] + matrix[i][2] * p[2] + offset;
    return q;
  }
  /// Whether the double evaluation at p is exact (compared in rationals).
  bool exact_at(const Point3& p) const {
    const Point3 q = (*this)(p);
    for (std::size_t i = 0; i < 3; ++i) {
      mpq_class e = offset;
      for (std::size_t j = 0; j < 3; ++j)
        e += mpq_class(matrix[i][j]) * mpq_class(p[j]);
      if (mpq_class(q[i]) != e) return false;
    }
    return true;
  }
};

/// The polycube's probes keep their labels under the map (points it does not keep exactly,
/// e.g. one ulp off a coordinate near 0, are left out). Brute force on every k-th point.
/// Returns how many points (every `recast_stride`-th; none if 0) see a degenerate first ray
/// in the mapped mesh.
std::size_t expect_same_labels(std::string_view name, const Polycube& p,
                               const PolycubeProbes& probes, const std::vector<Location>& labels,
                               const ExactMap& map, std::size_t brute_force_stride,
                               std::size_t recast_stride = 0) {
  Mesh mesh = p.mesh;
  for (Point3& v : mesh.vertices) {
    if (!map.exact_at(v)) {
      ADD_FAILURE() << map.name << " is not exact at vertex " << hex(v);
      return 0;
    }
    v = map(v);
  }
  std::vector<Probe> list;
  for (std::size_t i = 0; i < probes.points.size(); ++i)
    if (map.exact_at(probes.points[i]))
      list.push_back({map(probes.points[i]), labels[i], probes.rational[i]});
  EXPECT_GT(list.size(), probes.points.size() / 2) << map.name;
  check_solid(cat(name, " mapped by ", map.name), mesh, list, {true, false, brute_force_stride});
  return recast_stride == 0 ? 0 : degenerate_first_rays(mesh, list, recast_stride);
}

TEST(KnownTruthPolycube, PowerOfTwoScalingAndTranslationKeepLabels) {
  auto rng = testing::seeded_engine("KnownTruthPolycube.PowerOfTwoScalingAndTranslationKeepLabels");
  for (const bool triangles : {false, true}) {
    const Voxels voxels = polycube::random_voxels(rng, 4, 0.5);
    const Variant variant{triangles, true, rng()};
    const Polycube p = make(voxels, variant);
    SCOPED_TRACE(cat(describe(voxels), "; ", variant.describe()));
    PolycubeProbes probes;
    add_half_lattice_points(probes, voxels.n, true);
    add_face_points(probes, p, 4);
    add_random_ulp_points(probes, p, rng, 20);
    const std::string name = cat("scaling, ", variant.describe());
    const SolidReport base = check_polycube(name, voxels, variant, probes, {false, false});

    for (const int k : {-1000, -500, 500, 1000}) {
      // At 2^+-1000 the rays run in the unit frame (internal/unit_frame.hpp), as fast as
      // at 1: brute force checks the same sample of points at every scale.
      expect_same_labels(name, p, probes, base.exact, ExactMap::scaling(cat("2^", k), {k, k, k}),
                         4);
    }
    expect_same_labels(name, p, probes, base.exact,
                       ExactMap::scaling("+2^30", {0, 0, 0}, std::ldexp(1.0, 30)), 4);
    expect_same_labels(name, p, probes, base.exact,
                       ExactMap::scaling("2^500, +2^530", {500, 500, 500}, std::ldexp(1.0, 530)),
                       4);
  }
}

TEST(KnownTruthPolycube, ExactLinearMapsForceRecastsAndKeepLabels) {
  // Maps that make the first ray degenerate from many points. Scaling y by 2^-4 turns ray
  // direction k, (1, (2k+3)/16, ...), into (1, 2k+3, ...) in lattice units: it passes
  // through lattice lines at every integer step and meets edges and vertices of faces. The
  // shears put ray direction 0 into the planes of the faces normal to one axis: rays from
  // points in those planes lie in the plane of a flat face.
  auto rng = testing::seeded_engine("KnownTruthPolycube.ExactLinearMapsForceRecastsAndKeepLabels");
  std::uniform_int_distribution<int> exponent(-6, 6);
  constexpr double a = 3.0 / 16, b = 9.0 / 256;  // ray 0 is (1, a, b)
  std::vector<ExactMap> maps{
      ExactMap::scaling("(1, 2^-4, 1)", {0, -4, 0}),
      ExactMap::scaling("(1, 2^-4, 2^-8)", {0, -4, -8}),
      ExactMap::scaling("(2^4, 1, 1)", {4, 0, 0}),
      ExactMap::scaling("(1, 2^-3, 2^-6)", {0, -3, -6}),
      ExactMap::scaling("(z, x, y) scaled (1, 2^-4, 1)", {0, -4, 0}, 0, {2, 0, 1}),
      // e_z -> (0, a, b): planes y = c contain ray 0.
      {"shear: ray 0 in planes y = c", {{{1, 0, 0}, {0, 1, a}, {0, 0, b}}}},
      // e_z -> (1, 0, b): planes x = c contain ray 0.
      {"shear: ray 0 in planes x = c", {{{1, 0, 1}, {0, 1, 0}, {0, 0, b}}}},
      // e_y -> (0, a, b): planes z = c contain ray 0.
      {"shear: ray 0 in planes z = c", {{{1, 0, 0}, {0, a, 0}, {0, b, 1}}}},
  };
  std::array<std::size_t, 3> axes{0, 1, 2};
  std::shuffle(axes.begin(), axes.end(), rng);
  const std::array<int, 3> e{exponent(rng), exponent(rng), exponent(rng)};
  maps.push_back(ExactMap::scaling(
      cat("axes (", axes[0], axes[1], axes[2], ") scaled 2^(", e[0], ",", e[1], ",", e[2], ")"), e,
      0, axes));
  // (Skew patches with re-casts: ShearedSkewPatchesForceRecasts.)
  for (const Variant& variant : {Variant{false, false, rng()}, Variant{true, false, rng()}}) {
    const Voxels voxels = polycube::random_voxels(rng, 5, 0.5);
    const Polycube p = make(voxels, variant);
    SCOPED_TRACE(cat(describe(voxels), "; ", variant.describe()));
    PolycubeProbes probes;
    add_half_lattice_points(probes, voxels.n, false);
    const std::string name = cat("linear maps, ", variant.describe());
    const SolidReport base = check_polycube(name, voxels, variant, probes, {false, false});
    std::vector<Probe> unmapped(probes.points.size());
    for (std::size_t i = 0; i < unmapped.size(); ++i)
      unmapped[i].point = probes.points[i];
    std::string counts = cat(degenerate_first_rays(p.mesh, unmapped, 7), " unmapped");
    std::vector<std::size_t> recasts;
    for (const ExactMap& m : maps) {
      recasts.push_back(expect_same_labels(name, p, probes, base.exact, m, 2, 7));
      counts += cat(", ", recasts.back(), " ", m.name);
    }
    std::cout << "[ info     ] sampled points with a degenerate first ray: " << counts << "\n";
    // The premise of the test: the scalings and the shears make the classifier re-cast.
    EXPECT_GT(recasts[0], 0u);
    for (std::size_t k = 0; k < maps.size(); ++k)
      if (maps[k].name.starts_with("shear")) {
        EXPECT_GT(recasts[k], 0u) << maps[k].name;
      }
  }
}

// ---------------------------------------------------------------------------------------
// 5. Hand-made solids

using mesh::test_meshes::hexahedron;

std::array<Point3, 8> unit_box_corners() {
  std::array<Point3, 8> c{};
  for (std::size_t k = 0; k < 8; ++k)
    c[k] = {static_cast<double>(k & 1), static_cast<double>((k >> 1) & 1),
            static_cast<double>((k >> 2) & 1)};
  return c;
}

Mesh triangulated(const Mesh& quads, std::mt19937_64& rng) {
  Mesh out;
  out.vertices = quads.vertices;
  std::bernoulli_distribution first(0.5);
  for (const Face& f : quads.faces) {
    const auto& c = f.corners;
    if (first(rng)) {
      out.faces.push_back(make_triangle(c[0], c[1], c[2]));
      out.faces.push_back(make_triangle(c[0], c[2], c[3]));
    } else {
      out.faces.push_back(make_triangle(c[0], c[1], c[3]));
      out.faces.push_back(make_triangle(c[1], c[2], c[3]));
    }
  }
  return out;
}

/// Exact points on every face at dyadic parameters (boundary), and each of them moved by
/// one ulp along each axis both ways (truth from `truth`, or unknown).
template <class Truth>
void add_surface_probes(std::vector<Probe>& probes, const Mesh& mesh, Truth&& truth,
                        std::size_t& inexact) {
  for (const Face& f : mesh.faces)
    for (const Weights& w : dyadic_weights(f.is_triangle(), 2)) {
      bool exact = true;
      const Point3 q = face_point(mesh, f, w, exact);
      if (!exact) ++inexact;
      probes.push_back({q, Location::boundary, false});
      for (std::size_t a = 0; a < 3; ++a)
        for (const double towards : {kInf, -kInf}) {
          const Point3 r = nudged(q, a, towards);
          probes.push_back({r, truth(r), probes.size() % 3 == 0});
        }
    }
}

/// Grid points lo + i * step in every coordinate, i = 0 .. count - 1.
std::vector<Point3> grid(const Point3& lo, const std::array<double, 3>& step,
                         const std::array<int, 3>& count) {
  std::vector<Point3> out;
  for (int i = 0; i < count[0]; ++i)
    for (int j = 0; j < count[1]; ++j)
      for (int k = 0; k < count[2]; ++k)
        out.push_back({lo[0] + i * step[0], lo[1] + j * step[1], lo[2] + k * step[2]});
  return out;
}

/// Probes at the grid points and, around every boundary one, one ulp off along each axis
/// both ways; every `rational_every`-th of those is also checked with rationals.
template <class Truth>
std::vector<Probe> grid_probes(const std::vector<Point3>& points, const Truth& truth,
                               std::size_t rational_every) {
  std::vector<Probe> probes;
  for (const Point3& p : points) {
    probes.push_back({p, truth(p), false});
    if (*probes.back().truth != Location::boundary) continue;
    for (std::size_t a = 0; a < 3; ++a)
      for (const double towards : {kInf, -kInf}) {
        const Point3 q = nudged(p, a, towards);
        probes.push_back({q, truth(q), probes.size() % rational_every == 0});
      }
  }
  return probes;
}

Location box_truth(const Point3& p) {
  bool closed = true, open = true;
  for (const double x : p) {
    closed = closed && 0 <= x && x <= 1;
    open = open && 0 < x && x < 1;
  }
  return open ? Location::inside : closed ? Location::boundary : Location::outside;
}

TEST(KnownTruthSolid, UnitCubeAsQuadsTrianglesAndFlippedFaces) {
  auto rng = testing::seeded_engine("KnownTruthSolid.UnitCubeAsQuadsTrianglesAndFlippedFaces");
  const Mesh cube = hexahedron(unit_box_corners());
  // Grid points, and points one ulp off each face, edge and corner in every direction.
  std::vector<Probe> probes =
      grid_probes(grid({-0.5, -0.5, -0.5}, {0.25, 0.25, 0.25}, {9, 9, 9}), box_truth, 2);
  std::size_t inexact = 0;
  add_surface_probes(probes, cube, box_truth, inexact);
  EXPECT_EQ(inexact, 0u);

  check_solid("unit cube", cube, probes);
  check_solid("unit cube as triangles", triangulated(cube, rng), probes);
  // Inconsistent orientations: flip a random non-empty, non-full subset of faces.
  std::vector<bool> flips(cube.faces.size());
  do {
    for (std::size_t f = 0; f < flips.size(); ++f)
      flips[f] = std::bernoulli_distribution(0.5)(rng);
  } while (std::count(flips.begin(), flips.end(), true) % 6 == 0);
  const Mesh flipped = polycube::with_flipped_faces(cube, [&](std::size_t f) { return flips[f]; });
  EXPECT_EQ(mesh::check_mesh(flipped).consistently_oriented, std::optional<bool>(false));
  check_solid("unit cube, some faces flipped", flipped, probes);
}

TEST(KnownTruthSolid, BoxWithSkewTopAndBottom) {
  // Corners (x, y, bottom(x, y)) and (x, y, top(x, y)) over the unit square, with top and
  // bottom skew: the top and bottom patches are the graphs of the bilinear interpolants,
  // the sides are planar trapezoids. Inside: 0 < x, y < 1 and bottom < z < top (exact).
  auto rng = testing::seeded_engine("KnownTruthSolid.BoxWithSkewTopAndBottom");
  std::uniform_int_distribution<int> eighths(-2, 2);
  std::array<double, 4> bottom{}, top{};  // at (0,0), (1,0), (1,1), (0,1)
  const auto skew = [](const std::array<double, 4>& h) { return h[0] + h[2] != h[1] + h[3]; };
  do {
    for (std::size_t k = 0; k < 4; ++k) {
      bottom[k] = eighths(rng) / 8.0;
      top[k] = 1 + eighths(rng) / 8.0;
    }
  } while (!skew(bottom) || !skew(top));
  std::array<Point3, 8> corners{};
  const std::array<std::size_t, 4> square{0, 1, 3,
                                          2};  // box corner index of (0,0), (1,0), (1,1), (0,1)
  for (std::size_t k = 0; k < 4; ++k) {
    const double x = (square[k] & 1) ? 1 : 0, y = (square[k] & 2) ? 1 : 0;
    corners[square[k]] = {x, y, bottom[k]};
    corners[square[k] + 4] = {x, y, top[k]};
  }
  const Mesh solid = hexahedron(corners);
  ASSERT_EQ(mesh::check_mesh(solid).non_planar_quads.count, 2u);

  const auto truth = [&](const Point3& p) {
    const mpq_class x(p[0]), y(p[1]), z(p[2]);
    if (x < 0 || x > 1 || y < 0 || y > 1) return Location::outside;
    const auto height = [&](const std::array<double, 4>& h) -> mpq_class {
      return (1 - x) * (1 - y) * h[0] + x * (1 - y) * h[1] + x * y * h[2] + (1 - x) * y * h[3];
    };
    const mpq_class lo = height(bottom), hi = height(top);
    if (z < lo || z > hi) return Location::outside;
    if (x == 0 || x == 1 || y == 0 || y == 1 || z == lo || z == hi) return Location::boundary;
    return Location::inside;
  };
  std::vector<Probe> probes =
      grid_probes(grid({-0.125, -0.125, -0.5}, {0.125, 0.125, 0.0625}, {11, 11, 33}), truth, 5);
  std::size_t inexact = 0;
  add_surface_probes(probes, solid, truth, inexact);
  EXPECT_EQ(inexact, 0u);
  check_solid("box with skew top and bottom", solid, probes);
  std::vector<bool> flips{true, false, false, true, true, false};
  check_solid("box with skew top and bottom, some faces flipped",
              polycube::with_flipped_faces(solid, [&](std::size_t f) { return flips[f]; }), probes);
}

TEST(KnownTruthSolid, HexahedronWithVertexMovedAlongDiagonal) {
  // The unit cube with corner (1,1,1) moved to (1+d)(1,1,1): its three faces become skew,
  // each with one coordinate >= 1 (x-face: x = 1 + d uv), equal to 1 only on its two
  // unmoved edges. Known truth: points of the open unit cube are inside (the ray towards
  // -x crosses only the face x = 0, once); points of the closed cube with a zero
  // coordinate are on a planar face; points with a coordinate < 0 or > 1 + d are outside.
  // The rest (and every point one ulp off a face) is cross-checked only.
  auto rng = testing::seeded_engine("KnownTruthSolid.HexahedronWithVertexMovedAlongDiagonal");
  const double d = std::uniform_int_distribution<int>(1, 4)(rng) / 4.0;
  std::array<Point3, 8> corners = unit_box_corners();
  corners[7] = {1 + d, 1 + d, 1 + d};
  const Mesh solid = hexahedron(corners);
  ASSERT_EQ(mesh::check_mesh(solid).non_planar_quads.count, 3u);

  const auto truth = [&](const Point3& p) -> std::optional<Location> {
    bool open = true, closed = true, beyond = false, zero = false;
    for (const double x : p) {
      open = open && 0 < x && x < 1;
      closed = closed && 0 <= x && x <= 1;
      beyond = beyond || x < 0 || x > 1 + d;
      zero = zero || x == 0;
    }
    if (open) return Location::inside;
    if (beyond) return Location::outside;
    if (closed && zero) return Location::boundary;
    return std::nullopt;
  };
  std::vector<Probe> probes;
  std::size_t known = 0;
  for (const Point3& p : grid({-0.5, -0.5, -0.5}, {0.125, 0.125, 0.125}, {21, 21, 21})) {
    probes.push_back({p, truth(p), p[0] == p[1]});
    known += probes.back().truth ? 1 : 0;
  }
  EXPECT_GT(known, probes.size() / 2);
  std::size_t inexact = 0;
  const auto unknown = [](const Point3&) { return std::optional<Location>(); };
  const std::size_t first_surface = probes.size();
  add_surface_probes(probes, solid, unknown, inexact);
  EXPECT_EQ(inexact, 0u);
  const SolidReport r = check_solid("hexahedron with a moved vertex", solid, probes);
  // Points one ulp off a face are boundary exactly when they lie on some face.
  std::size_t wrong = 0;
  for (std::size_t i = first_surface; i < probes.size(); ++i) {
    if (probes[i].truth) continue;
    if ((r.exact[i] == Location::boundary) != on_some_face(solid, probes[i].point)) {
      if (++wrong <= 5) ADD_FAILURE() << hex(probes[i].point) << " is " << str(r.exact[i]);
    }
  }
  EXPECT_EQ(wrong, 0u);
}

TEST(KnownTruthSolid, TetrahedronOfTriangles) {
  // A random tetrahedron with integer corners; truth from the exact orientations of the
  // point against each face (GMP oracle): all on the side of the opposite corner -> inside,
  // some on the other side -> outside, else boundary.
  auto rng = testing::seeded_engine("KnownTruthSolid.TetrahedronOfTriangles");
  std::uniform_int_distribution<int> coordinate(-3, 3);
  std::array<Point3, 4> v{};
  do {
    for (Point3& p : v)
      for (double& x : p)
        x = coordinate(rng);
  } while (testing::orient3d_oracle(v[0], v[1], v[2], v[3]) == Sign::zero);
  Mesh tetra;
  tetra.vertices.assign(v.begin(), v.end());
  std::bernoulli_distribution flip(0.5);
  for (VertexIndex opposite = 0; opposite < 4; ++opposite) {
    std::array<VertexIndex, 3> f{};
    for (VertexIndex k = 0, j = 0; k < 4; ++k)
      if (k != opposite) f[j++] = k;
    if (flip(rng)) std::swap(f[1], f[2]);  // orientation must not matter
    tetra.faces.push_back(make_triangle(f[0], f[1], f[2]));
  }
  const auto truth = [&](const Point3& q) {
    bool all_inner = true;
    for (const Face& f : tetra.faces) {
      VertexIndex opposite = 0;
      while (std::find(f.corners.begin(), f.corners.end(), opposite) != f.corners.end())
        ++opposite;
      const auto& c = f.corners;
      const Sign side = testing::orient3d_oracle(v[c[0]], v[c[1]], v[c[2]], q) *
                        testing::orient3d_oracle(v[c[0]], v[c[1]], v[c[2]], v[opposite]);
      if (side == Sign::negative) return Location::outside;
      all_inner = all_inner && side == Sign::positive;
    }
    return all_inner ? Location::inside : Location::boundary;
  };
  std::vector<Probe> probes;
  for (const Point3& p : grid({-3.5, -3.5, -3.5}, {0.5, 0.5, 0.5}, {15, 15, 15}))
    probes.push_back({p, truth(p), false});
  std::size_t inexact = 0;
  add_surface_probes(probes, tetra, truth, inexact);
  EXPECT_EQ(inexact, 0u);
  std::size_t inside = 0;
  for (const Probe& p : probes)
    inside += p.truth == Location::inside ? 1 : 0;
  EXPECT_GT(inside, 0u);
  check_solid("tetrahedron", tetra, probes);
}

}  // namespace
}  // namespace exactgeo::inside::known_truth
