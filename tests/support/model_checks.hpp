// Checks shared by the tests of the models layer: points compared coordinate by coordinate, and
// the ModelError a call must throw with the words of its message.
#pragma once

#include <gtest/gtest.h>

#include <exception>
#include <string>

#include "pgamesh/core/vec3.hpp"
#include "pgamesh/models/model_error.hpp"

namespace pgamesh::test {

inline constexpr double pi = 3.14159265358979323846;

inline void expect_near(Vec3d a, Vec3d b, double tol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

// The message of the ModelError that f throws (a text saying otherwise when it throws nothing or
// something else, so that the caller's match fails).
template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const ModelError& e) {
    return e.what();
  } catch (const std::exception& e) {
    return std::string("wrong exception type: ") + e.what();
  }
  return "no exception";
}

}  // namespace pgamesh::test

// Expects `stmt` to throw a ModelError whose message contains `text`.
#define EXPECT_MODEL_ERROR(stmt, text)                                         \
  do {                                                                         \
    const std::string msg_ = ::pgamesh::test::error_of([&] { (void)(stmt); }); \
    EXPECT_NE(msg_.find(text), std::string::npos) << "message: " << msg_;      \
  } while (0)
