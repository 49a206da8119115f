#pragma once
// Chapter 5's wiring of the student's exercises into the kit's sprite system: ex 5.1 draws each
// new particle, ex 5.2 ages and kills, ex 5.3 composites "over" sprites. Not an exercise.
#include <kit/app/report.hpp>
#include <kit/render/image.hpp>
#include <kit/sprites/sprite_renderer.hpp>
#include <kit/sprites/sprite_system.hpp>

#include "sprite_age_kill.hpp"
#include "sprite_emit.hpp"
#include "sprite_over.hpp"

namespace kit {

/// The system's kernels, or a NotImplemented naming the first exercise that waits (one particle
/// drawn, one aged: a probe, so a chapter says what waits before it runs anything long).
inline SpriteKernels student_kernels(const Emitter& emitter) {
  Random random(0);
  Particles probe;
  probe.reserve(1);
  probe.add(sample_particle(emitter, 0, random));
  std::vector<Death> deaths;
  age_and_kill(probe, 0.0f, DeathRules{}, std::vector<bool>(1, false), deaths);
  return {&sample_particle, &age_and_kill};
}

/// The student's "over" compositing once ex 5.3 is written; until then nullptr, and the frames
/// use the renderer's own (the text says so).
inline CompositeOver student_over(Report& report) {
  const bool written = report.attempt("your over compositing (the frames use the kit's until then)", [] {
    Image image(1, 1, {0, 0, 0});
    SpriteTile tile;
    tile.reset(0, 0, 1, 1);
    composite_over(image, tile);
  });
  return written ? &composite_over : nullptr;
}

}  // namespace kit
