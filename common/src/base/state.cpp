#include <kit/base/state.hpp>

#include <fmt/format.h>

namespace kit {

std::string Divergence::describe() const {
  return fmt::format("diverged at step {} (t = {:.6g} s), |u| = {:.3g}", step, t, magnitude);
}

}  // namespace kit
