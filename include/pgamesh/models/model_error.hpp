#pragma once

#include <stdexcept>

namespace pgamesh {
struct ModelError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};
}  // namespace pgamesh
