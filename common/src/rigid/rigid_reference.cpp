#include <kit/rigid/rigid_reference.hpp>

#include <kit/rigid/rigid_integrators.hpp>

namespace kit {

std::vector<RigidState> free_rotation_reference(const RigidShape& shape, const RigidState& start,
                                                const std::vector<double>& times, Stats* stats) {
  using Vec7 = Eigen::Matrix<double, 7, 1>;
  const Quat q0(nearest_rotation(start.R));
  Vec7 y;
  y << q0.w(), q0.x(), q0.y(), q0.z(), q0.toRotationMatrix().transpose() * start.L;
  GslOptions options;
  options.rtol = options.atol = 1e-13;
  GslSolver solver(
      7,
      [&shape](double, const double* u, double* dudt) {
        const Eigen::Map<const Vec7> state(u);
        Eigen::Map<Vec7> rate(dudt);
        const Vec3 body = state.tail<3>();
        rate << quaternion_rate(state.head<4>(), shape.inverse_inertia * body), euler_equations(shape, body);
      },
      options);
  std::vector<RigidState> samples;
  double t = 0;
  for (double time : times) {
    solver.advance(t, y.data(), time);
    RigidState sample = start;
    sample.q = Quat(y[0], y[1], y[2], y[3]).normalized();
    sample.R = sample.q.toRotationMatrix();
    sample.L = sample.R * y.tail<3>();
    samples.push_back(sample);
  }
  if (stats) *stats = solver.stats();
  return samples;
}

}  // namespace kit
