#pragma once
// The placeholder students find in exercises/: it compiles, and fails at run time with a
// message that names the exercise and the file to edit.
#include <stdexcept>
#include <string>

namespace kit {

class NotImplemented : public std::logic_error {
 public:
  NotImplemented(const std::string& exercise, const std::string& file)
      : std::logic_error(exercise + " is not implemented yet: edit " + file + " (look for TODO(" + exercise +
                         "))") {}
};

}  // namespace kit
