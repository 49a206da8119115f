// The particle system of chapter 5: storage, emission statistics, lifetimes, counts, the
// integrators against the closed form of gravity plus linear drag, and work done only for the
// terms a scene lists.
#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <vector>

#include <kit_catch.hpp>

#include <kit/base/measure.hpp>
#include <kit/sprites/drag_motion.hpp>
#include <kit/sprites/emitter.hpp>
#include <kit/sprites/particle_update.hpp>

#include "printed_as.hpp"
#include "sprite_trade.hpp"

namespace {
kit::SpriteScene one_emitter_scene() {
  kit::SpriteScene scene;
  scene.name = "test";
  kit::Emitter e;
  e.name = "jet";
  e.shape = kit::EmitterShape::cone;
  e.angle_deg = 20;
  e.rate = {40, 10};
  e.speed = {5, 1};
  e.lifetime = {1.0, 0.5};
  scene.emitters.push_back(e);
  return scene;
}
}  // namespace

TEST_CASE("swap-remove keeps the particles dense and never reallocates", "[sprites]") {
  kit::Particles ps;
  ps.reserve(4);
  const float* before = ps.x.data();
  for (int i = 0; i < 4; ++i) REQUIRE(ps.add({.x = float(i), .id = std::uint32_t(i)}));
  CHECK_FALSE(ps.add({}));  // full: refused, nothing stored
  ps.swap_remove(1);        // the last (x = 3) moves into slot 1
  REQUIRE(ps.size() == 3);
  CHECK(ps.x[1] == 3.f);
  CHECK(ps.id[1] == 3u);
  ps.swap_remove(2);  // the last one itself
  CHECK(ps.size() == 2);
  CHECK(ps.x.data() == before);
  CHECK(ps.capacity() == 4);
}

TEST_CASE("the arrays hold positions to about 6e-8 of their size: 0.1 µm on a 2 m fountain", "[sprites]") {
  // The README's Float32 figures: positions (from the emitters' double arithmetic) stored in the
  // arrays and read back. Arrays of double would make the error 0 and fail the first check; of
  // half precision, 5e-4.
  kit::Particles ps;
  ps.reserve(1);
  std::mt19937_64 draw(11);
  std::uniform_real_distribution<double> position(0.05, 2.0);  // [m], a fountain's extent
  double worst = 0;                                            // relative
  for (int k = 0; k < 100000; ++k) {
    const double x = position(draw);
    ps.clear();
    REQUIRE(ps.add({.x = static_cast<float>(x)}));
    worst = std::max(worst, std::abs(double(ps.x[0]) - x) / x);
  }
  CHECK(worst == kit::test::printed("6e-8"));
  CHECK(2.0 * worst * 1e6 == kit::test::printed("0.1"));  // [µm] on 2 m
}

TEST_CASE("particles per frame follow mean + rand·variance, fractions included", "[sprites]") {
  kit::Random random(7);
  // The last is the fireworks' shells: 0.012 ± 0.012 a frame, 0 or 1 each frame.
  for (const kit::Spread rate :
       {kit::Spread{40, 10}, kit::Spread{0.3, 0}, kit::Spread{2.5, 1}, kit::Spread{0.012, 0.012}}) {
    const int frames = 200000;
    double sum = 0;
    for (int f = 0; f < frames; ++f) sum += double(kit::emission_count(rate, random));
    // Mean of ⌊N⌋ + Bernoulli(frac N) is E[N] = mean; its spread is at most variance²/3 + 1/4,
    // and below 1 a frame (a count of 0 or 1) at most the mean.
    const double bernoulli = std::min(0.25, rate.mean + rate.variance);
    const double sigma = std::sqrt(rate.variance * rate.variance / 3 + bernoulli) / std::sqrt(double(frames));
    INFO("rate " << rate.mean << " ± " << rate.variance);
    CHECK(std::abs(sum / frames - rate.mean) < 5 * sigma);
  }
}

TEST_CASE("directions are uniform over the cap: inside the cone, E[cos θ] = (1 + cos θmax)/2", "[sprites]") {
  kit::Random random(11);
  const int n = 100000;
  const kit::Vec3 axis{0, 0.6, 0.8};
  for (const double angle : {20.0, 90.0, 180.0}) {
    double cos_min = 1, cos_sum = 0, worst_norm = 0;
    for (int k = 0; k < n; ++k) {
      const kit::Vec3 d = kit::direction_in_cap(axis, angle, random);
      const double c = d[0] * axis[0] + d[1] * axis[1] + d[2] * axis[2];
      worst_norm = std::max(worst_norm, std::abs(std::hypot(d[0], d[1], d[2]) - 1));
      cos_min = std::min(cos_min, c), cos_sum += c;
    }
    CHECK(worst_norm < 1e-12);
    const double cos_max = std::cos(angle * M_PI / 180);
    INFO("cap of " << angle << " degrees");
    CHECK(cos_min >= cos_max - 1e-12);
    // cos θ is uniform on [cos θmax, 1]: its standard deviation is (1 − cos θmax)/√12.
    CHECK(cos_sum / n == Approx((1 + cos_max) / 2).margin(5 * (1 - cos_max) / std::sqrt(12.0 * n)));
  }
}

TEST_CASE("points are uniform over the disc's area and the ball's volume", "[sprites]") {
  kit::Random random(5);
  const int n = 100000;
  int disc_inner = 0, ball_inner = 0;
  double off_plane = 0;
  for (int k = 0; k < n; ++k) {
    const kit::Vec3 p = kit::offset_in_disc({0, 1, 0}, 2.0, random);
    off_plane = std::max(off_plane, std::abs(p[1]));  // in the plane normal to the axis
    disc_inner += std::hypot(p[0], p[2]) < 1.0;       // the inner half radius holds 1/4 of the area
    const kit::BallPoint b = kit::point_in_ball(2.0, random);
    ball_inner += std::hypot(b.offset[0], b.offset[1], b.offset[2]) < 1.0;  // 1/8 of the volume
  }
  const auto near = [&](int count, double p) {
    return std::abs(count - n * p) < 5 * std::sqrt(n * p * (1 - p));
  };
  CHECK(off_plane < 1e-12);
  CHECK(near(disc_inner, 0.25));
  CHECK(near(ball_inner, 0.125));
}

TEST_CASE("the closed form of gravity plus drag solves the ODE and is free fall at k = 0", "[sprites]") {
  const double g = -9.81, k = 0.7, w = 2.0, h = 1e-4;
  const kit::AxisState s{1.0, 3.0};
  for (const double t : {0.1, 1.0, 5.0}) {
    const auto a = kit::drag_motion(s, g, k, w, t - h), b = kit::drag_motion(s, g, k, w, t + h);
    const auto c = kit::drag_motion(s, g, k, w, t);
    CHECK((b.x - a.x) / (2 * h) == Approx(c.v).epsilon(1e-7));                // dx/dt = v
    CHECK((b.v - a.v) / (2 * h) == Approx(g - k * (c.v - w)).epsilon(1e-6));  // dv/dt = g − k (v − w)
  }
  // Two half steps make one step (the flow is a semigroup), and k → 0 is free fall.
  const auto half = kit::drag_motion(kit::drag_motion(s, g, k, w, 0.5), g, k, w, 0.5);
  const auto whole = kit::drag_motion(s, g, k, w, 1.0);
  CHECK(half.x == Approx(whole.x).epsilon(1e-14));
  CHECK(half.v == Approx(whole.v).epsilon(1e-14));
  const auto fall = kit::drag_motion(s, g, 1e-12, w, 2.0);
  CHECK(fall.x == Approx(1.0 + 3.0 * 2.0 + g * 2.0).epsilon(1e-10));
  CHECK(kit::drag_motion(s, g, 0.0, w, 2.0).x == 1.0 + 3.0 * 2.0 + g * 2.0);
}

TEST_CASE("each integrator's affine step is that scheme's step, written out", "[sprites]") {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> any(-5, 5), rate(0, 3), step(1e-3, 0.5);
  for (int trial = 0; trial < 200; ++trial) {
    const double k = rate(rng), h = step(rng), g = any(rng), w = any(rng), x = any(rng), v = any(rng);
    const auto a = [&](double u) { return g - k * (u - w); };  // dv/dt
    const auto apply = [&](kit::Integrator i) {
      const kit::AxisStep c = kit::axis_step(i, k, h, g, w);
      return std::pair{x + c.p * v + c.q, c.r * v + c.s};
    };
    const double half = v + h / 2 * a(v), kicked = v + h * a(v);
    const std::pair<double, double> expected[] = {
        {x + h * v, kicked},              // explicit Euler: the old velocity moves x
        {x + h * kicked, kicked},         // symplectic Euler: the new one does
        {x + h * half, v + h * a(half)},  // midpoint: the half-step velocity does both
        {kit::drag_motion({x, v}, g, k, w, h).x, kit::drag_motion({x, v}, g, k, w, h).v}};
    for (kit::Integrator i : kit::all_integrators) {
      const auto [x1, v1] = apply(i);
      INFO(kit::display_name(i) << ": k = " << k << ", h = " << h);
      CHECK(x1 == Approx(expected[int(i)].first).epsilon(1e-12).margin(1e-12));
      CHECK(v1 == Approx(expected[int(i)].second).epsilon(1e-12).margin(1e-12));
    }
  }
}

TEST_CASE("the integrators converge to the closed form at their orders; the exact step is exact",
          "[sprites]") {
  kit::DragProblem problem;
  problem.v0 = {1.0, 6.0, -0.5}, problem.gravity = {0, -9.81, 0}, problem.drag = 0.8;
  problem.wind = {1.5, 0, 0.3}, problem.t_end = 2.0;
  std::vector<double> dts;
  for (int n = 16; n <= 1024; n *= 2) dts.push_back(problem.t_end / n);
  for (kit::Integrator integrator : kit::all_integrators) {
    const auto runs = kit::trade_runs(problem, integrator, dts);
    std::vector<double> errors;
    for (const auto& run : runs) errors.push_back(run.error);
    INFO(kit::display_name(integrator));
    CHECK(runs.back().steps == 1024);
    if (integrator == kit::Integrator::exact) {
      for (double e : errors) CHECK(e < 1e-12);
    } else {
      CHECK(kit::fit_loglog(dts, errors).slope == Approx(kit::order(integrator)).margin(0.05));
    }
  }
}

TEST_CASE("the motion computes only the forces and rates a scene lists", "[sprites]") {
  kit::SpriteScene scene = one_emitter_scene();
  kit::Particles ps;
  ps.reserve(100);
  for (int i = 0; i < 100; ++i) ps.add({.vy = 1});
  const auto work_of = [&] {
    kit::ParticleUpdate update(scene, kit::Integrator::symplectic_euler);
    for (int f = 0; f < 10; ++f) update.step(ps, 1.0 / 30);
    return update.work();
  };
  const kit::UpdateWork bare = work_of();
  CHECK(bare.particle_steps == 1000);
  CHECK(bare.gravity + bare.drag + bare.colour + bare.alpha + bare.size == 0);
  scene.forces.gravity = kit::Vec3{0, -9.81, 0};
  scene.emitters[0].alpha_rate = -0.5;
  const kit::UpdateWork more = work_of();
  CHECK(more.gravity == 1000);
  CHECK(more.alpha == 1000);
  CHECK(more.drag + more.colour + more.size == 0);
  scene.forces.drag = 0.5;
  CHECK(work_of().drag == 1000);
}
