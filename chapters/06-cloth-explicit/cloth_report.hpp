#pragma once
// Chapter 6's sentences, apart from main.cpp's sections (its tables are cloth_tables.hpp): ex 6.1
// checked, the network ex 6.2 built, and what Provot's strain limit did.
#include <kit/app/report.hpp>
#include <kit/cloth/cloth_run.hpp>

#include "spring_force_check.hpp"

namespace kit {

/// Section 1: the spring force against Newton's third law, its energy, and its damping.
inline void say_spring_force_check(Report& report, const SpringForceCheck& c) {
  report.say("spring",
             "1. Your spring force on {n} random springs: F_a + F_b = {third:.1e} |F| "
             "(Newton's third law); F + ∇E = {gradient:.1e} |F| (it derives from ½K(l − L0)²); "
             "a pair moving together is damped by {rigid:.1e} μ|v|; a stretch rate w by μw to "
             "{stretch:.1e}.\n\n",
             {{"n", long(c.springs)},
              {"third", c.third_law},
              {"gradient", c.energy_gradient},
              {"rigid", c.rigid_damping},
              {"stretch", c.stretch_damping}});
}

/// Section 2: the springs ex 6.2 built for the scene, family by family, against the count expected.
inline void say_coupled_springs(Report& report, const ClothScene& scene, const Springs& springs) {
  const auto count = [&](SpringKind kind) { return springs.count(kind); };
  report.say("springs",
             "2. '{scene}': {nodes} nodes; your ex 6.2 built {structural} structural, "
             "{shear} shear and {bend} bend springs ({layout} neighbours): {total} of the {expected} "
             "expected.\n\n",
             {{"scene", scene.name},
              {"nodes", scene.grid.nodes()},
              {"structural", count(SpringKind::structural)},
              {"shear", count(SpringKind::shear)},
              {"bend", count(SpringKind::bend)},
              {"total", long(springs.size())},
              {"layout", scene.springs.bend_layout == BendLayout::four ? 4L : 8L},
              {"expected", spring_count(scene.grid.nx, scene.grid.ny, scene.springs)}});
}

/// Section 5: the peak stretch with springs alone and with Provot's limit [%].
inline void say_strain_limit(Report& report, const StrainComparison& c) {
  report.say("strain",
             "5. Peak stretch {free:.3g}% with springs alone, {limited:.3g}% with Provot's "
             "limit of {max:.3g}% ({fixes} springs pulled back).\n",
             {{"free", 100 * c.free.peak_strain},
              {"limited", 100 * c.limited.peak_strain},
              {"max", 100 * c.max_strain},
              {"fixes", c.limited.work.strain_corrections}});
}

}  // namespace kit
