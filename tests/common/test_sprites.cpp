// The particle system of chapter 5: storage, emission statistics, lifetimes, counts, the
// integrators against the closed form of gravity plus linear drag, and work done only for the
// terms a scene lists.
#include <cmath>
#include <map>
#include <vector>

#include <catch2/catch.hpp>

#include <kit/drag_motion.hpp>
#include <kit/emitter.hpp>
#include <kit/particle_update.hpp>
#include <kit/measure.hpp>
#include <kit/sprite_system.hpp>

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

TEST_CASE("particles per frame follow mean + rand·variance, fractions included", "[sprites]") {
  kit::SpriteRandom random(7);
  for (const kit::Spread rate : {kit::Spread{40, 10}, kit::Spread{0.3, 0}, kit::Spread{2.5, 1}}) {
    const int frames = 200000;
    double sum = 0;
    for (int f = 0; f < frames; ++f) sum += double(kit::emission_count(rate, random));
    // Mean of ⌊N⌋ + Bernoulli(frac N) is E[N] = mean; its spread is at most variance²/3 + 1/4.
    const double sigma = std::sqrt(rate.variance * rate.variance / 3 + 0.25) / std::sqrt(double(frames));
    INFO("rate " << rate.mean << " ± " << rate.variance);
    CHECK(std::abs(sum / frames - rate.mean) < 5 * sigma);
  }
}

TEST_CASE("each attribute is drawn uniformly in mean ± variance: chi-square over 10 bins", "[sprites]") {
  const kit::SpriteScene scene = one_emitter_scene();
  kit::SpriteRandom random(11);
  const int n = 100000, bins = 10;
  std::vector<int> lifetime(bins), speed(bins);
  double cos_min = 1, cos_sum = 0;
  for (int k = 0; k < n; ++k) {
    const kit::ParticleSpawn p = kit::sample_particle(scene.emitters[0], 0, random);
    const double v = std::hypot(p.vx, p.vy, p.vz);
    lifetime[std::min(bins - 1, int((p.lifetime - 0.5) / 1.0 * bins))]++;
    speed[std::min(bins - 1, int((v - 4.0) / 2.0 * bins))]++;
    cos_min = std::min(cos_min, p.vy / v);
    cos_sum += p.vy / v;
  }
  const auto chi2 = [&](const std::vector<int>& counts) {
    double c = 0;
    for (int count : counts) c += std::pow(count - n / bins, 2) / (n / bins);
    return c;
  };
  CHECK(chi2(lifetime) < 27.9);  // 9 degrees of freedom, p = 0.001
  CHECK(chi2(speed) < 27.9);
  // Directions: within the 20° cone, and uniform over the cap's area: E[cos θ] = (1 + cos 20°)/2.
  const double cos20 = std::cos(20 * M_PI / 180);
  CHECK(cos_min >= cos20 - 1e-6);
  CHECK(cos_sum / n == Approx((1 + cos20) / 2).margin(5 * (1 - cos20) / std::sqrt(12.0 * n)));
}

TEST_CASE("a particle lives exactly ceil(lifetime / dt) updates", "[sprites]") {
  const kit::SpriteScene scene = one_emitter_scene();
  kit::SpriteSystem system(scene, 100000, 30, 3, kit::Integrator::exact);
  std::map<std::uint32_t, std::pair<long, float>> born;  // id -> frame, lifetime
  long checked = 0, ambiguous = 0;
  std::map<std::uint32_t, bool> seen;
  for (int f = 0; f < 120; ++f) {
    system.step();
    seen.clear();
    const auto& ps = system.particles();
    for (std::size_t i = 0; i < ps.size(); ++i) {
      seen[ps.id[i]] = true;
      born.try_emplace(ps.id[i], f, ps.lifetime[i]);
    }
    for (auto it = born.begin(); it != born.end();) {
      if (seen.count(it->first)) {
        ++it;
        continue;
      }
      // Died in frame f: it was updated f − born + 1 times.
      const double updates = double(f - it->second.first + 1), steps = double(it->second.second) * 30.0;
      if (std::abs(steps - std::round(steps)) < 1e-4) {
        ++ambiguous;  // float age on a frame boundary: either frame is right
      } else {
        CHECK(updates == std::ceil(steps));
        ++checked;
      }
      it = born.erase(it);
    }
  }
  CHECK(checked > 1000);
  CHECK(ambiguous < checked / 100);
}

TEST_CASE("counts are conserved: alive = emitted − dead after every frame, bursts included", "[sprites]") {
  kit::SpriteScene scene = one_emitter_scene();
  scene.emitters[0].on_death = 1;
  kit::Emitter burst;
  burst.name = "burst", burst.burst_only = true, burst.rate = {20, 5}, burst.speed = {3, 1};
  burst.lifetime = {0.5, 0.2};
  scene.emitters.push_back(burst);
  kit::SpriteSystem system(scene, 3000, 30, 5, kit::Integrator::midpoint);  // small: some are dropped
  long emitted = 0, died = 0, dropped = 0;
  for (int f = 0; f < 90; ++f) {
    const kit::FrameCounts c = system.step();
    emitted += c.emitted, died += c.died, dropped += c.dropped;
    REQUIRE(c.alive == emitted - died);
    REQUIRE(system.totals().alive() == c.alive);
  }
  CHECK(died > 0);
  CHECK(dropped > 0);
  CHECK(system.totals().dropped == dropped);
}

TEST_CASE("the closed form of gravity plus drag solves the ODE and is free fall at k = 0", "[sprites]") {
  const double g = -9.81, k = 0.7, w = 2.0, h = 1e-4;
  const kit::AxisState s{1.0, 3.0};
  for (const double t : {0.1, 1.0, 5.0}) {
    const auto a = kit::drag_motion(s, g, k, w, t - h), b = kit::drag_motion(s, g, k, w, t + h);
    const auto c = kit::drag_motion(s, g, k, w, t);
    CHECK((b.x - a.x) / (2 * h) == Approx(c.v).epsilon(1e-7));               // dx/dt = v
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

TEST_CASE("the integrators converge to the closed form at their orders; the exact step is exact",
          "[sprites]") {
  const double g = -9.81, k = 0.8, w = 1.5, T = 2.0;
  const kit::AxisState s0{0.0, 6.0};
  const double exact = kit::drag_motion(s0, g, k, w, T).x;
  for (kit::Integrator integrator : kit::all_integrators) {
    std::vector<double> dts, errors;
    for (int n = 16; n <= 1024; n *= 2) {
      const double h = T / n;
      const kit::AxisStep a = kit::axis_step(integrator, k, h, g, w);
      double x = s0.x, v = s0.v;
      for (int i = 0; i < n; ++i) x += a.p * v + a.q, v = a.r * v + a.s;
      dts.push_back(h), errors.push_back(std::abs(x - exact));
    }
    INFO(kit::display_name(integrator));
    if (integrator == kit::Integrator::exact) {
      for (double e : errors) CHECK(e < 1e-12);
    } else {
      CHECK(kit::fit_loglog(dts, errors).slope == Approx(kit::order(integrator)).margin(0.05));
    }
  }
}

TEST_CASE("a scene computes only the terms it lists", "[sprites]") {
  kit::SpriteScene scene = one_emitter_scene();
  const auto work_after = [&](int frames) {
    kit::SpriteSystem system(scene, 100000, 30, 1, kit::Integrator::symplectic_euler);
    for (int f = 0; f < frames; ++f) system.step();
    return system.work();
  };
  kit::UpdateWork bare = work_after(10);
  CHECK(bare.particle_steps > 0);
  CHECK(bare.gravity == 0);
  CHECK(bare.drag == 0);
  CHECK(bare.colour + bare.alpha + bare.size + bare.alpha_checks + bare.region_checks == 0);
  scene.forces.gravity = kit::Vec3d{0, -9.81, 0};
  scene.emitters[0].alpha_rate = -0.5;
  scene.death.alpha_below = 0.1;
  const kit::UpdateWork more = work_after(10);
  CHECK(more.gravity == more.particle_steps);
  CHECK(more.alpha == more.particle_steps);
  CHECK(more.alpha_checks == more.particle_steps);
  CHECK(more.drag == 0);
  scene.forces.drag = 0.5;
  CHECK(work_after(10).drag == work_after(10).particle_steps);
}

TEST_CASE("the same seed gives identical particles, another seed different ones", "[sprites]") {
  const kit::SpriteScene scene = one_emitter_scene();
  const auto positions = [&](std::uint64_t seed) {
    kit::SpriteSystem system(scene, 100000, 30, seed, kit::Integrator::midpoint);
    for (int f = 0; f < 30; ++f) system.step();
    const auto& ps = system.particles();
    return std::vector<float>(ps.x.begin(), ps.x.begin() + long(ps.size()));
  };
  CHECK(positions(42) == positions(42));
  CHECK(positions(42) != positions(43));
}
