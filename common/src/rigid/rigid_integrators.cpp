#include <kit/rigid/rigid_integrators.hpp>

#include <cmath>

namespace kit {
Vec3 euler_equations(const RigidShape& shape, const Vec3& body_momentum) {
  return body_momentum.cross(shape.inverse_inertia * body_momentum);
}

Eigen::Vector4d quaternion_rate(const Eigen::Vector4d& q, const Vec3& omega_body) {
  const Quat rate = Quat(q[0], q[1], q[2], q[3]) * Quat(0, omega_body.x(), omega_body.y(), omega_body.z());
  return 0.5 * Eigen::Vector4d(rate.w(), rate.x(), rate.y(), rate.z());
}

void translation_step(const RigidShape& shape, RigidState& state, double h, const Vec3& force) {
  state.x += h * state.P / shape.mass + 0.5 * h * h * force / shape.mass;
  state.P += h * force;
}

Mat3 cayley(const Vec3& r) {
  // With a = r/2: (1 − a*)⁻¹(1 + a*) = 1 + 2 (a* + a*²) / (1 + |a|²); column j is that applied to
  // e_j, and a* v = a × v.
  const Vec3 a = 0.5 * r;
  const double scale = 2.0 / (1.0 + a.squaredNorm());
  Mat3 C;
  for (int j = 0; j < 3; ++j) {
    const Vec3 e = Vec3::Unit(j);
    C.col(j) = e + scale * (a.cross(e) + a.cross(a.cross(e)));
  }
  return C;
}

int midpoint_rotation_step(const RigidShape& shape, RigidState& state, double h) {
  const Vec3 before = state.R.transpose() * state.L;
  Vec3 after = before, previous;
  Mat3 turn = Mat3::Identity();
  // A contraction of rate about h|ω|·(I3 − I1)/I2: iterate until the change reaches round-off,
  // which shows as a change that no longer shrinks.
  double change = HUGE_VAL, last_change;
  int iterations = 0;
  do {
    previous = after;
    turn = cayley(h * (shape.inverse_inertia * (0.5 * (before + after))));
    after = turn.transpose() * before;
    last_change = change;
    change = (after - previous).norm();
    ++iterations;
  } while (change > 1e-16 * before.norm() && !(change >= last_change && change < 1e-12 * before.norm()) &&
           iterations < midpoint_max_iterations);
  state.R = state.R * turn;  // L = R L_b is left as it was: R⁺ L_b⁺ = R turn turnᵀ L_b
  return iterations;
}

bool midpoint_rotation_substeps(const RigidShape& shape, RigidState& state, double h, int depth) {
  RigidState trial = state;
  if (midpoint_rotation_step(shape, trial, h) < midpoint_max_iterations || depth >= 16) {
    state = trial;
    return true;
  }
  midpoint_rotation_substeps(shape, state, h / 2, depth + 1);
  midpoint_rotation_substeps(shape, state, h / 2, depth + 1);
  return false;
}

void rk4_rotation_step(const RigidShape& shape, RigidState& state, double h) {
  using Vec7 = Eigen::Matrix<double, 7, 1>;
  const auto rate = [&shape](const Vec7& y) {
    const Vec3 body = y.tail<3>();
    Vec7 dy;
    dy << quaternion_rate(y.head<4>(), shape.inverse_inertia * body), euler_equations(shape, body);
    return dy;
  };
  Vec7 y;
  y << state.q.w(), state.q.x(), state.q.y(), state.q.z(), state.q.toRotationMatrix().transpose() * state.L;
  const Vec7 k1 = rate(y), k2 = rate(y + 0.5 * h * k1), k3 = rate(y + 0.5 * h * k2), k4 = rate(y + h * k3);
  y += h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
  state.q = Quat(y[0], y[1], y[2], y[3]).normalized();
  state.R = state.q.toRotationMatrix();
  state.L = state.R * y.tail<3>();
}

}  // namespace kit
