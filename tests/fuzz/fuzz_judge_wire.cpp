// The judge reads what a student's program sends (tests/grading/remote/wire.hpp): whatever the
// bytes, decoding either yields a value or throws ProtocolError, and never reads or allocates
// past the message. The first byte picks the type, as an entry point's signature would.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <kit/cloth/cloth_implicit_kernels.hpp>
#include <kit/ode/adaptive_run.hpp>

#include "remote/fields/adaptive_run.hpp"
#include "remote/fields/cloth_implicit_kernels.hpp"
#include "remote/fields/death.hpp"
#include "remote/fields/image.hpp"
#include "remote/wire.hpp"

namespace {
template <class T>
void decode(kit::remote::Reader& r) {
  T value{};
  kit::remote::get(r, value);
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  kit::remote::Reader r(data + 1, size - 1);
  try {
    switch (data[0] % 12) {
      case 0:
        decode<std::vector<double>>(r);
        break;
      case 1:
        decode<std::string>(r);
        break;
      case 2:
        decode<Eigen::MatrixXd>(r);
        break;
      case 3:
        decode<kit::Mat3>(r);
        break;
      case 4:
        decode<kit::SparseMatrix>(r);
        break;
      case 5:
        decode<kit::Springs>(r);
        break;
      case 6:
        decode<kit::Particles>(r);
        break;
      case 7:
        decode<kit::Image>(r);
        break;
      case 8:
        decode<kit::PcgResult>(r);
        break;
      case 9:
        decode<kit::AdaptiveRun<kit::Vec<1>>>(r);
        break;
      case 10:
        decode<std::vector<kit::Death>>(r);
        break;
      default: {
        kit::remote::RandomBytes bytes{};
        kit::remote::get(r, bytes);
        kit::Random random(1);
        kit::remote::restore(random, bytes);
        random.unit();
      }
    }
  } catch (const kit::remote::ProtocolError&) {
  }
  return 0;
}
