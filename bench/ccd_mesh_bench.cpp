// Step-time benchmark of mesh-level CCD (docs/ccd.md, scripts/ccd-mesh-bench.py).
//
//   ccd_mesh_bench FRAME0 [FRAME1] [--motion A] [--seed S] [--threads T]
//                  [--method exact|parity] [--repeat R] [--standing F] [--compare]
//
// Without FRAME1, every vertex of FRAME0 moves by A times the mean edge length in each
// coordinate (uniform, seeded); with --standing F, the fraction F of vertices lowest on the
// widest axis stands still. Quads are split into two triangles. Prints one JSON object: the
// best of R runs of a fresh MeshCcd's first step, then the same MeshCcd's second step on the
// same frames (trees kept). Then the broad phase alone against the baseline
// (baseline/mesh_broad_phase.hpp, the broad phase before refitted trees), best of R each,
// on a following step: FRAME1 to FRAME1 plus a new random motion without FRAME1, the same
// frames again with it; the library's trees were built on the first step and are refitted;
// both candidate sets are compared. With --compare, the broad-phase structures on the same
// boxes in the same run: testing every pair (small meshes only), sweep and prune along x
// (sweep_and_prune.hpp), and a tree queried once per box (baseline/box_tree.hpp).

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "baseline/box_tree.hpp"
#include "baseline/mesh_broad_phase.hpp"
#include "exactgeo/predicates/kernel/unit_magnitude.hpp"
#include "exactgeo/ccd/mesh/internal/broad_phase.hpp"
#include "exactgeo/ccd/mesh/mesh_ccd.hpp"
#include "mesh_step.hpp"
#include "sweep_and_prune.hpp"

namespace {

using namespace exactgeo;

using ccd::bench::MeshStep;

double seconds(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct StructureTime {
  std::size_t overlaps = 0;
  double seconds = 0.0;
};

/// The broad-phase structures on the same boxes (every primitive counted as moving, no
/// adjacency filter): vertex-face and edge-edge box overlaps, and the time to find them.
struct StructureComparison {
  std::optional<StructureTime> all_pairs;  // only for small meshes: it is quadratic
  StructureTime sweep_and_prune;
  StructureTime tree;
};

StructureComparison compare_structures(const ccd::MeshCcd& mesh, const MeshStep& mesh_step) {
  using ccd::bench::baseline::swept_box;
  using ccd::bench::baseline::SweptBox;
  std::vector<SweptBox> vertices, edges, faces;
  for (std::uint32_t v = 0; v < mesh.vertex_count(); ++v)
    vertices.push_back(
        swept_box(std::array<std::uint32_t, 1>{v}, v, mesh_step.t0.data(), mesh_step.t1.data()));
  for (std::uint32_t e = 0; e < mesh.edges().size(); ++e)
    edges.push_back(swept_box(mesh.edges()[e], e, mesh_step.t0.data(), mesh_step.t1.data()));
  for (std::uint32_t f = 0; f < mesh.faces().size(); ++f)
    faces.push_back(swept_box(mesh.faces()[f], f, mesh_step.t0.data(), mesh_step.t1.data()));

  StructureComparison c;
  if (edges.size() <= 40000) {
    const auto start = std::chrono::steady_clock::now();
    StructureTime t;
    for (const auto& v : vertices)
      for (const auto& f : faces)
        t.overlaps += ccd::bench::baseline::overlap(v, f) ? 1 : 0;
    for (std::size_t a = 0; a < edges.size(); ++a)
      for (std::size_t b = a + 1; b < edges.size(); ++b)
        t.overlaps += ccd::bench::baseline::overlap(edges[a], edges[b]) ? 1 : 0;
    t.seconds = seconds(start);
    c.all_pairs = t;
  }
  {
    const auto start = std::chrono::steady_clock::now();
    auto v = vertices, e = edges, f = faces;
    const int axis = 0;
    for (auto* list : {&v, &e, &f})
      ccd::bench::sort_for_sweep(*list, axis);
    std::size_t n = 0;
    const auto count = [&n](std::uint32_t, std::uint32_t) { ++n; };
    using ccd::bench::Scan;
    ccd::bench::sweep(v, 0, v.size(), f, Scan::from_equal, axis, count);
    ccd::bench::sweep(f, 0, f.size(), v, Scan::from_above, axis, count);
    ccd::bench::sweep(e, 0, e.size(), e, Scan::after_self, axis, count);
    c.sweep_and_prune = {n, seconds(start)};
  }
  {
    const auto start = std::chrono::steady_clock::now();
    const ccd::bench::baseline::QueryTree face_tree(faces), edge_tree(edges);
    std::size_t n = 0;
    for (const auto& v : vertices)
      face_tree.query(v, [&n](std::uint32_t) { ++n; });
    for (const auto& e : edges)
      edge_tree.query(e, [&n, &e](std::uint32_t other) { n += other > e.id ? 1 : 0; });
    c.tree = {n, seconds(start)};
  }
  return c;
}

/// The library's broad phase on a following step (its trees built on `first`, refitted)
/// against the baseline's, on one thread count, best of `repeat` each.
struct BroadPhaseComparison {
  double baseline_seconds = INFINITY;
  double refit_seconds = INFINITY;
  bool rebuilt = false;  ///< the library rebuilt a tree on the following step
  std::size_t candidates = 0;
  bool same_candidates = false;
};

template <class Candidates>
std::vector<std::array<std::uint32_t, 3>> sorted_pairs(const Candidates& c) {
  std::vector<std::array<std::uint32_t, 3>> pairs;
  for (const auto& p : c.vertex_face)
    pairs.push_back({0, p.vertex, p.face});
  for (const auto& p : c.edge_edge)
    pairs.push_back({1, p.a, p.b});
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

BroadPhaseComparison compare_broad_phases(const ccd::MeshCcd& mesh, const ccd::StepPositions& first,
                                          const ccd::StepPositions& next, unsigned threads,
                                          int repeat) {
  BroadPhaseComparison c;
  ccd::internal::MeshBroadPhase library(mesh.vertex_count(), mesh.faces(), mesh.edges());
  ccd::bench::baseline::MeshBroadPhase baseline(mesh.vertex_count(), mesh.faces(), mesh.edges());
  // The library's broad phase is handed the step's largest magnitude, which MeshCcd::step
  // has from its magnitude check; here it is found inside the timed region, as the
  // baseline finds it.
  const auto largest = [](const ccd::StepPositions& f) {
    return std::max(kernel::largest_magnitude(f.t0), kernel::largest_magnitude(f.t1));
  };
  library.candidates(first, largest(first), threads);
  baseline.candidates(first, threads);  // its standing trees, as a MeshCcd would keep them
  std::vector<std::array<std::uint32_t, 3>> library_pairs, baseline_pairs;
  for (int r = 0; r < repeat; ++r) {
    auto start = std::chrono::steady_clock::now();
    const auto base = baseline.candidates(next, threads);
    c.baseline_seconds = std::min(c.baseline_seconds, seconds(start));
    start = std::chrono::steady_clock::now();
    const auto mine = library.candidates(next, largest(next), threads);
    c.refit_seconds = std::min(c.refit_seconds, seconds(start));
    if (r == 0) {
      c.rebuilt = mine.trees_rebuilt;
      c.candidates = mine.vertex_face.size() + mine.edge_edge.size();
      c.same_candidates = sorted_pairs(mine) == sorted_pairs(base);
    }
  }
  return c;
}

[[noreturn]] void usage(const std::string& why) {
  std::cerr << "ccd_mesh_bench: " << why << "\n";
  std::exit(2);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> paths;
  double motion = 0.5, standing = 0.0;
  std::uint64_t seed = 1;
  unsigned threads = 1;
  int repeat = 3;
  bool compare = false;
  ccd::Method method = ccd::Method::exact;
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
      threads = static_cast<unsigned>(std::stoul(value()));
    else if (a == "--repeat")
      repeat = std::stoi(value());
    else if (a == "--standing")
      standing = std::stod(value());
    else if (a == "--compare")
      compare = true;

    else if (a == "--method") {
      const auto m = ccd::parse_method(value());
      if (!m) usage("unknown method");
      method = *m;
    } else if (!a.empty() && a[0] == '-')
      usage("unknown option " + a);
    else
      paths.push_back(a);
  }
  if (paths.empty() || paths.size() > 2) usage("one or two mesh files expected");

  const std::optional<MeshStep> loaded = ccd::bench::load_step(paths, motion, standing, seed);
  if (!loaded) usage("frames differ in vertex count");
  const MeshStep& mesh_step = *loaded;

  const ccd::StepPositions view{mesh_step.t0, mesh_step.t1};
  const ccd::MeshCcdOptions options{method, std::nullopt, threads};
  ccd::MeshCcdResult best, second;
  double best_total = INFINITY;
  for (int r = 0; r < repeat; ++r) {
    ccd::MeshCcd mesh(mesh_step.t0.size() / 3, mesh_step.faces);
    const ccd::MeshCcdResult result = mesh.step(view, options);
    const double total = result.broad_phase_seconds + result.narrow_phase_seconds;
    if (total < best_total) {
      best_total = total;
      best = result;
      second = mesh.step(view, options);
    }
  }
  // The following step: from FRAME1 on by a new random motion, or the same frames again.
  const MeshStep following =
      paths.size() == 1 ? ccd::bench::moved_on(mesh_step, motion, standing, seed + 1) : mesh_step;
  const BroadPhaseComparison broad =
      compare_broad_phases(ccd::MeshCcd(mesh_step.t0.size() / 3, mesh_step.faces), view,
                           ccd::StepPositions{following.t0, following.t1}, threads, repeat);

  std::optional<StructureComparison> structures;
  if (compare)
    structures = compare_structures(ccd::MeshCcd(mesh_step.t0.size() / 3, mesh_step.faces), mesh_step);

  const std::size_t collisions = best.vertex_face.size() + best.edge_edge.size();
  std::printf(
      "{\"mesh\": \"%s\", \"triangles\": %zu, \"vertices\": %zu, \"method\": \"%s\", "
      "\"threads\": %u, \"motion\": %g, \"standing\": %g, \"vertex_face_candidates\": %zu, "
      "\"edge_edge_candidates\": %zu, \"vertex_face\": %zu, \"edge_edge\": %zu, "
      "\"broad_phase_seconds\": %.6g, \"narrow_phase_seconds\": %.6g, "
      "\"ns_per_candidate\": %.6g, \"candidates_per_collision\": %.6g, "
      "\"second_step_broad_phase_seconds\": %.6g, \"second_step_rebuilt\": %s, "
      "\"next_step_candidates\": %zu, \"next_step_baseline_broad_phase_seconds\": %.6g, "
      "\"next_step_broad_phase_seconds\": %.6g, \"next_step_rebuilt\": %s, "
      "\"broad_phase_speedup\": %.4g, \"same_candidates_as_baseline\": %s",
      paths[0].c_str(), mesh_step.faces.size(), mesh_step.t0.size() / 3,
      std::string(ccd::to_string(method)).c_str(), threads, motion, standing,
      best.vertex_face_candidates, best.edge_edge_candidates, best.vertex_face.size(),
      best.edge_edge.size(), best.broad_phase_seconds, best.narrow_phase_seconds,
      best.candidates() ? 1e9 * best.narrow_phase_seconds / static_cast<double>(best.candidates())
                        : 0.0,
      collisions ? static_cast<double>(best.candidates()) / static_cast<double>(collisions) : 0.0,
      second.broad_phase_seconds, second.trees_rebuilt ? "true" : "false", broad.candidates,
      broad.baseline_seconds, broad.refit_seconds, broad.rebuilt ? "true" : "false",
      broad.baseline_seconds / broad.refit_seconds, broad.same_candidates ? "true" : "false");
  if (structures) {
    const auto print = [](const char* name, const StructureTime& t) {
      std::printf(", \"%s_overlaps\": %zu, \"%s_seconds\": %.6g", name, t.overlaps, name,
                  t.seconds);
    };
    if (structures->all_pairs) print("all_pairs", *structures->all_pairs);
    print("sweep_and_prune", structures->sweep_and_prune);
    print("tree", structures->tree);
  }
  std::printf("}\n");
  return 0;
}
