// The student's program for cloth_sphere.hpp (ex 6.4): its entry points call the student's functions and
// return what they return (remote/student.hpp). It checks nothing.
#include "cloth_sphere.hpp"
#include "remote/fields/cloth_scene.hpp"
#include "remote/student.hpp"

void register_entries(kit::remote::Entries& e) {
  e.add("collide_sphere", [](kit::NodeArray& x, kit::NodeArray& v, const kit::SphereCollider& sphere) {
    return kit::collide_sphere(x, v, sphere);
  });
}
