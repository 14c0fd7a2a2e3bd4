// PGA R(3,0,1), hand-specialised by grade (the hot path). Conventions: docs/conventions.md §1–§7 —
// basis 1, e0, e1, e2, e3, e01, e02, e03, e12, e31, e23, e021, e013, e032, e123, e0123;
// e0² = 0, e1² = e2² = e3² = 1; point (x,y,z) = e123 + x e032 + y e013 + z e021;
// plane a x + b y + c z + d = 0  ↔  a e1 + b e2 + c e3 + d e0; join A ∨ B = (A* ∧ B*)^(−*)
// (eq. 2.2).
//
// Grade types, named as klein names them: Plane (grade 1), Line (grade 2), Point (grade 3),
// Motor (even: scalar + bivector + pseudoscalar), and the full 16-component Multivector. The parts
// live in pga3/ (docs/pga3.md).
#pragma once

#include "pgamesh/algebra/pga3/batch.hpp"
#include "pgamesh/algebra/pga3/convert.hpp"
#include "pgamesh/algebra/pga3/exp_log.hpp"
#include "pgamesh/algebra/pga3/grades.hpp"
#include "pgamesh/algebra/pga3/join.hpp"
#include "pgamesh/algebra/pga3/linear.hpp"
#include "pgamesh/algebra/pga3/metric.hpp"
#include "pgamesh/algebra/pga3/motor.hpp"
#include "pgamesh/algebra/pga3/multivector.hpp"
#include "pgamesh/algebra/pga3/norm.hpp"
#include "pgamesh/algebra/pga3/products.hpp"
