// ./kit bench cloth-explicit: the explicit cloth of chapter 6 on one core. An N×N sheet of 1 m
// (structural, shear and 4-neighbour bend springs, k = 2000 N/m, 0.1 kg/m², gravity, two corners
// of one edge pinned) at N = 32, 64, 128, 256:
//   1. ns per spring for the production force pass (ClothForces) and for a whole symplectic step
//      (ex 6.3), against a straightforward spring loop written here, timed in the same run, after
//      checking that both compute the same forces;
//   2. what bounds the step: bytes and flops per spring against a triad measured in the same run;
//   3. Bullet's soft-body cloth, the peer a game programmer would use: cost per simulated second
//      and how far its links stretch, against the kit at its own stable step.
// Timings live here, never in the tests.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include <fmt/format.h>

#include <kit/app/table.hpp>
#include <kit/base/stopwatch.hpp>
#include <kit/cloth/cloth.hpp>
#include <kit/cloth/cloth_forces.hpp>
#include <kit/cloth/cloth_stability.hpp>

#include "bandwidth.hpp"
#include "bullet_cloth.hpp"
#include "cloth_springs.hpp"
#include "cloth_step.hpp"

namespace {
using kit_bench::fastest;

constexpr double stiffness = 2000;  // [N/m], every family
// [N·s/m], every family: small enough that it barely moves the stable step (symplectic Euler on
// a mode of damping rate c = ω²μ/k needs (hω)² < 4 − 2hc; here hc ≤ 0.13 up to N = 256),
// non-zero so that the damping term is timed and checked.
constexpr double damping = 1e-3;
constexpr double density = 0.1;         // [kg/m²]
constexpr double t_end = 2;             // [s] simulated in part 3
constexpr double bullet_h = 1.0 / 240;  // [s], a game's step
const kit::Vec3 gravity{0, -9.81, 0};   // [m/s²]

// The sheet: horizontal (x, z) at height 1 m, held by the two corners of its j = 0 edge, so it
// swings down under gravity: the springs work, unlike a sheet that merely hangs at rest.
struct Sheet {
  kit::ClothGrid grid;
  kit::Springs springs;
  Eigen::VectorXd masses;          // [kg]
  std::vector<std::int32_t> pins;  // node indices
  double omega_max = 0;            // [rad/s]
  double dt = 0;                   // the kit's stable step [s]
};

Sheet make_sheet(int n) {
  Sheet sheet;
  sheet.grid.nx = sheet.grid.ny = n;
  sheet.grid.width = sheet.grid.height = 1;
  sheet.grid.origin = kit::Vec3(-0.5, 1, -0.5);
  sheet.grid.areal_density = density;
  kit::SpringLayout layout;
  layout.structural = layout.shear = layout.bend = kit::SpringFamily{stiffness, damping};
  layout.bend_layout = kit::BendLayout::four;
  sheet.springs = kit::build_springs(sheet.grid, layout);
  sheet.masses = sheet.grid.node_masses();
  sheet.pins = {std::int32_t(sheet.grid.index(0, 0)), std::int32_t(sheet.grid.index(n - 1, 0))};
  // The kit's own stable step: 0.9 of symplectic Euler's limit for the stiffest mode of the sheet
  // at rest (2/ω_max undamped, a little less with this damping, μ = c·k with c = μ/k), ω_max by
  // power iteration. ω_max² is about 15.4 k/m_node here, m_node = ρ·dx·dy: the stiffest mode
  // sits at a free corner (a quarter of m_node held by 2.5 springs' worth of stiffness along an
  // axis, pulled against its neighbours), above the 10 k/m_node of the corner alone.
  const kit::OmegaMax omega =
      kit::omega_max(sheet.springs, sheet.masses, sheet.grid.rest_positions(), sheet.pins, 1e-6);
  sheet.omega_max = omega.omega;
  sheet.dt =
      0.9 * kit::predicted_dt_max(kit::ClothIntegrator::symplectic_euler, omega.omega, damping / stiffness);
  return sheet;
}

// What a student writes first: double, struct of arrays, one loop over the spring list that
// computes each force and scatters it to both ends, then a symplectic update. The same model as
// ClothForces: f_a = [K (L0 − l) − μ dl/dt] x̂ with x = x_a − x_b, plus gravity m·g.
void plain_forces(const kit::Springs& springs, const Eigen::VectorXd& masses, const kit::NodeArray& x,
                  const kit::NodeArray& v, kit::NodeArray& f) {
  const long n = x.rows();
  f.resize(n, 3);
  const double *px = x.col(0).data(), *py = x.col(1).data(), *pz = x.col(2).data();
  const double *qx = v.col(0).data(), *qy = v.col(1).data(), *qz = v.col(2).data();
  double *fx = f.col(0).data(), *fy = f.col(1).data(), *fz = f.col(2).data();
  for (long i = 0; i < n; ++i)
    fx[i] = masses[i] * gravity.x(), fy[i] = masses[i] * gravity.y(), fz[i] = masses[i] * gravity.z();
  const std::size_t count = springs.size();
  for (std::size_t s = 0; s < count; ++s) {
    const long a = springs.a[s], b = springs.b[s];
    const double dx = px[a] - px[b], dy = py[a] - py[b], dz = pz[a] - pz[b];
    const double l = std::sqrt(dx * dx + dy * dy + dz * dz);
    const double rate = ((qx[a] - qx[b]) * dx + (qy[a] - qy[b]) * dy + (qz[a] - qz[b]) * dz) / l;  // dl/dt
    const double scale = (springs.stiffness[s] * (springs.rest[s] - l) - springs.damping[s] * rate) / l;
    fx[a] += scale * dx, fy[a] += scale * dy, fz[a] += scale * dz;
    fx[b] -= scale * dx, fy[b] -= scale * dy, fz[b] -= scale * dz;
  }
}

void plain_step(const Sheet& sheet, kit::NodeArray& x, kit::NodeArray& v, kit::NodeArray& f, double dt) {
  plain_forces(sheet.springs, sheet.masses, x, v, f);
  const long n = x.rows();
  for (int axis = 0; axis < 3; ++axis) {
    double* pv = v.col(axis).data();
    const double* pf = f.col(axis).data();
    for (long i = 0; i < n; ++i) pv[i] += dt * pf[i] / sheet.masses[i];
  }
  for (std::int32_t p : sheet.pins) v.row(p).setZero();
  x += dt * v;
}

// max |p − q| / max |q| over all entries: relative to the largest entry, since single entries
// (a node where springs and gravity cancel) can be near zero.
double relative_difference(const kit::NodeArray& p, const kit::NodeArray& q) {
  return (p - q).cwiseAbs().maxCoeff() / q.cwiseAbs().maxCoeff();
}

// A state where every spring works: rest positions moved by up to 5 % of a cell, and velocities
// up to 0.1 m/s, drawn from a fixed seed.
void disturbed_state(const Sheet& sheet, kit::NodeArray& x, kit::NodeArray& v) {
  std::mt19937_64 random(20261121);
  std::uniform_real_distribution<double> unit(-1, 1);
  x = sheet.grid.rest_positions();
  v.resize(x.rows(), 3);
  for (long i = 0; i < x.rows(); ++i)
    for (int axis = 0; axis < 3; ++axis) {
      x(i, axis) += 0.05 * sheet.grid.dx() * unit(random);
      v(i, axis) = 0.1 * unit(random);
    }
  for (std::int32_t p : sheet.pins) v.row(p).setZero();
}

// What one step moves and computes, per spring, counted once (the square root and the divide
// as one flop each). Memory: each spring's rest, K and μ (24 B; the plain loop also reads a and
// b, 8 B); each node's x, v and m read and f written by the force pass (56 B + 48 B, the write
// counting the read that brings its line in, as the triad's 32 B do), then f, m, x, v read and
// x, v written by the update (80 B + 48 B): the traffic when the node arrays leave the cache
// between passes. Flops per spring: x_a − x_b 3, l² 5, √ 1, 1/l 1, v_a − v_b 3, dot 5, rate 2,
// K (L0 − l)/l 3, − μ rate 2, scale·x 3, scatter 6 = 34; per node, gravity 3 and the update 9 + 6.
struct Traffic {
  double bytes = 0, flops = 0;
};
Traffic per_spring(const Sheet& sheet, bool whole_step) {
  const double nodes_per_spring = double(sheet.grid.nodes()) / double(sheet.springs.size());
  const double node_bytes = whole_step ? 104.0 + 128.0 : 104.0;
  const double node_flops = whole_step ? 3.0 + 15.0 : 3.0;
  return {24.0 + node_bytes * nodes_per_spring, 34.0 + node_flops * nodes_per_spring};
}

// A strain as a percentage; past 100 % as the stretch l/L0; past 1000x (or NaN) as blown up.
std::string strain_text(double strain) {
  if (!std::isfinite(strain) || strain + 1 > 1000) return fmt::format("{:.1e} x L0, blew up", strain + 1);
  if (strain > 1) return fmt::format("{:.1f} x L0", strain + 1);
  return fmt::format("{:.2f} %", 100 * strain);
}

// --- the kit at its own stable step ------------------------------------------------------------
struct Run {
  double h = 0;        // [s]
  double seconds = 0;  // CPU time of the whole run [s]
  long steps = 0;
  double structural = 0;  // max (l − L0)/L0 of the structural springs at t_end
  double links = 0;       // the same over structural and shear springs: Bullet's links
};

Run kit_run(const Sheet& sheet) {
  Run run;
  run.steps = long(std::ceil(t_end / sheet.dt));
  run.h = t_end / double(run.steps);
  kit::NodeArray x = sheet.grid.rest_positions(), v = kit::NodeArray::Zero(x.rows(), 3), f(x.rows(), 3);
  const kit::ClothForces forces(sheet.springs, sheet.masses, gravity, std::nullopt);
  const kit::Stopwatch clock;
  for (long k = 0; k < run.steps; ++k)
    kit::symplectic_cloth_step(x, v, sheet.masses, sheet.pins, forces, f, run.h);
  run.seconds = clock.seconds();
  run.structural = kit::max_strain(sheet.springs, x, kit::SpringKind::structural);
  run.links = std::max(run.structural, kit::max_strain(sheet.springs, x, kit::SpringKind::shear));
  if (!x.allFinite()) run.structural = run.links = NAN;
  return run;
}

// --- Bullet's soft-body cloth (bullet_cloth.hpp) ---------------------------------------------
Run bullet_run(int n, int iterations) {
  kit_bench::BulletCloth cloth(n, density * 1.0, gravity, iterations);  // 1 m²
  Run run;
  run.h = bullet_h;
  run.steps = long(std::lround(t_end / bullet_h));
  const kit::Stopwatch clock;
  for (long k = 0; k < run.steps; ++k) cloth.step(bullet_h);
  run.seconds = clock.seconds();
  cloth.max_strain(run.structural, run.links);
  return run;
}
}  // namespace

int main() {
  double stream = 0;
  const double bandwidth = kit_bench::triad_bandwidth(stream);
  fmt::print(
      "Memory bandwidth, one core: {:.1f} GB/s moved by a triad over arrays 4x the {:.0f} MB last-level "
      "cache ({:.1f} GB/s as STREAM counts it)\n\n",
      bandwidth / 1e9, kit_bench::last_level_cache() / 1e6, stream / 1e9);

  const std::vector<int> sizes{32, 64, 128, 256};
  std::vector<Sheet> sheets;
  for (int n : sizes) sheets.push_back(make_sheet(n));

  fmt::print(
      "1. ns per spring per step: the production force pass (ClothForces, springs in runs of equal offset)\n"
      "   and ex 6.3's symplectic step with it, against a straightforward spring loop (double, struct of\n"
      "   arrays, one loop over a[s], b[s], L0[s], K[s], mu[s] computing and scattering each force)\n");
  kit::Table speed({"N", "springs", "forces kit", "forces plain", "plain/kit", "step kit", "step plain",
                    "plain/kit", "forces rel. diff"});
  std::vector<double> step_ns(sizes.size()), step_ratio(sizes.size());
  double worst_difference = 0;
  for (std::size_t k = 0; k < sizes.size(); ++k) {
    const Sheet& sheet = sheets[k];
    const double springs = double(sheet.springs.size());
    const kit::ClothForces forces(sheet.springs, sheet.masses, gravity, std::nullopt);
    kit::NodeArray x, v;
    disturbed_state(sheet, x, v);
    kit::NodeArray f_kit(x.rows(), 3), f_plain(x.rows(), 3);
    forces(x, v, f_kit);
    plain_forces(sheet.springs, sheet.masses, x, v, f_plain);
    const double difference = relative_difference(f_kit, f_plain);
    worst_difference = std::max(worst_difference, difference);

    const double forces_kit = fastest([&] { forces(x, v, f_kit); }, 5, 0.1) / springs * 1e9;
    const double forces_plain =
        fastest([&] { plain_forces(sheet.springs, sheet.masses, x, v, f_plain); }, 5, 0.1) / springs * 1e9;
    // The steps run on from the disturbed state at the stable step: the sheet stays bounded.
    kit::NodeArray xk = x, vk = v, xp = x, vp = v;
    const auto kit_step = [&] {
      kit::symplectic_cloth_step(xk, vk, sheet.masses, sheet.pins, forces, f_kit, sheet.dt);
    };
    const double step_kit = fastest(kit_step, 5, 0.1) / springs * 1e9;
    const double step_plain =
        fastest([&] { plain_step(sheet, xp, vp, f_plain, sheet.dt); }, 5, 0.1) / springs * 1e9;
    if (!xk.allFinite() || !xp.allFinite()) {  // a blown-up sheet would time NaN arithmetic
      fmt::print(stderr, "bench: the sheet blew up at N = {} (kit {}, plain {})\n", sizes[k], xk.allFinite(),
                 xp.allFinite());
      return 1;
    }
    step_ns[k] = step_kit, step_ratio[k] = step_plain / step_kit;
    speed.add_row({std::to_string(sizes[k]), std::to_string(sheet.springs.size()), kit::fixed(forces_kit, 2),
                   kit::fixed(forces_plain, 2), kit::fixed(forces_plain / forces_kit, 2),
                   kit::fixed(step_kit, 2), kit::fixed(step_plain, 2), kit::fixed(step_plain / step_kit, 2),
                   fmt::format("{:.1e}", difference)});
  }
  speed.print(std::cout);
  const std::size_t at128 = 2;
  fmt::print(
      "   Forces agree to {:.1e} relative (max |f_kit − f_plain| / max |f_plain|, disturbed sheet): {}.\n",
      worst_difference, worst_difference < 1e-12 ? "the same forces, an honest comparison" : "NOT THE SAME");
  const auto verdict = [](bool met) { return met ? "met" : "NOT met"; };
  fmt::print("   Target at N = 128, one core: at most 3 ns per spring-step ({:.2f} ns: {}) and at least\n"
             "   2x faster than the straightforward step ({:.2f}x: {}).\n\n",
             step_ns[at128], verdict(step_ns[at128] <= 3), step_ratio[at128],
             verdict(step_ratio[at128] >= 2));
  fmt::print("2. What bounds the step (bytes if node arrays leave the cache between passes; see Traffic)\n");
  kit::Table bound({"N", "working set [MB]", "B/spring", "flop/spring", "step [ns/spring]", "GB/s", "GFLOP/s",
                    "of triad", "bandwidth bound [ns]"});
  double most_bandwidth = 0;  // the largest fraction of the triad any size uses
  for (std::size_t k = 0; k < sizes.size(); ++k) {
    const Sheet& sheet = sheets[k];
    const Traffic t = per_spring(sheet, true);
    most_bandwidth = std::max(most_bandwidth, t.bytes / step_ns[k] / (bandwidth / 1e9));
    // x, v, f, m per node and rest, K, μ per spring: what one step touches.
    const double working = (80.0 * double(sheet.grid.nodes()) + 24.0 * double(sheet.springs.size())) / 1e6;
    bound.add_row(
        {std::to_string(sizes[k]), kit::fixed(working, 1), kit::fixed(t.bytes, 1), kit::fixed(t.flops, 1),
         kit::fixed(step_ns[k], 2), kit::fixed(t.bytes / step_ns[k], 1), kit::fixed(t.flops / step_ns[k], 1),
         kit::fixed(t.bytes / step_ns[k] / (bandwidth / 1e9), 2), kit::fixed(t.bytes / bandwidth * 1e9, 2)});
  }
  bound.print(std::cout);
  fmt::print("   The working set fits in the {:.0f} MB L2 up to N = 64 and in the last-level cache above.\n"
             "   The step uses at most {:.2f} of the triad's bandwidth: {}\n\n",
             double(sysconf(_SC_LEVEL2_CACHE_SIZE)) / 1e6, most_bandwidth,
             most_bandwidth < 0.5 ? "memory is not what bounds it,\n"
                                    "   the arithmetic is (a square root and a divide per spring)."
                                  : "memory bandwidth is close to bounding it.");
  fmt::print("3. Bullet {}.{:02d} soft-body cloth (float) against the kit, {} s simulated from rest\n",
             btGetVersion() / 100, btGetVersion() % 100, t_end);
  fmt::print("   The kit: symplectic Euler at 0.9 of its stable step for omega_max (power iteration).\n"
             "   Bullet: h = 1/240 s, 10 solver iterations, and its defaults (1 iteration).\n"
             "   Strain = (l - L0)/L0 at t = {} s.\n",
             t_end);
  for (std::size_t k = 0; k < 3; ++k)
    fmt::print("   N = {}: omega_max = {:.3g} rad/s, omega_max^2 = {:.2f} k/m_node, h = {:.2e} s\n", sizes[k],
               sheets[k].omega_max,
               sheets[k].omega_max * sheets[k].omega_max * density * sheets[k].grid.dx() *
                   sheets[k].grid.dy() / stiffness,
               sheets[k].dt);
  kit::Table peer({"N", "cloth", "h [s]", "ms/step", "CPU s per simulated s", "kit / this",
                   "max structural strain", "max strain, struct.+shear"});
  Run kit_at128, bullet_at128;
  for (std::size_t k = 0; k < 3; ++k) {
    const int n = sizes[k];
    const Run kit_result = kit_run(sheets[k]);
    const Run bullet_10 = bullet_run(n, 10), bullet_default = bullet_run(n, 0);
    const double kit_cost = kit_result.seconds / t_end;
    for (const auto& [name, r] : {std::pair<const char*, const Run&>{"kit, explicit", kit_result},
                                  {"Bullet, 10 iterations", bullet_10},
                                  {"Bullet, defaults", bullet_default}}) {
      const double cost = r.seconds / t_end;
      peer.add_row({std::to_string(n), name, fmt::format("{:.2e}", r.h),
                    kit::fixed(r.seconds / double(r.steps) * 1e3, 3), kit::fixed(cost, 3),
                    &r == &kit_result ? "" : kit::fixed(kit_cost / cost, 1), strain_text(r.structural),
                    strain_text(r.links)});
    }
    if (n == 128) kit_at128 = kit_result, bullet_at128 = bullet_10;
  }
  peer.print(std::cout);
  fmt::print("   kit / this: the kit's CPU time per simulated second over that cloth's (above 1: it is\n"
             "   faster than the kit).\n");
  const double kit_cost = kit_at128.seconds / t_end, bullet_cost = bullet_at128.seconds / t_end;
  fmt::print("   At N = 128, Bullet with 10 iterations costs {:.2f} s of CPU per simulated second, the kit\n"
             "   {:.2f} s:"
             " {} is {:.1f}x faster. At t = {} s Bullet's structural links stretch {}, the kit's {}:\n"
             "   {} stretches more.\n",
             bullet_cost, kit_cost, bullet_cost < kit_cost ? "Bullet" : "the kit",
             std::max(bullet_cost, kit_cost) / std::min(bullet_cost, kit_cost), t_end,
             strain_text(bullet_at128.structural), strain_text(kit_at128.structural),
             !(kit_at128.structural >= bullet_at128.structural) ? "Bullet" : "the kit");
  fmt::print(
      "   Bullet at h = 1/240 s is what a game programmer would use. The explicit kit must take steps\n"
      "   {:.0f}x smaller (h = {:.1e} s) to stay stable at k = {} N/m: the case for the implicit chapter.\n",
      bullet_h / kit_at128.h, kit_at128.h, stiffness);
  return 0;
}
