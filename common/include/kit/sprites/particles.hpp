#pragma once
// The particles of a sprite scene (lecture, "Applications / Sprites"; Reeves 1983), stored as a
// struct of arrays in float32: one contiguous array per attribute, so the update streams through
// memory and a million particles take 60 MB. Alive particles occupy [0, size()); a death is a
// swap-remove (the last particle moves into the hole), so the arrays stay dense and nothing is
// allocated once reserve() has run.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace kit {

/// An allocator whose resize leaves new floats uninitialised: reserving room for 50 million
/// particles then costs address space, not memory, until particles are actually added.
template <class T>
struct UninitializedAllocator : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = UninitializedAllocator<U>;
  };
  UninitializedAllocator() = default;
  template <class U>
  UninitializedAllocator(const UninitializedAllocator<U>&) noexcept {}
  template <class U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;  // default-initialisation: no zeroing
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};
/// One attribute of every particle, contiguous.
template <class T>
using ParticleArray = std::vector<T, UninitializedAllocator<T>>;

/// One new particle's attributes, as an emitter samples them (emitter.hpp).
struct ParticleSpawn {
  float x = 0, y = 0, z = 0;     ///< position [m]; y is up
  float vx = 0, vy = 0, vz = 0;  ///< velocity [m/s]
  float lifetime = 1;            ///< [s], > 0
  float size = 0.1f;             ///< sprite edge [m]
  float r = 1, g = 1, b = 1;     ///< colour, linear, each in [0, 1]
  float alpha = 1;               ///< opacity in [0, 1]
  std::uint8_t emitter = 0;      ///< index of the emitter that made it (its rates, texture, blend)
  std::uint32_t id = 0;          ///< serial number of emission, to follow one particle's path
};

/// Struct-of-arrays storage for up to capacity() particles.
class Particles {
 public:
  /// Sizes every array for `capacity` particles once; later adds and removes never allocate.
  void reserve(std::size_t capacity);
  std::size_t capacity() const { return x.size(); }
  std::size_t size() const { return count_; }
  bool full() const { return count_ == capacity(); }
  /// Appends one particle with age 0. Returns false (and stores nothing) when full.
  bool add(const ParticleSpawn& spawn);
  /// Removes particle i by moving the last particle into its slot: O(1), order not kept.
  void swap_remove(std::size_t i);
  /// Removes every particle.
  void clear() { count_ = 0; }
  /// Bytes per particle over all arrays.
  static constexpr std::size_t bytes_per_particle =
      13 * sizeof(float) + sizeof(std::uint8_t) + sizeof(std::uint32_t);

  // The arrays, each of length capacity(); entries at and past size() are unspecified.
  ParticleArray<float> x, y, z;         ///< position [m]
  ParticleArray<float> vx, vy, vz;      ///< velocity [m/s]
  ParticleArray<float> age;             ///< time since emission [s]
  ParticleArray<float> lifetime;        ///< age at which it dies [s]
  ParticleArray<float> size_m;          ///< sprite edge [m]
  ParticleArray<float> r, g, b;         ///< colour, linear in [0, 1]
  ParticleArray<float> alpha;           ///< opacity in [0, 1]
  ParticleArray<std::uint8_t> emitter;  ///< which emitter made it
  ParticleArray<std::uint32_t> id;      ///< serial number of emission (never read by the update)

 private:
  std::size_t count_ = 0;
};

}  // namespace kit
