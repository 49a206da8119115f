// ./kit bench rigid: chapter 8's six rotation integrators (rigid_stepper.hpp) on the free T-handle
// of the Dzhanibekov effect (t_handle_shape(0.5): 0.5 kg, principal axes = body axes, x the
// intermediate one), started at ω_body = (10, 0, 0.1) rad/s, against the peer a game programmer
// would use, Bullet's btRigidBody, measured in the same process:
//   1. ns per body-step of each integrator at h = 1 ms (fastest of several samples);
//   2. Bullet: one btRigidBody in a btDiscreteDynamicsWorld without gravity, stepped as a game
//      steps it (stepSimulation(1/60, 0): one fixed step a call), with the T-handle's mass and
//      principal inertia, with its gyroscopic options off, explicit, implicit in the body frame
//      (Bullet's default), and that default on the body with M and I ×100; and why the default
//      does nothing on this body: btMatrix3x3::solve33, checked on the installed Bullet;
//   3. every Bullet variant and every integrator at h = 1/60 s over 60 s: the largest relative
//      drift of the energy, of |L| and of L itself (world frame), and the flips of ω along the
//      intermediate axis against the closed form's count (rigid_free_rotation.hpp);
//   4. equal cost: each integrator at the step that makes its CPU time per simulated second that
//      of Bullet's default at 1/60 s, its drifts beside Bullet's, as ratios.
// Timings live here, never in the tests.
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <time.h>
#include <unistd.h>

#include <btBulletDynamicsCommon.h>
#include <fmt/format.h>

#include <kit/app/table.hpp>
#include <kit/base/stopwatch.hpp>
#include <kit/rigid/rigid_body.hpp>
#include <kit/rigid/rigid_free_rotation.hpp>
#include <kit/rigid/rigid_integrators.hpp>
#include <kit/rigid/rigid_stepper.hpp>

#include "cpu_clock.hpp"
#include "rigid_kernels.hpp"

namespace {
using kit::bench::CpuClock, kit::bench::load_average;  // every time below is read from it

constexpr double mass = 0.5;          // [kg], the T-handle of chapter 8
const kit::Vec3 omega0(10, 0, 0.1);   // [rad/s], body frame = world frame at t = 0
constexpr double h_bench = 1e-3;      // [s], part 1
constexpr long bench_steps = 10000;   // steps of one part-1 sample: 10 s, from the start each time
constexpr double h_game = 1.0 / 60;   // [s], a game's frame, Bullet's fixed step
constexpr double t_end = 60;          // [s] simulated in parts 3 and 4
constexpr double h_reference = 1e-4;  // [s], the midpoint's reference run for the flips
constexpr double heavy = 100;         // the factor on M and I of the last Bullet variant
// Samples per timing: a busy machine only ever slows a sample, so the fastest is kept.
constexpr int samples = 9;

// Whatever a timed loop computes ends here, so that the compiler cannot drop the loop.
volatile double sink = 0;

long steps_for(double h) { return std::lround(t_end / h); }

std::string ratio_text(double kit, double peer) {
  if (!std::isfinite(kit)) return "NaN";
  if (peer == 0) return kit == 0 ? "=" : "inf";
  return kit::sci(kit / peer, 2);
}

// --- what a run is measured by -------------------------------------------------------------------
struct Drift {
  double energy = 0;        // max |E − E0|/E0 over the run
  double energy_end = 0;    // (E − E0)/E0 at the end: its sign says gained or lost
  double momentum = 0;      // max ||L| − |L0||/|L0|, L in the world frame
  double direction = 0;     // max |L − L0|/|L0|: L's drift as a vector (its turning too)
  double frame = 0;         // max ‖RᵀR − 1‖: how far R left the rotations
  int flips = 0;            // reversals of ω_body along the intermediate axis
  double last_flip = -1;    // [s], the time of the last one; −1: none
  double diverged_at = -1;  // [s], the time E or L stopped being finite; −1: never
};

// Counts the reversals of ω along the intermediate axis with hysteresis: a flip is counted when ω
// reaches half its starting amplitude with the sign opposite to the last one reached, so that
// round-off near zero cannot count twice.
class DriftMeter {
 public:
  DriftMeter(double e0, const kit::Vec3& l0, double omega_start)
      : e0_(e0), l0_(l0), threshold_(0.5 * omega_start) {
    sign_ = omega_start > 0 ? 1 : -1;
  }
  // False once the run has diverged (then stop stepping).
  bool see(double t, double energy, const kit::Vec3& momentum, const kit::Mat3& R, double omega_axis) {
    if (!std::isfinite(energy) || !momentum.allFinite() || !R.allFinite()) {
      drift_.diverged_at = t;
      return false;
    }
    drift_.energy = std::max(drift_.energy, std::abs(energy - e0_) / e0_);
    drift_.energy_end = (energy - e0_) / e0_;
    drift_.momentum = std::max(drift_.momentum, std::abs(momentum.norm() - l0_.norm()) / l0_.norm());
    drift_.direction = std::max(drift_.direction, (momentum - l0_).norm() / l0_.norm());
    drift_.frame = std::max(drift_.frame, kit::orthonormality_error(R));
    const int now = omega_axis > threshold_ ? 1 : omega_axis < -threshold_ ? -1 : 0;
    if (now != 0 && now != sign_) {
      ++drift_.flips;
      drift_.last_flip = t;
      sign_ = now;
    }
    return true;
  }
  const Drift& drift() const { return drift_; }

 private:
  double e0_;
  kit::Vec3 l0_;
  double threshold_;  // [rad/s]
  int sign_;
  Drift drift_;
};

// --- the kit's integrators -----------------------------------------------------------------------
const kit::RigidKernels kernels = kit::student_rigid_kernels();

struct Setup {
  kit::RigidShape shape = kit::t_handle_shape(mass);
  kit::RigidState start = kit::spinning_state(shape, kit::Vec3::Zero(), omega0);
  int axis = 0;  // the body axis of the intermediate moment (x for the T-handle)
};

Drift kit_run(const Setup& s, kit::RotationIntegrator integrator, double h) {
  kit::RigidState state = s.start;
  DriftMeter meter(kit::kinetic_energy(s.shape, state), state.L,
                   kit::body_angular_velocity(s.shape, state)[s.axis]);
  const long steps = steps_for(h);
  for (long k = 1; k <= steps; ++k) {
    kit::rotation_step(kernels, integrator, s.shape, state, h);
    if (!meter.see(double(k) * h, kit::kinetic_energy(s.shape, state), state.L, state.R,
                   kit::body_angular_velocity(s.shape, state)[s.axis]))
      break;
  }
  return meter.drift();
}

// CPU seconds per step of `steps` steps of h from the start, the fastest of `samples` samples.
double kit_cost(const Setup& s, kit::RotationIntegrator integrator, double h, long steps) {
  double best = INFINITY;
  for (int i = 0; i < samples; ++i) {
    kit::RigidState state = s.start;
    const CpuClock clock;
    for (long k = 0; k < steps; ++k) kit::rotation_step(kernels, integrator, s.shape, state, h);
    best = std::min(best, clock.seconds() / double(steps));
    sink = sink + state.R(0, 0) + state.q.w() + state.L(0);
  }
  return best;
}

// --- Bullet ------------------------------------------------------------------------------------------
btVector3 to_bt(const kit::Vec3& v) { return btVector3(btScalar(v.x()), btScalar(v.y()), btScalar(v.z())); }
kit::Vec3 from_bt(const btVector3& v) { return kit::Vec3(double(v.x()), double(v.y()), double(v.z())); }

// One T-handle in a world of its own, without gravity, built as a game builds a body: its shape a
// compound of the two boxes (it collides with nothing here; the broadphase still tracks it), its
// mass and principal inertia given (the kit's, times `scale`), its body axes the principal ones.
// Deactivation is off: a body that slows below Bullet's sleeping thresholds for 2 s is frozen,
// which is no integrator's doing (this one never gets that slow anyway).
class BulletBody {
 public:
  // `flags`: the body's gyroscopic options (btRigidBodyFlags), or Bullet's default when empty.
  BulletBody(const kit::RigidShape& shape, double scale, std::optional<int> flags, const kit::Vec3& omega)
      : inertia_(scale * shape.inertia.diagonal()) {
    world_.setGravity(btVector3(0, 0, 0));
    for (const kit::BoxPart& part : shape.parts) {
      boxes_.push_back(std::make_unique<btBoxShape>(to_bt(0.5 * part.sides)));
      btTransform where;
      where.setIdentity();
      where.setOrigin(to_bt(part.centre));
      compound_.addChildShape(where, boxes_.back().get());
    }
    const btRigidBody::btRigidBodyConstructionInfo info(btScalar(scale * shape.mass), nullptr, &compound_,
                                                        to_bt(inertia_));
    body_ = std::make_unique<btRigidBody>(info);
    default_flags_ = body_->getFlags();
    if (flags) body_->setFlags(*flags);
    body_->setAngularVelocity(to_bt(omega));  // world = body at t = 0
    body_->setActivationState(DISABLE_DEACTIVATION);
    world_.addRigidBody(body_.get());
  }
  ~BulletBody() { world_.removeRigidBody(body_.get()); }
  BulletBody(const BulletBody&) = delete;
  BulletBody& operator=(const BulletBody&) = delete;

  void step(double h) { world_.stepSimulation(btScalar(h), 0); }  // 0: one step of exactly h

  kit::Mat3 R() const {
    const btMatrix3x3& b = body_->getWorldTransform().getBasis();
    kit::Mat3 out;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) out(i, j) = double(b[i][j]);
    return out;
  }
  kit::Vec3 omega() const { return from_bt(body_->getAngularVelocity()); }  // world [rad/s]
  kit::Vec3 omega_body() const { return R().transpose() * omega(); }
  // Bullet's state read in double: L = R I Rᵀ ω [kg·m²/s], E = ½ ω·L [J].
  kit::Vec3 momentum() const { return R() * inertia_.cwiseProduct(omega_body()); }
  double energy() const { return 0.5 * omega().dot(momentum()); }
  int default_flags() const { return default_flags_; }
  btRigidBody& body() { return *body_; }

 private:
  kit::Vec3 inertia_;  // [kg·m²], principal, body axes
  int default_flags_ = 0;
  btDefaultCollisionConfiguration configuration_;
  btCollisionDispatcher dispatcher_{&configuration_};
  btDbvtBroadphase broadphase_;
  btSequentialImpulseConstraintSolver solver_;
  btDiscreteDynamicsWorld world_{&dispatcher_, &broadphase_, &solver_, &configuration_};
  std::vector<std::unique_ptr<btBoxShape>> boxes_;
  btCompoundShape compound_;
  std::unique_ptr<btRigidBody> body_;
};

struct Variant {
  std::string name;
  std::optional<int> flags;  // empty: Bullet's default
  double scale = 1;
};

Drift bullet_run(const Setup& s, const Variant& v, double h) {
  BulletBody b(s.shape, v.scale, v.flags, omega0);
  DriftMeter meter(b.energy(), b.momentum(), b.omega_body()[s.axis]);
  const long steps = steps_for(h);
  for (long k = 1; k <= steps; ++k) {
    b.step(h);
    if (!meter.see(double(k) * h, b.energy(), b.momentum(), b.R(), b.omega_body()[s.axis])) break;
  }
  return meter.drift();
}

// CPU seconds per stepSimulation over one 60 s run from the start, the fastest of `samples` runs
// (the world is built outside the clock).
double bullet_cost(const Setup& s, const Variant& v, double h) {
  double best = INFINITY;
  const long steps = steps_for(h);
  for (int i = 0; i < samples; ++i) {
    BulletBody b(s.shape, v.scale, v.flags, omega0);
    const CpuClock clock;
    for (long k = 0; k < steps; ++k) b.step(h);
    best = std::min(best, clock.seconds() / double(steps));
    sink = sink + double(b.body().getAngularVelocity().x());
  }
  return best;
}

// Bullet's implicit gyroscopic step (computeGyroscopicImpulseImplicit_Body) at t = 0 against the
// same single Newton step solved exactly in double, on the body with M and I times `scale`.
struct ImplicitCheck {
  double det = 0;      // det J as solve33 computes it (float) [kg³·m⁶]
  double bullet = 0;   // |Δω| Bullet returns [rad/s]
  double exact = 0;    // |Δω| of the exact solve [rad/s]
  double solve33 = 0;  // |J.solve33(f)| / |J⁻¹ f|: 1 for a correct solve
};

kit::Mat3 skew(const kit::Vec3& w) {
  kit::Mat3 S;
  S << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
  return S;
}

ImplicitCheck implicit_check(const Setup& s, double scale, double h) {
  BulletBody b(s.shape, scale, std::nullopt, omega0);
  ImplicitCheck c;
  c.bullet = from_bt(b.body().computeGyroscopicImpulseImplicit_Body(btScalar(h))).norm();
  // Bullet's Newton step for ω⁺ in the body frame (R = 1 at t = 0): f = h ω × Iω,
  // J = I + h (ω* I − (Iω)*), Δω = −J⁻¹ f.
  const kit::Mat3 I = (scale * s.shape.inertia.diagonal()).asDiagonal();
  const kit::Vec3 f = h * omega0.cross(I * omega0);
  const kit::Mat3 J = I + h * (skew(omega0) * I - skew(I * omega0));
  const kit::Vec3 exact = J.partialPivLu().solve(f);
  c.exact = exact.norm();
  btMatrix3x3 Jb;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) Jb[i][j] = btScalar(J(i, j));
  c.det = double(Jb.getColumn(0).dot(Jb.getColumn(1).cross(Jb.getColumn(2))));  // solve33's own det
  c.solve33 = from_bt(Jb.solve33(to_bt(f))).norm() / exact.norm();
  return c;
}

std::string flags_name(int flags) {
  if (flags == 0) return "0";
  std::string out;
  const auto add = [&](int bit, const char* name) {
    if (flags & bit) out += (out.empty() ? "" : " | ") + std::string(name);
  };
  add(BT_DISABLE_WORLD_GRAVITY, "DISABLE_WORLD_GRAVITY");
  add(BT_ENABLE_GYROSCOPIC_FORCE_EXPLICIT, "GYROSCOPIC_FORCE_EXPLICIT");
  add(BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_WORLD, "GYROSCOPIC_FORCE_IMPLICIT_WORLD");
  add(BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY, "GYROSCOPIC_FORCE_IMPLICIT_BODY");
  return out;
}

// "a, b, c", or "none".
std::string join_names(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& name : names) out += (out.empty() ? "" : ", ") + name;
  return out.empty() ? std::string("none") : out;
}

std::string flips_text(const Drift& d, int expected) { return fmt::format("{} / {}", d.flips, expected); }

// One row of the drift tables: NaN-aware.
std::vector<std::string> drift_cells(const Drift& d) {
  if (d.diverged_at >= 0) return {fmt::format("NaN at {:.2f} s", d.diverged_at), "NaN", "NaN", "NaN", "NaN"};
  return {kit::sci(d.energy, 2), fmt::format("{:+.2e}", d.energy_end), kit::sci(d.momentum, 2),
          kit::sci(d.direction, 2), kit::sci(d.frame, 2)};
}

}  // namespace

int main() {
  const kit::Stopwatch total;  // wall time of the whole benchmark
  Setup setup;
  const kit::RigidShape& shape = setup.shape;
  const kit::Vec3 diagonal = shape.inertia.diagonal();
  // The body axes must be the principal ones: Bullet takes a diagonal inertia in the body frame.
  const double off_diagonal = (shape.inertia - kit::Mat3(diagonal.asDiagonal())).norm() / diagonal.norm();
  if (off_diagonal > 1e-12) {
    fmt::print(stderr, "bench: the T-handle's inertia is not diagonal in its body axes ({:.1e})\n",
               off_diagonal);
    return 1;
  }
  // The principal moments ascending, and ω0 in that order; the intermediate one's axis flips.
  std::vector<int> order{0, 1, 2};
  std::sort(order.begin(), order.end(), [&](int a, int b) { return diagonal[a] < diagonal[b]; });
  setup.axis = order[1];
  const kit::Vec3 moments(diagonal[order[0]], diagonal[order[1]], diagonal[order[2]]);
  const kit::Vec3 omega_principal(omega0[order[0]], omega0[order[1]], omega0[order[2]]);
  const kit::FreeRotation motion = kit::free_rotation(moments, omega_principal);
  const double period = motion.period();  // [s]
  // ω starts at its extreme along the intermediate axis (ω is 0 along the smallest one): it
  // crosses zero first a quarter period later, then every half period.
  const int expected = period / 4 <= t_end ? int(std::floor((t_end - period / 4) / (period / 2))) + 1 : 0;
  const char axis_name = "xyz"[setup.axis];

  fmt::print("Load average at the start: {:.2f} on {} cores. Times are this thread's CPU time, the fastest "
             "of {} samples.\n\n",
             load_average(), sysconf(_SC_NPROCESSORS_ONLN), samples);
  fmt::print("The body: the T-handle of chapter 8, M = {} kg, I_body = diag({:.4e}, {:.4e}, {:.4e}) kg.m^2 "
             "(principal:\n"
             "off-diagonal {:.0e} of the diagonal), intermediate axis {}; omega0 = ({}, {}, {}) rad/s in the "
             "body frame,\n"
             "= world at t = 0. No gravity, no contact: the torque-free body, E = {:.6g} J and |L| = {:.6g} "
             "kg.m^2/s\n"
             "conserved. Closed form (Landau & Lifshitz §37): period {:.4f} s (k = {:.6f}), omega_{} "
             "reverses every half\n"
             "period from T/4 = {:.4f} s: {} flips in {} s.\n\n",
             shape.mass, diagonal.x(), diagonal.y(), diagonal.z(), off_diagonal, axis_name, omega0.x(),
             omega0.y(), omega0.z(), motion.energy, motion.momentum, period, motion.modulus(), axis_name,
             period / 4, expected, t_end);

  // --- 1 ------------------------------------------------------------------------------------------
  const auto& integrators = kit::rotation_integrators;
  std::vector<double> bench_ns;
  for (const auto integrator : integrators)
    bench_ns.push_back(1e9 * kit_cost(setup, integrator, h_bench, bench_steps));
  const std::size_t midpoint =
      std::size_t(std::find(integrators.begin(), integrators.end(), kit::RotationIntegrator::midpoint) -
                  integrators.begin());
  const double midpoint_ns = bench_ns[midpoint];
  fmt::print(
      "1. ns per body-step, free T-handle, h = {} ms, {} steps from the start per sample ({} s simulated),\n"
      "   through rotation_step (the lecture's four call the student kernels through RigidKernels)\n",
      1e3 * h_bench, bench_steps, double(bench_steps) * h_bench);
  kit::Table per_step({"integrator", "exercises", "ns / step", "/ implicit midpoint"});
  for (std::size_t i = 0; i < integrators.size(); ++i)
    per_step.add_row({kit::display_name(integrators[i]) + " (" + kit::flag_name(integrators[i]) + ")",
                      kit::exercises_of(integrators[i]).empty() ? "kit" : kit::exercises_of(integrators[i]),
                      kit::fixed(bench_ns[i], 1), kit::fixed(bench_ns[i] / midpoint_ns, 2)});
  per_step.print(std::cout);
  {
    kit::RigidState state = setup.start;
    long iterations = 0;
    for (long k = 0; k < bench_steps; ++k) iterations += kit::midpoint_rotation_step(shape, state, h_bench);
    fmt::print("   The midpoint's fixed point takes {:.1f} iterations a step here.\n\n",
               double(iterations) / double(bench_steps));
  }

  // --- 2 ------------------------------------------------------------------------------------------
  const std::vector<Variant> variants{
      {"Bullet, no gyroscopic term (flags 0)", 0, 1},
      {"Bullet, GYROSCOPIC_FORCE_EXPLICIT", BT_ENABLE_GYROSCOPIC_FORCE_EXPLICIT, 1},
      {"Bullet default (GYROSCOPIC_FORCE_IMPLICIT_BODY)", std::nullopt, 1},
      {fmt::format("Bullet default, M and I x{:.0f}", heavy), std::nullopt, heavy},
  };
  const int default_flags = BulletBody(shape, 1, std::nullopt, omega0).default_flags();
  const ImplicitCheck as_given = implicit_check(setup, 1, h_game),
                      scaled = implicit_check(setup, heavy, h_game);
  fmt::print("2. Bullet {}.{:02d} ({}, btScalar of {} bytes): one btRigidBody in a btDiscreteDynamicsWorld, "
             "gravity 0,\n"
             "   shape a compound of the two boxes, mass and principal inertia given, deactivation off;\n"
             "   stepSimulation(1/60, 0).\n"
             "   A new body's flags: {} ({}).\n",
             btGetVersion() / 100, btGetVersion() % 100,
             sizeof(btScalar) == sizeof(float) ? "float" : "double", sizeof(btScalar), default_flags,
             flags_name(default_flags));
  fmt::print(
      "   The default's implicit gyroscopic step (computeGyroscopicImpulseImplicit_Body, one Newton step on\n"
      "   I w+ + h w+ x I w+ = I w) solves J dw = f with btMatrix3x3::solve33 (Cramer's rule), which divides "
      "by\n"
      "   det J only when |det J| > SIMD_EPSILON = {:.3e} and otherwise MULTIPLIES by it. At t = 0, h = 1/60 "
      "s:\n",
      double(SIMD_EPSILON));
  kit::Table check({"body", "det J [kg^3.m^6]", "> SIMD_EPSILON", "solve33 / exact solve",
                    "|dw| Bullet [rad/s]", "|dw| exact [rad/s]"});
  for (const auto& [name, c] : {std::pair<std::string, const ImplicitCheck&>{"as given", as_given},
                                {fmt::format("M and I x{:.0f}", heavy), scaled}})
    check.add_row({name, kit::sci(c.det, 3), std::abs(c.det) > double(SIMD_EPSILON) ? "yes" : "no",
                   kit::sci(c.solve33, 3), kit::sci(c.bullet, 3), kit::sci(c.exact, 3)});
  check.print(std::cout);
  const bool finding = std::abs(as_given.det) <= double(SIMD_EPSILON) && as_given.solve33 < 1e-6 &&
                       std::abs(scaled.det) > double(SIMD_EPSILON) && std::abs(scaled.solve33 - 1) < 1e-3;
  fmt::print(
      "   {}\n\n",
      finding
          ? fmt::format(
                "Holds: on the T-handle as given, solve33 returns det^2 = {:.1e} times the solution,\n"
                "   so the default's gyroscopic correction is ~0 and the body turns as if the option were\n"
                "   off; with M and I x{:.0f} (the same motion) det J = {:.2g} > SIMD_EPSILON and the\n"
                "   correction is the exact solve's.",
                as_given.det * as_given.det, heavy, scaled.det)
          : std::string("Does NOT hold on this Bullet: see the table."));

  // --- 3 ------------------------------------------------------------------------------------------
  std::vector<Drift> bullet_drift;
  std::vector<double> bullet_us;
  for (const Variant& v : variants) {
    bullet_drift.push_back(bullet_run(setup, v, h_game));
    bullet_us.push_back(1e6 * bullet_cost(setup, v, h_game));
  }
  std::vector<Drift> kit_drift;
  std::vector<double> kit_us;
  for (const auto integrator : integrators) {
    kit_drift.push_back(kit_run(setup, integrator, h_game));
    kit_us.push_back(1e6 * kit_cost(setup, integrator, h_game, steps_for(h_game)));
  }
  const Drift reference = kit_run(setup, kit::RotationIntegrator::midpoint, h_reference);
  fmt::print(
      "3. h = 1/60 s, {} s ({} steps). Drifts are the largest over the run, relative to t = 0: E the "
      "kinetic\n"
      "   energy, |L| and L the angular momentum in the world frame (L's drift as a vector also counts its\n"
      "   turning), R^T R - 1 (Frobenius). Flips: reversals of omega_{} in the body frame (counted at half "
      "its\n"
      "   amplitude) / the closed form's count. (The implicit midpoint at h = {:.0e} s flips {} times.)\n",
      t_end, steps_for(h_game), axis_name, h_reference, reference.flips);
  const std::vector<std::string> drift_headers{"method",          "us / step",      "max |dE|/E",
                                               "dE/E at 60 s",    "max |d|L||/|L|", "max |L - L0|/|L0|",
                                               "max |R^T R - 1|", "flips"};
  kit::Table game(drift_headers);
  const auto add_drift_row = [&](kit::Table& table, const std::string& name, double us, const Drift& d) {
    std::vector<std::string> row{name, kit::fixed(us, 3)};
    for (auto& cell : drift_cells(d)) row.push_back(cell);
    row.push_back(flips_text(d, expected));
    table.add_row(row);
  };
  for (std::size_t i = 0; i < variants.size(); ++i)
    add_drift_row(game, variants[i].name, bullet_us[i], bullet_drift[i]);
  for (std::size_t i = 0; i < integrators.size(); ++i)
    add_drift_row(game, "kit: " + kit::display_name(integrators[i]), kit_us[i], kit_drift[i]);
  game.print(std::cout);
  fmt::print("\n");

  // --- 4 ------------------------------------------------------------------------------------------
  // h_kit = (1/60) c_kit / c_bullet: the same CPU per simulated second as Bullet's default. The
  // midpoint's cost per step falls with h (fewer fixed-point iterations), so c_kit is measured
  // again at the new h, twice.
  const double c_bullet = bullet_us[2] * 1e-6;  // [s] per step
  const Drift& bullet_default = bullet_drift[2];
  const Drift& bullet_heavy = bullet_drift[3];
  struct EqualCost {
    double h = 0, cost = 0;  // [s], [s per step]
    Drift drift;
  };
  std::vector<EqualCost> equal;
  for (std::size_t i = 0; i < integrators.size(); ++i) {
    EqualCost e;
    double cost = kit_us[i] * 1e-6;
    for (int pass = 0; pass < 3; ++pass) {
      e.h = t_end / double(std::max(1L, std::lround(t_end / (h_game * cost / c_bullet))));
      cost = kit_cost(setup, integrators[i], e.h, steps_for(e.h));
    }
    e.cost = cost;
    e.drift = kit_run(setup, integrators[i], e.h);
    equal.push_back(e);
  }
  fmt::print("4. Equal cost: each integrator at h = (1/60 s) c_kit / c_Bullet (c: CPU per step), so that its "
             "CPU per\n"
             "   simulated second is Bullet's default's at 1/60 s ({:.3f} us a step, {:.1f} us per simulated "
             "s), {} s.\n"
             "   Ratios kit / Bullet (below 1: the kit drifts less for the same CPU), against Bullet's "
             "default on the\n"
             "   T-handle as given and on the body x{:.0f} (the default doing what it is meant to).\n",
             1e6 * c_bullet, 1e6 * c_bullet / h_game, t_end, heavy);
  kit::Table cost({"integrator", "h [s]", "CPU kit / Bullet", "max |dE|/E", "/ default", "/ x100",
                   "max |d|L||/|L|", "/ default", "/ x100", "max |L - L0|/|L0|", "/ default", "/ x100",
                   "flips"});
  for (std::size_t i = 0; i < integrators.size(); ++i) {
    const EqualCost& e = equal[i];
    const Drift& d = e.drift;
    const bool nan = d.diverged_at >= 0;
    const auto cell = [&](double value) { return nan ? std::string("NaN") : kit::sci(value, 2); };
    const auto ratio = [&](double value, double peer) {
      return nan ? std::string("NaN") : ratio_text(value, peer);
    };
    cost.add_row({kit::display_name(integrators[i]), kit::sci(e.h, 3),
                  kit::fixed((e.cost / e.h) / (c_bullet / h_game), 2),
                  nan ? fmt::format("NaN at {:.2f} s", d.diverged_at) : cell(d.energy),
                  ratio(d.energy, bullet_default.energy), ratio(d.energy, bullet_heavy.energy),
                  cell(d.momentum), ratio(d.momentum, bullet_default.momentum),
                  ratio(d.momentum, bullet_heavy.momentum), cell(d.direction),
                  ratio(d.direction, bullet_default.direction), ratio(d.direction, bullet_heavy.direction),
                  flips_text(d, expected)});
  }
  cost.print(std::cout);
  fmt::print("   Bullet at 1/60 s for reference: default {} / {} / {} (flips {}), x{:.0f} {} / {} / {} "
             "(flips {}).\n\n",
             kit::sci(bullet_default.energy, 2), kit::sci(bullet_default.momentum, 2),
             kit::sci(bullet_default.direction, 2), flips_text(bullet_default, expected), heavy,
             kit::sci(bullet_heavy.energy, 2), kit::sci(bullet_heavy.momentum, 2),
             kit::sci(bullet_heavy.direction, 2), flips_text(bullet_heavy, expected));

  // --- conclusions, from the numbers above ---------------------------------------------------------
  fmt::print("Conclusions (from this run's numbers)\n");
  {
    const auto cheapest = std::min_element(bench_ns.begin(), bench_ns.end()) - bench_ns.begin();
    const auto dearest = std::max_element(bench_ns.begin(), bench_ns.end()) - bench_ns.begin();
    const double bullet_ns = 1e9 * c_bullet;
    fmt::print(
        " - Cost: the kit's integrators take {:.0f} ns ({}) to {:.0f} ns ({}) a body-step at h = 1 ms; one\n"
        "   Bullet world step with its one body takes {:.0f} ns: {:.1f}x the cheapest, {:.1f}x the midpoint, "
        "{:.1f}x\n"
        "   the dearest (a world step also runs the broadphase, the islands and the solver's set-up).\n",
        bench_ns[std::size_t(cheapest)], kit::flag_name(integrators[std::size_t(cheapest)]),
        bench_ns[std::size_t(dearest)], kit::flag_name(integrators[std::size_t(dearest)]), bullet_ns,
        bullet_ns / bench_ns[std::size_t(cheapest)], bullet_ns / midpoint_ns,
        bullet_ns / bench_ns[std::size_t(dearest)]);
  }
  for (std::size_t i = 0; i < variants.size(); ++i) {
    const Drift& d = bullet_drift[i];
    std::string verdict;
    if (d.diverged_at >= 0)
      verdict = fmt::format("diverges (NaN at {:.2f} s)", d.diverged_at);
    else if (d.flips == expected)
      verdict = "flips as the closed form does";
    else if (d.flips == 0)
      verdict = "never flips: no Dzhanibekov effect";
    else
      verdict = fmt::format("flips {} times where the closed form flips {}, the last at {:.1f} s", d.flips,
                            expected, d.last_flip);
    std::string energy;
    if (d.energy_end > 1)
      energy = fmt::format("; E ends at {:.2g}x its start", 1 + d.energy_end);
    else if (std::abs(d.energy_end) > 1e-3)
      energy =
          fmt::format("; E ends {:.1f}% {}", 100 * std::abs(d.energy_end), d.energy_end > 0 ? "up" : "down");
    fmt::print(" - {}: {}.\n   max |dE|/E {}, max |L - L0|/|L0| {}{}.\n", variants[i].name, verdict,
               kit::sci(d.energy, 2), kit::sci(d.direction, 2), energy);
  }
  if (const Drift& off = bullet_drift[0]; off.diverged_at < 0 && off.energy < 1e-4 && off.flips != expected)
    fmt::print(" - Without the gyroscopic term Bullet keeps E and |L| to {} and L within {} of L0, yet flips "
               "{} times\n"
               "   of {}: small drifts alone do not make the motion right; the flips show it wrong.\n",
               kit::sci(std::max(off.energy, off.momentum), 1), kit::sci(off.direction, 1), off.flips,
               expected);
  if (finding)
    fmt::print(" - The default's implicit term is lost to solve33 on this body (det J = {:.1e} <= "
               "FLT_EPSILON): {} flips\n"
               "   as given, {} with M and I x{:.0f}, the same motion.\n",
               as_given.det, bullet_default.flips, bullet_heavy.flips, heavy);
  {
    // With L untouched (the lecture's steps and the midpoint keep the world L as it is), E is at
    // most |L|²/(2 I_min): a first-order step that gains energy ends up spinning about the
    // smallest axis, the other stable one, where the flips stop.
    const double ceiling = moments[1] / moments[0];  // E_max / E0 for this |L|: ω0 is along I_mid
    std::vector<std::string> exact_l, saturated;
    for (std::size_t i = 0; i < integrators.size(); ++i) {
      const Drift& d = kit_drift[i];
      if (d.diverged_at >= 0) continue;
      if (d.momentum == 0 && d.direction == 0) exact_l.push_back(kit::flag_name(integrators[i]));
      if (std::abs(1 + d.energy_end - ceiling) < 1e-2 * ceiling)
        saturated.push_back(kit::flag_name(integrators[i]));
    }
    fmt::print(" - L stays exactly L0 (the world L is the state these steps leave alone; their errors show "
               "in E, R and\n"
               "   the flips) in: {}.\n"
               "   At h = 1/60 s E ends at |L|^2/(2 I_min) = {:.2f} E0, the most this |L| allows: the body "
               "spins about\n"
               "   its smallest axis, where the flips stop, in: {}.\n",
               join_names(exact_l), ceiling, join_names(saturated));
  }
  {
    std::vector<std::string> better, right;
    for (std::size_t i = 0; i < integrators.size(); ++i) {
      const Drift& d = equal[i].drift;
      if (d.diverged_at >= 0) continue;
      if (d.energy < bullet_heavy.energy && d.direction < bullet_heavy.direction)
        better.push_back(kit::flag_name(integrators[i]));
      if (d.flips == expected) right.push_back(kit::flag_name(integrators[i]));
    }
    fmt::print(" - At equal CPU per simulated second, drifting less than Bullet's working default (x{:.0f}) "
               "in both E and L:\n"
               "   {}; flipping {} times as the closed form does: {}.\n",
               heavy, join_names(better), expected, join_names(right));
    const EqualCost& m = equal[midpoint];
    if (m.drift.diverged_at < 0)
      fmt::print("   The implicit midpoint at h = {:.2e} s: max |dE|/E {} and |L - L0|/|L0| {};\n"
                 "   kit / Bullet x{:.0f}: {} and {}.\n",
                 m.h, kit::sci(m.drift.energy, 1), kit::sci(m.drift.direction, 1), heavy,
                 ratio_text(m.drift.energy, bullet_heavy.energy),
                 ratio_text(m.drift.direction, bullet_heavy.direction));
  }
  fmt::print("\nThe whole benchmark: {:.1f} s.\n", total.seconds());
  return 0;
}
