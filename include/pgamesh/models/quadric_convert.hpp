// Conversions of quadrics between the three models through their coefficients (Breuils §4–§8):
// the reciprocal operators read the ten coefficients of one model (eqs. 54, 59, 61) and the
// construction of the other builds its element (eqs. 10, 34, 74). docs/models-quadrics.md §5.
#pragma once

#include "pgamesh/models/dcga.hpp"
#include "pgamesh/models/dpga.hpp"
#include "pgamesh/models/qcga.hpp"

namespace pgamesh {

namespace dpga {
// Breuils eq. 71: Q_DPGA from q* through Q^k·q*.
inline Bivector from_qcga(const qcga::Vector& qstar) {
  return quadric(qcga::coefficients(qstar));
}
inline Bivector from_dcga(const clifford::Multivector& q) {
  return quadric(dcga::coefficients(q));
}
}  // namespace dpga

namespace qcga {
// Breuils eq. 74: q* from Q_DPGA through W^k·Q.
inline Vector from_dpga(const dpga::Bivector& q) {
  return dual_quadric(dpga::coefficients(q));
}
inline Vector from_dcga(const clifford::Multivector& q) {
  return dual_quadric(dcga::coefficients(q));
}
}  // namespace qcga

namespace dcga {
inline clifford::Multivector from_dpga(const dpga::Bivector& q) {
  return quadric(dpga::coefficients(q));
}
inline clifford::Multivector from_qcga(const qcga::Vector& qstar) {
  return quadric(qcga::coefficients(qstar));
}
}  // namespace dcga

}  // namespace pgamesh
