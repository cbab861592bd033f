// exactgeo-cloth: an example simulator loop on the mesh-level CCD (exactgeo/ccd/mesh/mesh_ccd.hpp).
//
// A square cloth sheet falls onto a static floor with a raised block (scene.hpp), drapes
// around it and folds onto itself. Each step the sheet's motion is predicted by a mass-spring
// model (cloth_model.hpp), then made collision free by velocity filtering with exact CCD on
// the whole mesh, sheet and obstacle together (collision_filter.hpp says why the filter ends
// and why its result is safe). After the filter, a second MeshCcd object, which sees only
// the filtered steps, checks every step again: a collision there exits with code 1, so the
// example is also a test.
//
// Exit codes: 0 success, 1 a filtered step still collides (or the filter could not make
// progress), 2 usage or output error (message on stderr).

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
#include "obj_output.hpp"
#include "scene.hpp"

namespace {

namespace fs = std::filesystem;
using exactgeo::cloth::FilterStats;

constexpr int kSuccess = 0;
constexpr int kCollision = 1;
constexpr int kUsageError = 2;

struct Options {
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

void print_summary(const Options& o, const exactgeo::cloth::Scene& scene, const Totals& t) {
  const FilterStats& f = t.filter;
  const std::size_t steps = o.steps;
  if (o.json) {
    std::printf(
        "{\"steps\": %zu, \"resolution\": %u, \"filter\": \"%s\", \"triangles\": %zu, "
        "\"vertices\": %zu, \"cloth_vertices\": %zu, \"candidates_total\": %zu, "
        "\"collisions_total\": %zu, \"self_collisions_total\": %zu, "
        "\"obstacle_collisions_total\": %zu, \"rounds_total\": %zu, \"frozen_total\": %zu, "
        "\"trees_rebuilt_total\": %zu, "
        "\"ccd_seconds\": %.6f, \"broad_phase_seconds\": %.6f, \"narrow_phase_seconds\": %.6f, "
        "\"verify_seconds\": %.6f}\n",
        steps, o.resolution, o.toi ? "toi" : "freeze", scene.faces.size(),
        scene.positions.size() / 3, scene.cloth_vertices, f.candidates, f.collisions(),
        f.self_pairs, f.obstacle_pairs, f.rounds, f.frozen, f.trees_rebuilt, f.seconds,
        f.broad_phase_seconds, f.narrow_phase_seconds, t.verify_seconds);
    return;
  }
  std::printf("steps %zu, vertices %zu (sheet %zu), triangles %zu (sheet %zu)\n", steps,
              scene.positions.size() / 3, scene.cloth_vertices, scene.faces.size(),
              scene.cloth_faces);
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
  std::printf("verified: every filtered step collision free (%.3f s)\n", t.verify_seconds);
}

int run(const Options& o) {
  using Clock = std::chrono::steady_clock;
  exactgeo::cloth::SceneOptions scene_options;
  scene_options.resolution = o.resolution;
  scene_options.jitter = o.jitter;
  scene_options.seed = o.seed;
  const exactgeo::cloth::Scene scene = exactgeo::cloth::make_scene(scene_options);
  const std::size_t vertex_count = scene.positions.size() / 3;
  const std::size_t nc = scene.cloth_vertices;

  const exactgeo::cloth::ClothModel model(scene);
  exactgeo::cloth::FilterOptions filter_options;
  filter_options.kind =
      o.toi ? exactgeo::cloth::FilterKind::time_of_impact : exactgeo::cloth::FilterKind::freeze;
  filter_options.separation = o.toi ? 0.0 : o.separation;
  filter_options.threads = o.threads;
  exactgeo::cloth::CollisionFilter filter(vertex_count, scene.faces, nc, filter_options);
  exactgeo::ccd::MeshCcd checker(vertex_count, scene.faces);  // independent of the filter's
  exactgeo::ccd::MeshCcdOptions check_options;
  check_options.threads = o.threads;

  if (!o.output.empty()) make_directory(o.output, "--output");
  if (!o.queries.empty()) make_directory(o.queries, "--queries");

  std::vector<double> x0 = scene.positions;
  std::vector<double> x1(x0.size());
  std::vector<double> velocity(3 * nc, 0.0);
  std::vector<double> first_t1;
  if (!o.output.empty()) {
    exactgeo::cloth::write_obj(fs::path(o.output) / numbered("frame_", 0, ".obj"), x0, scene.faces);
  }
  if (!o.json) {
    std::printf("%5s %6s %10s %10s %6s %8s %7s %9s\n", "step", "rounds", "candidates", "collisions",
                "self", "obstacle", "frozen", "ccd_ms");
  }
  Totals totals;
  for (std::size_t step = 1; step <= o.steps; ++step) {
    model.predict(x0, velocity, x1, o.dt);
    const FilterStats stats =
        filter.filter(x0, x1, velocity, o.queries.empty() ? nullptr : &first_t1);
    if (!o.queries.empty()) {
      exactgeo::cloth::write_obj(fs::path(o.queries) / numbered("step_", step, "_t0.obj"), x0,
                                 scene.faces);
      exactgeo::cloth::write_obj(fs::path(o.queries) / numbered("step_", step, "_t1.obj"), first_t1,
                                 scene.faces);
    }

    // The explicit check of the filtered step, by a second MeshCcd that sees only these.
    const Clock::time_point start = Clock::now();
    const exactgeo::ccd::MeshCcdResult check = checker.step({x0, x1}, check_options);
    totals.verify_seconds += std::chrono::duration<double>(Clock::now() - start).count();
    if (check.collision()) {
      std::fflush(stdout);
      std::cerr << "exactgeo-cloth: step " << step << ": the filtered step still collides ("
                << check.vertex_face.size() << " vertex-face, " << check.edge_edge.size()
                << " edge-edge pairs)\n";
      if (!o.output.empty()) {
        exactgeo::cloth::write_obj(fs::path(o.output) / numbered("failed_", step, "_t0.obj"), x0,
                                   scene.faces);
        exactgeo::cloth::write_obj(fs::path(o.output) / numbered("failed_", step, "_t1.obj"), x1,
                                   scene.faces);
        std::cerr << "exactgeo-cloth: the step's frames are in " << o.output << "/"
                  << numbered("failed_", step, "_t{0,1}.obj") << '\n';
      }
      return kCollision;
    }

    totals.add(stats);
    if (!o.json) {
      std::printf("%5zu %6zu %10zu %10zu %6zu %8zu %7zu %9.3f\n", step, stats.rounds,
                  stats.candidates, stats.collisions(), stats.self_pairs, stats.obstacle_pairs,
                  stats.frozen, 1e3 * stats.seconds);
    }
    x0.swap(x1);
    if (!o.output.empty() && step % o.every == 0) {
      exactgeo::cloth::write_obj(fs::path(o.output) / numbered("frame_", step, ".obj"), x0,
                                 scene.faces);
    }
  }
  print_summary(o, scene, totals);
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
  // The sheet's start gap does not depend on the resolution.
  const double start_gap = exactgeo::cloth::make_scene({2, 0.0, 1}).start_gap;
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
