// Tank attitude → the up vector in the tank frame.
//
// Tank frame (right-handed): x forward, y left, z up (the level tank's up is +z unless --up says
// otherwise). Pitch θ about the lateral axis, positive nose up; roll φ about the forward axis,
// positive right side down. Order: the tank is rotated by the pitch, then by the roll about its
// own (pitched) forward axis — aerospace z-y-x order with no yaw (yaw does not move the fuel).
// The up vector (opposite of gravity) in the tank frame is the world's up seen from the rotated
// tank: for a level up of +z, up = (sin θ, sin φ cos θ, cos φ cos θ).
#pragma once

#include "pgamesh/core/vec3.hpp"

namespace pgamesh::tank {

/// The unit up vector in the tank frame for pitch and roll (radians), starting from the level
/// tank's up vector `level_up` (normalized). Built with the PGA rotors of docs/conventions.md §7:
/// R = R_pitch R_roll, up = R̃ level_up R.
Vec3d up_from_attitude(Vec3d level_up, double pitch, double roll);

/// The up vector for an apparent gravity (gravity minus the tank's acceleration, in the tank
/// frame, e.g. (0, 0, −9.81) at rest): up = −g/|g|. Throws for a zero or non-finite vector.
Vec3d up_from_gravity(Vec3d apparent_gravity);

}  // namespace pgamesh::tank
