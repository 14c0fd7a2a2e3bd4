// The general Clifford algebra engine: any signature R(p,q,r) or symmetric bilinear form (null
// bases through a change of basis), sparse multivectors, all the usual products and functions.
#pragma once

#include "pgamesh/algebra/clifford/algebra.hpp"
#include "pgamesh/algebra/clifford/blade.hpp"
#include "pgamesh/algebra/clifford/closed_forms.hpp"
#include "pgamesh/algebra/clifford/multivector.hpp"
#include "pgamesh/algebra/clifford/products.hpp"
