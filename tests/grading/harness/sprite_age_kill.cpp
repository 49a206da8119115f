// The student's program for sprite_age_kill.hpp (ex 5.2): its entry points call the student's functions and
// return what they return (remote/student.hpp). It checks nothing.
#include "sprite_age_kill.hpp"
#include "remote/fields/death.hpp"
#include "remote/student.hpp"

void register_entries(kit::remote::Entries& e) {
  e.add("age_and_kill", [](kit::Particles& particles, float dt, const kit::DeathRules& rules,
                           const std::vector<bool>& bursts_on_death, std::vector<kit::Death>& deaths) {
    // Whether the function kept the arrays' storage: the judge mirrors it (stubs/sprite_age_kill.hpp).
    std::vector<const void*> storage;
    kit::remote::Codec<kit::Particles>::each_array(particles, [&](auto& a) { storage.push_back(a.data()); });
    const long removed = kit::age_and_kill(particles, dt, rules, bursts_on_death, deaths);
    bool kept = true;
    std::size_t k = 0;
    kit::remote::Codec<kit::Particles>::each_array(particles,
                                                   [&](auto& a) { kept = kept && a.data() == storage[k++]; });
    return std::pair<long, bool>(removed, kept);
  });
}
