// exactgeo-cloth: an example simulator loop on the mesh-level CCD (exactgeo/ccd/mesh/mesh_ccd.hpp).
//
// Cloth falls onto obstacles (scene.hpp: a sheet onto a block, the default; a long ribbon
// that stacks on itself; sheets over a spinning ball), drapes and folds onto itself. Each
// step the sheets' motion is predicted (the block scene's grid of springs,
// cloth_model.hpp, or position-based dynamics on any triangulation, mesh_cloth_model.hpp),
// then made collision free by velocity filtering with exact CCD on the whole mesh, sheets
// and obstacles together (collision_filter.hpp says why the filter ends and why its result
// is safe). After the filter, a second MeshCcd object, which sees only the filtered steps,
// checks every step again: a collision there exits with code 1, so the example is also a
// test. With --remesh the sheets are remeshed after every step (remesher.hpp), each
// operation collision safe; with the mesh model, the exact self-intersection finder
// checks the whole mesh after every step and every remesh, and any intersecting pair
// exits with code 1 as well.
//
// Exit codes: 0 success, 1 a filtered step still collides, the mesh intersects itself or
// the filter could not make progress, 2 usage or output error (message on stderr).

#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "cloth_model.hpp"
#include "collision_filter.hpp"
#include "exactgeo/ccd/mesh/mesh_ccd.hpp"
#include "exactgeo/mesh/self_intersection.hpp"
#include "mesh_cloth_model.hpp"
#include "narrow_phase_timing.hpp"
#include "obj_output.hpp"
#include "remesher.hpp"
#include "scene.hpp"

namespace {

namespace fs = std::filesystem;
using exactgeo::cloth::FilterStats;
using exactgeo::cloth::SceneKind;

constexpr int kSuccess = 0;
constexpr int kCollision = 1;
constexpr int kUsageError = 2;

struct Options {
  SceneKind scene = SceneKind::block;
  std::uint32_t layers = 3;
  bool remesh = false;
  bool time_narrow_phase = false;
  std::uint32_t resolution = 40;
  double dt = 1.0 / 120.0;
  std::size_t steps = 200;
  std::string output;
  std::size_t every = 1;
  std::string queries;
  bool json = false;
  bool toi = false;
  double separation = 0.002;
  unsigned threads = 0;
  double jitter = 0.0;
  std::uint64_t seed = 1;
};

/// The message for options that parse but make no sense, or nothing.
std::optional<std::string> check(const Options& o, double start_gap) {
  if (o.resolution < 2 || o.resolution > 2048) return "--resolution must be in [2, 2048]";
  if (!std::isfinite(o.dt) || o.dt <= 0.0 || o.dt > 0.1) return "--dt must be in (0, 0.1]";
  if (o.every == 0) return "--every must be at least 1";
  if (!std::isfinite(o.separation) || o.separation < 0.0 || o.separation > 0.1) {
    return "--separation must be in [0, 0.1] metres";
  }
  if (o.layers < 1 || o.layers > 16) return "--layers must be in [1, 16]";
  if (o.jitter != 0.0 && o.scene != SceneKind::block) return "--jitter is for the block scene";
  if (!std::isfinite(o.jitter) || o.jitter < 0.0 || o.jitter >= start_gap) {
    return "--jitter must be in [0, " + std::to_string(start_gap) +
           ") metres (the start must be collision free)";
  }
  return std::nullopt;
}

/// Totals over the run.
struct Totals {
  FilterStats filter;
  std::size_t steps_with_collisions = 0;
  std::size_t max_rounds = 0;
  double verify_seconds = 0.0;
  exactgeo::cloth::RemeshCounts remesh;
  std::size_t intersection_checks = 0;
  double intersection_seconds = 0.0;
  std::size_t triangles_start = 0;
  std::size_t triangles_end = 0;
  std::size_t sheet_triangles_start = 0;
  std::size_t sheet_triangles_end = 0;
  std::optional<exactgeo::cloth::NarrowPhaseTiming> timing;

  void add(const FilterStats& s) {
    filter += s;
    if (s.collisions() > 0) ++steps_with_collisions;
    if (s.rounds > max_rounds) max_rounds = s.rounds;
  }
};

std::string numbered(const char* prefix, std::size_t step, const char* suffix) {
  char name[64];
  std::snprintf(name, sizeof name, "%s%04zu%s", prefix, step, suffix);
  return name;
}

void make_directory(const std::string& dir, const char* option) {
  std::error_code error;
  fs::create_directories(dir, error);
  if (error || !fs::is_directory(dir)) {
    throw std::runtime_error(std::string(option) + ": cannot create directory '" + dir +
                             "': " + error.message());
  }
}

std::string counts_json(const exactgeo::cloth::VerdictCounts& c) {
  char text[160];
  std::snprintf(text, sizeof text,
                "{\"applied\": %zu, \"refused_collision\": %zu, \"refused_topology\": %zu, "
                "\"deferred\": %zu}",
                c.applied, c.refused_collision, c.refused_topology, c.deferred);
  return text;
}

std::string calls_json(const exactgeo::cloth::CallTimes& t) {
  char text[200];
  std::snprintf(text, sizeof text,
                "{\"calls\": %zu, \"ns_per_call\": %.1f, \"colliding_calls\": %zu, "
                "\"ns_per_colliding_call\": %.1f, \"ns_per_colliding_call_min\": %.1f, "
                "\"ns_per_colliding_call_max\": %.1f}",
                t.calls, t.nanoseconds_per_call(), t.colliding_calls,
                t.nanoseconds_per_colliding_call(), t.colliding_min(), t.colliding_max());
  return text;
}

std::string timing_json(const exactgeo::cloth::NarrowPhaseTiming& timing) {
  std::string out = "{";
  for (const auto& [name, m] :
       {std::pair{"exact", &timing.exact()}, std::pair{"cubic", &timing.cubic()}}) {
    if (out.size() > 1) out.append(", ");
    out.append("\"").append(name).append("\": {\"vertex_face\": ");
    out.append(calls_json(m->vertex_face)).append(", \"edge_edge\": ");
    out.append(calls_json(m->edge_edge)).append("}");
  }
  return out + "}";
}

void print_summary(const Options& o, const exactgeo::cloth::ClothMesh& mesh, const Totals& t) {
  const FilterStats& f = t.filter;
  const std::size_t steps = o.steps;
  if (o.json) {
    std::printf(
        "{\"scene\": \"%s\", \"steps\": %zu, \"resolution\": %u, \"filter\": \"%s\", "
        "\"triangles\": %zu, "
        "\"vertices\": %zu, \"cloth_vertices\": %zu, \"candidates_total\": %zu, "
        "\"collisions_total\": %zu, \"self_collisions_total\": %zu, "
        "\"obstacle_collisions_total\": %zu, \"rounds_total\": %zu, \"frozen_total\": %zu, "
        "\"trees_rebuilt_total\": %zu, \"obstacle_held_steps\": %zu, "
        "\"ccd_seconds\": %.6f, \"broad_phase_seconds\": %.6f, \"narrow_phase_seconds\": %.6f, "
        "\"verify_seconds\": %.6f, \"intersection_checks\": %zu, "
        "\"intersection_check_seconds\": %.6f",
        std::string(exactgeo::cloth::to_string(o.scene)).c_str(), steps, o.resolution,
        o.toi ? "toi" : "freeze", mesh.faces.size(), mesh.vertex_count(), mesh.sheet_vertices(),
        f.candidates, f.collisions(), f.self_pairs, f.obstacle_pairs, f.rounds, f.frozen,
        f.trees_rebuilt, f.obstacle_held, f.seconds, f.broad_phase_seconds, f.narrow_phase_seconds,
        t.verify_seconds, t.intersection_checks, t.intersection_seconds);
    if (o.remesh) {
      std::printf(
          ", \"remesh\": true, \"triangles_start\": %zu, \"triangles_end\": %zu, "
          "\"sheet_triangles_start\": %zu, \"sheet_triangles_end\": %zu, "
          "\"remesh_seconds\": %.6f, \"operations\": {\"split\": %s, \"collapse\": %s, "
          "\"flip\": %s}",
          t.triangles_start, t.triangles_end, t.sheet_triangles_start, t.sheet_triangles_end,
          t.remesh.seconds, counts_json(t.remesh.split).c_str(),
          counts_json(t.remesh.collapse).c_str(), counts_json(t.remesh.flip).c_str());
    }
    if (t.timing) std::printf(", \"narrow_phase_per_call\": %s", timing_json(*t.timing).c_str());
    std::printf("}\n");
    return;
  }
  std::printf("steps %zu, vertices %zu (cloth %zu), triangles %zu (cloth %zu)\n", steps,
              mesh.vertex_count(), mesh.sheet_vertices(), mesh.faces.size(), mesh.sheet_faces);
  std::printf(
      "ccd: %zu rounds (at most %zu in a step; %zu built a tree anew), %.3f s "
      "(broad phase %.3f s, narrow phase %.3f s), %.3f ms per step\n",
      f.rounds, t.max_rounds, f.trees_rebuilt, f.seconds, f.broad_phase_seconds,
      f.narrow_phase_seconds, steps > 0 ? 1e3 * f.seconds / static_cast<double>(steps) : 0.0);
  std::printf(
      "collisions: %zu pairs (self %zu, obstacle %zu; vertex-face %zu, edge-edge %zu) "
      "in %zu steps; %zu candidates; %zu vertices stopped\n",
      f.collisions(), f.self_pairs, f.obstacle_pairs, f.vertex_face, f.edge_edge,
      t.steps_with_collisions, f.candidates, f.frozen);
  if (f.obstacle_held > 0) std::printf("obstacle held back in %zu steps\n", f.obstacle_held);
  if (o.remesh) {
    const auto line = [](const char* kind, const exactgeo::cloth::VerdictCounts& c) {
      std::printf(
          "  %-8s %8zu applied, %6zu refused (collision), %6zu refused (topology), %6zu "
          "deferred\n",
          kind, c.applied, c.refused_collision, c.refused_topology, c.deferred);
    };
    std::printf("remesh: cloth triangles %zu -> %zu, %.3f s\n", t.sheet_triangles_start,
                t.sheet_triangles_end, t.remesh.seconds);
    line("split", t.remesh.split);
    line("collapse", t.remesh.collapse);
    line("flip", t.remesh.flip);
  }
  std::printf("verified: every filtered step collision free (%.3f s)\n", t.verify_seconds);
  if (t.intersection_checks > 0) {
    std::printf("verified: no intersecting faces in %zu exact checks (%.3f s)\n",
                t.intersection_checks, t.intersection_seconds);
  }
  if (t.timing) {
    for (const auto& [name, m] :
         {std::pair{"exact", &t.timing->exact()}, std::pair{"cubic", &t.timing->cubic()}}) {
      std::printf(
          "narrow phase, %s: vertex-face %.0f ns per call (%.0f ns per colliding call, "
          "replays %.0f-%.0f), edge-edge %.0f ns (%.0f ns, %.0f-%.0f)\n",
          name, m->vertex_face.nanoseconds_per_call(),
          m->vertex_face.nanoseconds_per_colliding_call(), m->vertex_face.colliding_min(),
          m->vertex_face.colliding_max(), m->edge_edge.nanoseconds_per_call(),
          m->edge_edge.nanoseconds_per_colliding_call(), m->edge_edge.colliding_min(),
          m->edge_edge.colliding_max());
    }
  }
}

/// The first pair of intersecting faces of the whole mesh, found exactly, or nothing.
std::optional<std::string> intersection(const exactgeo::cloth::ClothMesh& mesh, unsigned threads,
                                        Totals& totals) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  exactgeo::mesh::Mesh m;
  m.vertices.resize(mesh.vertex_count());
  for (std::size_t v = 0; v < m.vertices.size(); ++v) {
    m.vertices[v] = {mesh.positions[3 * v], mesh.positions[3 * v + 1], mesh.positions[3 * v + 2]};
  }
  for (const exactgeo::ccd::Triangle& t : mesh.faces)
    m.faces.push_back(exactgeo::mesh::make_triangle(t[0], t[1], t[2]));
  // Cloth must stay apart: a sheet lying flat on another, facing the other way, is a
  // contact too (the rule for solids set face to face would let it pass).
  const exactgeo::mesh::SelfIntersections found = exactgeo::mesh::find_self_intersections(
      m, threads, exactgeo::mesh::CoplanarOverlap::intersecting);
  ++totals.intersection_checks;
  totals.intersection_seconds += std::chrono::duration<double>(Clock::now() - start).count();
  if (found.intersecting.empty() && found.undecided.empty()) return std::nullopt;
  const exactgeo::mesh::FacePair pair =
      found.intersecting.empty() ? found.undecided.front() : found.intersecting.front();
  return std::to_string(found.intersecting.size()) + " intersecting face pairs (faces " +
         std::to_string(pair.first) + " and " + std::to_string(pair.second) + " first)";
}

/// The scene as the simulation holds it.
exactgeo::cloth::ClothMesh cloth_mesh(const exactgeo::cloth::Scene& scene) {
  exactgeo::cloth::ClothMesh mesh;
  mesh.positions = scene.positions;
  mesh.velocity.assign(3 * scene.cloth_vertices, 0.0);
  mesh.material = scene.material;
  mesh.faces = scene.faces;
  mesh.sheet_faces = scene.cloth_faces;
  return mesh;
}

/// The CCD objects of a mesh's connectivity: the filter's and the independent checker's.
struct Collisions {
  exactgeo::cloth::CollisionFilter filter;
  exactgeo::ccd::MeshCcd checker;

  Collisions(const exactgeo::cloth::ClothMesh& mesh, const exactgeo::cloth::FilterOptions& options)
      : filter(mesh.vertex_count(), mesh.faces, mesh.sheet_vertices(), options),
        checker(mesh.vertex_count(), mesh.faces) {}
};

int run(const Options& o) {
  using Clock = std::chrono::steady_clock;
  exactgeo::cloth::SceneOptions scene_options;
  scene_options.kind = o.scene;
  scene_options.resolution = o.resolution;
  scene_options.jitter = o.jitter;
  scene_options.seed = o.seed;
  scene_options.layers = o.layers;
  const exactgeo::cloth::Scene scene = exactgeo::cloth::make_scene(scene_options);
  exactgeo::cloth::ClothMesh mesh = cloth_mesh(scene);
  const std::vector<double> obstacle_rest(
      scene.positions.begin() + static_cast<std::ptrdiff_t>(3 * scene.cloth_vertices),
      scene.positions.end());

  // The block scene keeps its grid of springs unless it is remeshed.
  const bool mesh_model = o.remesh || o.scene != SceneKind::block;
  std::optional<exactgeo::cloth::ClothModel> grid_model;
  std::optional<exactgeo::cloth::MeshClothModel> cloth_model;
  if (mesh_model) {
    cloth_model.emplace(scene);
  } else {
    grid_model.emplace(scene);
  }
  exactgeo::cloth::RemeshParameters remesh_parameters;
  remesh_parameters.max_length = scene.spacing;
  remesh_parameters.min_length = scene.spacing / 2.0;
  exactgeo::remesh::PassWorkspace remesh_workspace;  // the passes' memory, kept for the run
  exactgeo::cloth::KeptSheetEdges remesh_edges;      // the sheet edges one remesh leaves the next

  Totals totals;
  if (o.time_narrow_phase) totals.timing.emplace();
  exactgeo::cloth::FilterOptions filter_options;
  filter_options.kind =
      o.toi ? exactgeo::cloth::FilterKind::time_of_impact : exactgeo::cloth::FilterKind::freeze;
  filter_options.separation = o.toi ? 0.0 : o.separation;
  filter_options.threads = o.threads;
  if (totals.timing) filter_options.timing = &*totals.timing;
  std::optional<Collisions> collisions(std::in_place, mesh, filter_options);
  exactgeo::ccd::MeshCcdOptions check_options;
  check_options.threads = o.threads;

  if (!o.output.empty()) make_directory(o.output, "--output");
  if (!o.queries.empty()) make_directory(o.queries, "--queries");

  totals.triangles_start = mesh.faces.size();
  totals.sheet_triangles_start = mesh.sheet_faces;
  const auto intersecting = [&](const char* when, std::size_t step) {
    if (!mesh_model) return false;
    const std::optional<std::string> found = intersection(mesh, o.threads, totals);
    if (!found) return false;
    std::fflush(stdout);
    std::cerr << "exactgeo-cloth: step " << step << ", " << when
              << ": the mesh intersects itself: " << *found << '\n';
    if (!o.output.empty()) {
      exactgeo::cloth::write_obj(fs::path(o.output) / numbered("failed_", step, ".obj"),
                                 mesh.positions, mesh.faces, mesh.sheet_faces);
    }
    return true;
  };
  if (intersecting("at the start", 0)) return kCollision;

  std::vector<double> x1(mesh.positions.size());
  std::vector<double> first_t1;
  double ball_angle = 0.0;
  if (!o.output.empty()) {
    exactgeo::cloth::write_obj(fs::path(o.output) / numbered("frame_", 0, ".obj"), mesh.positions,
                               mesh.faces, mesh.sheet_faces);
  }
  if (!o.json) {
    std::printf("%5s %6s %10s %10s %6s %8s %7s %9s\n", "step", "rounds", "candidates", "collisions",
                "self", "obstacle", "frozen", "ccd_ms");
  }
  for (std::size_t step = 1; step <= o.steps; ++step) {
    const std::vector<double>& x0 = mesh.positions;
    x1.resize(x0.size());
    const double turn = scene.ball ? scene.ball->angular_speed * o.dt : 0.0;
    if (grid_model) {
      grid_model->predict(x0, mesh.velocity, x1, o.dt);
    } else {
      cloth_model->predict(x0, mesh.velocity, x1, o.dt, turn);
      const std::size_t obstacle = 3 * mesh.sheet_vertices();
      exactgeo::cloth::place_obstacle(scene, obstacle_rest, ball_angle + turn,
                                      std::span<double>(x1).subspan(obstacle));
    }
    FilterStats stats =
        collisions->filter.filter(x0, x1, mesh.velocity, o.queries.empty() ? nullptr : &first_t1);
    // The frozen vertices pin the sheet around them for a second projection, so that it
    // follows them instead of stretching away (the filter then checks that step again).
    if (cloth_model && stats.frozen > 0) {
      cloth_model->relax(x0, mesh.velocity, x1, collisions->filter.frozen(), o.dt, turn);
      stats += collisions->filter.filter(x0, x1, mesh.velocity);
    }
    if (!o.queries.empty()) {
      exactgeo::cloth::write_obj(fs::path(o.queries) / numbered("step_", step, "_t0.obj"), x0,
                                 mesh.faces, mesh.sheet_faces);
      exactgeo::cloth::write_obj(fs::path(o.queries) / numbered("step_", step, "_t1.obj"), first_t1,
                                 mesh.faces, mesh.sheet_faces);
    }

    // The explicit check of the filtered step, by a second MeshCcd that sees only these.
    const Clock::time_point start = Clock::now();
    const exactgeo::ccd::MeshCcdResult check = collisions->checker.step({x0, x1}, check_options);
    totals.verify_seconds += std::chrono::duration<double>(Clock::now() - start).count();
    if (check.collision()) {
      std::fflush(stdout);
      std::cerr << "exactgeo-cloth: step " << step << ": the filtered step still collides ("
                << check.vertex_face.size() << " vertex-face, " << check.edge_edge.size()
                << " edge-edge pairs)\n";
      if (!o.output.empty()) {
        exactgeo::cloth::write_obj(fs::path(o.output) / numbered("failed_", step, "_t0.obj"), x0,
                                   mesh.faces, mesh.sheet_faces);
        exactgeo::cloth::write_obj(fs::path(o.output) / numbered("failed_", step, "_t1.obj"), x1,
                                   mesh.faces, mesh.sheet_faces);
        std::cerr << "exactgeo-cloth: the step's frames are in " << o.output << "/"
                  << numbered("failed_", step, "_t{0,1}.obj") << '\n';
      }
      return kCollision;
    }

    totals.add(stats);
    if (stats.obstacle_held == 0) ball_angle += turn;
    if (!o.json) {
      std::printf("%5zu %6zu %10zu %10zu %6zu %8zu %7zu %9.3f\n", step, stats.rounds,
                  stats.candidates, stats.collisions(), stats.self_pairs, stats.obstacle_pairs,
                  stats.frozen, 1e3 * stats.seconds);
    }
    mesh.positions.swap(x1);
    if (intersecting("after the step", step)) return kCollision;
    if (o.remesh) {
      const exactgeo::cloth::RemeshCounts counts =
          exactgeo::cloth::remesh(mesh, remesh_parameters, &remesh_workspace, &remesh_edges);
      totals.remesh += counts;
      if (counts.split.applied + counts.collapse.applied + counts.flip.applied > 0) {
        cloth_model->set_topology(mesh.faces, mesh.sheet_faces, mesh.material);
        collisions.reset();
        collisions.emplace(mesh, filter_options);
        if (intersecting("after remeshing", step)) return kCollision;
      }
    }
    if (!o.output.empty() && step % o.every == 0) {
      exactgeo::cloth::write_obj(fs::path(o.output) / numbered("frame_", step, ".obj"),
                                 mesh.positions, mesh.faces, mesh.sheet_faces);
    }
  }
  totals.triangles_end = mesh.faces.size();
  totals.sheet_triangles_end = mesh.sheet_faces;
  if (totals.timing) totals.timing->finish();  // the colliding calls still kept
  print_summary(o, mesh, totals);
  return kSuccess;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "exactgeo-cloth: a cloth sheet falls onto a floor with a raised block; every step is made "
      "collision free with the mesh-level exact CCD (velocity filtering) and checked again.",
      "exactgeo-cloth"};
  Options o;
  // CLI11 2.1 wraps "-1" around for unsigned options: refuse negative numbers first.
  const CLI::Validator non_negative(
      [](std::string& text) {
        return text.find('-') == std::string::npos ? std::string() : "must not be negative";
      },
      "", "NONNEGATIVE");
  std::string scene_name = "block";
  app.add_option("--scene", scene_name,
                 "block: a sheet onto a block; stack: a long ribbon (resolution x 10 resolution "
                 "vertices) that piles up on itself; ball: sheets over a spinning ball")
      ->check(CLI::IsMember({"block", "stack", "ball"}))
      ->capture_default_str();
  app.add_option("--layers", o.layers, "ball scene: the number of sheets")
      ->check(non_negative)
      ->capture_default_str();
  app.add_flag("--remesh", o.remesh,
               "remesh the cloth after every step (split, collapse, flip; curvature-adaptive "
               "sizes), every operation collision safe");
  app.add_flag("--time-narrow-phase", o.time_narrow_phase,
               "also time the exact and the cubic narrow phase per call on every CCD round's "
               "candidates (one thread)");
  app.add_option("--resolution", o.resolution, "sheet vertices per side")
      ->check(non_negative)
      ->capture_default_str();
  app.add_option("--dt", o.dt, "time step in seconds")->capture_default_str();
  app.add_option("--steps", o.steps, "time steps")->check(non_negative)->capture_default_str();
  app.add_option("--output", o.output,
                 "write the whole mesh after every --every steps as DIR/frame_NNNN.obj "
                 "(frame_0000: the start)");
  app.add_option("--every", o.every, "steps between frames")
      ->check(non_negative)
      ->capture_default_str();
  app.add_option("--queries", o.queries,
                 "write each step's first CCD call as DIR/step_NNNN_t0.obj and _t1.obj "
                 "(inputs for `exactgeo ccd-mesh` and benchmarks)");
  app.add_flag("--json", o.json, "print one JSON summary object instead of the table");
  CLI::Option* toi = app.add_flag(
      "--toi", o.toi,
      "filter by scaling the step to 0.8 times the time of impact instead of freezing");
  CLI::Option* separation =
      app.add_option("--separation", o.separation,
                     "freeze filter: stop vertices about this far (metres) before a contact")
          ->capture_default_str();
  toi->excludes(separation);
  app.add_option("--threads", o.threads, "CCD threads; 0: one per hardware thread")
      ->check(non_negative)
      ->capture_default_str();
  app.add_option("--jitter", o.jitter,
                 "seeded vertical perturbation of the sheet at the start (metres)")
      ->capture_default_str();
  app.add_option("--seed", o.seed, "seed of --jitter")->check(non_negative)->capture_default_str();

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);  // prints help or the error
    return code == 0 ? kSuccess : kUsageError;
  }
  o.scene = *exactgeo::cloth::parse_scene(scene_name);
  // The sheets' start gap depends on the scene only.
  exactgeo::cloth::SceneOptions smallest;
  smallest.kind = o.scene;
  smallest.resolution = 2;
  smallest.layers = 1;
  const double start_gap = exactgeo::cloth::make_scene(smallest).start_gap;
  if (const std::optional<std::string> message = check(o, start_gap)) {
    std::cerr << "exactgeo-cloth: " << *message << '\n';
    return kUsageError;
  }
  try {
    return run(o);
  } catch (const std::runtime_error& e) {  // output files
    std::fflush(stdout);
    std::cerr << "exactgeo-cloth: " << e.what() << '\n';
    return kUsageError;
  } catch (const std::exception& e) {  // the filter could not make progress
    std::fflush(stdout);
    std::cerr << "exactgeo-cloth: " << e.what() << '\n';
    return kCollision;
  }
}
