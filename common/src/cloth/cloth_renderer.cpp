#include <kit/cloth/cloth_renderer.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include <kit/cloth/obj_mesh.hpp>
#include <kit/render/raster.hpp>

namespace kit {
namespace {

// Sphere colliders: a neutral blue-grey with a small highlight, so the sheet's colours stand out.
constexpr Colour sphere_colour{0.72, 0.74, 0.78};

// The nearest t ≥ t_min with |origin + t·ray − centre| = radius, or nullopt.
std::optional<double> hit_sphere(const Vec3& origin, const Vec3& ray, const SphereCollider& sphere,
                                 double t_min) {
  const Vec3 to_origin = origin - sphere.center;
  const double a = ray.squaredNorm(), half_b = ray.dot(to_origin);
  const double c = to_origin.squaredNorm() - sphere.radius * sphere.radius;
  const double discriminant = half_b * half_b - a * c;
  if (!(discriminant >= 0)) return std::nullopt;
  const double root = std::sqrt(discriminant);
  for (const double t : {(-half_b - root) / a, (-half_b + root) / a})
    if (t >= t_min) return t;
  return std::nullopt;
}

// The background, ground and spheres, per pixel by ray casting (the spheres shadow the ground).
void draw_surroundings(const Pinhole& camera, const ClothScene& scene, DepthCanvas& canvas) {
  const Vec3 eye = camera.eye(), light = key_light_direction();
  std::optional<double> ground_height;
  if (scene.ground) ground_height = scene.ground->height;
  ShadowTest in_shadow;  // empty without spheres: no per-pixel call for nothing
  RayForeground spheres;
  if (!scene.spheres.empty()) {
    in_shadow = [&](const Vec3& p) {
      return std::any_of(scene.spheres.begin(), scene.spheres.end(), [&](const SphereCollider& sphere) {
        return bool(hit_sphere(p, light, sphere, 1e-6));
      });
    };
    spheres = [&](const Vec3& ray, RayHit& hit) {
      for (const SphereCollider& sphere : scene.spheres) {
        const auto t = hit_sphere(eye, ray, sphere, Pinhole::near_depth);
        if (!t || *t >= hit.depth) continue;
        hit.depth = *t;
        const Vec3 n = (eye + *t * ray - sphere.center) / sphere.radius;
        const Vec3 half_way = (light - ray.normalized()).normalized();
        const double highlight = 0.2 * std::pow(std::max(0.0, n.dot(half_way)), 40);
        const Colour colour = scale_colour(sphere_colour, light_intensity(n));
        hit.colour = {colour[0] + highlight, colour[1] + highlight, colour[2] + highlight};
      }
    };
  }
  draw_backdrop(camera, ground_height, in_shadow, spheres, canvas);
}

}  // namespace

Image render_cloth(const ClothGrid& grid, const NodeArray& x, const ClothScene& scene, int width, int height,
                   ClothRenderStats* stats) {
  const Pinhole camera(scene.camera, width, height);
  const NodeArray normals = vertex_normals(grid, x);  // also checks that x fits the grid
  DepthCanvas canvas(width, height, cloth_sky_top);
  draw_surroundings(camera, scene, canvas);

  // Every node projected once; a node behind the near plane or not finite has no screen vertex.
  std::vector<std::optional<ScreenVertex>> screen(std::size_t(x.rows()));
  for (long k = 0; k < x.rows(); ++k) screen[std::size_t(k)] = screen_vertex(camera, x.row(k).transpose());
  const Vec3 eye = camera.eye();
  ClothRenderStats counted;
  auto draw_triangle = [&](long a, long b, long c) {
    const auto &sa = screen[std::size_t(a)], &sb = screen[std::size_t(b)], &sc = screen[std::size_t(c)];
    // Which side faces the eye decides the tint; the shading normal is turned towards the eye.
    const Vec3 pa = x.row(a), pb = x.row(b), pc = x.row(c);
    const bool front = (pb - pa).cross(pc - pa).dot(eye - pa) >= 0;
    const Colour& tint = front ? cloth_front_colour : cloth_back_colour;
    const double side = front ? 1 : -1;
    const Vec3 na = normals.row(a), nb = normals.row(b), nc = normals.row(c);
    // The normal interpolated perspective-correctly, renormalised.
    auto shade = [&](double wa, double wb, double wc) {
      Vec3 n = (wa * na + wb * nb + wc * nc) * side;
      const double length = n.norm();
      n = length > 1e-12 ? Vec3(n / length) : Vec3(0, 1, 0);
      return scale_colour(tint, light_intensity(n));
    };
    const bool drawn = sa && sb && sc && fill_triangle(*sa, *sb, *sc, canvas, shade);
    ++(drawn ? counted.triangles_drawn : counted.triangles_skipped);
  };
  const int nx = grid.nx, ny = grid.ny;
  for (int j = 0; j + 1 < ny; ++j)
    for (int i = 0; i + 1 < nx; ++i) {
      const long a = long(j) * nx + i, b = a + 1, c = a + nx + 1, d = a + nx;
      draw_triangle(a, b, c);
      draw_triangle(a, c, d);
    }
  if (stats) *stats = counted;
  return std::move(canvas.image);
}

}  // namespace kit
