#include <kit/cloth_renderer.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include <kit/obj_mesh.hpp>
#include <kit/sprite_camera.hpp>

namespace kit {
namespace {

// Projected coordinates beyond this many pixels mark a diverged sheet: edge functions of such
// triangles would lose pixel precision, and nothing sensible is drawn from them [px].
constexpr double max_pixel_coordinate = 1e6;
constexpr double checker_square = 0.25;  // [m]
// Sphere colliders: a neutral blue-grey with a small highlight, so the sheet's colours stand out.
constexpr Vec3d sphere_colour{0.72, 0.74, 0.78};
constexpr Vec3d ground_light{0.70, 0.68, 0.63}, ground_dark{0.46, 0.44, 0.41};

Vector3 to_vector(const Vec3d& v) { return {v[0], v[1], v[2]}; }
Vec3d to_vec3d(const Vector3& v) { return {v.x(), v.y(), v.z()}; }

Vec3d mix(const Vec3d& a, const Vec3d& b, double t) {
  return {a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t};
}
Vec3d scaled(const Vec3d& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }

void put(Image& image, int px, int py, const Vec3d& colour) {
  float* p = image.pixel(px, py);
  p[0] = float(colour[0]), p[1] = float(colour[1]), p[2] = float(colour[2]);
}

Vector3 key_light() { return to_vector(cloth_key_light).normalized(); }

// A dim fill light from the side opposite the key (and a little from below the horizon's glow),
// so that what the key light misses keeps its shape instead of flattening into the ambient.
constexpr double fill_strength = 0.22;
const Vector3 fill_light = Vector3(0.6, 0.25, -0.35).normalized();

// Ambient plus Lambert from the key and fill lights for a unit normal n, at most 1.
double lit(const Vector3& n, const Vector3& light) {
  return std::min(1.0, cloth_ambient + (1 - cloth_ambient) * std::max(0.0, n.dot(light)) +
                           fill_strength * std::max(0.0, n.dot(fill_light)));
}

// The nearest t ≥ t_min with |origin + t·ray − centre| = radius, or nullopt.
std::optional<double> hit_sphere(const Vector3& origin, const Vector3& ray, const SphereCollider& sphere,
                                 double t_min) {
  const Vector3 to_origin = origin - sphere.center;
  const double a = ray.squaredNorm(), half_b = ray.dot(to_origin);
  const double c = to_origin.squaredNorm() - sphere.radius * sphere.radius;
  const double discriminant = half_b * half_b - a * c;
  if (!(discriminant >= 0)) return std::nullopt;
  const double root = std::sqrt(discriminant);
  for (const double t : {(-half_b - root) / a, (-half_b + root) / a})
    if (t >= t_min) return t;
  return std::nullopt;
}

// The background, ground and spheres, per pixel by ray casting; fills depth [m along the view axis].
void draw_surroundings(const SpriteCamera& camera, const ClothScene& scene, Image& image,
                       std::vector<float>& depth) {
  const Vector3 eye = to_vector(camera.eye()), light = key_light();
  const int width = image.width, height = image.height;
  for (int py = 0; py < height; ++py) {
    for (int px = 0; px < width; ++px) {
      // The ray's view-axis component is 1, so the parameter t along it is the depth.
      const Vector3 ray = to_vector(camera.ray(px + 0.5, py + 0.5));
      const double inv_ray_length = 1 / ray.norm();
      double nearest = std::numeric_limits<double>::infinity();
      Vec3d colour = cloth_sky(ray.y() * inv_ray_length);
      if (scene.ground && ray.y() != 0) {
        const double t = (scene.ground->height - eye.y()) / ray.y();
        if (t >= SpriteCamera::near_depth) {
          const Vector3 p = eye + t * ray;
          const bool light_square =
              (long(std::floor(p.x() / checker_square)) + long(std::floor(p.z() / checker_square))) % 2 == 0;
          // A pixel spans about t/F metres across (more at grazing angles); once a square is only a
          // few pixels wide the checker would alias, so it fades to its mean and then into the sky.
          const double footprint = t / camera.focal_px() / std::max(0.05, std::abs(ray.y()) * inv_ray_length);
          const double contrast = std::clamp(1.5 - 3 * footprint / checker_square, 0.0, 1.0);
          Vec3d ground = mix(mix(ground_light, ground_dark, 0.5), light_square ? ground_light : ground_dark,
                             contrast);
          // Sphere shadows: the key light blocked on its way to this point.
          double shade = lit({0, 1, 0}, light);
          for (const SphereCollider& sphere : scene.spheres)
            if (hit_sphere(p, light, sphere, 1e-6)) shade = cloth_ambient;
          ground = scaled(ground, shade);
          const double haze = std::clamp(footprint / (4 * checker_square), 0.0, 1.0);
          colour = mix(ground, cloth_sky_bottom, haze);
          nearest = t;
        }
      }
      for (const SphereCollider& sphere : scene.spheres) {
        const auto t = hit_sphere(eye, ray, sphere, SpriteCamera::near_depth);
        if (!t || *t >= nearest) continue;
        nearest = *t;
        const Vector3 n = (eye + *t * ray - sphere.center) / sphere.radius;
        const Vector3 half_way = (light - ray * inv_ray_length).normalized();
        const double highlight = 0.2 * std::pow(std::max(0.0, n.dot(half_way)), 40);
        colour = scaled(sphere_colour, lit(n, light));
        colour = {colour[0] + highlight, colour[1] + highlight, colour[2] + highlight};
      }
      put(image, px, py, colour);
      depth[std::size_t(py) * std::size_t(width) + std::size_t(px)] = float(nearest);
    }
  }
}

struct ScreenVertex {
  double px = 0, py = 0, depth = 0;
};

}  // namespace

Vec3d cloth_sky(double elevation) {
  return mix(cloth_sky_bottom, cloth_sky_top, std::clamp(elevation / 0.5, 0.0, 1.0));  // sin 30° = 0.5
}

Image render_cloth(const ClothGrid& grid, const NodeArray& x, const ClothScene& scene, int width, int height,
                   ClothRenderStats* stats) {
  const Camera view{to_vec3d(scene.camera.position), to_vec3d(scene.camera.target), scene.camera.fov_deg};
  const SpriteCamera camera(view, width, height);
  const NodeArray normals = vertex_normals(grid, x);  // also checks that x fits the grid
  Image image(width, height, cloth_sky_top);
  std::vector<float> depth(std::size_t(width) * std::size_t(height), std::numeric_limits<float>::infinity());
  draw_surroundings(camera, scene, image, depth);

  // Every node projected once; a node behind the near plane or not finite has no screen vertex.
  std::vector<std::optional<ScreenVertex>> screen(std::size_t(x.rows()));
  for (long k = 0; k < x.rows(); ++k) {
    if (!x.row(k).allFinite()) continue;
    const auto p = camera.project(x(k, 0), x(k, 1), x(k, 2));
    if (p && std::abs(p->px) < max_pixel_coordinate && std::abs(p->py) < max_pixel_coordinate)
      screen[std::size_t(k)] = ScreenVertex{p->px, p->py, p->depth};
  }
  const Vector3 eye = to_vector(camera.eye()), light = key_light();
  ClothRenderStats counted;
  auto draw_triangle = [&](long a, long b, long c) {
    const auto &sa = screen[std::size_t(a)], &sb = screen[std::size_t(b)], &sc = screen[std::size_t(c)];
    if (!sa || !sb || !sc) return ++counted.triangles_skipped, void();
    const double area = (sb->px - sa->px) * (sc->py - sa->py) - (sb->py - sa->py) * (sc->px - sa->px);
    const int x0 = std::max(0, int(std::floor(std::min({sa->px, sb->px, sc->px}))));
    const int x1 = std::min(width - 1, int(std::ceil(std::max({sa->px, sb->px, sc->px}))));
    const int y0 = std::max(0, int(std::floor(std::min({sa->py, sb->py, sc->py}))));
    const int y1 = std::min(height - 1, int(std::ceil(std::max({sa->py, sb->py, sc->py}))));
    if (!(std::abs(area) > 1e-12) || x0 > x1 || y0 > y1) return ++counted.triangles_skipped, void();
    ++counted.triangles_drawn;
    // Which side faces the eye decides the tint; the shading normal is turned towards the eye.
    const Vector3 pa = x.row(a), pb = x.row(b), pc = x.row(c);
    const bool front = (pb - pa).cross(pc - pa).dot(eye - pa) >= 0;
    const Vec3d& tint = front ? cloth_front_colour : cloth_back_colour;
    const double side = front ? 1 : -1;
    const Vector3 na = normals.row(a), nb = normals.row(b), nc = normals.row(c);
    const double inv_area = 1 / area;
    for (int py = y0; py <= y1; ++py)
      for (int px = x0; px <= x1; ++px) {
        const double cx = px + 0.5, cy = py + 0.5;
        // Barycentric weights from edge functions; all ≥ 0 inside whatever the winding.
        const double wa = ((sb->px - cx) * (sc->py - cy) - (sb->py - cy) * (sc->px - cx)) * inv_area;
        const double wb = ((sc->px - cx) * (sa->py - cy) - (sc->py - cy) * (sa->px - cx)) * inv_area;
        const double wc = 1 - wa - wb;
        if (wa < 0 || wb < 0 || wc < 0) continue;
        // 1/depth is linear on screen; the normal is interpolated perspective-correctly.
        const double qa = wa / sa->depth, qb = wb / sb->depth, qc = wc / sc->depth, q = qa + qb + qc;
        const double z = 1 / q;
        float& stored = depth[std::size_t(py) * std::size_t(width) + std::size_t(px)];
        // Cloth lying on the ground (or a padded sphere) is as deep as it: a bias of 1e-4 of the
        // depth (0.3 mm at 3 m) lets the cloth win the tie instead of flickering against it.
        if (!(z * (1 - 1e-4) < stored)) continue;
        stored = float(z);
        Vector3 n = (qa * na + qb * nb + qc * nc) * side;
        const double length = n.norm();
        n = length > 1e-12 ? Vector3(n / length) : Vector3(0, 1, 0);
        put(image, px, py, scaled(tint, lit(n, light)));
      }
  };
  const int nx = grid.nx, ny = grid.ny;
  for (int j = 0; j + 1 < ny; ++j)
    for (int i = 0; i + 1 < nx; ++i) {
      const long a = long(j) * nx + i, b = a + 1, c = a + nx + 1, d = a + nx;
      draw_triangle(a, b, c);
      draw_triangle(a, c, d);
    }
  if (stats) *stats = counted;
  return image;
}

}  // namespace kit
