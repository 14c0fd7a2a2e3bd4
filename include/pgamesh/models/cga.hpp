// Conformal geometric algebra CGA R(4,1) for Euclidean objects (Hitzer, "Euclidean Geometric
// Objects in the Clifford Geometric Algebra of {Origin, 3-Space, Infinity}"): every formula, its
// equation and the corrections it relies on are in docs/models-cga.md; the conventions (the null
// basis, e_o·e_∞ = −1, Hitzer's eq. 9 sign) are docs/conventions.md §15.
//
//   cga_algebra.hpp  the null basis e_o, e1, e2, e3, e_∞, products, metric dual, blade keys
//   cga_point.hpp    up, down, weight, normalisation
//   cga_objects.hpp  point pairs, lines, circles, planes, spheres: direct and dual forms
//   cga_extract.hpp  centres, radii, directions, normals, distances; Kind classification
//   cga_motor.hpp    rotor, translator, dilator, motors and their sandwich action
//   cga_fit.hpp      least-squares sphere, plane and cylinder fits
#pragma once

#include "pgamesh/models/cga_algebra.hpp"
#include "pgamesh/models/cga_extract.hpp"
#include "pgamesh/models/cga_fit.hpp"
#include "pgamesh/models/cga_motor.hpp"
#include "pgamesh/models/cga_objects.hpp"
#include "pgamesh/models/cga_point.hpp"
#include "pgamesh/models/model_error.hpp"
