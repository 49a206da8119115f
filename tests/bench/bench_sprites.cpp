// ./kit bench sprites: the particle update (gravity, drag, ageing, death) in ns per particle-step
// at 1e4, 1e5 and 1e6 particles, as a fraction of this machine's memory-bandwidth bound measured
// in the same run (a STREAM-like triad), against a straightforward array-of-structs double
// update, and the render cost of a frame. One core. Timings live here, never in the tests.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <vector>

#include <fmt/format.h>

#include <kit/app/run_estimate.hpp>
#include <kit/app/table.hpp>
#include <kit/base/stopwatch.hpp>
#include <kit/base/usage.hpp>
#include <kit/render/image.hpp>
#include <kit/sprites/particle_update.hpp>
#include <kit/sprites/sprite_renderer.hpp>
#include <kit/sprites/sprite_scene_file.hpp>
#include <kit/sprites/sprite_system.hpp>

#include "bandwidth.hpp"
#include "sprite_age_kill.hpp"
#include "sprite_emit.hpp"
#include "sprite_flags.hpp"

namespace {
using kit_bench::fastest, kit_bench::last_level_cache, kit_bench::triad_bandwidth;

// The fountain's physics with lifetimes long enough that nobody dies while timing: the update
// streams through every array once per step.
kit::SpriteScene bench_scene() {
  return kit::parse_sprite_scene(
      "name = 'bench'\n[forces]\ngravity = [0, -9.81, 0]\ndrag = 0.1\nwind = [0.5, 0, 0]\n"
      "[[emitter]]\nname = 'jet'\nshape = 'cone'\nangle_deg = 12\nrate = 1\nspeed = { mean = 6, variance = "
      "0.6 }\n"
      "lifetime = 1e6\n",
      "bench.toml");
}

kit::Particles filled(const kit::SpriteScene& scene, std::size_t n) {
  kit::Particles ps;
  ps.reserve(n);
  kit::Random random(1);
  for (std::size_t i = 0; i < n; ++i) ps.add(kit::sample_particle(scene.emitters[0], 0, random));
  return ps;
}

// What a student writes first: one struct per particle, in double, the force evaluated per
// particle, the dead erased by swapping with the last.
struct AosParticle {
  double x, y, z, vx, vy, vz, age, lifetime, size, r, g, b, alpha;
};
void aos_update(std::vector<AosParticle>& ps, double dt) {
  const double gx = 0, gy = -9.81, gz = 0, k = 0.1, wx = 0.5, wy = 0, wz = 0;
  for (std::size_t i = 0; i < ps.size();) {
    AosParticle& p = ps[i];
    p.x += dt * p.vx, p.y += dt * p.vy, p.z += dt * p.vz;
    p.vx += dt * (gx - k * (p.vx - wx)), p.vy += dt * (gy - k * (p.vy - wy)),
        p.vz += dt * (gz - k * (p.vz - wz));
    p.age += dt;
    if (p.age >= p.lifetime) {
      p = ps.back();
      ps.pop_back();
    } else {
      ++i;
    }
  }
}
}  // namespace

int main() {
  // KIT_MEMORY_LIMIT, when set, bounds the sizes below: a malformed one is refused here, before
  // anything is measured, as the chapter refuses it (exit 2, naming the variable).
  try {
    (void)kit::machine_memory();
  } catch (const kit::UsageError& e) {
    fmt::print(stderr, "bench_sprites: {}\n", e.what());
    return 2;
  }
  double stream = 0;
  const double bandwidth = triad_bandwidth(stream);
  fmt::print("Memory bandwidth, one core: {:.1f} GB/s moved by a triad over arrays 4x the {:.0f} MB "
             "last-level cache "
             "({:.1f} GB/s as STREAM counts it, without the write-allocate read)\n\n",
             bandwidth / 1e9, last_level_cache() / 1e6, stream / 1e9);

  const kit::SpriteScene scene = bench_scene();
  // Bytes the update moves per particle-step: motion reads and writes x, y, z, vx, vy, vz (48);
  // ex 5.2's ageing reads and writes age (8), its death scan reads age and lifetime (8).
  const double bytes = 64.0;
  const double bound_ns = bytes / bandwidth * 1e9;
  fmt::print(
      "1. The update (gravity, drag, wind, ageing, death), exact integrator, float32 struct of arrays\n");
  fmt::print("   moves {:.0f} B per particle-step: the bandwidth bound is {:.2f} ns per particle-step\n",
             bytes, bound_ns);
  kit::Table table({"particles", "arrays [MB]", "kit [ns/particle-step]", "fraction of bound",
                    "baseline AoS double [ns]", "baseline / kit"});
  const float dt = 1.0f / 30;
  // 1e7 and 3e7 as well: when 1e6 particles fit in a large last-level cache, only these show memory.
  for (std::size_t n : {std::size_t(10'000), std::size_t(100'000), std::size_t(1'000'000),
                        std::size_t(10'000'000), std::size_t(30'000'000)}) {
    // The struct of arrays, the array of structs (13 doubles) and the triad's arrays, freed by now.
    if (double(n) * double(kit::Particles::bytes_per_particle + sizeof(AosParticle)) >
        0.5 * kit::machine_memory()) {
      fmt::print("   {:.0e} particles: skipped, over half of this machine's memory\n", double(n));
      continue;
    }
    kit::Particles ps = filled(scene, n);
    kit::ParticleUpdate update(scene, kit::Integrator::exact);
    std::vector<kit::Death> deaths;
    const double kit_s = fastest([&] {
      update.step(ps, dt);
      kit::age_and_kill(ps, dt, scene.death, update.bursts_on_death(), deaths);
    });
    if (ps.size() != n) std::abort();  // nobody died: every step moved all n
    std::vector<AosParticle> aos;
    aos.reserve(n);
    for (std::size_t i = 0; i < n; ++i)
      aos.push_back({ps.x[i], ps.y[i], ps.z[i], ps.vx[i], ps.vy[i], ps.vz[i], 0, 1e6, 0.1, 1, 1, 1, 1});
    const double aos_s = fastest([&] { aos_update(aos, dt); });
    const double kit_ns = kit_s / double(n) * 1e9, aos_ns = aos_s / double(n) * 1e9;
    table.add_row({fmt::format("{:.0e}", double(n)), kit::fixed(double(n) * 33 / 1e6, 0),
                   kit::fixed(kit_ns, 3), kit::fixed(bound_ns / kit_ns, 2), kit::fixed(aos_ns, 3),
                   kit::fixed(aos_ns / kit_ns, 1)});
  }
  table.print(std::cout);
  fmt::print(
      "   arrays: the 9 the update reads or writes (x, y, z, vx, vy, vz, age, lifetime: 32 B a particle, and "
      "the\n"
      "   1-byte emitter index of the dying). Above 1: the arrays sit in the cache, faster than memory.\n");
  fmt::print(
      "   For scale: Filipek's C++ particle system takes about 15 ns per particle-frame (2011 desktop).\n\n");

  fmt::print(
      "2. The four integrators cost the same per particle-step (1e6 particles; one affine map per axis)\n");
  kit::Table integrators({"integrator", "ns/particle-step"});
  for (kit::Integrator i : kit::all_integrators) {
    kit::Particles ps = filled(scene, 1'000'000);
    kit::ParticleUpdate update(scene, i);
    const double s = fastest([&] { update.step(ps, dt); }, 3);
    integrators.add_row({std::string(kit::display_name(i)), kit::fixed(s / 1e6 * 1e9, 3)});
  }
  integrators.print(std::cout);

  fmt::print(
      "\n3. Rendering the fountain at 640x360 (its steady state, ex 5.3's over compositing not used)\n");
  const kit::SpriteScene fountain = kit::load_sprite_scene(KIT_SCENES_DIR "/fountain.toml");
  kit::SpriteSystem system(fountain, fountain.max_particles, fountain.fps, 1, kit::Integrator::exact,
                           {&kit::sample_particle, &kit::age_and_kill});
  for (int f = 0; f < 90; ++f) system.step();
  kit::SpriteRenderer renderer(fountain, 640, 360);
  kit::Image image(640, 360, fountain.background);
  const double render_s = fastest([&] { renderer.render(system.particles(), image); }, 5, 0.5);
  const auto png = std::filesystem::temp_directory_path() / "kit-bench-frame.png";
  const double png_s = fastest([&] { kit::write_png(image, png); }, 3, 0.5);
  std::filesystem::remove(png);
  fmt::print("   {} sprites: {:.2f} ms a frame to render ({:.0f} ns a sprite), {:.2f} ms to write the PNG\n",
             system.particles().size(), render_s * 1e3, render_s / double(system.particles().size()) * 1e9,
             png_s * 1e3);
  return 0;
}
