// Compile-time graded multivectors of a diagonal signature R(p,q,r) with at most 8 generators:
// storage for exactly the grades present and products whose term lists and result grades are
// computed at compile time (docs/clifford.md, "graded"). The same blade masks, signs and product
// definitions as the general engine (pgamesh::clifford), which the tests check them against.
#pragma once

#include "pgamesh/algebra/graded/algebra.hpp"
#include "pgamesh/algebra/graded/convert.hpp"
#include "pgamesh/algebra/graded/multivector.hpp"
#include "pgamesh/algebra/graded/products.hpp"
