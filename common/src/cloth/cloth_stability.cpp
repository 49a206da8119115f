// Explicit cloth stability: the predicted and the measured largest step (cloth_stability.hpp).
#include <kit/cloth/cloth_stability.hpp>

#include <algorithm>
#include <cmath>
#include <complex>
#include <random>

#include <fmt/format.h>

namespace kit {

namespace {
// y = K u for the springs' stiffness at rest: each spring adds k (x̂·(u_a − u_b)) x̂ to a and
// subtracts it from b [N per m of displacement].
void stiffness_times(const Springs& springs, const NodeArray& x, const NodeArray& u, NodeArray& y) {
  y.setZero(u.rows(), 3);
  for (std::size_t s = 0; s < springs.size(); ++s) {
    const auto a = springs.a[s], b = springs.b[s];
    const Vec3 d = x.row(a) - x.row(b);
    const double l = d.norm();
    if (l == 0) continue;
    const Vec3 along = d / l;
    const Vec3 force = springs.stiffness[s] * along.dot((u.row(a) - u.row(b)).transpose()) * along;
    y.row(a) += force.transpose(), y.row(b) -= force.transpose();
  }
}
}  // namespace

OmegaMax omega_max(const Springs& springs, const Eigen::VectorXd& masses, const NodeArray& x,
                   const std::vector<std::int32_t>& pins, double tolerance, int max_iterations) {
  // Iterate u ← M⁻¹K u (pins zeroed). M⁻¹K is self-adjoint in ⟨u, w⟩_M = Σ m uᵀw, so its
  // Rayleigh quotient uᵀKu / uᵀMu rises monotonically to the largest eigenvalue.
  std::mt19937_64 random(20261122);
  std::uniform_real_distribution<double> uniform(-1, 1);
  NodeArray u(x.rows(), 3), ku;
  for (Eigen::Index i = 0; i < u.rows(); ++i)
    for (int axis = 0; axis < 3; ++axis) u(i, axis) = uniform(random);
  for (auto p : pins) u.row(p).setZero();
  const auto m_norm2 = [&](const NodeArray& w) { return masses.dot(w.rowwise().squaredNorm()); };
  OmegaMax result;
  double previous = 0;
  for (int k = 1; k <= max_iterations; ++k) {
    u /= std::sqrt(m_norm2(u));
    stiffness_times(springs, x, u, ku);
    for (auto p : pins) ku.row(p).setZero();
    const double quotient = (u.array() * ku.array()).sum();  // uᵀKu with uᵀMu = 1
    for (int axis = 0; axis < 3; ++axis) u.col(axis) = ku.col(axis).cwiseQuotient(masses);
    for (auto p : pins) u.row(p).setZero();
    result = {std::sqrt(std::max(quotient, 0.0)), k};
    if (k > 1 && std::abs(quotient - previous) <= tolerance * quotient) break;
    previous = quotient;
  }
  return result;
}

namespace {
// The spectral radius of one step of `integrator` on the mode x'' = −ω² x − c ω² x', step h.
double amplification(ClothIntegrator integrator, double h, double omega, double c) {
  const double w2 = omega * omega;
  if (integrator == ClothIntegrator::symplectic_euler) {
    // v' = (1 − h c ω²) v − h ω² x,  x' = x + h v'  →  [[1 − h²ω², h(1 − hcω²)], [−hω², 1 − hcω²]]
    const double p = 1 - h * h * w2, q = h * (1 - h * c * w2), r = -h * w2, s = 1 - h * c * w2;
    // Eigenvalues (p + s ± √((p − s)² + 4qr))/2: this form of the discriminant has no
    // cancellation at small h, where trace² − 4·det would lose it all to round-off.
    const double discriminant = (p - s) * (p - s) + 4 * q * r;
    if (discriminant < 0) return std::sqrt(p * s - q * r);  // a complex pair: |λ|² = det
    const double root = std::sqrt(discriminant);
    return std::max(std::abs(p + s + root), std::abs(p + s - root)) / 2;
  }
  // One-step Runge–Kutta methods: |R(hλ)| for both roots λ of λ² + cω² λ + ω² = 0.
  const std::complex<double> disc = std::sqrt(std::complex<double>(c * c * w2 * w2 - 4 * w2));
  double worst = 0;
  for (const auto& lambda : {(-c * w2 + disc) / 2.0, (-c * w2 - disc) / 2.0}) {
    const std::complex<double> z = h * lambda;
    std::complex<double> r = 1.0 + z;
    if (integrator == ClothIntegrator::midpoint) r += z * z / 2.0;
    if (integrator == ClothIntegrator::rk4) r += z * z / 2.0 + z * z * z / 6.0 + z * z * z * z / 24.0;
    worst = std::max(worst, std::abs(r));
  }
  return worst;
}

bool every_mode_bounded(ClothIntegrator integrator, double h, double omega_max, double c) {
  constexpr int samples = 4000;  // the modes fill (0, ω_max] densely on a fine grid
  for (int k = 1; k <= samples; ++k)
    if (amplification(integrator, h, omega_max * k / samples, c) > 1 + 1e-12) return false;
  return true;
}
}  // namespace

double predicted_dt_max(ClothIntegrator integrator, double omega_max, double damping_time) {
  if (!(omega_max > 0)) return 0;
  // Undamped, explicit Euler (|R|² = 1 + (hω)²) and midpoint (|R|² = 1 + (hω)⁴/4) grow at every
  // step size, by less than round-off per step when h is small: say so rather than sample it.
  const bool grows_always =
      integrator == ClothIntegrator::explicit_euler || integrator == ClothIntegrator::midpoint;
  if (damping_time == 0 && grows_always) return 0;
  double lo = 1e-6 / omega_max, hi = 10 / omega_max;
  if (!every_mode_bounded(integrator, lo, omega_max, damping_time)) return 0;
  for (int k = 0; k < 60; ++k) {
    const double mid = std::sqrt(lo * hi);
    (every_mode_bounded(integrator, mid, omega_max, damping_time) ? lo : hi) = mid;
  }
  return lo;
}

MeasuredDtMax measure_dt_max(const ClothScene& scene, const Springs& springs, ClothKernels kernels,
                             ClothIntegrator integrator, double lo, double hi, long steps, double relative) {
  MeasuredDtMax result;
  const double amplitude = 1e-6 * std::min(scene.grid.dx(), scene.grid.dy());
  const auto grows = [&](double dt) {
    ClothSystem cloth(scene, springs, kernels);
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> uniform(-amplitude, amplitude);
    const NodeArray rest = cloth.x;
    for (Eigen::Index i = 0; i < cloth.x.rows(); ++i)
      for (int axis = 0; axis < 3; ++axis) cloth.x(i, axis) += uniform(random);
    for (auto p : cloth.pins()) cloth.x.row(p) = rest.row(p);
    ++result.runs;
    for (long k = 0; k < steps; ++k) {
      cloth.step(integrator, dt);
      ++result.steps;
      // Checked every 16 steps: a growing mode multiplies its amplitude many times over by then.
      if (k % 16 == 15 && !((cloth.x - rest).cwiseAbs().maxCoeff() < 1e3 * amplitude)) return true;
    }
    return !((cloth.x - rest).cwiseAbs().maxCoeff() < 1e3 * amplitude);
  };
  if (grows(lo)) return {0, lo, result.runs, result.steps};
  if (!grows(hi)) return {hi, hi, result.runs, result.steps};
  while (hi / lo > 1 + relative) {
    const double mid = std::sqrt(lo * hi);
    (grows(mid) ? hi : lo) = mid;
  }
  result.stable = lo, result.unstable = hi;
  return result;
}

ClothScene springs_only(const ClothScene& scene) {
  ClothScene bare = scene;
  bare.gravity.reset(), bare.drag.reset(), bare.ground.reset(), bare.strain_limit.reset();
  bare.spheres.clear();
  // Undamped: the prediction c/ω_max is for undamped modes; stability_at adds damping in
  // proportion to stiffness when it is asked to, so that prediction and run agree.
  for (auto* family : {&bare.springs.structural, &bare.springs.shear, &bare.springs.bend})
    if (*family) (*family)->damping = 0;
  return bare;
}

StabilityAtResolution stability_at(const ClothScene& scene, int n, ClothKernels kernels,
                                   ClothIntegrator integrator, double damping_time, long steps) {
  ClothScene bare = springs_only(at_longest_side(scene, n));
  for (auto* family : {&bare.springs.structural, &bare.springs.shear, &bare.springs.bend})
    if (*family) (*family)->damping = damping_time * (*family)->stiffness;
  const Springs springs = kernels.build_springs(bare.grid, bare.springs);
  const ClothSystem rest(bare, springs, kernels);
  StabilityAtResolution r;
  r.n = n;
  r.springs = long(springs.size());
  r.omega_max = omega_max(springs, rest.masses(), rest.x, rest.pins()).omega;
  r.predicted = predicted_dt_max(integrator, r.omega_max, damping_time);
  // Bracket around the prediction, or around symplectic Euler's 2/ω when there is none.
  const double guess = r.predicted > 0 ? r.predicted : 2 / r.omega_max;
  r.measured = measure_dt_max(bare, springs, kernels, integrator, 0.05 * guess, 4 * guess, steps);
  if (r.measured.estimate() > 0)
    r.spring_evaluations_per_second = double(r.springs) * stages(integrator) / (0.9 * r.measured.estimate());
  return r;
}

std::vector<StabilityCase> stability_cases(const ClothScene& scene, int n, ClothKernels kernels,
                                           double damping_time) {
  const double k = scene.springs.structural ? scene.springs.structural->stiffness : 1000.0;
  std::vector<StabilityCase> cases;
  const auto run = [&](const std::string& name, int families, ClothIntegrator integrator, double c) {
    ClothScene variant = scene;
    variant.springs = SpringLayout{};
    variant.springs.bend_layout = scene.springs.bend_layout;
    const SpringFamily family{k, c * k};
    variant.springs.structural = family;
    if (families >= 2) variant.springs.shear = family;
    if (families >= 3) variant.springs.bend = family;
    const bool slow_growth =
        c > 0 && (integrator == ClothIntegrator::explicit_euler || integrator == ClothIntegrator::midpoint);
    cases.push_back(
        {name, integrator, c, stability_at(variant, n, kernels, integrator, c, slow_growth ? 20000 : 2000)});
  };
  const char* names[] = {"structural", "+ shear", "+ shear + bend"};
  for (int families = 1; families <= 3; ++families)
    for (ClothIntegrator integrator : {ClothIntegrator::symplectic_euler, ClothIntegrator::rk4})
      run(names[families - 1], families, integrator, 0);
  for (ClothIntegrator integrator : all_cloth_integrators)
    run(fmt::format("all three, μ = {:.2g} s·K", damping_time), 3, integrator, damping_time);
  return cases;
}

}  // namespace kit
