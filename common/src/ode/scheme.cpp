#include <kit/ode/scheme.hpp>

#include <kit/app/look.hpp>

namespace kit {

int order(Scheme s) {
  switch (s) {
    case Scheme::midpoint:
      return 2;
    case Scheme::rk4:
      return 4;
    default:
      return 1;
  }
}

int evaluations_per_step(Scheme s) {
  switch (s) {
    case Scheme::midpoint:
      return 2;
    case Scheme::rk4:
      return 4;
    default:
      return 1;
  }
}

const char* style(Scheme s) {
  switch (s) {
    case Scheme::explicit_euler:
      return look::explicit_euler.c_str();
    case Scheme::implicit_euler:
      return look::implicit_euler.c_str();
    case Scheme::symplectic_euler:
      return look::symplectic_euler.c_str();
    case Scheme::midpoint:
      return look::midpoint.c_str();
    case Scheme::rk4:
      return look::rk4.c_str();
  }
  return "";
}

const char* marker(Scheme s) {
  switch (s) {
    case Scheme::explicit_euler:
      return "pt 7 ps 0.7";
    case Scheme::implicit_euler:
      return "pt 6 ps 0.9";
    case Scheme::symplectic_euler:
      return "pt 5 ps 0.7";
    case Scheme::midpoint:
      return "pt 9 ps 0.9";
    case Scheme::rk4:
      return "pt 13 ps 0.9";
  }
  return "";
}

}  // namespace kit
