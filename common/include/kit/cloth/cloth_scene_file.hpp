#pragma once
// A cloth scene read from a TOML file (chapters 6 and 7). The file lists only what the scene
// models: a spring family, force, collider or strain limit it leaves out is never built. Every
// mistake is a UsageError (exit 2) naming the file, the line, the full dotted key, the bad value
// and what is allowed:
//   scenes/flag.toml:31: springs.bend.layout = 5: must be 4 (two steps along the axes, Provot) or 8 ...
//
// Schema (units in brackets; a key marked "default" may be left out):
//
//   name            string, required, not empty
//   description     string                                              default ""
//   pins            [[i, j], ...] grid coordinates, integers; negative counts from the far end
//                   (−1 = last column or row); each within the grid     default: none
//   [cloth]         required
//     nodes         [nx, ny] integers, each in [2, 4096], required
//     size          [width, height] [m], each in (0, 1000], required
//     origin        [x, y, z] [m], node (0, 0)                          default [0, 0, 0]
//     u, v          [x, y, z] directions of i and j, not zero, not parallel; u is normalised, v is
//                   made orthogonal to u and normalised                  default u = x, v = z
//     density       areal density [kg/m²] in (0, 1000]                  default 0.1
//   [springs.structural], [springs.shear], [springs.bend]: each family built only if present;
//                   structural is required
//     stiffness     K [N/m] in (0, 1e9], required
//     damping       μ [N·s/m] in [0, 1e6], along the spring only          default 0
//     layout        bend only: 4 (two steps along the axes, Provot) or 8 (also the two-step
//                   diagonals; ERRATA 12)                                default 4
//   [forces]        gravity [x, y, z] [m/s²], each in [−1000, 1000]; drag [1/s] in [0, 1000]
//                   (f = −m·drag·v); each absent unless named
//   [[sphere]]      center [x, y, z] [m] required; radius [m] in (0, 1e6] required;
//                   friction μ in [0, 10] (Coulomb)                       default 0
//   [ground]        height [m] in [−1e6, 1e6] (y < height is solid)      default 0;
//                   friction μ in [0, 10]                                default 0
//   [strain_limit]  max_strain in (0, 10] (relative)                     default 0.1;
//                   iterations in [1, 100] (passes per step)             default 4
//   [camera]        position, target [x, y, z] [m], target != position; fov_deg [deg] in (0, 180)
//   [run]           integrator "explicit-euler" | "symplectic-euler" | "midpoint" | "rk4"
//                   (default "symplectic-euler"); dt [s] in (0, 1] (default 1e-4);
//                   t_end [s] in (0, 1e4] (default 2); frames integer in [1, 20000] (default 60)
//
// chapters/06-cloth-explicit/scenes/README.md has the same schema as a table.
#include <filesystem>
#include <string_view>

#include <kit/cloth/cloth_scene.hpp>

namespace kit {

/// Reads and checks a scene file. Throws UsageError, also when the file cannot be read.
ClothScene load_cloth_scene(const std::filesystem::path& file);

/// Parses and checks a scene held in `text`; `file_name` names it in messages.
ClothScene parse_cloth_scene(std::string_view text, std::string_view file_name);

}  // namespace kit
