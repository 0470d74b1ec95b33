// Whether a state is still inside the model's domain, element by element, checked at a step's
// end (implicit: every accepted step; central differences: with each estimate of the critical
// step, 'Critical Step Interval'):
//
//  - inverted: det F <= 0 at a quadrature point of an element, or at a corner of a one-point
//    element (det F = det J(x) / det J(X) of the deformed and reference maps). A one-point
//    element's force sees only its mean gradient, an F-bar element's only its points' modified
//    F: an element tangled at its corners (one-point) or at a point (F-bar) can keep both
//    positive. A failure (exit 2).
//  - a small-strain block whose displacement gradient H (at each element's centre) has left the
//    small-strain domain: the strain ||sym H|| (Frobenius) or the rotation |skew H| (the
//    rotation vector's length, rad). Past kSmallStrainWarning (5 % / 0.05 rad, where the
//    rotation's spurious strain theta^2 / 2 reaches a steel's yield strain) a warning; past
//    kSmallStrainLimit (50 % / 0.5 rad: the linear strain measure no longer describes the motion)
//    a failure, as an inverted element is.
//
// `failure` and `warning` are one line each naming the element (the lowest-numbered one of the
// worst kind, so that the message does not depend on the number of ranks), its block and the
// value; empty when there is nothing to say. The same on every rank.
#pragma once
#include <string>

namespace choc {

struct ElementValidity {
  static constexpr double kSmallStrainWarning = 0.05, kSmallStrainLimit = 0.5;
  std::string failure, warning;
};

}  // namespace choc
