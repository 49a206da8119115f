#include "continuum_experiments.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>
#include <Eigen/Geometry>

#include <kit/base/stopwatch.hpp>
#include <kit/fem/fem_material.hpp>

namespace kit {

namespace {

/// The beam's weight per length q = ρ g h t [N/m].
double beam_load(const FemMaterial& material, double gravity) {
  return material.density * gravity * cantilever_height * material.thickness;
}

}  // namespace

double euler_bernoulli_tip(const FemMaterial& material, double gravity) {
  return cantilever_tip_deflection(beam_load(material, gravity), cantilever_length, material.young,
                                   rectangle_second_moment(material.thickness, cantilever_height));
}

double timoshenko_tip(const FemMaterial& material, double gravity) {
  return timoshenko_tip_deflection(beam_load(material, gravity), cantilever_length, material.young,
                                   rectangle_second_moment(material.thickness, cantilever_height),
                                   material.young / (2 * (1 + material.poisson)),
                                   cantilever_height * material.thickness);
}

double cantilever_first_frequency(const FemMaterial& material) {
  const double beta_l = 1.87510407;  // the first root of 1 + cos(βL) cosh(βL) = 0
  const double bending = material.young * rectangle_second_moment(material.thickness, cantilever_height);
  const double mass_per_length = material.density * material.thickness * cantilever_height;
  return beta_l * beta_l * std::sqrt(bending / (mass_per_length * std::pow(cantilever_length, 4)));
}

TriangleMesh continuum_mesh(double width, double height, int nx, int ny, MeshKind kind) {
  return kind == MeshKind::regular ? regular_rectangle_mesh(width, height, nx, ny, CellDiagonal::alternating)
                                   : irregular_rectangle_mesh(width, height, nx, ny, 9);
}

namespace {

/// Pins every node on the edge x = 0 and keeps the body in its plane.
void clamp_left_edge(FemBody& body) {
  for (long i = 0; i < body.nodes(); ++i)
    if (body.mesh().nodes[i].x() == 0) body.pin(i);
  body.hold_in_plane();
}

/// The mean of `value(i)` over the nodes on the edge x = `at`.
template <class Value>
double mean_on_edge(const FemBody& body, double at, Value&& value) {
  double sum = 0;
  int count = 0;
  for (long i = 0; i < body.nodes(); ++i)
    if (body.mesh().nodes[i].x() == at) {
      sum += value(i);
      ++count;
    }
  return sum / count;
}

double tip_deflection(const FemBody& body) {
  return mean_on_edge(body, cantilever_length,
                      [&](long i) { return body.mesh().nodes[i].y() - body.x(i, 1); });
}

}  // namespace

TipRun run_cantilever(const FemMaterial& material, FemModel model, TipSolver solver, int ny,
                      const ContinuumKernels& kernels, long step_budget) {
  FemBody body(continuum_mesh(cantilever_length, cantilever_height, 10 * ny, ny, MeshKind::regular), material,
               model, kernels);
  clamp_left_edge(body);
  add_weight(body);
  TipRun run;
  run.model = model;
  run.solver = solver;
  run.ny = ny;
  run.elements = body.elements();
  const double omega = cantilever_first_frequency(material);
  const double drag = 2 * omega, rest_time = 20 / omega;  // critical damping of the first mode
  // At rest: what motion is left would move no node by 1e-6 of the tip's sag over the whole
  // relaxation (after 20/ω1 at critical damping, about 21 e^−20 ≈ 4e-8 of the start is left).
  // Not the force residual: its round-off floor, a sum of element forces up to 1e4 times the
  // weight, reaches 1e-6 of the load on the finer meshes.
  const auto at_rest = [&] {
    return body.v.cwiseAbs().maxCoeff() * rest_time <= 1e-6 * std::abs(tip_deflection(body));
  };
  const Stopwatch clock;
  if (solver == TipSolver::newton) {
    const StaticSolve s = solve_static(body);
    run.steps = s.iterations;
    run.done = s.converged;
    run.failure = s.failure;
  } else if (solver == TipSolver::explicit_relaxation) {
    const double limit = 0.9 * explicit_step_limit(body);
    run.steps = static_cast<long>(std::ceil(rest_time / limit));
    if (run.steps > step_budget) {
      run.failure =
          fmt::format("needs {} steps of {:.3g} s, over the budget of {}", run.steps, limit, step_budget);
      return run;
    }
    const double h = rest_time / static_cast<double>(run.steps);
    for (long step = 0; step < run.steps; ++step) explicit_step(body, h, drag);
    run.done = body.x.allFinite() && at_rest();
    if (!run.done) run.failure = body.x.allFinite() ? "not at rest" : "diverged";
  } else {
    run.steps = 60;  // of 1/(2ω1): implicit Euler damps the first mode by about 0.6 a step
    run.done = true;
    for (long step = 0; step < run.steps; ++step) {
      const ImplicitStep s = implicit_step(body, 0.5 / omega, drag, 1e-10);
      run.iterations += s.iterations;
      if (!s.converged) {
        run.done = false;
        run.failure = fmt::format("PCG did not converge at step {}", step);
        break;
      }
    }
    if (run.done && !at_rest()) {
      run.done = false;
      run.failure = "not at rest";
    }
  }
  run.seconds = clock.seconds();
  run.tip = tip_deflection(body);
  run.error = run.tip / euler_bernoulli_tip(material) - 1;
  return run;
}

TipConvergence cantilever_convergence(const FemMaterial& material, FemModel model,
                                      const ContinuumKernels& kernels, int finest) {
  TipConvergence c;
  for (int ny = 1; ny <= finest; ny *= 2)
    c.runs.push_back(run_cantilever(material, model, TipSolver::newton, ny, kernels));
  const std::size_t n = c.runs.size();
  if (n < 4)
    throw std::invalid_argument(
        fmt::format("cantilever_convergence: finest {} (expected at least 8)", finest));
  if (c.runs[n - 3].done && c.runs[n - 2].done && c.runs[n - 1].done)
    c.richardson = richardson(c.runs[n - 3].tip, c.runs[n - 2].tip, c.runs[n - 1].tip);
  if (!c.richardson.converges) return c;  // no limit, no order
  // Least squares of log|tip − limit| = a − p log(ny) from ny = 2 (one cell through the height
  // is not yet in the asymptotic range) to the next-to-finest (the finest sits where Richardson's
  // estimate puts it).
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double count = static_cast<double>(n - 2);
  for (std::size_t k = 1; k + 1 < n; ++k) {
    const double lx = std::log(static_cast<double>(c.runs[k].ny)),
                 ly = std::log(std::abs(c.runs[k].tip - c.richardson.limit));
    sx += lx;
    sy += ly;
    sxx += lx * lx;
    sxy += lx * ly;
  }
  c.order = -(count * sxy - sx * sy) / (count * sxx - sx * sx);
  return c;
}

std::vector<TurnedElement> turn_sweep(const FemMaterial& material, const ContinuumKernels& kernels,
                                      int samples) {
  const Lame lame = plane_stress_lame(material.young, material.poisson);
  const Eigen::Vector2d rest[3] = {{0, 0}, {0.1, 0}, {0, 0.1}};
  const RestTriangle shape = rest_triangle(rest[0], rest[1], rest[2], material.thickness);
  const auto gradient = [&](const Eigen::Matrix3d& motion) {
    Vec3 x[3];
    for (int i = 0; i < 3; ++i) x[i] = motion * Vec3(rest[i].x(), rest[i].y(), 0);
    return kernels.element.deformation_gradient(x[0], x[1], x[2], shape.inverse);
  };
  const Eigen::Matrix3d stretch = Eigen::Vector3d(1.01, 1, 1).asDiagonal();
  const double scale =
      linear_forces(gradient(stretch), shape.inverse, shape.volume, lame).cwiseAbs().maxCoeff();
  std::vector<TurnedElement> sweep;
  for (int k = 0; k < samples; ++k) {
    const double degrees = 180.0 * k / (samples - 1);
    const Matrix32 F = gradient(Eigen::AngleAxisd(degrees * M_PI / 180, Vec3::UnitZ()).toRotationMatrix());
    sweep.push_back(
        {degrees, cauchy_strain(F).norm(), kernels.element.green_strain(F).norm(),
         linear_forces(F, shape.inverse, shape.volume, lame).cwiseAbs().maxCoeff() / scale,
         kernels.element.forces(F, shape.inverse, shape.volume, lame).cwiseAbs().maxCoeff() / scale});
  }
  return sweep;
}

PlateRun spin_plate(const FemMaterial& material, FemModel model, TimeIntegrator integrator, int resolution,
                    MeshKind mesh, double h, double t_end, const ContinuumKernels& kernels, int samples,
                    const std::function<void(const FemBody&, int, double)>& on_sample) {
  FemBody body(continuum_mesh(plate_side, plate_side, resolution, resolution, mesh), material, model,
               kernels);
  body.hold_in_plane();
  const Eigen::RowVector3d centre(plate_side / 2, plate_side / 2, 0);
  for (long i = 0; i < body.nodes(); ++i) {
    const Eigen::RowVector3d r = body.x.row(i) - centre;
    body.v.row(i) << -plate_spin * r.y(), plate_spin * r.x(), 0;
  }
  // The edge from corner (0, 0) to corner (side, 0): both boundary nodes, in every mesh.
  long first = 0, second = 0;
  for (long i = 0; i < body.nodes(); ++i)
    if ((body.mesh().nodes[i] - Eigen::Vector2d(plate_side, 0)).norm() < 1e-12) second = i;
  PlateRun run;
  if (h <= 0) h = integrator == TimeIntegrator::explicit_euler ? 0.9 * explicit_step_limit(body) : 1e-3;
  run.steps = std::max<long>(1, static_cast<long>(std::ceil(t_end / h)));
  run.h = t_end / static_cast<double>(run.steps);
  samples = static_cast<int>(std::min<long>(samples, run.steps));
  // The angle is unwrapped at every step: a step turns the plate by far less than π.
  double turned = 0, last_angle = 0;
  const auto track_angle = [&] {
    const Eigen::RowVector3d edge = body.x.row(second) - body.x.row(first);
    const double angle = std::atan2(edge.y(), edge.x());
    turned += std::remainder(angle - last_angle, 2 * M_PI);
    last_angle = angle;
  };
  const auto energy = [&] {
    return 0.5 * (body.masses.asDiagonal() * body.v).cwiseProduct(body.v).sum() + body.elastic_energy();
  };
  const double start_energy = energy();
  const auto sample = [&](double t, int index) {
    run.samples.push_back({t, body.largest_green_strain(), turned, energy()});
    if (on_sample) on_sample(body, index, t);
  };
  sample(0, 0);
  long done = 0;
  for (int k = 1; k <= samples && !run.diverged; ++k) {
    const long until = run.steps * k / samples;
    for (; done < until; ++done) {
      if (integrator == TimeIntegrator::explicit_euler) {
        explicit_step(body, run.h, 0);
      } else {
        run.iterations += implicit_step(body, run.h, 0).iterations;
      }
      track_angle();
    }
    // Diverged: no force acts from outside, so the energy can only stay or fall; an unstable
    // step makes it grow without bound. A hundredfold is far past any integrator's error and
    // well before the numbers overflow. (The linear plate's strain grows without bound while its
    // energy stays put: that is its motion, not a divergence.)
    if (!body.x.allFinite() || !(energy() <= 100 * start_energy)) {
      run.diverged = true;
      run.diverged_at = static_cast<double>(done) * run.h;
      break;
    }
    sample(static_cast<double>(done) * run.h, k);
  }
  return run;
}

std::optional<double> sheet_stretch(const FemMaterial& material, FemModel model, MeshKind mesh, int n,
                                    const ContinuumKernels& kernels) {
  FemBody body(continuum_mesh(1, 1, n, n, mesh), material, model, kernels);
  clamp_left_edge(body);
  const double stress = 1e-3 * material.young;  // [Pa]
  // The right edge's nodes by height; each carries the traction over half of each edge beside it.
  std::vector<long> edge;
  for (long i = 0; i < body.nodes(); ++i)
    if (body.mesh().nodes[i].x() == 1) edge.push_back(i);
  std::sort(edge.begin(), edge.end(),
            [&](long a, long b) { return body.mesh().nodes[a].y() < body.mesh().nodes[b].y(); });
  for (std::size_t k = 0; k < edge.size(); ++k) {
    const double below = k > 0 ? body.mesh().nodes[edge[k]].y() - body.mesh().nodes[edge[k - 1]].y() : 0;
    const double above =
        k + 1 < edge.size() ? body.mesh().nodes[edge[k + 1]].y() - body.mesh().nodes[edge[k]].y() : 0;
    body.loads(edge[k], 0) = stress * material.thickness * (below + above) / 2;
  }
  if (!solve_static(body).converged) return std::nullopt;
  const double stretch = mean_on_edge(body, 1, [&](long i) { return body.x(i, 0) - 1; });
  return stretch / (stress / material.young);
}

std::optional<double> StretchRow::difference() const {
  if (!regular || !irregular) return std::nullopt;
  return std::abs(*irregular - *regular) / *regular;
}

std::vector<StretchRow> stretch_sweep(const FemMaterial& material, FemModel model,
                                      const std::vector<int>& sizes, const ContinuumKernels& kernels) {
  std::vector<StretchRow> rows;
  for (const int n : sizes)
    rows.push_back({n, sheet_stretch(material, model, MeshKind::regular, n, kernels),
                    sheet_stretch(material, model, MeshKind::irregular, n, kernels)});
  return rows;
}

}  // namespace kit
