// Chapter 8's model and the kit's own rigid-body steps: mass properties against integration over
// the solid, the closed form of the torque-free body against GSL, what each step conserves, and
// contact with the ground.
#include <cmath>
#include <vector>

#include <kit_catch.hpp>

#include <kit/rigid/rigid_body.hpp>
#include <kit/rigid/rigid_contact.hpp>
#include <kit/rigid/rigid_free_rotation.hpp>
#include <kit/rigid/rigid_integrators.hpp>
#include <kit/rigid/rigid_reference.hpp>

using kit::Mat3;
using kit::Vec3;

namespace {

// The inertia about the origin of the union of the shape's boxes, by the midpoint rule on a grid
// of `cells`³ cells over their bounding box, at the density that gives the shape's mass.
Mat3 integrated_inertia(const kit::RigidShape& shape, int cells, Vec3* centre_of_mass) {
  Vec3 low = Vec3::Constant(HUGE_VAL), high = -low;
  for (const auto& part : shape.parts) {
    low = low.cwiseMin(part.centre - part.sides / 2);
    high = high.cwiseMax(part.centre + part.sides / 2);
  }
  const Vec3 cell = (high - low) / cells;
  Mat3 second_moment = Mat3::Zero();
  Vec3 first_moment = Vec3::Zero();
  double volume = 0;
  for (int i = 0; i < cells; ++i)
    for (int j = 0; j < cells; ++j)
      for (int k = 0; k < cells; ++k) {
        const Vec3 p = low + cell.cwiseProduct(Vec3(i + 0.5, j + 0.5, k + 0.5));
        bool inside = false;
        for (const auto& part : shape.parts)
          inside = inside || ((p - part.centre).cwiseAbs().array() < part.sides.array() / 2).all();
        if (!inside) continue;
        volume += 1;
        first_moment += p;
        second_moment += p.squaredNorm() * Mat3::Identity() - p * p.transpose();
      }
  *centre_of_mass = first_moment / volume;
  return shape.mass / volume * second_moment;
}

// The body-frame angular velocity I⁻¹ Rᵀ L [rad/s].
Vec3 omega_body(const kit::RigidShape& shape, const kit::RigidState& state) {
  return shape.inverse_inertia * kit::body_momentum(state);
}

// The times at which ω_body's component `axis` changes sign, from samples every `dt` [s]
// (linear interpolation between the two samples around each change).
std::vector<double> sign_changes(const std::vector<double>& times, const std::vector<double>& values) {
  std::vector<double> changes;
  for (std::size_t n = 1; n < values.size(); ++n)
    if ((values[n] > 0) != (values[n - 1] > 0))
      changes.push_back(times[n - 1] +
                        (times[n] - times[n - 1]) * values[n - 1] / (values[n - 1] - values[n]));
  return changes;
}

double mean_interval(const std::vector<double>& changes) {
  return (changes.back() - changes.front()) / double(changes.size() - 1);
}

}  // namespace

TEST_CASE(
    "rigid shapes: the inertia of the box and the cylinder is the closed form, the T-handle's the integral") {
  const auto box = kit::box_shape(2.0, Vec3(0.4, 0.2, 0.3));
  CHECK(box.inertia(0, 0) == Approx(2.0 / 12 * (0.04 + 0.09)));
  CHECK(box.inertia(1, 1) == Approx(2.0 / 12 * (0.16 + 0.09)));
  CHECK(box.inertia(2, 2) == Approx(2.0 / 12 * (0.16 + 0.04)));
  CHECK(box.corners.size() == 8);
  const auto cylinder = kit::cylinder_shape(3.0, 0.1, 0.5);
  CHECK(cylinder.inertia(1, 1) == Approx(3.0 * 0.01 / 2));
  CHECK(cylinder.inertia(0, 0) == Approx(3.0 * (0.03 + 0.25) / 12));

  const auto handle = kit::t_handle_shape(0.5);
  Vec3 centre;
  const Mat3 integrated = integrated_inertia(handle, 160, &centre);
  INFO("kit:\n" << handle.inertia << "\nintegrated:\n" << integrated);
  CHECK(centre.norm() < 2e-3);  // the body frame sits on the centre of mass, to a cell (2.1 mm)
  CHECK((handle.inertia - integrated).norm() < 5e-3 * handle.inertia.norm());
  CHECK((handle.inertia * handle.inverse_inertia - Mat3::Identity()).norm() < 1e-12);
  // Principal axes along the body axes, y < x < z: the bar (x) is the intermediate axis.
  CHECK(std::abs(handle.inertia(0, 1)) + std::abs(handle.inertia(0, 2)) + std::abs(handle.inertia(1, 2)) <
        1e-15);
  CHECK(handle.inertia(1, 1) < 0.6 * handle.inertia(0, 0));
  CHECK(handle.inertia(0, 0) < 0.85 * handle.inertia(2, 2));
  CHECK_THROWS_WITH(kit::shape_named("sphere"), ContainsSubstring("sphere") && ContainsSubstring("t-handle"));
  CHECK_THROWS_WITH(kit::box_shape(-1, Vec3::Ones()), ContainsSubstring("mass"));
}

TEST_CASE(
    "the nearest rotation of a drifted R is a rotation, and the Cayley map is one to third order of exp") {
  const Mat3 rotation = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  Mat3 drifted = rotation;
  drifted(0, 1) += 1e-3;
  drifted(2, 0) -= 2e-3;
  const Mat3 nearest = kit::nearest_rotation(drifted);
  CHECK(kit::orthonormality_error(drifted) > 1e-3);
  CHECK(kit::orthonormality_error(nearest) < 1e-14);
  CHECK(nearest.determinant() == Approx(1.0));
  CHECK((nearest - rotation).norm() < (drifted - rotation).norm());

  const Vec3 axis = Vec3(-1, 0.5, 2).normalized();
  double previous = 0;
  for (double angle : {0.1, 0.05, 0.025}) {
    const Mat3 C = kit::cayley(angle * axis);
    CHECK(kit::orthonormality_error(C) < 1e-15);
    CHECK(C.determinant() == Approx(1.0));
    const double gap = (C - Eigen::AngleAxisd(angle, axis).toRotationMatrix()).norm();
    if (previous > 0) CHECK(previous / gap == Approx(8).epsilon(0.02));  // third order
    previous = gap;
  }
}

TEST_CASE("the torque-free closed form: its flip period is GSL's, and small wobbles about the largest axis") {
  const auto handle = kit::t_handle_shape(0.5);
  const Vec3 moments = handle.principal_moments();  // y, x, z of the body
  const Vec3 omega0(10.0, 0.0, 0.1);                // about the bar (intermediate), a little about z
  const auto motion = kit::free_rotation(moments, Vec3(omega0.y(), omega0.x(), omega0.z()));
  REQUIRE(std::isfinite(motion.period()));
  CHECK(motion.modulus() > 0.999);  // near the separatrix: long stays, quick flips

  // GSL, sampled every 2 ms over three periods: ω along the bar changes sign every half period.
  const auto start = kit::spinning_state(handle, Vec3::Zero(), omega0);
  std::vector<double> times, along_bar;
  for (double t = 0.002; t < 3 * motion.period(); t += 0.002) times.push_back(t);
  kit::Stats stats;
  for (const auto& state : kit::free_rotation_reference(handle, start, times, &stats))
    along_bar.push_back(omega_body(handle, state).x());
  const auto changes = sign_changes(times, along_bar);
  REQUIRE(changes.size() >= 5);
  INFO("closed form " << motion.period() / 2 << " s, GSL " << mean_interval(changes) << " s");
  CHECK(mean_interval(changes) == Approx(motion.period() / 2).epsilon(1e-4));
  CHECK(stats.rhs_evals > 0);

  // A small wobble about the largest axis: the linearised period 2π / (ω3 sqrt((I3−I1)(I3−I2)/(I1 I2))).
  const double spin = 5.0;
  const auto wobble = kit::free_rotation(moments, Vec3(1e-4, 1e-4, spin));
  CHECK(wobble.about_largest_axis());
  const double linear =
      2 * M_PI /
      (spin * std::sqrt((moments[2] - moments[0]) * (moments[2] - moments[1]) / (moments[0] * moments[1])));
  CHECK(wobble.period() == Approx(linear).epsilon(1e-6));
  CHECK_FALSE(kit::free_rotation(moments, Vec3(1e-4, 1e-4, spin)).period() > 1.01 * linear);
  CHECK_FALSE(kit::free_rotation(moments, Vec3(1e-4, spin, 1e-4)).about_largest_axis() ==
              kit::free_rotation(moments, Vec3(spin, 1e-4, 1e-4)).about_largest_axis());
  CHECK_THROWS(kit::free_rotation(Vec3(3, 2, 1), omega0));
}

TEST_CASE("the midpoint Lie–Poisson step keeps E, L and RᵀR = 1 to round-off, even at a coarse step") {
  const auto handle = kit::t_handle_shape(0.5);
  auto state = kit::spinning_state(handle, Vec3::Zero(), Vec3(10.0, 0.0, 0.1));
  const double energy = kit::rotational_energy(handle, state);
  const Vec3 momentum = state.L;
  const double h = 0.01;  // h|ω| = 0.1
  long iterations = 0;
  double worst_energy = 0, worst_orthonormality = 0;
  for (int n = 0; n < 100'000; ++n) {
    iterations += kit::midpoint_rotation_step(handle, state, h);
    worst_energy = std::max(worst_energy, std::abs(kit::rotational_energy(handle, state) / energy - 1));
    worst_orthonormality = std::max(worst_orthonormality, kit::orthonormality_error(state.R));
  }
  CHECK(worst_energy < 1e-12);
  CHECK((state.L - momentum).norm() == 0.0);  // never touched: R⁺ L_b⁺ = R L_b by construction
  CHECK((state.R * kit::body_momentum(state) - momentum).norm() < 1e-12 * momentum.norm());
  CHECK(worst_orthonormality < 1e-11);
  CHECK(double(iterations) / 100'000 < 20);  // the fixed point converges in a few iterations
}

TEST_CASE("RK4 on (q, L_b) is fourth order against GSL, and flips the T-handle at GSL's times") {
  const auto handle = kit::t_handle_shape(0.5);
  const auto start = kit::spinning_state(handle, Vec3::Zero(), Vec3(10.0, 0.0, 0.1));
  const double t_end = 2.0;
  const auto reference = kit::free_rotation_reference(handle, start, {t_end}).front();
  double previous = 0;
  for (long steps : {200, 400, 800}) {  // h|ω| from 0.1 to 0.025; finer meets GSL's own error
    auto state = start;
    for (long n = 0; n < steps; ++n) kit::rk4_rotation_step(handle, state, t_end / double(steps));
    const double error = (state.R - reference.R).norm();
    INFO(steps << " steps: error " << error);
    if (previous > 0) CHECK(std::log2(previous / error) == Approx(4).margin(0.2));
    previous = error;
    CHECK(kit::orthonormality_error(state.R) < 1e-14);
  }
}

TEST_CASE("the largest and smallest axes are stable, the intermediate one flips") {
  const auto handle = kit::t_handle_shape(0.5);
  const double spin = 10.0, nudge = 0.1, h = 1e-3;
  for (int axis = 0; axis < 3; ++axis) {  // body x: intermediate; y: smallest; z: largest
    Vec3 omega = Vec3::Constant(nudge);
    omega[axis] = spin;
    auto state = kit::spinning_state(handle, Vec3::Zero(), omega);
    double lowest = spin;
    for (int n = 0; n < 20'000; ++n) {
      kit::midpoint_rotation_step(handle, state, h);
      lowest = std::min(lowest, omega_body(handle, state)[axis]);
    }
    INFO("axis " << axis << ": the spin about it went down to " << lowest << " rad/s");
    if (axis == 0)
      CHECK(lowest < -0.9 * spin);  // reversed: the flip
    else
      CHECK(lowest > 0.9 * spin);
  }
}

TEST_CASE("a box dropped flat bounces to e² of its height and never stays below the ground") {
  const auto box = kit::box_shape(1.0, Vec3(0.4, 0.2, 0.3));
  for (double e : {0.0, 0.5, 0.8}) {
    for (double h : {1e-3, 1e-4}) {
      kit::RigidState state;
      state.x = Vec3(0, 1.0 + 0.1, 0);  // the lowest face 1 m above the ground
      kit::GroundContact contact;
      contact.restitution = e;
      double rise = 0, deepest_after = 0, deepest_before = 0;
      int contacts = 0;
      for (long n = 0; n < long(6.0 / h); ++n) {  // e = 0.8 comes to rest after about 4 s
        kit::translation_step(box, state, h, Vec3(0, -9.81, 0));
        kit::midpoint_rotation_step(box, state, h);
        deepest_before = std::min(deepest_before, kit::lowest_point(box, state));
        const auto event = kit::resolve_ground_contact(box, state, contact);
        deepest_after = std::min(deepest_after, kit::lowest_point(box, state));
        if (event.normal_impulse > 0) ++contacts;
        if (contacts == 1) rise = std::max(rise, kit::lowest_point(box, state));
      }
      INFO("e = " << e << ", h = " << h << ": rises to " << rise << " m; deepest " << deepest_before << " m");
      CHECK(rise == Approx(e * e).margin(h * 10));  // 1 cm at h = 1 ms, 1 mm at 0.1 ms
      CHECK(deepest_after > -1e-12);
      CHECK(deepest_before > -std::sqrt(2 * 9.81) * h * 1.5);  // at most a step's travel at impact speed
      CHECK(state.x.y() == Approx(0.1).margin(1e-3));          // at rest on its face at the end
      CHECK((state.R - Mat3::Identity()).norm() < 1e-12);      // a flat drop does not turn it
    }
  }
}
