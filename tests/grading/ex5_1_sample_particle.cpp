// ex 5.1: one new particle of an emitter, every attribute mean + rand·variance (sprite_emit.hpp).
#include <algorithm>
#include <cmath>
#include <vector>

#include <kit_catch.hpp>

#include "cases.hpp"
#include "sprite_emit.hpp"

namespace {
kit::Emitter cone_emitter() {
  kit::Emitter e;
  e.shape = kit::EmitterShape::cone;
  e.position = {1, 2, 3};
  e.axis = {0, 1, 0};
  e.angle_deg = 25;
  e.speed = {6, 2};
  e.lifetime = {1.5, 0.5};
  e.size = {0.2, 0.1};
  e.colour = {0.5, 0.4, 0.6};
  e.colour_variance = {0.2, 0.3, 0.1};
  e.alpha = {0.6, 0.3};
  return e;
}
double length(double x, double y, double z) { return std::hypot(x, y, z); }

// Pearson's chi-square of `values` against the uniform law on [lo, hi], over 10 equal bins.
double chi_square_uniform(std::vector<double> values, double lo, double hi) {
  const int bins = 10;
  std::vector<double> count(bins, 0.0);
  for (double v : values) {
    // Outside mean ± variance, beyond the float rounding of the particle's components.
    if (v < lo - 1e-5 * std::abs(lo) || v > hi + 1e-5 * std::abs(hi)) return INFINITY;
    v = std::clamp(v, lo, hi);
    count[std::min(bins - 1, int((v - lo) / (hi - lo) * bins))] += 1;
  }
  const double expected = double(values.size()) / bins;
  double chi2 = 0;
  for (double c : count) chi2 += (c - expected) * (c - expected) / expected;
  return chi2;
}
// 9 degrees of freedom, p = 1e-6: a correct draw fails one check in a million, while a draw
// that ignores the variance or biases it scores in the hundreds of thousands.
constexpr double chi2_limit = 45.0;
}  // namespace

TEST_CASE("ex 5.1: speed, lifetime, size, colour and alpha are each uniform in mean ± variance",
          "[grade][05-sprites][ex5.1]") {
  const kit::Emitter e = cone_emitter();
  kit::Random random(kit::testing::seed());
  std::vector<double> speed, lifetime, size, r, g, b, alpha;
  for (const kit::ParticleSpawn& p : kit::remote::sample_particles(e, 3, random, 50000)) {
    speed.push_back(length(p.vx, p.vy, p.vz));
    lifetime.push_back(p.lifetime), size.push_back(p.size), alpha.push_back(p.alpha);
    r.push_back(p.r), g.push_back(p.g), b.push_back(p.b);
  }
  CHECK(chi_square_uniform(speed, 4, 8) < chi2_limit);
  CHECK(chi_square_uniform(lifetime, 1, 2) < chi2_limit);
  CHECK(chi_square_uniform(size, 0.1, 0.3) < chi2_limit);
  CHECK(chi_square_uniform(alpha, 0.3, 0.9) < chi2_limit);
  CHECK(chi_square_uniform(r, 0.3, 0.7) < chi2_limit);
  CHECK(chi_square_uniform(g, 0.1, 0.7) < chi2_limit);
  CHECK(chi_square_uniform(b, 0.5, 0.7) < chi2_limit);
  // Each attribute has its own draw: one rand reused for all would correlate them fully.
  const auto correlation = [](const std::vector<double>& x, const std::vector<double>& y) {
    double mx = 0, my = 0, sxy = 0, sxx = 0, syy = 0;
    for (std::size_t i = 0; i < x.size(); ++i) mx += x[i] / double(x.size()), my += y[i] / double(y.size());
    for (std::size_t i = 0; i < x.size(); ++i)
      sxy += (x[i] - mx) * (y[i] - my), sxx += (x[i] - mx) * (x[i] - mx), syy += (y[i] - my) * (y[i] - my);
    return sxy / std::sqrt(sxx * syy);
  };
  // Every pair of the seven: a draw shared by any two of them (lifetime and alpha, r and b)
  // correlates them by ±1. Independent draws: each |ρ| < 5/√n fails once in 1.7 million, the 21
  // pairs once in 80000.
  const double bound = 5 / std::sqrt(double(speed.size()));
  const std::vector<const std::vector<double>*> attributes = {&speed, &lifetime, &size, &alpha, &r, &g, &b};
  for (std::size_t i = 0; i < attributes.size(); ++i)
    for (std::size_t j = i + 1; j < attributes.size(); ++j) {
      INFO("attributes " << i << " and " << j << " of speed, lifetime, size, alpha, r, g, b");
      CHECK(std::abs(correlation(*attributes[i], *attributes[j])) < bound);
    }
}

TEST_CASE("ex 5.1: with no variance every attribute is its mean, and the emitter index is kept",
          "[grade][05-sprites][ex5.1]") {
  kit::Emitter e = cone_emitter();
  e.angle_deg = 0, e.speed.variance = 0, e.lifetime.variance = 0, e.size.variance = 0, e.alpha.variance = 0;
  e.colour_variance = {0, 0, 0};
  kit::Random random(kit::testing::seed());
  const kit::ParticleSpawn p = kit::sample_particle(e, 7, random);
  CHECK(p.emitter == 7);
  CHECK(p.x == 1.f);
  CHECK(p.y == 2.f);
  CHECK(p.z == 3.f);
  CHECK(p.vx == Approx(0).margin(1e-6));
  CHECK(p.vy == Approx(6));
  CHECK(p.vz == Approx(0).margin(1e-6));
  CHECK(p.lifetime == Approx(1.5));
  CHECK(p.size == Approx(0.2));
  CHECK(p.alpha == Approx(0.6));
  CHECK(p.r == Approx(0.5));
  CHECK(p.g == Approx(0.4));
  CHECK(p.b == Approx(0.6));
}

TEST_CASE("ex 5.1: colour and alpha are clamped to [0, 1] and size to >= 0", "[grade][05-sprites][ex5.1]") {
  kit::Emitter e = cone_emitter();
  e.colour = {0.9, 0.1, 0.5}, e.colour_variance = {0.5, 0.5, 0.5}, e.alpha = {0.9, 0.5}, e.size = {0.05, 0.2};
  kit::Random random(kit::testing::seed());
  bool clamped_high = false, clamped_low = false;
  for (const kit::ParticleSpawn& p : kit::remote::sample_particles(e, 0, random, 5000)) {
    for (float c : {p.r, p.g, p.b, p.alpha}) {
      REQUIRE(c >= 0.f);
      REQUIRE(c <= 1.f);
      clamped_high |= c == 1.f, clamped_low |= c == 0.f;
    }
    REQUIRE(p.size >= 0.f);
  }
  CHECK(clamped_high);  // the draws did leave the range, and were brought back to its ends
  CHECK(clamped_low);
}

TEST_CASE("ex 5.1: each shape places and aims as specified", "[grade][05-sprites][ex5.1]") {
  kit::Random random(kit::testing::seed());
  kit::Emitter e = cone_emitter();
  e.speed = {2, 0};
  const int n = 20000;
  SECTION("cone: at the position, within angle_deg of the axis, uniform over the cap") {
    e.axis = {0.6, 0, 0.8};
    double mean_cos = 0;
    for (const kit::ParticleSpawn& p : kit::remote::sample_particles(e, 0, random, n)) {
      REQUIRE(p.x == 1.f);
      const double c = (0.6 * p.vx + 0.8 * p.vz) / 2.0;
      REQUIRE(c >= std::cos(25 * M_PI / 180) - 1e-5);
      mean_cos += c / n;
    }
    const double cos_max = std::cos(25 * M_PI / 180);
    CHECK(mean_cos == Approx((1 + cos_max) / 2).margin(5 * (1 - cos_max) / std::sqrt(12.0 * n)));
  }
  SECTION("disc: on the disc of radius R normal to the axis, a quarter of them within R/2") {
    e.shape = kit::EmitterShape::disc, e.radius = 2.0, e.angle_deg = 0;
    int inner = 0;
    for (const kit::ParticleSpawn& p : kit::remote::sample_particles(e, 0, random, n)) {
      REQUIRE(p.y == Approx(2.0).margin(1e-5));  // in the plane y = 2 (axis +y)
      const double r = std::hypot(p.x - 1.0, p.z - 3.0);
      REQUIRE(r <= 2.0 + 1e-5);
      inner += r < 1.0;
      REQUIRE(p.vy == Approx(2.0).epsilon(1e-5));  // angle 0: along the axis
    }
    CHECK(std::abs(inner - n / 4.0) < 5 * std::sqrt(n * 0.25 * 0.75));
  }
  SECTION("disc: directions within angle_deg of the axis, uniform over the cap, wherever it starts") {
    e.shape = kit::EmitterShape::disc, e.radius = 1.0, e.angle_deg = 40;
    double mean_cos = 0, worst = 1;
    for (const kit::ParticleSpawn& p : kit::remote::sample_particles(e, 0, random, n)) {
      const double c = p.vy / 2.0;
      worst = std::min(worst, c);
      mean_cos += c / n;
    }
    const double cos_max = std::cos(40 * M_PI / 180);
    CHECK(worst >= cos_max - 1e-5);
    CHECK(mean_cos == Approx((1 + cos_max) / 2).margin(5 * (1 - cos_max) / std::sqrt(12.0 * n)));
  }
  SECTION("sphere: in the ball of radius R, flying radially out, an eighth within R/2") {
    e.shape = kit::EmitterShape::sphere, e.radius = 2.0;
    int inner = 0;
    for (const kit::ParticleSpawn& p : kit::remote::sample_particles(e, 0, random, n)) {
      const double dx = p.x - 1.0, dy = p.y - 2.0, dz = p.z - 3.0, r = length(dx, dy, dz);
      REQUIRE(r <= 2.0 + 1e-5);
      inner += r < 1.0;
      if (r > 0.1) REQUIRE((dx * p.vx + dy * p.vy + dz * p.vz) / (2.0 * r) == Approx(1.0).epsilon(1e-4));
    }
    CHECK(std::abs(inner - n / 8.0) < 5 * std::sqrt(n * 0.125 * 0.875));
  }
  SECTION("point: at the position, directions over the whole sphere (mean velocity 0)") {
    e.shape = kit::EmitterShape::point;
    double mx = 0, my = 0, mz = 0, below = 0;
    for (const kit::ParticleSpawn& p : kit::remote::sample_particles(e, 0, random, n)) {
      REQUIRE(p.z == 3.f);
      mx += p.vx / n, my += p.vy / n, mz += p.vz / n, below += p.vy < 0;
    }
    const double tolerance = 5 * 2.0 / std::sqrt(3.0 * n);  // each component has variance 4/3
    CHECK(std::abs(mx) < tolerance);
    CHECK(std::abs(my) < tolerance);
    CHECK(std::abs(mz) < tolerance);
    CHECK(std::abs(below - n / 2.0) < 5 * std::sqrt(n / 4.0));
  }
}
