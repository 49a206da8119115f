// ./kit bench continuum: chapter 9's finite-element sheet (fem_body.hpp) on one core, on the
// reference solutions of ex 9.1 to 9.3 (the element), ex 6.1 and 7.1 (the springs model) and
// ex 7.3 (the filtered PCG), called the way the chapter calls them, through ContinuumKernels:
//   1. the nodal forces (FemBody::forces) of a square sheet at about 1e4 and 1e5 linear triangles,
//      stretched 1 % and turned out of its plane so that F ≠ I, in ns per element: St Venant–
//      Kirchhoff, the linear model and the springs model (ns per spring too); beside StVK, the
//      same loop calling the element's functions directly (what the indirection costs) and a
//      hand-written loop computing F, E, S, P and H inline (what Eigen's small matrices cost);
//   2. the stiffness (FemBody::stiffness: a scatter into the sparsity pattern the body found once)
//      at the same sizes, split into the element kernel alone (F and the 9×9 ∂f/∂x) and the sparse
//      assembly around it, against the straightforward assembly written here (the kernel, a fresh
//      triplet list, setFromTriplets: what FemBody did before; checked equal first); in both, the
//      bound from the same run: the bytes each element must move, at the bandwidth of a triad from
//      memory and of one over the loop's own working set;
//   3. one implicit step (implicit_step) of chapter 9's spinning plate at about 1e4 elements, split
//      into the stiffness, the building of A and b, and the filtered PCG (ex 7.3), against Eigen's
//      diagonal CG on the same A and b to the same tolerance and Eigen's SimplicialLDLT.
// No GSL peer: GSL has no finite elements, and for the solve only an unpreconditioned GMRES
// (gsl_splinalg); Eigen's CG and LDLᵀ, which the kit already links, are the peers.
// Timings live here, never in the tests.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include <unistd.h>

#include <fmt/format.h>
#include <Eigen/Geometry>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>

#include <kit/app/table.hpp>
#include <kit/base/stopwatch.hpp>
#include <kit/fem/fem_body.hpp>
#include <kit/fem/fem_element.hpp>
#include <kit/fem/fem_integrators.hpp>

#include "bandwidth.hpp"
#include "cloth_jacobian.hpp"
#include "cloth_pcg.hpp"
#include "cloth_spring_force.hpp"
#include "continuum_experiments.hpp"
#include "cpu_clock.hpp"
#include "fem_kernels.hpp"
#include "machine_note.hpp"

namespace {
// Every time below is read from the CPU clock; the triads keep bandwidth.hpp's wall clock.
using kit::bench::CpuClock, kit::bench::load_average;

// Whatever a timed loop computes ends here, so that the compiler cannot drop the loop.
volatile double sink = 0;

// Fastest sample of each of several pieces of work [CPU s per call], the pieces sampled in turn
// so that a busy spell of the machine slows them alike; each sample repeats its piece for at
// least `min_seconds`. `slowest`, when given, receives each piece's slowest sample: the noise.
std::vector<double> in_turn(const std::vector<std::function<void()>>& runs, int samples = 5,
                            double min_seconds = 0.1, std::vector<double>* slowest = nullptr) {
  std::vector<double> best(runs.size(), INFINITY), worst(runs.size(), 0.0);
  for (int i = 0; i < samples; ++i)
    for (std::size_t k = 0; k < runs.size(); ++k) {
      const CpuClock clock;
      long calls = 0;
      do {
        runs[k]();
        ++calls;
      } while (clock.seconds() < min_seconds);
      best[k] = std::min(best[k], clock.seconds() / double(calls));
      worst[k] = std::max(worst[k], clock.seconds() / double(calls));
    }
  if (slowest) *slowest = worst;
  return best;
}

constexpr std::array<int, 2> cells = {71, 224};  // per side of the sheet: 2 n² = 10082 and 100352 triangles
constexpr double stretch = 1.01;                 // along the rest x axis
constexpr double turn = 0.3;                     // [rad], about (1, 1, 1)/√3: F has no zero entry
const kit::FemMaterial material{};               // chapter 9's: E = 1 GPa, ν = 0.3, 1000 kg/m³, 1 cm thick

// The chapter's wiring (ex 9.1 to 9.3, ex 6.1, ex 7.1, ex 7.3), here on the reference solutions.
kit::ContinuumKernels continuum_kernels() {
  return {kit::student_fem_kernels(), &kit::spring_force, &kit::spring_stiffness_block, &kit::filtered_pcg};
}

// The unit sheet in `n` × `n` cells (alternating diagonals), as `model`, stretched and turned.
kit::FemBody deformed_sheet(int n, kit::FemModel model) {
  kit::FemBody body(kit::continuum_mesh(1, 1, n, n, kit::MeshKind::regular), material, model,
                    continuum_kernels());
  const Eigen::Matrix3d R = Eigen::AngleAxisd(turn, Eigen::Vector3d::Ones().normalized()).toRotationMatrix();
  for (long i = 0; i < body.nodes(); ++i) {
    const Eigen::Vector2d& X = body.mesh().nodes[std::size_t(i)];
    body.x.row(i) = (R * Eigen::Vector3d(stretch * X.x(), X.y(), 0)).transpose();
  }
  return body;
}

kit::Vec3 node(const kit::NodeArray& x, int i) { return x.row(i).transpose(); }

// The rest shapes again (FemBody keeps its own private): what the loops written here read, in
// the same layout as FemBody's (one RestTriangle, 40 B, per element).
std::vector<kit::RestTriangle> rest_shapes(const kit::FemBody& body) {
  std::vector<kit::RestTriangle> rest;
  rest.reserve(body.mesh().triangles.size());
  for (const auto& t : body.mesh().triangles)
    rest.push_back(kit::rest_triangle(body.mesh().nodes[std::size_t(t[0])],
                                      body.mesh().nodes[std::size_t(t[1])],
                                      body.mesh().nodes[std::size_t(t[2])], body.material().thickness));
  return rest;
}

// FemBody::forces of the StVK model with ex 9.1 and 9.2 called directly, so that the compiler
// may inline them: the same arithmetic, no function pointer.
void direct_forces(const kit::FemBody& body, const std::vector<kit::RestTriangle>& rest,
                   kit::NodeArray& out) {
  out = body.loads;
  const auto& triangles = body.mesh().triangles;
  for (std::size_t e = 0; e < triangles.size(); ++e) {
    const auto& t = triangles[e];
    const kit::Matrix32 F = kit::deformation_gradient(node(body.x, t[0]), node(body.x, t[1]),
                                                      node(body.x, t[2]), rest[e].inverse);
    const kit::ElementForces f = kit::stvk_forces(F, rest[e].inverse, rest[e].volume, body.lame());
    for (int k = 0; k < 3; ++k) out.row(t[k]) += f.col(k).transpose();
  }
}

// The baseline: the StVK forces written out in scalars, no Eigen and no call (fem_element.hpp's
// equations). With Dm⁻¹ = [a b; c d] and the edges e1 = x1 − x0, e2 = x2 − x0 [m]:
//   F = [e1 e2] Dm⁻¹,  C = FᵀF,  E = ½(C − I),  S = λ tr(E) I + 2μ E,  P = F S,  H = −V P Dm⁻ᵀ.
void hand_forces(const kit::FemBody& body, const std::vector<kit::RestTriangle>& rest, kit::NodeArray& out) {
  out = body.loads;
  const double *px = body.x.col(0).data(), *py = body.x.col(1).data(), *pz = body.x.col(2).data();
  double *fx = out.col(0).data(), *fy = out.col(1).data(), *fz = out.col(2).data();
  const double lambda = body.lame().lambda, mu = body.lame().mu;
  const auto& triangles = body.mesh().triangles;
  for (std::size_t e = 0; e < triangles.size(); ++e) {
    const int i0 = triangles[e][0], i1 = triangles[e][1], i2 = triangles[e][2];
    const double a = rest[e].inverse(0, 0), b = rest[e].inverse(0, 1);
    const double c = rest[e].inverse(1, 0), d = rest[e].inverse(1, 1);
    const double e1x = px[i1] - px[i0], e1y = py[i1] - py[i0], e1z = pz[i1] - pz[i0];
    const double e2x = px[i2] - px[i0], e2y = py[i2] - py[i0], e2z = pz[i2] - pz[i0];
    // F's columns u, w
    const double ux = e1x * a + e2x * c, uy = e1y * a + e2y * c, uz = e1z * a + e2z * c;
    const double wx = e1x * b + e2x * d, wy = e1y * b + e2y * d, wz = e1z * b + e2z * d;
    const double E00 = 0.5 * (ux * ux + uy * uy + uz * uz - 1), E11 = 0.5 * (wx * wx + wy * wy + wz * wz - 1);
    const double E01 = 0.5 * (ux * wx + uy * wy + uz * wz);
    const double trace = lambda * (E00 + E11);
    const double S00 = trace + 2 * mu * E00, S11 = trace + 2 * mu * E11, S01 = 2 * mu * E01;
    // P's columns p = S00 u + S01 w, q = S01 u + S11 w; H's columns −V (a p + b q), −V (c p + d q)
    const double px0 = S00 * ux + S01 * wx, py0 = S00 * uy + S01 * wy, pz0 = S00 * uz + S01 * wz;
    const double qx = S01 * ux + S11 * wx, qy = S01 * uy + S11 * wy, qz = S01 * uz + S11 * wz;
    const double V = rest[e].volume;
    const double h1x = -V * (a * px0 + b * qx), h1y = -V * (a * py0 + b * qy), h1z = -V * (a * pz0 + b * qz);
    const double h2x = -V * (c * px0 + d * qx), h2y = -V * (c * py0 + d * qy), h2z = -V * (c * pz0 + d * qz);
    fx[i0] -= h1x + h2x, fy[i0] -= h1y + h2y, fz[i0] -= h1z + h2z;
    fx[i1] += h1x, fy[i1] += h1y, fz[i1] += h1z;
    fx[i2] += h2x, fy[i2] += h2y, fz[i2] += h2z;
  }
}

// hand_forces' arithmetic an element: the edges 6, F 18, E 20, S 10, P 18, H 24, the three nodes'
// sums 12 (each multiplication and addition one flop, as written; the compiler may fuse a few).
constexpr int hand_flops = 108;

double max_abs(const kit::NodeArray& a) { return a.cwiseAbs().maxCoeff(); }

// One element's 9×9 K as 81 triplets, block by block (node a's rows, node b's columns), row-major
// within a block: the order FemBody::stiffness filled its list in before it found its pattern once.
void add_triplets(std::vector<Eigen::Triplet<double>>& entries, const std::array<int, 3>& tri,
                  const kit::Matrix9& K) {
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
          entries.emplace_back(3 * tri[std::size_t(a)] + r, 3 * tri[std::size_t(b)] + c,
                               K(3 * a + r, 3 * b + c));
}

// The baseline: the StVK stiffness assembled the straightforward way, as FemBody::stiffness did
// before: the element kernel through FemKernels, a fresh triplet list, Eigen's setFromTriplets.
void triplet_stiffness(const kit::FemBody& body, const std::vector<kit::RestTriangle>& rest,
                       kit::SparseMatrix& out) {
  const kit::FemKernels& kernels = body.kernels().element;
  const auto& triangles = body.mesh().triangles;
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(81 * triangles.size());
  for (std::size_t e = 0; e < triangles.size(); ++e) {
    const auto& t = triangles[e];
    const kit::Matrix32 F = kernels.deformation_gradient(node(body.x, t[0]), node(body.x, t[1]),
                                                         node(body.x, t[2]), rest[e].inverse);
    add_triplets(entries, t, kernels.stiffness(F, rest[e].inverse, rest[e].volume, body.lame()));
  }
  out.resize(3 * body.nodes(), 3 * body.nodes());
  out.setFromTriplets(entries.begin(), entries.end());
}

// --- the bytes an element step moves, at the least --------------------------------------------
// Element data streamed once a call: three node indices (12 B) and the rest shape (Dm⁻¹ 32 B and
// V 8 B). Node data, each node once (its neighbours share it while it is in cache): x 24 B read,
// the loads 24 B read into the output (out = loads), the output 24 B written, and a write counts
// the read that brings its line in first (as the triad's do): 96 B a node. Springs: per spring
// the two indices, rest length and stiffness (24 B); per node v as well (24 B), 120 B.
double element_forces_bytes(double elements, double nodes) { return 52 * elements + 96 * nodes; }
double spring_forces_bytes(double springs, double nodes) { return 24 * springs + 120 * nodes; }
// The stiffness by FemBody::stiffness: the element data and x (24 B a node); the check that `out`
// holds the pattern already, both row-start arrays (3 rows a node, 4 B each: 24 B a node) and both
// column-index arrays (8 B a stored entry) read; each element's 27 slots (where each of its nine
// blocks' three rows starts, 4 B); and the value array zeroed (8 B, ×2 with the read for
// ownership) then summed into (read and written back once, ×2): 40 B a stored entry.
double scatter_stiffness_bytes(double elements, double nodes, double stored) {
  return 52 * elements + 48 * nodes + 27 * 4 * elements + 40 * stored;
}
// The baseline (triplet_stiffness): the element data and x, then per element 81 triplets of 16 B
// (two int indices, the value), written (twice, with the read for ownership) and read by
// setFromTriplets' counting and inserting passes: 4 × 16 B each; its transposed copy takes the 81
// entries (12 B: value and index) written (×2) and read when duplicates are summed (×1); the
// stored entries (12 B) are then read and written into the result (×3).
double triplet_stiffness_bytes(double elements, double nodes, double stored) {
  return 52 * elements + 24 * nodes + 81 * elements * (4 * 16 + 3 * 12) + 3 * 12 * stored;
}
// The same bounds for the element kernel alone: its element data and x.
double kernel_bytes(double elements, double nodes) { return 52 * elements + 24 * nodes; }

// A triad over three arrays that together hold `bytes` [B/s]: the bandwidth of the cache level
// (or memory) a loop with that working set runs from.
double triad_at(double bytes) {
  double stream = 0;
  return kit_bench::triad_bandwidth(std::max<std::size_t>(std::size_t(bytes / 24), 1024), stream);
}

std::string ns(double seconds_per_item) { return kit::fixed(1e9 * seconds_per_item, 1); }

// --- 3. the implicit step --------------------------------------------------------------------
// Applies each node's 3×3 filter to its three entries of w (what implicit_step does to b).
void filter_in_place(const std::vector<kit::Mat3>& filters, Eigen::VectorXd& w) {
  for (std::size_t node = 0; node < filters.size(); ++node) {
    auto entries = w.segment<3>(3 * Eigen::Index(node));
    entries = filters[node] * entries;
  }
}

double relative_difference(const Eigen::VectorXd& p, const Eigen::VectorXd& q) {
  return (p - q).cwiseAbs().maxCoeff() / q.cwiseAbs().maxCoeff();
}

/// The same deformed sheet by each model, and the StVK one's rest shapes.
struct Sheets {
  explicit Sheets(int n)
      : stvk(deformed_sheet(n, kit::FemModel::stvk)),
        linear(deformed_sheet(n, kit::FemModel::linear)),
        springs(deformed_sheet(n, kit::FemModel::springs)),
        rest(rest_shapes(stvk)) {}
  kit::FemBody stvk, linear, springs;
  std::vector<kit::RestTriangle> rest;
};

}  // namespace

int main() {
  const kit::Stopwatch total;  // wall time of the whole benchmark
  const double bandwidth = kit_bench::print_machine_note("the fastest of 5 samples (pieces sampled in turn)");
  const kit::Lame lame = kit::plane_stress_lame(material.young, material.poisson);
  fmt::print(
      "The sheet: 1 m x 1 m in n x n cells, alternating diagonals (continuum_mesh), E = {:.0e} Pa, nu = {},\n"
      "plane-stress Lame lambda = {:.3e} Pa, mu = {:.3e} Pa; stretched by {} along x and turned by {} rad "
      "about\n"
      "(1, 1, 1)/sqrt(3), at rest (v = 0, no loads), so F != I in every element.\n\n",
      material.young, material.poisson, lame.lambda, lame.mu, stretch, turn);

  // --- 1: forces ----------------------------------------------------------------------------------
  fmt::print("1. Nodal forces (FemBody::forces), ns per element (springs: per spring too). floor: the bytes "
             "counted\n"
             "   in bench_continuum.cpp (element data once, each node once) at the triad's bandwidth from "
             "memory, and\n"
             "   at that of a triad over the loop's own working set (the cache it runs from).\n");
  kit::Table forces({"n", "elements", "model", "loop", "ns / element", "ns / spring", "B / element",
                     "floor, memory", "floor, working set", "x hand-written"});
  std::vector<std::string> checks;
  std::vector<std::array<double, 3>> stvk_times;  // per element [s]: pointers, called directly, hand-written
  for (const int n : cells) {
    const Sheets sheets(n);
    const kit::FemBody &stvk = sheets.stvk, &linear = sheets.linear, &springs = sheets.springs;
    const std::vector<kit::RestTriangle>& rest = sheets.rest;
    const double E = double(stvk.elements()), N = double(stvk.nodes()), S = double(springs.springs().size());
    kit::NodeArray f_body, f_direct, f_hand, f_linear, f_springs;
    const std::vector<double> t = in_turn({
        [&] { stvk.forces(f_body); },
        [&] { direct_forces(stvk, rest, f_direct); },
        [&] { hand_forces(stvk, rest, f_hand); },
        [&] { linear.forces(f_linear); },
        [&] { springs.forces(f_springs); },
    });
    sink = sink + f_body(0, 0) + f_direct(0, 0) + f_hand(0, 0) + f_linear(0, 0) + f_springs(0, 0);
    stvk_times.push_back({t[0] / E, t[1] / E, t[2] / E});
    const double scale = max_abs(f_body);
    checks.push_back(fmt::format("n = {}: called directly {:.1e}, hand-written {:.1e}", n,
                                 max_abs(f_direct - f_body) / scale, max_abs(f_hand - f_body) / scale));
    const double element_bytes = element_forces_bytes(E, N), spring_bytes = spring_forces_bytes(S, N);
    const double element_cache = triad_at(element_bytes), spring_cache = triad_at(spring_bytes);
    const auto row = [&](const char* model, const char* loop, double seconds, double bytes, double cache,
                         bool per_spring) {
      forces.add_row({std::to_string(n), std::to_string(stvk.elements()), model, loop, ns(seconds / E),
                      per_spring ? ns(seconds / S) : "", kit::fixed(bytes / E, 0), ns(bytes / bandwidth / E),
                      ns(bytes / cache / E), kit::fixed(seconds / t[2], 2)});
    };
    row("StVK", "FemBody::forces (pointers)", t[0], element_bytes, element_cache, false);
    row("StVK", "ex 9.1, 9.2 called directly", t[1], element_bytes, element_cache, false);
    row("StVK", "hand-written, scalars", t[2], element_bytes, element_cache, false);
    row("linear", "FemBody::forces", t[3], element_bytes, element_cache, false);
    row("springs", fmt::format("FemBody::forces, {} springs", springs.springs().size()).c_str(), t[4],
        spring_bytes, spring_cache, true);
  }
  forces.print(std::cout);
  fmt::print(
      "   Checked first, the same forces, max |f - f_FemBody| / max |f_FemBody|:\n   {}.\n"
      "   x hand-written: the time over the hand-written StVK loop's. The linear model also computes F (ex "
      "9.1\n"
      "   through its pointer) and calls linear_forces out of line; the springs model calls ex 6.1 per "
      "spring,\n"
      "   about 1.5 springs an element (one per mesh edge).\n"
      "   Every loop takes several times both floors: compute-bound. The function pointers cost {:.0f} % "
      "and\n"
      "   {:.0f} % (FemBody's loop over the same loop calling ex 9.1 and 9.2 directly); the rest of the gap "
      "to the\n"
      "   hand-written loop is in the kernels' Eigen code as GCC compiles it, inlined or not (fixed-size "
      "3x2\n"
      "   and 2x2 products and their temporaries). The hand-written loop does {} flops an element (counted\n"
      "   at hand_forces): {:.1f} and {:.1f} GFLOP/s, scalar arithmetic (the build targets baseline "
      "x86-64).\n\n",
      fmt::format("{};\n   {}", checks[0], checks[1]), 100 * (stvk_times[0][0] / stvk_times[0][1] - 1),
      100 * (stvk_times[1][0] / stvk_times[1][1] - 1), hand_flops, hand_flops / stvk_times[0][2] / 1e9,
      hand_flops / stvk_times[1][2] / 1e9);

  // --- 2: stiffness -------------------------------------------------------------------------------
  fmt::print(
      "2. Stiffness dF/dx (FemBody::stiffness: each element's 9x9 scattered into the sparsity pattern the "
      "body\n"
      "   found once), ns per element, split into the element kernel alone (F and the 9x9 K of ex 9.1 and "
      "9.3\n"
      "   through FemKernels, summed into a dummy) and the sparse assembly around it; against the baseline\n"
      "   written here, the straightforward assembly (what FemBody::stiffness did before): the same kernel,\n"
      "   81 triplets an element into a fresh list, then Eigen's setFromTriplets.\n");
  kit::Table stiffness({"n", "elements", "stored / element", "what", "ns / element", "x kernel",
                        "B / element", "floor, memory", "floor, working set"});
  checks.clear();
  std::vector<double> list_seconds;  // the triplet list alone, per element [s]
  std::vector<double> ratios;        // the baseline over FemBody::stiffness
  for (const int n : cells) {
    const Sheets sheets(n);
    const kit::FemBody &stvk = sheets.stvk, &linear = sheets.linear, &springs = sheets.springs;
    const std::vector<kit::RestTriangle>& rest = sheets.rest;
    const double E = double(stvk.elements()), N = double(stvk.nodes()), S = double(springs.springs().size());
    kit::SparseMatrix K_body, K_baseline, K_linear, K_springs;
    // Checked first: the same matrix both ways.
    stvk.stiffness(K_body);
    triplet_stiffness(stvk, rest, K_baseline);
    const kit::SparseMatrix difference = K_body - K_baseline;
    checks.push_back(
        fmt::format("n = {}: {} and {} stored entries, ||K - K_triplets||_F / ||K_triplets||_F = {:.1e}", n,
                    K_body.nonZeros(), K_baseline.nonZeros(), difference.norm() / K_baseline.norm()));
    const kit::FemKernels& pointers = stvk.kernels().element;
    kit::Matrix9 dummy = kit::Matrix9::Zero();
    const auto kernel = [&] {
      const auto& triangles = stvk.mesh().triangles;
      for (std::size_t e = 0; e < triangles.size(); ++e) {
        const auto& tri = triangles[e];
        const kit::Matrix32 F = pointers.deformation_gradient(node(stvk.x, tri[0]), node(stvk.x, tri[1]),
                                                              node(stvk.x, tri[2]), rest[e].inverse);
        dummy += pointers.stiffness(F, rest[e].inverse, rest[e].volume, stvk.lame());
      }
    };
    const auto direct_kernel = [&] {
      const auto& triangles = stvk.mesh().triangles;
      for (std::size_t e = 0; e < triangles.size(); ++e) {
        const auto& tri = triangles[e];
        const kit::Matrix32 F = kit::deformation_gradient(node(stvk.x, tri[0]), node(stvk.x, tri[1]),
                                                          node(stvk.x, tri[2]), rest[e].inverse);
        dummy += kit::stvk_stiffness(F, rest[e].inverse, rest[e].volume, stvk.lame());
      }
    };
    // The baseline's two assembly steps apart: its triplet list (a fresh vector each call, 81 entries
    // an element in the same order; unit values: the cost does not depend on them), and
    // setFromTriplets on such a list, built once.
    using Triplet = Eigen::Triplet<double>;
    const kit::Matrix9 ones = kit::Matrix9::Ones();
    const auto fill_triplets = [&](std::vector<Triplet>& entries) {
      entries.reserve(81 * stvk.mesh().triangles.size());
      for (const auto& tri : stvk.mesh().triangles) add_triplets(entries, tri, ones);
    };
    const auto triplet_list = [&] {
      std::vector<Triplet> entries;
      fill_triplets(entries);
      sink = sink + entries.back().value();
    };
    std::vector<Triplet> prebuilt;
    fill_triplets(prebuilt);
    kit::SparseMatrix K_list;
    const auto from_triplets = [&] {
      K_list.resize(3 * stvk.nodes(), 3 * stvk.nodes());
      K_list.setFromTriplets(prebuilt.begin(), prebuilt.end());
    };
    const std::vector<double> t = in_turn({
        [&] { stvk.stiffness(K_body); },
        kernel,
        direct_kernel,
        [&] { linear.stiffness(K_linear); },
        [&] { springs.stiffness(K_springs); },
        [&] { triplet_stiffness(stvk, rest, K_baseline); },
        triplet_list,
        from_triplets,
    });
    sink = sink + dummy.sum() + K_body.coeff(0, 0) + K_baseline.coeff(0, 0) + K_linear.coeff(0, 0) +
           K_springs.coeff(0, 0) + K_list.coeff(0, 0);
    list_seconds.push_back(t[6] / E);
    ratios.push_back(t[5] / t[0]);
    const double stored = double(K_body.nonZeros());
    const double scatter_bytes = scatter_stiffness_bytes(E, N, stored);
    const double triplet_bytes = triplet_stiffness_bytes(E, N, stored);
    const double element_bytes = kernel_bytes(E, N);
    const double scatter_cache = triad_at(scatter_bytes), triplet_cache = triad_at(triplet_bytes);
    const double kernel_cache = triad_at(element_bytes);
    const double list_bytes = 81 * 16 * 2 * E;  // the triplets written, each with its read for ownership
    const double list_cache = triad_at(list_bytes);
    const auto row = [&](const std::string& what, double seconds, double per, double stored_per, double bytes,
                         double cache) {
      stiffness.add_row(
          {std::to_string(n), std::to_string(stvk.elements()), kit::fixed(stored_per, 1), what,
           ns(seconds / per), kit::fixed(seconds / t[1], 2), bytes > 0 ? kit::fixed(bytes / per, 0) : "",
           bytes > 0 ? ns(bytes / bandwidth / per) : "", bytes > 0 ? ns(bytes / cache / per) : ""});
    };
    row("StVK, FemBody::stiffness (scatter into a pattern found once)", t[0], E, stored / E, scatter_bytes,
        scatter_cache);
    row("  element kernel (pointers)", t[1], E, stored / E, element_bytes, kernel_cache);
    row("  element kernel, called directly", t[2], E, stored / E, element_bytes, kernel_cache);
    row("  assembly: the rest", t[0] - t[1], E, stored / E, scatter_bytes - element_bytes, scatter_cache);
    row("linear, FemBody::stiffness", t[3], E, double(K_linear.nonZeros()) / E, 0, 0);
    row(fmt::format("springs, FemBody::stiffness (per spring: {} ns)", kit::fixed(1e9 * t[4] / S, 1)), t[4],
        E, double(K_springs.nonZeros()) / E, 0, 0);
    row("baseline: kernel + fresh triplets + setFromTriplets", t[5], E, stored / E, triplet_bytes,
        triplet_cache);
    row("  assembly: the rest", t[5] - t[1], E, stored / E, triplet_bytes - element_bytes, triplet_cache);
    row("    the triplet list alone", t[6], E, stored / E, list_bytes, list_cache);
    row("    setFromTriplets alone", t[7], E, stored / E, triplet_bytes - element_bytes - list_bytes,
        triplet_cache);
  }
  stiffness.print(std::cout);
  fmt::print(
      "   Checked first, the same matrix: {};\n   {}.\n"
      "   The baseline over FemBody::stiffness: {:.1f} times at n = {}, {:.1f} times at n = {}.\n"
      "   x kernel: the time over the element kernel's through pointers. 'the rest': the first row of its\n"
      "   group less the kernel (pointers): FemBody::stiffness's check that the matrix holds its pattern\n"
      "   already (both index arrays compared), the values zeroed, and 81 indexed additions an element (27\n"
      "   slots: a block's row is three adjacent values); the baseline's triplet vector (allocated anew "
      "every\n"
      "   call, 81 x 16 B an element) and Eigen's setFromTriplets (a count, a transposed copy, duplicates\n"
      "   summed, a transposed copy back), each also timed alone. The list alone: {:.0f} ns an element at\n"
      "   n = {} ({:.0f} MB, which the allocator reuses from call to call), {:.0f} ns at n = {} ({:.0f} MB:\n"
      "   above glibc's largest mmap threshold, 32 MB, each call maps it anew, the system faults in and "
      "zeroes\n"
      "   every page, and unmaps it).\n"
      "   B / element: bytes counted in bench_continuum.cpp (scatter_stiffness_bytes for "
      "FemBody::stiffness,\n"
      "   triplet_stiffness_bytes for the baseline).\n\n",
      checks[0], checks[1], ratios[0], cells[0], ratios[1], cells[1], 1e9 * list_seconds[0], cells[0],
      81 * 16 * 2.0 * cells[0] * cells[0] / 1e6, 1e9 * list_seconds[1], cells[1],
      81 * 16 * 2.0 * cells[1] * cells[1] / 1e6);

  // --- 3: one implicit step ---------------------------------------------------------------------
  // Chapter 9's spinning plate (spin_plate): 0.5 m, held in its plane, spinning at pi rad/s about its
  // centre, StVK, h = 1 ms (the chapter's implicit step), solved to implicit_step's default 1e-8.
  constexpr int plate_cells = 71;
  constexpr double h = 1e-3;          // [s]
  constexpr double tolerance = 1e-8;  // relative residual, ‖r‖ ≤ tol ‖S b‖, both CGs
  constexpr int max_iterations = 20000;
  constexpr int warm_steps = 10;  // steps from rest before the timed state: the plate under way
  constexpr int samples = 7;      // of each piece: a solve takes two calls of ~0.1 s a sample
  kit::FemBody plate(
      kit::continuum_mesh(kit::plate_side, kit::plate_side, plate_cells, plate_cells, kit::MeshKind::regular),
      material, kit::FemModel::stvk, continuum_kernels());
  plate.hold_in_plane();
  for (long i = 0; i < plate.nodes(); ++i) {
    const double rx = plate.x(i, 0) - kit::plate_side / 2, ry = plate.x(i, 1) - kit::plate_side / 2;
    plate.v.row(i) << -kit::plate_spin * ry, kit::plate_spin * rx, 0;  // v = ω × r
  }
  for (int k = 0; k < warm_steps; ++k) kit::implicit_step(plate, h, 0, tolerance, max_iterations);
  const kit::NodeArray x0 = plate.x, v0 = plate.v;
  const auto restore = [&] { plate.x = x0, plate.v = v0; };

  // implicit_step's pieces, written as it writes them (fem_integrators.cpp), each timed alone. Its K
  // is a fresh matrix every step, so FemBody::stiffness copies its pattern in before the scatter:
  // here too (the old K freed, as at the end of a step).
  kit::SparseMatrix K, A;
  kit::NodeArray f;
  Eigen::VectorXd b;
  const auto assemble_stiffness = [&] {
    kit::SparseMatrix fresh;
    plate.stiffness(fresh);
    K.swap(fresh);
  };
  const auto build_system = [&] {  // A = −h² K, then M (1 + h c) on its diagonal (c = 0); b = S h (f + h K v)
    plate.forces(f, 0);
    const Eigen::VectorXd v = kit::flatten(plate.v);
    A = (-h * h) * K;
    for (long i = 0; i < plate.nodes(); ++i)
      for (int axis = 0; axis < 3; ++axis) A.coeffRef(3 * i + axis, 3 * i + axis) += plate.masses[i];
    b = h * (kit::flatten(f) + h * (K * v));
    filter_in_place(plate.filters, b);
  };
  assemble_stiffness(), build_system();
  kit::PcgResult pcg;
  const auto pcg_solve = [&] { pcg = plate.kernels().pcg(A, b, plate.filters, tolerance, max_iterations); };
  // Eigen's CG on the same A and b: A is symmetric, so its full product (Lower | Upper) on the
  // stored rows; b is already filtered, and on the flat plate A couples no z to x or y (F's third
  // row is zero), so the z entries stay zero without a filter.
  Eigen::ConjugateGradient<kit::SparseMatrix, Eigen::Lower | Eigen::Upper> cg;
  cg.setTolerance(tolerance);
  cg.setMaxIterations(max_iterations);
  Eigen::VectorXd dv_cg, dv_ldlt;
  const auto cg_solve = [&] {
    cg.compute(A);
    dv_cg = cg.solve(b);
  };
  // LDLᵀ reads a column-major lower triangle: the row-major arrays of the symmetric A are those of
  // its transpose, A itself, column-major, so a map serves without a copy (made anew at each use:
  // build_system reallocates A). The ordering and the symbolic factorisation depend only on the
  // pattern, the mesh's: done once, as a simulation would.
  using ColumnMap = Eigen::Map<const Eigen::SparseMatrix<double>>;
  const auto columns = [&] {
    return ColumnMap(A.rows(), A.cols(), A.nonZeros(), A.outerIndexPtr(), A.innerIndexPtr(), A.valuePtr());
  };
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;
  const CpuClock analyse_clock;
  ldlt.analyzePattern(columns());
  const double analyse = analyse_clock.seconds();
  const auto ldlt_solve = [&] {
    ldlt.factorize(columns());
    dv_ldlt = ldlt.solve(b);
  };
  const auto whole = [&] {
    restore();
    kit::implicit_step(plate, h, 0, tolerance, max_iterations);
  };
  pcg_solve(), cg_solve(), ldlt_solve();
  if (ldlt.info() != Eigen::Success) {
    fmt::print(stderr, "bench: SimplicialLDLT failed on the plate's A\n");
    return 1;
  }
  // The pieces give implicit_step's answer: the same v after the step, to the last bit.
  restore();
  kit::implicit_step(plate, h, 0, tolerance, max_iterations);
  kit::NodeArray v_pieces;
  kit::unflatten(kit::flatten(v0) + pcg.x, v_pieces);
  const double step_difference = max_abs(plate.v - v_pieces);
  restore();
  std::vector<double> slowest;
  const std::vector<double> t =
      in_turn({assemble_stiffness, build_system, pcg_solve, cg_solve, ldlt_solve, whole, restore}, samples,
              0.1, &slowest);
  restore();
  const double whole_step = t[5] - t[6];
  const double rest_of_step = whole_step - t[0] - t[1] - t[2];
  const double rows = double(A.rows()), stored = double(A.nonZeros());
  const double elements = double(plate.elements());
  fmt::print("3. One implicit step (implicit_step, Baraff & Witkin's (M - h^2 K) dv = h (f + h K v)) of "
             "chapter 9's\n"
             "   spinning plate: {} m in {} x {} cells ({} elements, {} nodes), StVK, held in its plane, "
             "spinning at\n"
             "   pi rad/s, h = {} s, after {} steps from rest; A has {:.0f} rows and {:.0f} stored entries "
             "({:.1f} a row).\n"
             "   Solves to {:.0e} relative residual. Each piece timed alone on the same state, fastest of {} "
             "samples.\n",
             kit::plate_side, plate_cells, plate_cells, plate.elements(), plate.nodes(), h, warm_steps, rows,
             stored, stored / rows, tolerance, samples);
  kit::Table step({"piece", "ms", "slowest sample", "ns / element", "of the step", "iterations",
                   "ms / iteration", "solve / filtered PCG"});
  const auto piece = [&](const std::string& name, double seconds, double slow, int iterations, bool solve) {
    step.add_row({name, kit::fixed(1e3 * seconds, 3), slow > 0 ? kit::fixed(1e3 * slow, 3) : "",
                  kit::fixed(1e9 * seconds / elements, 0), kit::fixed(100 * seconds / whole_step, 1) + " %",
                  iterations > 0 ? std::to_string(iterations) : "",
                  iterations > 0 ? kit::fixed(1e3 * seconds / iterations, 4) : "",
                  solve ? kit::fixed(seconds / t[2], 2) : ""});
  };
  piece("stiffness K (FemBody::stiffness, a fresh K)", t[0], slowest[0], 0, false);
  piece("A and b (forces, -h^2 K + M, b, filter)", t[1], slowest[1], 0, false);
  piece("solve: filtered PCG (ex 7.3)", t[2], slowest[2], pcg.iterations, true);
  piece("rest (v += dv, x += h v, copies)", rest_of_step, 0, 0, false);
  piece("the whole implicit_step", whole_step, slowest[5] - t[6], 0, false);
  piece("peer: Eigen CG, diagonal preconditioner", t[3], slowest[3], int(cg.iterations()), true);
  piece("peer: Eigen SimplicialLDLT, factorise + solve", t[4], slowest[4], 0, true);
  step.print(std::cout);
  fmt::print("   rest: the whole step (less the copy that restores the state before each) less the three "
             "pieces, each\n"
             "   piece's fastest sample; within the noise (the slowest samples) it may come out near zero or "
             "below.\n");
  // One CG iteration reads A once (8 B a value, 4 B a column index, 4 B a row start) and at least
  // the vectors of the algorithm: q = A c (c read, q written), cᵀq, x += α c, r −= α q, s = P⁻¹ r,
  // rᵀs, c = s + β c: 12 reads and 5 writes of 8 B a row, a write with its read for ownership, 22
  // in all. The filtered PCG also reads the filters (72 B a node) twice an iteration: 48 B a row.
  const double cg_bytes = 12 * stored + 4 * (rows + 1) + 22 * 8 * rows;
  const double pcg_bytes = cg_bytes + 48 * rows;
  const double solve_cache = triad_at(12 * stored + 8 * 8 * rows);  // A and eight vectors
  fmt::print("   Eigen's SimplicialLDLT: the ordering (AMD) and symbolic analysis, once for the mesh, {:.2f} "
             "ms more;\n"
             "   its factor holds {} entries. The answers: the pieces give implicit_step's v to {:.1e} m/s; "
             "dv of Eigen's\n"
             "   CG and of LDL^T differ from the PCG's by {:.1e} and {:.1e} of the largest |dv|. Eigen's "
             "iterations()\n"
             "   counts one product less than the PCG's: it stops inside its last one.\n"
             "   Bound on the solve: one PCG iteration moves at least {:.2f} MB (Eigen's CG {:.2f} MB, no "
             "filters):\n"
             "   {:.3f} ms at the triad from memory, {:.3f} ms at that of a triad over A and eight vectors "
             "({:.1f} GB/s);\n"
             "   measured {:.3f} ms (PCG) and {:.3f} ms (Eigen CG) an iteration.\n",
             1e3 * analyse, ldlt.matrixL().nestedExpression().nonZeros(), step_difference,
             relative_difference(dv_cg, pcg.x), relative_difference(dv_ldlt, pcg.x), pcg_bytes / 1e6,
             cg_bytes / 1e6, 1e3 * pcg_bytes / bandwidth, 1e3 * pcg_bytes / solve_cache, solve_cache / 1e9,
             1e3 * t[2] / std::max(pcg.iterations, 1),
             1e3 * t[3] / std::max<double>(double(cg.iterations()), 1));
  if (step_difference != 0) {
    fmt::print(stderr, "bench: the timed pieces do not give implicit_step's answer\n");
    return 1;
  }
  fmt::print("\nThe whole benchmark: {:.0f} s.\n", total.seconds());
  return 0;
}
