// ex 5.2: age every particle, remove the dead by swap-remove (sprite_age_kill.hpp).
#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include <kit_catch.hpp>

#include "cases.hpp"
#include "sprite_age_kill.hpp"

namespace {
kit::Particles make(const std::vector<float>& lifetimes, std::size_t capacity = 64) {
  kit::Particles ps;
  ps.reserve(capacity);
  for (std::size_t i = 0; i < lifetimes.size(); ++i)
    ps.add({.x = float(i), .vy = float(10 * i), .lifetime = lifetimes[i], .id = std::uint32_t(i)});
  return ps;
}
std::set<std::uint32_t> ids(const kit::Particles& ps) {
  return std::set<std::uint32_t>(ps.id.begin(), ps.id.begin() + long(ps.size()));
}
const std::vector<bool> no_bursts(4, false);
}  // namespace

TEST_CASE("ex 5.2: each particle ages by dt and lives exactly ceil(lifetime/dt) calls",
          "[grade][05-sprites][ex5.2]") {
  auto rng = kit::test::random_engine();
  const float dt = 1.f / 30;
  std::vector<float> lifetimes;
  for (int i = 0; i < 300; ++i) {
    // Lifetimes away from a whole number of frames, where float ages may round either way.
    const double frames = std::floor(kit::test::uniform(rng, 0, 60)) + kit::test::uniform(rng, 0.01, 0.99);
    lifetimes.push_back(float(frames / 30.0));
  }
  kit::Particles ps = make(lifetimes, 300);
  std::vector<kit::Death> deaths;
  std::vector<int> died_after(300, -1);
  for (int call = 1; call <= 70; ++call) {
    const auto before = ids(ps);
    const long removed = kit::age_and_kill(ps, dt, {}, no_bursts, deaths);
    const auto after = ids(ps);
    CHECK(removed == long(before.size() - after.size()));
    for (auto id : before)
      if (!after.count(id)) died_after[id] = call;
    for (std::size_t i = 0; i < ps.size(); ++i) REQUIRE(ps.age[i] == Approx(call * dt).epsilon(1e-5));
  }
  for (std::size_t i = 0; i < lifetimes.size(); ++i) {
    INFO("lifetime " << lifetimes[i] << " s = " << lifetimes[i] * 30 << " frames");
    CHECK(died_after[i] == int(std::ceil(double(lifetimes[i]) * 30.0)));
  }
  CHECK(deaths.empty());  // no emitter bursts
}

TEST_CASE("ex 5.2: swap-remove keeps the alive particles dense, also when the last ones die",
          "[grade][05-sprites][ex5.2]") {
  // Particles 1, 3, 4 and 5 die in the first call; 4 and 5 are the last ones, so the particle
  // moved into slot 1 or 3 may itself be dead and must be tested again.
  kit::Particles ps = make({5, 0.01f, 5, 0.01f, 0.01f, 0.01f});
  const float* storage = ps.x.data();
  std::vector<kit::Death> deaths;
  CHECK(kit::age_and_kill(ps, 0.1f, {}, no_bursts, deaths) == 4);
  CHECK(ps.size() == 2);
  CHECK(ids(ps) == std::set<std::uint32_t>{0, 2});
  for (std::size_t i = 0; i < ps.size(); ++i) CHECK(ps.x[i] == float(ps.id[i]));  // attributes moved together
  CHECK(ps.x.data() == storage);                                                  // nothing reallocated
  CHECK(ps.capacity() == 64);
}

TEST_CASE("ex 5.2: the opacity threshold and the region kill only when the scene sets them",
          "[grade][05-sprites][ex5.2]") {
  std::vector<kit::Death> deaths;
  kit::Particles ps = make({9, 9, 9, 9});
  ps.alpha[1] = 0.05f;
  ps.y[2] = -1.f;  // below the floor of the region
  kit::DeathRules rules;
  CHECK(kit::age_and_kill(ps, 0.1f, rules, no_bursts, deaths) == 0);
  rules.alpha_below = 0.1;
  CHECK(kit::age_and_kill(ps, 0.1f, rules, no_bursts, deaths) == 1);
  CHECK(ids(ps) == std::set<std::uint32_t>{0, 2, 3});
  rules.region = std::array<kit::Vec3, 2>{kit::Vec3{-10, 0, -10}, kit::Vec3{10, 10, 10}};
  CHECK(kit::age_and_kill(ps, 0.1f, rules, no_bursts, deaths) == 1);
  CHECK(ids(ps) == std::set<std::uint32_t>{0, 3});
  ps.x[0] = 10.5f;  // out through the +x face
  CHECK(kit::age_and_kill(ps, 0.1f, rules, no_bursts, deaths) == 1);
  CHECK(ids(ps) == std::set<std::uint32_t>{3});
}

TEST_CASE("ex 5.2: a death is recorded for a burst exactly when its emitter bursts",
          "[grade][05-sprites][ex5.2]") {
  kit::Particles ps = make({0.01f, 0.01f, 9, 0.01f});
  ps.emitter[0] = 1, ps.emitter[1] = 0, ps.emitter[2] = 1, ps.emitter[3] = 1;
  for (std::size_t i = 0; i < ps.size(); ++i)
    ps.y[i] = 100.f + float(i), ps.z[i] = 200.f + float(i), ps.vx[i] = 300.f + float(i),
    ps.vz[i] = 400.f + float(i);
  std::vector<kit::Death> deaths;
  const std::vector<bool> bursts{false, true};
  CHECK(kit::age_and_kill(ps, 0.1f, {}, bursts, deaths) == 3);
  REQUIRE(deaths.size() == 2);  // particles 0 and 3 (emitter 1); particle 1's emitter does not burst
  std::vector<float> xs{deaths[0].x, deaths[1].x};
  std::sort(xs.begin(), xs.end());
  CHECK(xs == std::vector<float>{0.f, 3.f});
  for (const kit::Death& d : deaths) {  // every field its own, not its neighbour's
    const std::size_t i = std::size_t(d.x);
    CHECK(d.emitter == 1);
    CHECK(d.y == 100.f + float(i));
    CHECK(d.z == 200.f + float(i));
    CHECK(d.vx == 300.f + float(i));
    CHECK(d.vy == 10 * d.x);
    CHECK(d.vz == 400.f + float(i));
  }
}

TEST_CASE("ex 5.2: on the boundaries: age = lifetime dies; alpha = threshold and a face of the region live",
          "[grade][05-sprites][ex5.2]") {
  std::vector<kit::Death> deaths;
  kit::Particles ps = make({0.5f, 9, 9, 9});
  ps.age[0] = 0.25f;              // 0.25 + 0.25 = 0.5 exactly: its lifetime is reached
  ps.alpha[1] = 0.25f;            // exactly the threshold: not below it
  ps.y[2] = 0.f, ps.x[3] = 10.f;  // on the floor and on the +x face
  kit::DeathRules rules;
  rules.alpha_below = 0.25;
  rules.region = std::array<kit::Vec3, 2>{kit::Vec3{-10, 0, -10}, kit::Vec3{10, 10, 10}};
  CHECK(kit::age_and_kill(ps, 0.25f, rules, no_bursts, deaths) == 1);
  CHECK(ids(ps) == std::set<std::uint32_t>{1, 2, 3});
}
