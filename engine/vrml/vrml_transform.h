// VRML97 Transform fields to matrices and back (ISO/IEC 14772-1, 6.52):
//   P' = T × C × R × SR × S × -SR × -C × P
// Composition is done in double precision; the writer decomposes a shape's matrix
// into the same fields (with center 0) so that reading its output gives the same
// single-precision matrix back.
#pragma once

#include <glm/glm.hpp>

namespace pw::engine::vrml {

struct TransformFields {
  glm::dvec3 translation{0.0};
  glm::dvec4 rotation{0.0, 0.0, 1.0, 0.0};  // axis, angle in radians
  glm::dvec3 scale{1.0};
  glm::dvec4 scaleOrientation{0.0, 0.0, 1.0, 0.0};
  glm::dvec3 center{0.0};
};

// Rotation matrix of an axis-angle; a zero axis gives the identity (the standard leaves
// it undefined; treating it as "no rotation" is what viewers do).
glm::dmat3 rotationMatrix(const glm::dvec4& axisAngle);
// The axis-angle of a rotation matrix (orthonormal, det +1); angle in [0, pi], axis
// (0 0 1) for the identity.
glm::dvec4 axisAngle(const glm::dmat3& rotation);

glm::dmat4 composeTransform(const TransformFields& fields);

// Splits an affine matrix into translation, rotation, scale and scaleOrientation
// (by singular value decomposition: A = U S V^T, rotation U V^T, scaleOrientation V).
// A mirror becomes a negative scale. Identity parts come out exactly as the defaults.
TransformFields decomposeTransform(const glm::dmat4& matrix);

// The single-precision matrix a shape stores. Entries of the 3x3 part smaller than
// 1e-12 of its largest entry are rounding noise of a 90-degree rotation and become 0,
// so that a file written from the matrix reads back to the same matrix.
glm::mat4 toFloatMatrix(const glm::dmat4& matrix);

// The closest rotation to the 3x3 part of a matrix (for placing viewpoints and light
// directions under scaled transforms).
glm::dmat3 rotationPart(const glm::dmat4& matrix);

}  // namespace pw::engine::vrml
